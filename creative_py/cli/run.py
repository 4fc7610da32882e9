"""``creative run``: a case end to end into a new run folder, or an interrupted run
folder resumed (``--resume``); Ctrl-C exits 130 and a lost backend 75, each with how to
go on."""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Optional

import typer

from creative_py.cli.errors import DEBUG, fail, one_line_errors, stdout_to_stderr
from creative_py.cli.options import (
    BACKEND_HELP, EVAL_TRIALS_MAX, PROFILE_HELP, ROOM_BELOW_OUT, SEED_MAX, TRIALS_MAX,
    backend_override, case_manifest, check_counts, given_options, need_display, path_option,
)
from creative_py.learning.strategies import UnknownStrategy, strategies_help


def run(
    ctx: typer.Context,
    case: str = typer.Argument(..., help="A case id (creative cases lists them)."),
    seed: int = typer.Option(0, "--seed", help="Seed of the physics and sensor noise."),
    out: str = typer.Option("runs", "--out", help="Parent folder of the run folder."),
    phase: str = typer.Option("all", "--phase", help="use (tool-use learning only), "
                              "create or all (then tool creation on the harder task)."),
    max_trials: Optional[int] = typer.Option(None, "--max-trials", help="N of Algorithm 1 "
                                             "(default: the case manifest's trial_budget)."),
    consecutive: int = typer.Option(2, "--consecutive", help="K of Algorithm 1."),
    eval_trials: int = typer.Option(4, "--eval-trials", help="Evaluation trials of the "
                                    "learned model after tool-use learning."),
    strategy: str = typer.Option("informative", "--strategy", help="How experiments are "
                                 "chosen: " + strategies_help() + "."),
    world: Optional[str] = typer.Option(None, "--world", help="World folder (default: the "
                                         "shipped one of the case)."),
    resume: Optional[str] = typer.Option(None, "--resume", help="Resume this interrupted "
                                          "run folder: replay its recorded trials without "
                                          "physics, then go on with the options recorded "
                                          "in its run.json (no other option may be "
                                          "given)."),
    video: str = typer.Option("key", "--video", help="MP4 clips in videos/: key (the "
                              "demonstration, the first success, each creation trial, the "
                              "first trial of each failure reason), all or none."),
    gui: bool = typer.Option(False, "--gui", help="Show the trials in pybullet's GUI "
                             "(needs a display)."),
    world_seed: Optional[int] = typer.Option(None, "--world-seed", help="Draw a randomised "
                                             "world from the case's manifest (catalogue "
                                             "numbers inside their qualitative ranges, "
                                             "order shuffled, locations jittered); the "
                                             "same N gives the same world."),
    catalogue_first: Optional[bool] = typer.Option(
        None, "--catalogue-first/--no-catalogue-first", help="Before manufacturing a tool "
        "for the harder task, try the catalogued objects the generalised model admits; "
        "make a tool only if none succeeds (default: on, except with --strategy paper)."),
    demonstrate_creation: bool = typer.Option(
        False, "--demonstrate-creation", help="When a catalogued object solved the harder "
        "task, still create a tool afterwards as a demonstration (make hook does)."),
    prior: Optional[str] = typer.Option(None, "--prior", help="Transfer: start tool-use "
                                        "learning from another case's learned model (its "
                                        "run folder or model.pl) where the ontology maps "
                                        "its literals; test only the rest."),
    backend: Optional[str] = typer.Option(None, "--backend", help=BACKEND_HELP),
    robot: Optional[str] = typer.Option(None, "--robot", "--robot-profile", help=PROFILE_HELP),
) -> None:
    """Run a case end to end and write its run folder (trials, model, PDDL, tools, plot,
    video clips)."""
    out, world = path_option("--out", out, ROOM_BELOW_OUT), path_option("--world", world)
    resume = path_option("--resume", resume, ROOM_BELOW_OUT)
    if video not in ("all", "key", "none"):
        fail(f"--video must be all, key or none, got {video!r}")
    if gui:
        need_display()
    if resume is not None:
        _resume(ctx, case, resume)
        return
    case_manifest(case, world)
    backend_override(backend, robot)
    check_counts(("--seed", seed, 0, SEED_MAX), ("--max-trials", max_trials, 1, TRIALS_MAX),
                 ("--consecutive", consecutive, 1, TRIALS_MAX),
                 ("--eval-trials", eval_trials, 0, EVAL_TRIALS_MAX),
                 ("--world-seed", world_seed, 0, SEED_MAX))
    if out.exists() and not out.is_dir():
        fail(f"--out {out}: not a folder")
    opts = _run_options(seed=seed, phase=phase, max_trials=max_trials,
                        consecutive=consecutive, eval_trials=eval_trials, video=video,
                        gui=gui, strategy=strategy, world_seed=world_seed,
                        catalogue_first=catalogue_first,
                        demonstrate_creation=demonstrate_creation, prior=prior,
                        backend=backend, robot=robot)
    _run_case(case, out, world, opts, max_trials)


