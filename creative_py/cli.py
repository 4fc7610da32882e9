"""The ``creative`` command line.

``creative run CASE`` runs a case end to end (demonstration, tool-use learning, tool
creation) and writes a run folder; ``creative repl [RUN]`` opens SWI-Prolog with the
engine (and a run's learned model) loaded; ``creative report RUN`` summarises a run
folder; ``creative make-tool CASE SPEC`` sizes and writes a tool from a qualitative spec.
``creative trial CASE ...`` runs one physical trial in pybullet and prints its result
(JSON with ``--json``); ``creative trial CASE --list`` prints the case's objects,
locations, variants and default pose as JSON; ``creative cases`` lists the cases. The
command is generic: a case is a world folder with a ``case.toml`` manifest
(:mod:`creative_py.case`).
"""

from __future__ import annotations

import errno
import json
import logging
import os
import sys
import traceback
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Optional

import typer

from creative_py.learning.strategies import STRATEGIES, UnknownStrategy, strategies_help

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="CREATIVE: learn to use tools from one demonstration, and create new ones.")


def _flags_take_no_value() -> None:
    """Show no value type beside a plain flag (``--gui``, ``--help``) in ``--help``:
    typer's rich help panel labels every flag ``<bool>`` although a flag takes no value
    (its plain help, ``get_help_record``, already leaves flags out)."""
    from typer.core import TyperOption

    shown = TyperOption.display_type_rich
    if getattr(shown, "creative_flags", False):
        return

    def display_type_rich(self, ctx):  # type: ignore[no-untyped-def]
        return None if self.is_flag or self.count else shown(self, ctx)

    display_type_rich.creative_flags = True  # type: ignore[attr-defined]
    TyperOption.display_type_rich = display_type_rich  # type: ignore[method-assign]


_flags_take_no_value()


_DEBUG = {"on": False}
"""Whether ``--debug`` was given: then an error shows its traceback."""


@app.callback()
def main(ctx: typer.Context,
         verbose: bool = typer.Option(False, "--verbose", "-v", help="Log progress."),
         debug: bool = typer.Option(False, "--debug", help="Show the traceback of an "
                                    "error instead of its one-line message.")) -> None:
    """CREATIVE in Python and Prolog (Wicaksono & Sammut, IJECE 2020)."""
    _DEBUG["on"] = debug
    logging.basicConfig(level=logging.INFO if verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")


@contextmanager
def _one_line_errors() -> Iterator[None]:
    """Turn what user data can cause (a world or ontology file, Prolog's answer to it, the
    file system) into one line ``error: ...`` and exit code 2; ``--debug`` re-raises."""
    from creative_py.bridge import BridgeError
    from creative_py.mesh.slicer import SliceError
    from creative_py.world_files import WorldFileError

    try:
        yield
    except (BridgeError, WorldFileError, OSError, SliceError) as exc:
        if _DEBUG["on"]:
            raise
        text = " ".join(str(exc).split())
        if isinstance(exc, OSError) and exc.filename:
            text = f"{exc.filename}: {exc.strerror or exc}"
        _fail(text)


@contextmanager
def _stdout_to_stderr() -> Iterator[None]:
    """Send what C libraries print to stdout (pybullet's banner and URDF warnings) to
    stderr, so that stdout carries only the command's output (e.g. one JSON line)."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        os.dup2(2, 1)
        yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(saved)


def _fail(message: str) -> None:
    """Print ``error: message`` and exit with code 2; under ``--debug``, when an
    exception is being handled, its traceback first."""
    if _DEBUG["on"] and sys.exc_info()[1] is not None:
        traceback.print_exc()
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)


SEED_MAX = 2 ** 63 - 1
"""The largest seed (``--seed``, ``--world-seed``): a 64-bit signed integer."""

TRIALS_MAX = 10000
"""The largest ``--max-trials`` and ``--consecutive``."""

EVAL_TRIALS_MAX = 1000
"""The largest ``--eval-trials``."""

CPUS_MAX = 1024
"""The largest ``--num-cpus``."""


def _check_counts(*checks: tuple[str, Optional[int], int, int]) -> None:
    """Fail in one line unless each ``(option, value, least, most)`` has its value
    (when given) within ``least..most``."""
    for option, value, least, most in checks:
        if value is None:
            continue
        if value < least:
            _fail(f"{option} must be at least {least}, got {value}")
        if value > most:
            _fail(f"{option} must be at most {most}, got {value}")


def _path(option: str, text: Optional[str], room: int = 0) -> Optional[Path]:
    """Return the path an option names (None if not given); fail in one line on an
    empty one (``--out ''`` would otherwise mean the current folder), or as
    :func:`_usable` does."""
    if text is None:
        return None
    if not text.strip():
        _fail(f"{option} must name a folder, got an empty string")
    return _usable(option, Path(text), room)


def _usable(option: str, path: Path, room: int = 0) -> Path:
    """Return ``path`` if the file system can look it up, and, for a folder the command
    writes below, if ``room`` more bytes of path fit under Linux's PATH_MAX (a run's
    folder and files: :data:`ROOM_BELOW_OUT`); fail in one line naming the option
    otherwise (a component longer than the file system allows, ENAMETOOLONG, which
    ``Path.exists`` raises; a run that would fail at its first deep file)."""
    text = str(path)
    shown = text if len(text) <= 80 else f"{text[:60]}...{text[-12:]}"
    longest = max((len(os.fsencode(p)) for p in path.parts), default=0)
    if longest > NAME_MAX:  # even below a folder not made yet
        _fail(f"{option} {shown}: {os.strerror(errno.ENAMETOOLONG)} (a name of {longest} "
              f"bytes, at most {NAME_MAX})")
    length = len(os.fsencode(os.path.abspath(path)))
    if room and length + room > PATH_MAX:
        _fail(f"{option} {shown}: {os.strerror(errno.ENAMETOOLONG)} (a path of {length} "
              f"bytes leaves no room for the {room} bytes of what is written below it; "
              f"at most {PATH_MAX - room})")
    try:
        path.exists()
    except OSError as exc:
        _fail(f"{option} {shown}: {exc.strerror or exc}")
    return path


NAME_MAX = 255
"""The longest file name (one path component), bytes: Linux's NAME_MAX."""

