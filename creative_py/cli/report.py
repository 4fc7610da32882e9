"""``creative report``: a run folder summarised in the terminal (and, if asked, its plot
redrawn and its HTML page written)."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from creative_py.cli.errors import fail, one_line_errors
from creative_py.cli.options import usable


def report(run_dir: Path = typer.Argument(..., help="A run folder."),
           plot: bool = typer.Option(False, "--plot", help="Also redraw trials.png from "
                                     "the readable trials."),
           html: bool = typer.Option(False, "--html", help="Also write report.html in the "
                                     "run folder: trials, plot, video clips, created tools, "
                                     "hypotheses, plan."),
           width: Optional[int] = typer.Option(None, "--width", help="Width of the "
                                               "table (default: the terminal's; the widest "
                                               "row's when not a terminal).")) -> None:
    """Summarise a run folder: every trial in full (phase, tool, variant, location, pose,
    tested and violated literals, outcome, reason), the learned hypotheses, the plan,
    created tools. Writes nothing unless --plot or --html is given."""
    from rich.console import Console

    from creative_py.report import plot_trials
    from creative_py.report.contents import read_run
    from creative_py.report.page import write_html_report
    from creative_py.report.table import print_report

    usable("RUN_DIR", run_dir)
    if width is not None and width < 40:
        fail(f"--width {width}: under 40 columns")
    if width is not None and width > 1000:
        fail(f"--width {width}: over 1000 columns")
    try:
        contents = read_run(run_dir)
    except (FileNotFoundError, ValueError) as exc:  # not a run folder, trials.jsonl a folder
        fail(str(exc))
    for w in contents.warnings:
        typer.echo(f"warning: {w}", err=True)
    console = Console()
    print_report(contents, console, width)
    with one_line_errors():
        if plot:
            png = plot_trials(contents.trials, Path(run_dir) / "trials.png", title=str(run_dir))
            console.print(f"plot: {png}", markup=False, highlight=False, soft_wrap=True)
        if html:
            page = write_html_report(run_dir)
            console.print(f"html: {page}", markup=False, highlight=False, soft_wrap=True)