def _resume(ctx: typer.Context, case: str, resume: Path) -> None:
    """Go on with the interrupted run folder ``resume`` of ``case`` with the options its
    run.json records (no other option may be given), and print its folder; fail in one
    line if it is no resumable run of ``case``."""
    from rich.console import Console

    from creative_py.learning.options import read_run_json
    from creative_py.learning.run import resume_run
    from creative_py.report.progress import RunProgress
    from creative_py.world_files import WorldFileError

    given = given_options(ctx, exclude=("case", "resume"))
    if given:
        fail(f"{', '.join(given)}: not allowed with --resume (a resumed run uses the "
             f"options recorded in {resume / 'run.json'})")
    if not (resume / "run.json").is_file():
        fail(f"--resume {resume}: not a resumable run folder (no run.json)")
    try:
        recorded = read_run_json(resume)[0]
    except ValueError as exc:
        fail(str(exc))
    if recorded != case:
        fail(f"--resume {resume}: the run is not of case {case!r}")
    try:
        with interrupt_exits(), one_line_errors(), stdout_to_stderr():
            with RunProgress(Console(stderr=True)) as progress:
                folder = resume_run(resume, progress=progress)
    except (WorldFileError, ValueError) as exc:
        fail(str(exc))
    typer.echo(str(folder.path))


def _run_options(**fields):
    """Return the run's :class:`~creative_py.learning.options.RunOptions` from the
    command line's ``fields``, or fail in one line naming the option it refuses."""
    from creative_py.learning.options import RunOptions

    try:
        return RunOptions(**fields)
    except UnknownStrategy as exc:
        fail(f"--strategy: {exc}")
    except ValueError as exc:
        fail(f"--phase: {exc}" if "phase" in str(exc) else str(exc))


def _run_case(case: str, out: Path, world: Optional[Path], opts, max_trials: Optional[int]) -> None:
    """Run ``case`` end to end with ``opts`` into a new run folder under ``out`` (the
    live progress line on stderr), and print its folder; fail in one line on bad input."""
    from rich.console import Console

    from creative_py.learning.run import run_case
    from creative_py.report.progress import RunProgress
    from creative_py.world_files import WorldFileError

    try:
        with interrupt_exits(), one_line_errors(), stdout_to_stderr():
            with RunProgress(Console(stderr=True), _budget(case, world, max_trials)) as progress:
                folder = run_case(case, out, opts, progress=progress, world_dir=world)
    except (WorldFileError, ValueError) as exc:
        fail(str(exc))
    except OSError as exc:
        fail(f"{exc.filename or out}: {exc.strerror or exc}")
    typer.echo(str(folder.path))


@contextmanager
def interrupt_exits() -> Iterator[None]:
    """Ctrl-C (SIGINT) at any moment of a run ends it with exit code 130 (the run has
    printed how to resume it), even when something on its way swallowed the
    KeyboardInterrupt (:mod:`creative_py.learning.interrupts`). A backend lost mid-run
    (:class:`creative_py.simulator.BackendLost`: an arm gone silent) ends it with one
    line naming what went away and how to resume, exit code 75 (EX_TEMPFAIL)."""
    from creative_py.learning import interrupts

    from creative_py.simulator import BackendLost

    try:
        with interrupts.watching():
            yield
    except KeyboardInterrupt:
        raise typer.Exit(130) from None
    except BackendLost as exc:  # the arm or simulator went away: resumable, exit 75
        if DEBUG["on"]:
            raise
        hint = getattr(exc, "resume_command", None)
        typer.echo(f"error: the backend was lost: {' '.join(str(exc).split())}"
                   + (f"; the run stopped, to go on: {hint}" if hint else ""), err=True)
        raise typer.Exit(75) from None
    if interrupts.interrupted():
        typer.echo("interrupted (Ctrl-C) as the run ended; its folder is complete", err=True)
        raise typer.Exit(130)


def _budget(case: str, world: Optional[Path], max_trials: Optional[int]) -> Optional[int]:
    """The tool-use trial budget a run will have (for its progress line)."""
    if max_trials is not None:
        return max_trials
    try:
        return case_manifest(case, world).trial_budget
    except Exception:  # noqa: BLE001 - the run itself reports a bad case or world
        return None