PATH_MAX = 4095
"""The longest path, bytes: Linux's PATH_MAX (4096) less its terminating NUL."""

ROOM_BELOW_OUT = 256
"""The bytes of path a run writes below ``--out`` (its folder ``<case>-<time>-s<seed>``
and, deepest, ``tools/<tool>/ros/<tool>_description/meshes/<file>``), with room to
spare; a sweep's run folders sit one level deeper."""

TOOL_NAME_MAX = 200
"""The longest ``make-tool --name``: its files' names add to it (``<name>_description``,
the writer's temporary ``.<name>.<random>.tmp``) and must stay within NAME_MAX."""


def _name(option: str, text: Optional[str]) -> Optional[str]:
    """Return a name an option gives (None if not given); fail in one line on an empty
    one (``--variant ''`` would otherwise mean the default), or as :func:`_text`."""
    if text is not None and not text.strip():
        _fail(f"{option} must not be empty")
    return _text(option, text)


def _text(option: str, text: Optional[str]) -> Optional[str]:
    """Return text an option gives for the engine (a name, a spec, Prolog text); fail
    in one line when the command line held bytes that are not UTF-8 (Python keeps them
    as lone surrogates, which no encoder takes)."""
    if text is not None:
        try:
            text.encode("utf-8")
        except UnicodeEncodeError as exc:
            byte = os.fsencode(text[exc.start:exc.start + 1])
            _fail(f"{option}: not UTF-8 text (byte 0x{byte[0]:02x} at character "
                  f"{exc.start + 1})")
    return text


def _need_display(manifest=None) -> None:
    """Fail in one line unless the simulator's window can open (the display is set and
    can be opened: pybullet aborts the process on one it cannot open): the window of
    ``manifest``'s backend, or the default backend's before a manifest is read."""
    from creative_py.learning.checks import require_display

    try:
        require_display(manifest)
    except ValueError as exc:
        _fail(str(exc))


def _backend_override(backend: Optional[str], robot: Optional[str]) -> None:
    """Check ``--backend`` (a registered backend whose packages are installed) and
    ``--robot`` (a robot profile that loads), or fail in one line."""
    from creative_py.robots import load_profile
    from creative_py.simulator.loader import BackendError, backend as load_backend
    from creative_py.world_files import WorldFileError

    if backend is not None:
        try:
            load_backend(backend)
        except BackendError as exc:
            _fail(f"--backend {backend}: {exc}")
    if robot is not None:
        if not robot.strip():
            _fail("--robot must not be empty")
        try:
            load_profile(robot)
        except WorldFileError as exc:
            _fail(f"--robot {robot}: {exc}")


