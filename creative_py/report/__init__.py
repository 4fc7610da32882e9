"""Reports of a run folder: the trial plot, the terminal table and the HTML page.

``plot`` draws ``trials.png`` (the paper's Figures 5 and 6); ``contents`` reads a run
folder into one value (:class:`~creative_py.report.contents.RunContents`) without writing
anything; ``headline`` says what the run did in a few sentences; ``table`` prints it as
rich tables in a terminal; ``page`` writes it as ``report.html`` beside the files it
shows, with relative links only. :func:`write_reports` is what a finished run calls.
"""

from __future__ import annotations

from pathlib import Path
from typing import Union

from creative_py.records.summary import RunSummary
from creative_py.report.plot import MARKERS, Trials, plot_title, plot_trials, trial_labels


def write_reports(run_dir: Union[Path, str], trials: Trials, summary: RunSummary) -> None:
    """Write the reports of a finished run into its folder: ``trials.png`` of its
    ``trials`` (titled with the summary's case and seed) and, last, ``report.html``
    (of the folder as written, its ``summary.json`` included)."""
    from creative_py.report.page import write_html_report

    plot_trials(trials, Path(run_dir) / "trials.png", title=plot_title(summary))
    write_html_report(run_dir)


__all__ = ["MARKERS", "plot_title", "plot_trials", "trial_labels", "write_reports"]
