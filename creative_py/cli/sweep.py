"""``creative sweep``: every combination of cases, strategies, seeds and world seeds, run
on Ray (or one after another), into sweep.csv and sweep.png."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from creative_py.cli.errors import fail, one_line_errors
from creative_py.cli.options import (
    CPUS_MAX, EVAL_TRIALS_MAX, PROFILE_HELP, ROOM_BELOW_OUT, TRIALS_MAX, backend_override,
    check_counts, path_option,
)
from creative_py.learning.strategies import STRATEGIES


def sweep(
    cases: list[str] = typer.Argument(..., help="Case ids (creative cases lists them)."),
    strategies: str = typer.Option("informative", "--strategies",
                                   help="Comma-separated: " + ", ".join(STRATEGIES) + "."),
    seeds: str = typer.Option("0", "--seeds", help="Seeds: N, A-B or a comma list."),
    world_seeds: Optional[str] = typer.Option(None, "--world-seeds", help="World seeds "
                                              "(N, A-B, a comma list); default: the world "
                                              "files as shipped."),
    out: str = typer.Option("runs", "--out", help="Parent folder of the sweep's folder."),
    address: Optional[str] = typer.Option(None, "--address", help="Attach to this Ray "
                                          "cluster instead of starting a local one."),
    num_cpus: Optional[int] = typer.Option(None, "--num-cpus", help="Cores of the local "
                                           "Ray instance (default: every core)."),
    serial: bool = typer.Option(False, "--serial", help="Run the runs one after another "
                                "in this process, without Ray."),
    fresh_workers: bool = typer.Option(False, "--fresh-workers", help="A fresh Ray worker "
                                       "process for every run (default: each worker runs "
                                       "several, one after another)."),
    phase: str = typer.Option("all", "--phase", help="use, create or all (every run)."),
    max_trials: Optional[int] = typer.Option(None, "--max-trials", help="N of Algorithm 1 "
                                             "(default: each manifest's trial_budget)."),
    eval_trials: int = typer.Option(4, "--eval-trials", help="Evaluation trials of the "
                                    "learned model."),
    video: str = typer.Option("none", "--video", help="MP4 clips of every run: none, key "
                              "or all (as creative run --video)."),
    prior: Optional[str] = typer.Option(None, "--prior", help="A prior for every run (as "
                                        "creative run --prior); {world} and {seed} in it "
                                        "stand for each run's world seed and seed."),
    robot: Optional[str] = typer.Option(None, "--robot", help=PROFILE_HELP),
) -> None:
    """Run every combination of cases, strategies, seeds and world seeds on Ray and
    write sweep.csv and sweep.png.

    SIGTERM or Ctrl-C stops the sweep in one line (the finished runs stay in
    sweep.csv) with exit code 143 or 130."""
    from creative_py.learning.clips import VIDEO_MODES
    from creative_py.learning.options import PHASES
    from creative_py.sweep import SweepOptions, SweepStopped, run_sweep

    out = path_option("--out", out, 2 * ROOM_BELOW_OUT)   # <sweep>/runs/<run>/...
    runs = _planned_runs(cases, strategies, seeds, world_seeds)
    if phase not in PHASES:
        fail(f"--phase must be one of {', '.join(PHASES)}, got {phase!r}")
    check_counts(("--max-trials", max_trials, 1, TRIALS_MAX),
                 ("--eval-trials", eval_trials, 0, EVAL_TRIALS_MAX),
                 ("--num-cpus", num_cpus, 1, CPUS_MAX))
    if out.exists() and not out.is_dir():
        fail(f"--out {out}: not a folder")
    if address is not None and not serial:
        _check_address(address)
    if video not in VIDEO_MODES:
        fail(f"--video must be one of {', '.join(VIDEO_MODES)}, got {video!r}")
    if prior is not None:
        _check_priors(prior, runs)
    backend_override(None, robot)
    opts = SweepOptions(phase=phase, max_trials=max_trials, eval_trials=eval_trials,
                        video=video, prior=prior, robot=robot)
    try:
        with one_line_errors():
            result = run_sweep(runs, out, opts, address=address, num_cpus=num_cpus,
                               serial=serial, fresh_workers=fresh_workers)
    except SweepStopped as exc:
        typer.echo(str(exc), err=True)
        raise typer.Exit(code=exc.exit_code) from None
    ok = sum(r["status"] == "ok" for r in result.rows)
    typer.echo(f"{result.folder}: {ok} of {len(result.rows)} runs ok in "
               f"{result.wall_time_s} s", err=True)
    typer.echo(str(result.folder))


def _planned_runs(cases: list[str], strategies: str, seeds: str,
                  world_seeds: Optional[str]) -> list:
    """Return the sweep's runs, every combination of ``cases``, ``--strategies``,
    ``--seeds`` and ``--world-seeds``, or fail in one line naming the wrong option."""
    from creative_py.sweep import parse_ints, parse_strategies, plan_runs

    try:
        names = parse_strategies(strategies)
        seed_list = parse_ints(seeds, "--seeds")
        worlds = parse_ints(world_seeds, "--world-seeds") if world_seeds is not None else [None]
        return plan_runs(cases, names, seed_list, worlds)
    except ValueError as exc:
        fail(str(exc))


def _check_address(address: str) -> None:
    """Fail in one line unless something accepts a connection at ``--address`` (Ray's
    ``host:port``) in time."""
    from creative_py.sweep import check_ray_address

    try:
        check_ray_address(address)
    except ValueError as exc:
        fail(str(exc))


def _check_priors(prior: str, runs: list) -> None:
    """Fail in one line unless ``--prior``, with each run's world seed and seed in it,
    names a run folder with a model.pl, or a model file, for every run."""
    from creative_py.learning.prior import model_file_of
    from creative_py.sweep import prior_for

    if not prior.strip():
        fail("--prior: empty")
    for spec in runs:
        given = Path(prior_for(spec, prior))
        if not model_file_of(given).is_file():
            fail(f"--prior {given}: "
                 + ("the run folder has no model.pl" if given.is_dir()
                    else "no such run folder or model file"))