_BACKEND_HELP = ("Run on this simulator backend instead of the case manifest's (ros: the "
                 "arm over ROS 2, docs/real-robot.md).")
_PROFILE_HELP = ("The robot: a profile under robots/ (creative robots lists them) or a "
                 ".toml path; default: the case's robot. --robot-profile is a synonym.")


@app.command()
def robots(
    names: Optional[list[str]] = typer.Argument(None, help="Profiles to check: names under "
                                                "robots/ or .toml paths (default: every "
                                                "shipped profile)."),
) -> None:
    """List the robot profiles, each with a one-line check: the URDF loads, the joints
    and links are found, the home posture is reachable (docs/robots.md).

    Exit 2 if a profile fails its check (each failure is one line naming the file and
    the field)."""
    from creative_py.case import DEFAULT_BACKEND
    from creative_py.robots import profile_names
    from creative_py.simulator.loader import backend as load_backend
    from creative_py.world_files import WorldFileError

    physics = load_backend(DEFAULT_BACKEND)
    specs = names or profile_names()
    width = max(len(str(s)) for s in specs)
    failed = 0
    for spec in specs:
        try:
            with _stdout_to_stderr():
                line = physics.check_profile(spec)
        except (WorldFileError, FileNotFoundError) as exc:
            failed += 1
            line = f"FAILED: {exc}"
        typer.echo(f"{str(spec):<{width}} {line}")
    if failed:
        raise typer.Exit(2)


@app.command()
def cases(as_json: bool = typer.Option(False, "--json", help="Print the cases as JSON.")) -> None:
    """List the cases: id, world folder, variants (the harder one marked) and trial budget.

    A case folder whose manifest does not load is listed as broken with its error line;
    the other cases still load and run.
    """
    from creative_py.case import broken_cases, load_cases

    found = load_cases(strict=False)
    broken = broken_cases()
    listing = [m.listing() for m in found.values()]
    if as_json:
        listing += [{"id": None, "manifest": str(path), "broken": error}
                    for path, error in broken.items()]
        typer.echo(json.dumps(listing, indent=2))
        return
    width = max([len("broken")] + [len(c["id"]) for c in listing])  # the longest id's
    for c in listing:
        variants = ", ".join(v["name"] + (" (harder)" if v["harder"] else "")
                             for v in c["variants"])
        typer.echo(f"{c['id']:<{width}} {c['title']}\n{'':<{width}} world {c['world']}; "
                   f"variants {variants}; trial budget {c['trial_budget']}")
    for error in dict.fromkeys(broken.values()):  # a duplicate id: one line, both folders
        typer.echo(f"{'broken':<{width}} {error}")


def _manifest(case: str, world: Optional[Path]):
    """Return the manifest of ``case`` (from ``world`` if given), or fail in one line."""
    from creative_py.case import get_case, read_manifest
    from creative_py.world_files import WorldFileError

    try:
        m = get_case(case) if world is None else read_manifest(world)
    except KeyError as exc:
        _fail(exc.args[0])
    except WorldFileError as exc:
        _fail(str(exc))
    if m.id != case:
        _fail(f"{world / 'case.toml'}: declares case {m.id!r}, not {case!r}")
    return m


@app.command()
def trial(
    case: str = typer.Argument(..., help="A case id (creative cases lists them)."),
    tool: Optional[str] = typer.Option(None, "--tool", "--object", "-t",
                                       help="The object used as a tool (--object is a synonym)."),
    location: int = typer.Option(1, "--location", "-l", help="Predefined target location, 1-based."),
    variant: Optional[str] = typer.Option(None, "--variant",
                                          help="Task variant; default: the demonstration's."),
    pose: Optional[str] = typer.Option(None, "--pose",
                                       help="Pose numbers relative to the target, comma "
                                            "separated, as the case manifest's [pose] names "
                                            "them (hook: DX,DY,ROLL in m, m, rad); default: "
                                            "the demonstration's."),
    seed: int = typer.Option(0, "--seed", help="Seed of every random choice (sensor noise)."),
    as_json: bool = typer.Option(False, "--json", help="Print the result as one JSON line."),
    save_images: Optional[str] = typer.Option(None, "--save-images",
                                               help="Save camera snapshots in this folder."),
    gui: bool = typer.Option(False, "--gui", help="Show the pybullet GUI (needs a display)."),
    world: Optional[str] = typer.Option(None, "--world", help="World folder (default: the "
                                        "shipped one of the case)."),
    list_: bool = typer.Option(False, "--list", help="Print objects, locations, variants "
                               "and the default pose as JSON, and exit."),
    backend: Optional[str] = typer.Option(None, "--backend", help=_BACKEND_HELP),
    robot: Optional[str] = typer.Option(None, "--robot", "--robot-profile", help=_PROFILE_HELP),
) -> None:
    """Run one physical trial and report its outcome (success, failure, blocked,
    unreachable or invalid)."""
    variant = _name("--variant", variant)
    save_images, world = _path("--save-images", save_images, 64), _path("--world", world)
    _backend_override(backend, robot)
    with _one_line_errors(), _stdout_to_stderr():
        lines = _trial(case, tool, location, variant, pose, seed, as_json, save_images, gui,
                       world, list_, backend, robot)
    for line in lines:
        typer.echo(line)


def _trial(case, tool, location, variant, pose, seed, as_json, save_images, gui, world,
           list_, backend=None, robot=None) -> list[str]:
    out: list[str] = []
    from creative_py.bridge import Engine
    from creative_py.learning.poses import pose_resolver
    from creative_py.records.trial import verdict_words
    from creative_py.simulator import backend_for
    from creative_py.simulator.trial import run_trial
    from creative_py.world_files import WorldFileError

    m = _manifest(case, world)
    if backend is not None and backend != m.backend:
        from dataclasses import replace

        m = replace(m, backend=backend)
    if robot is not None and m.robot is None:
        _fail(f"--robot {robot}: the case {case} runs in the {m.backend!r} backend, which "
              "brings its own arm")
    if robot is not None:
        from dataclasses import replace

        m = replace(m, robot=robot)  # the backend builds this arm
    _check_counts(("--seed", seed, 0, SEED_MAX))
    if save_images is not None and save_images.exists() and not save_images.is_dir():
        _fail(f"--save-images {save_images}: not a folder")
    try:
        physics = backend_for(m)
        w = physics.load_world(m)
    except WorldFileError as exc:
        _fail(str(exc))
    if gui:
        _need_display(m)
    if list_:
        return [json.dumps(w.listing(), indent=2, sort_keys=True)]
    objects = list(w.catalogue)
    if tool is None:
        _fail(f"--tool is required; available: {', '.join(objects)}")
    if tool not in objects:
        _fail(f"unknown tool {tool!r}; available: {', '.join(objects)}")
    variant = variant or m.demonstration.variant
    if variant not in m.variant_names:
        _fail(f"unknown variant {variant!r}; variants: {', '.join(m.variant_names)}")
    if location not in w.locations:
        _fail(f"--location must lie in 1..{len(w.locations)}, got {location}")
    parsed = None
    if pose is not None:
        try:
            parsed = m.parse_pose(pose)
        except ValueError as exc:
            _fail(str(exc))
    result = run_trial(w, tool, variant, location, pose=parsed, seed=seed,
                       images_dir=save_images, gui=gui,
                       pose_target=pose_resolver(Engine.instance(), m))
    if as_json:
        return [result.to_json()]
    p = ", ".join(f"{v:g}" for v in result.pose)
    out.append(f"{case} trial: {tool} at location {location} ({variant}), pose ({p}) -> "
               f"{result.outcome}" + (f": {result.reason}" if result.reason else ""))
    if result.verdict:
        out.append(f"  measured: {verdict_words(result.verdict)}")
    out.append(f"  {result.steps} steps, {result.sim_time_s:.2f} s simulated, "
               f"{result.wall_time_s:.2f} s wall ({result.render_time_s:.2f} s rendering)")
    for name, truth in sorted(result.true_final.items()):
        seen = (result.perceived_final or {}).get(name)
        seen_txt = ("perceived (" + ", ".join(f"{v:.3f}" for v in seen) + ")"
                    if seen is not None else "not perceived")
        out.append(f"  {name}: true (" + ", ".join(f"{v:.3f}" for v in truth) + f"), {seen_txt}")
    return out


@app.command()
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
    robot: Optional[str] = typer.Option(None, "--robot", help=_PROFILE_HELP),
) -> None:
    """Run every combination of cases, strategies, seeds and world seeds on Ray and
    write sweep.csv and sweep.png.

    SIGTERM or Ctrl-C stops the sweep in one line (the finished runs stay in
    sweep.csv) with exit code 143 or 130."""
    from creative_py.learning.options import PHASES
    from creative_py.sweep import (SweepOptions, SweepStopped, parse_ints,
                                   parse_strategies, plan_runs, run_sweep)

    out = _path("--out", out, 2 * ROOM_BELOW_OUT)   # <sweep>/runs/<run>/...
    try:
        names = parse_strategies(strategies)
        seed_list = parse_ints(seeds, "--seeds")
        worlds = parse_ints(world_seeds, "--world-seeds") if world_seeds is not None else [None]
        runs = plan_runs(cases, names, seed_list, worlds)
    except ValueError as exc:
        _fail(str(exc))
    if phase not in PHASES:
        _fail(f"--phase must be one of {', '.join(PHASES)}, got {phase!r}")
    _check_counts(("--max-trials", max_trials, 1, TRIALS_MAX),
                  ("--eval-trials", eval_trials, 0, EVAL_TRIALS_MAX),
                  ("--num-cpus", num_cpus, 1, CPUS_MAX))
    if out.exists() and not out.is_dir():
        _fail(f"--out {out}: not a folder")
    if address is not None and not serial:
        from creative_py.sweep import check_ray_address

        try:
            check_ray_address(address)
        except ValueError as exc:
            _fail(str(exc))
    from creative_py.learning.clips import VIDEO_MODES

    if video not in VIDEO_MODES:
        _fail(f"--video must be one of {', '.join(VIDEO_MODES)}, got {video!r}")
    if prior is not None:
        from creative_py.learning.prior import model_file_of
        from creative_py.sweep import prior_for

        if not prior.strip():
            _fail("--prior: empty")
        for spec in runs:
            given = Path(prior_for(spec, prior))
            if not model_file_of(given).is_file():
                _fail(f"--prior {given}: "
                      + ("the run folder has no model.pl" if given.is_dir()
                         else "no such run folder or model file"))
    _backend_override(None, robot)
    opts = SweepOptions(phase=phase, max_trials=max_trials, eval_trials=eval_trials,
                        video=video, prior=prior, robot=robot)
    try:
        with _one_line_errors():
            result = run_sweep(runs, out, opts, address=address, num_cpus=num_cpus,
                               serial=serial, fresh_workers=fresh_workers)
    except SweepStopped as exc:
        typer.echo(str(exc), err=True)
        raise typer.Exit(code=exc.exit_code) from None
    ok = sum(r["status"] == "ok" for r in result.rows)
    typer.echo(f"{result.folder}: {ok} of {len(result.rows)} runs ok in "
               f"{result.wall_time_s} s", err=True)
    typer.echo(str(result.folder))


@app.command()
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
    backend: Optional[str] = typer.Option(None, "--backend", help=_BACKEND_HELP),
    robot: Optional[str] = typer.Option(None, "--robot", "--robot-profile", help=_PROFILE_HELP),
) -> None:
    """Run a case end to end and write its run folder (trials, model, PDDL, tools, plot,
    video clips)."""
    from rich.console import Console

    from creative_py.learning.options import RunOptions, read_run_json
    from creative_py.learning.run import resume_run, run_case
    from creative_py.report.progress import RunProgress
    from creative_py.world_files import WorldFileError

    console = Console(stderr=True)
    out, world = _path("--out", out, ROOM_BELOW_OUT), _path("--world", world)
    resume = _path("--resume", resume, ROOM_BELOW_OUT)
    if video not in ("all", "key", "none"):
        _fail(f"--video must be all, key or none, got {video!r}")
    if gui:
        _need_display()
    if resume is not None:
        given = _given_options(ctx, exclude=("case", "resume"))
        if given:
            _fail(f"{', '.join(given)}: not allowed with --resume (a resumed run uses the "
                  f"options recorded in {resume / 'run.json'})")
        if not (resume / "run.json").is_file():
            _fail(f"--resume {resume}: not a resumable run folder (no run.json)")
        try:
            recorded = read_run_json(resume)[0]
        except ValueError as exc:
            _fail(str(exc))
        if recorded != case:
            _fail(f"--resume {resume}: the run is not of case {case!r}")
        try:
            with _interrupt_exits(), _one_line_errors(), _stdout_to_stderr():
                with RunProgress(console) as progress:
                    folder = resume_run(resume, progress=progress)
        except (WorldFileError, ValueError) as exc:
            _fail(str(exc))
        typer.echo(str(folder.path))
        return
    _manifest(case, world)
    _backend_override(backend, robot)
    _check_counts(("--seed", seed, 0, SEED_MAX), ("--max-trials", max_trials, 1, TRIALS_MAX),
                  ("--consecutive", consecutive, 1, TRIALS_MAX),
                  ("--eval-trials", eval_trials, 0, EVAL_TRIALS_MAX),
                  ("--world-seed", world_seed, 0, SEED_MAX))
    if out.exists() and not out.is_dir():
        _fail(f"--out {out}: not a folder")
    try:
        opts = RunOptions(seed=seed, phase=phase, max_trials=max_trials,
                          consecutive=consecutive, eval_trials=eval_trials, video=video,
                          gui=gui, strategy=strategy, world_seed=world_seed,
                          catalogue_first=catalogue_first,
                          demonstrate_creation=demonstrate_creation, prior=prior,
                          backend=backend, robot=robot)
    except UnknownStrategy as exc:
        _fail(f"--strategy: {exc}")
    except ValueError as exc:
        _fail(f"--phase: {exc}" if "phase" in str(exc) else str(exc))
    try:
        with _interrupt_exits(), _one_line_errors(), _stdout_to_stderr():
            with RunProgress(console, _budget(case, world, max_trials)) as progress:
                folder = run_case(case, out, opts, progress=progress, world_dir=world)
    except (WorldFileError, ValueError) as exc:
        _fail(str(exc))
    except OSError as exc:
        _fail(f"{exc.filename or out}: {exc.strerror or exc}")
    typer.echo(str(folder.path))


@contextmanager
def _interrupt_exits() -> Iterator[None]:
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
        if _DEBUG["on"]:
            raise
        hint = getattr(exc, "resume_command", None)
        typer.echo(f"error: the backend was lost: {' '.join(str(exc).split())}"
                   + (f"; the run stopped, to go on: {hint}" if hint else ""), err=True)
        raise typer.Exit(75) from None
    if interrupts.interrupted():
        typer.echo("interrupted (Ctrl-C) as the run ended; its folder is complete", err=True)
        raise typer.Exit(130)


def _given_options(ctx: typer.Context, exclude: tuple[str, ...] = ()) -> list[str]:
    """Return the options of the command that the command line (or the environment)
    gave, as their first spelling (``--seed``), in the command's order."""
    given = []
    for param in ctx.command.params:
        if param.name in exclude or param.param_type_name != "option":
            continue
        source = ctx.get_parameter_source(param.name)  # typer's own click's enum: by name
        if getattr(source, "name", None) in ("COMMANDLINE", "ENVIRONMENT"):
            given.append(max(param.opts, key=len))
    return given


def _budget(case: str, world: Optional[Path], max_trials: Optional[int]) -> Optional[int]:
    """The tool-use trial budget a run will have (for its progress line)."""
    if max_trials is not None:
        return max_trials
    try:
        return _manifest(case, world).trial_budget
    except Exception:  # noqa: BLE001 - the run itself reports a bad case or world
        return None


@app.command()
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

    _usable("RUN_DIR", run_dir)
    if width is not None and width < 40:
        _fail(f"--width {width}: under 40 columns")
    if width is not None and width > 1000:
        _fail(f"--width {width}: over 1000 columns")
    try:
        contents = read_run(run_dir)
    except (FileNotFoundError, ValueError) as exc:  # not a run folder, trials.jsonl a folder
        _fail(str(exc))
    for w in contents.warnings:
        typer.echo(f"warning: {w}", err=True)
    console = Console()
    print_report(contents, console, width)
    with _one_line_errors():
        if plot:
            png = plot_trials(contents.trials, Path(run_dir) / "trials.png", title=str(run_dir))
            console.print(f"plot: {png}", markup=False, highlight=False, soft_wrap=True)
        if html:
            page = write_html_report(run_dir)
            console.print(f"html: {page}", markup=False, highlight=False, soft_wrap=True)


@app.command()
def repl(run_dir: Optional[Path] = typer.Argument(None, help="A run folder whose model.pl "
                                                   "is loaded.")) -> None:
    """Open SWI-Prolog with the engine loaded (and a run's learned model)."""
    import shutil

    root = Path(__file__).resolve().parents[1]
    goals = []
    if run_dir is not None:
        model = Path(run_dir) / "model.pl"
        if not model.exists():
            _fail(f"{model}: no such file (is {run_dir} a run folder?)")
        goals.append(f"load_model_file({_quoted(str(model.resolve()))})")
    banner = ("CREATIVE-py engine loaded. Try:\n"
              "  ?- learned_model(Task, Action, Pre, Eff).\n"
              "  ?- learned_hypothesis(Task, hg, Clause).\n"
              "  ?- term_lgg(f(a, g(a)), f(b, g(b)), G).\n"
              "  ?- replacement(handle_length(T, medium), G, Alternatives).\n"
              "  ?- case_info(Case, Info).\n")
    goals.append(f"format({_quoted(banner)})")
    swipl = shutil.which("swipl")
    if swipl is None:
        _fail("swipl is not installed (make setup installs it)")
    # Options must precede the file: swipl passes what follows it to the program.
    os.execv(swipl, [swipl, "-g", ", ".join(goals), str(root / "prolog" / "creative.pl")])


BUILD_VOLUME_MAX_MM = 10000.0
"""The largest side of ``--build-volume``, millimetres."""


def _print_settings(text: str):
    """Return the print settings of a ``--build-volume X,Y,Z`` (mm), or fail in one line."""
    from creative_py.mesh.printability import PrintSettings
    from creative_py.mesh.tolerances import MM_PER_M

    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 3 or not all(0 < v <= BUILD_VOLUME_MAX_MM for v in values):
        _fail(f"--build-volume {text!r}: expected three positive numbers of millimetres "
              f"X,Y,Z, each at most {BUILD_VOLUME_MAX_MM:g}, e.g. 250,210,210")
    return PrintSettings(build_volume=tuple(v / MM_PER_M for v in values))


def _quoted(text: str) -> str:
    """Return ``text`` as a quoted Prolog atom (the bridge's encoder)."""
    from creative_py.bridge import encode

    return encode(text)


@app.command("make-tool")
def make_tool_cmd(
    case: str = typer.Argument(..., help="A case id (creative cases lists them)."),
    spec: str = typer.Argument(..., help="Qualitative spec in the case's vocabulary, e.g. "
                               "handle_length=long,hook_side=left (hook) or "
                               "shape=triangular_prism,block_length=long (wedge); a wrong "
                               "property lists the allowed ones."),
    name: str = typer.Option("new_tool", "--name", help="Tool name (a Prolog atom)."),
    out: str = typer.Option("tools", "--out", help="Folder for the tool's files."),
    variant: Optional[str] = typer.Option(None, "--variant", help="Task variant whose "
                                          "perceived geometry bounds the sizes (default: "
                                          "the demonstration's)."),
    context: Optional[str] = typer.Option(None, "--context", help="Extra task facts, e.g. "
                                          "'max_tool_length(0.5)'."),
    overwrite: bool = typer.Option(False, "--overwrite", help="Replace the tool's folder "
                                   "if it exists."),
    build_volume: Optional[str] = typer.Option(None, "--build-volume", help="The printer's "
                                               "build volume X,Y,Z in mm (default "
                                               "250,210,210); a larger tool is split into "
                                               "pieces that fit."),
    no_slice: bool = typer.Option(False, "--no-slice", help="Write the printed pieces' "
                                  "STL but do not slice them to G-code."),
) -> None:
    """Size a tool from a qualitative spec with CLP(R) and write URDF, SDF, SCAD, STL,
    the printed pieces (split to fit the build volume) and their G-code (PrusaSlicer)."""
    from creative_py.bridge import Engine, PrologError
    from creative_py.fabrication.manufacture import (
        InfeasibleSpec, default_context, make_tool, parse_context, parse_spec, with_context,
    )
    from creative_py.mesh.printability import PrintSettings
    from creative_py.mesh.slicer import require_slicer
    from creative_py.world_files import WorldFileError

    variant, name = _name("--variant", variant), _name("--name", name)
    case, spec, context = _text("CASE", case), _text("SPEC", spec), _text("--context", context)
    if len(name) > TOOL_NAME_MAX:
        _fail(f"--name: at most {TOOL_NAME_MAX} characters (the tool's file names add to "
              f"it), got {len(name)}")
    # deepest: <out>/<name>/ros/<name>_description/meshes/<name>...
    out = _path("--out", out, 3 * len(name.encode("utf-8", "surrogateescape")) + 64)
    if out.exists() and not out.is_dir():
        _fail(f"--out {out}: not a folder")
    settings = PrintSettings()
    if build_volume is not None:
        settings = _print_settings(build_volume)
    with _one_line_errors():  # what the specific messages below do not cover
        if not no_slice:
            require_slicer()
        try:
            with _stdout_to_stderr():
                engine = Engine.instance()
                lits = parse_spec(case, spec)
                extra = parse_context(engine, context) if context else []  # no scene yet
                ctx = with_context(default_context(case, variant), extra)
                files = make_tool(engine, case, lits, ctx, name, out, picture=True,
                                  overwrite=overwrite, settings=settings,
                                  gcode=not no_slice)
        except FileExistsError as exc:
            _fail(f"{exc.filename or out}: the tool's folder exists (--overwrite replaces it)")
        except (InfeasibleSpec, ValueError, WorldFileError) as exc:
            _fail(str(exc))
        except PrologError as exc:
            if not context:
                raise
            shown = context if len(context) <= 80 else f"{context[:60]}...{context[-12:]}"
            _fail(f"--context {shown!r}: the size model cannot use it: {exc.formal}")
    typer.echo(tool_summary(files.manifest))
    for p in files.paths():
        typer.echo(str(p))
    if no_slice:
        typer.echo(unsliced_warning(files.manifest), err=True)


def unsliced_warning(manifest: Path) -> str:
    """Return the one-line warning of a tool written with ``--no-slice``: that it cannot
    be printed (its print entry says why), or that no slicer has checked its pieces."""
    data = json.loads(Path(manifest).read_text())
    name, printed = data.get("name", "?"), data.get("print") or {}
    if not printed.get("printable", False):
        why = " ".join(str(printed.get("reason") or "no printable pieces").split())
        return f"warning: {name}: cannot be printed: {why}"
    pieces = len(printed.get("pieces") or [])
    return (f"warning: {name}: {pieces} printed piece(s) written but not sliced "
            f"(--no-slice): no slicer has checked them")


def tool_summary(manifest: Path) -> str:
    """Return a written tool in a few lines: its size, mass, printed pieces, print time
    and filament (from its JSON)."""
    from creative_py.report.table import print_text

    data = json.loads(Path(manifest).read_text())
    extent = (data.get("printability") or {}).get("extent")
    size = (" x ".join(f"{v * 1000:.1f}" for v in extent) + " mm"
            if isinstance(extent, list) else "?")
    mass = data.get("mass_kg")
    lines = [f"tool {data.get('name', '?')}: {size}, "
             f"{f'{mass * 1000:.1f} g' if isinstance(mass, (int, float)) else 'mass ?'}"]
    printed = data.get("print")
    if isinstance(printed, dict):
        lines.append(f"print: {print_text(printed)}")
    return "\n".join(lines)



def main(args: Optional[list[str]] = None) -> None:
    """The ``creative`` command (``pyproject.toml``'s script): :data:`app`, with a
    wrong command line (an unknown option, ``--seed 1.5``, a missing argument) told in
    one line ``error: ...`` naming the option and the command's ``--help``, exit code
    2, instead of click's usage box."""
    # typer's click (its own copy or click itself): the bases of its BadParameter
    bases = {c.__name__: c for c in typer.BadParameter.__mro__}
    UsageError, ClickException, Abort = (bases["UsageError"], bases["ClickException"],
                                         typer.Abort)

    try:
        code = app(args=args, standalone_mode=False)
    except UsageError as exc:
        if type(exc).__name__ == "NoArgsIsHelpError":  # bare ``creative``: help shown
            sys.exit(exc.exit_code)
        where = f" (see {exc.ctx.command_path} --help)" if exc.ctx else ""
        text = " ".join(exc.format_message().split()).rstrip(".")
        typer.echo(f"error: {text}{where}", err=True)
        sys.exit(2)
    except ClickException as exc:
        typer.echo(f"error: {' '.join(exc.format_message().split())}", err=True)
        sys.exit(exc.exit_code)
    except Abort:
        typer.echo("aborted", err=True)
        sys.exit(1)
    sys.exit(code if isinstance(code, int) else 0)


if __name__ == "__main__":  # pragma: no cover
    main()

