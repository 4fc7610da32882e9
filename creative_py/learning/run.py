"""One run of a case end to end: demonstration, tool-use learning, tool creation.

:func:`run_case` is what ``creative run hook`` and ``make hook`` call, :func:`resume_run`
what ``creative run --resume`` calls. A run checks its case
(:mod:`creative_py.learning.checks`), draws its world when asked
(:mod:`creative_py.learning.drawn_world`), runs its phases
(:mod:`creative_py.learning.phases`) and writes the run folder described in
:mod:`creative_py.records.folder` as it goes, so an interrupted run leaves a readable
``trials.jsonl`` of the finished trials; at the end it writes ``summary.json``
(:class:`~creative_py.records.summary.RunSummary`) and the reports
(:func:`creative_py.report.write_reports`).
"""

from __future__ import annotations

import json
import logging
import shutil
import time
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Engine
from creative_py.learning import phases
from creative_py.learning.checks import check_catalogue, check_manifest, require_display
from creative_py.learning.clips import ClipKeeper
from creative_py.learning.drawn_world import draw_catalogue_world
from creative_py.learning.options import RunOptions, read_run_json, run_json
from creative_py.learning.prior import load_prior
from creative_py.learning.trials import TrialRunner
from creative_py.records.folder import RunFolder, read_resume, resume_command, running_pid
from creative_py.records.summary import (Resumed, RunSummary, TrialCounts, VideoEntry,
                                         WallTimes)
from creative_py.report import write_reports
from creative_py.robots import load_profile
from creative_py.simulator import BackendLost, World, backend_for
from creative_py.simulator.randomise import apply_drawn

log = logging.getLogger(__name__)


def resume_run(run_dir: Path, progress: Optional[Callable[[str], None]] = None) -> RunFolder:
    """Resume a run that was interrupted (killed, out of power) and return its folder.

    The folder is locked first (:meth:`RunFolder.open`: a run still going refuses the
    resume). The run's case, options and world come from its ``run.json``
    (:func:`read_run_json`); every line of ``trials.jsonl`` is checked
    (:func:`creative_py.records.folder.read_resume`; a torn last line is dropped, and
    a run killed before its first trial has none), then the trials are replayed into
    the version space without physics, each checked against its record (the trial
    decided now, and the h_s and h_g it led to), and the run goes on from the next
    trial. Until the replay is checked the folder is sealed: a refused resume writes
    nothing. Runs are deterministic, so the result equals an uninterrupted run of the
    same seed, timings aside.

    Raises
    ------
    ValueError
        One line naming the file, line and field: ``run_dir`` is not a run folder
        that can be resumed, a line or ``run.json`` is invalid, or the recorded trials
        are not those the learner decides now;
        :class:`~creative_py.records.folder.FolderInUse` when another process holds
        the folder.
    """
    run_dir = Path(run_dir)
    if not (run_dir / "run.json").is_file():
        raise ValueError(f"{run_dir}: not a resumable run folder (no run.json)")
    folder = RunFolder.open(run_dir)
    try:
        case, options, world_dir, drawn = read_run_json(run_dir)
        warnings: list[str] = []
        trials, lines = read_resume(run_dir, warn=warnings.append)
        for w in warnings:
            log.warning("%s", w)
        return run_case(case, run_dir.parent, options, progress, world_dir,
                        resume=(folder, trials, lines), drawn=drawn)
    finally:
        folder.release()


def run_case(case: str, out: Path = Path("runs"), options: RunOptions = RunOptions(),
             progress: Optional[Callable[[str], None]] = None,
             world_dir: Optional[Path] = None, run_name: Optional[str] = None,
             resume: Optional[tuple[RunFolder, list, list]] = None,
             drawn: Optional[dict[str, Any]] = None) -> RunFolder:
    """Run one case end to end and return its run folder.

    Parameters
    ----------
    case : str
        A case id of a manifest ``worlds/<folder>/case.toml`` (``creative cases``).
    out : Path
        Parent folder of the run folder.
    options : RunOptions
    progress : callable or None
        Receives one line of text per step (the CLI shows it); without it, each line is
        logged at INFO level to the ``creative_py.learning.run`` logger (Python's
        ``logging``), so a caller that configures logging sees the run go on. Prolog
        variables are written A, B, ... as the reports write them.
    world_dir : Path or None
        A world folder other than the shipped one (with its own ``case.toml``).
    resume : (RunFolder, list of TrialRecord, list of int) or None
        Used by :func:`resume_run`: the run folder (locked), its recorded trials and
        their line numbers in ``trials.jsonl``.
    drawn : dict or None
        Used by :func:`resume_run`: the randomised world recorded in ``run.json``
        (otherwise drawn from ``options.world_seed``).
    """
    say = _readable(progress or log.info)
    t_start = time.perf_counter()
    engine, world, drawn = _checked_world(case, options, world_dir, drawn,
                                          resume[0].path / "run.json" if resume else None)
    if options.robot is None and world.manifest.robot and resume is None:
        options = replace(options, robot=world.manifest.robot)  # run.json names the arm
    if options.prior:
        load_prior(engine, case, options.prior)  # a bad --prior fails before the folder
    run, replay, lines, before, resumed = _open_folder(out, case, options, world_dir,
                                                       drawn, run_name, resume, say)
    clips: Optional[ClipKeeper] = None
    try:
        runner = _trial_runner(engine, world, run, options, say, replay, lines)
        clips = runner.clips
        wall: dict[str, float] = {}
        parts = _run_phases(runner, case, options, drawn, world.manifest, wall, say)
        runner.end_replay()  # a resume with nothing left to run: the replay was checked
        _finish(runner, clips, parts, wall, t_start, say,
                before if resume is not None and runner.physical == 0 else None, resumed)
        (run.path / STOPPED).unlink(missing_ok=True)  # a resumed run went on to its end
    except BaseException as exc:
        _stopped_early(exc, run, case, clips, resume is not None, say)
        raise
    finally:
        if resume is None:
            run.release()  # a resumed folder's lock is resume_run's
    return run


def _run_phases(runner: TrialRunner, case: str, options: RunOptions,
                drawn: Optional[dict[str, Any]], manifest, wall: dict[str, float],
                say: Callable[[str], None]) -> dict[str, Any]:
    """Run the run's phases (tool-use learning, the plan and the evaluation, tool
    creation when ``options.phase`` asks for it) and return the parts of its summary;
    ``wall`` receives each phase's wall time (s)."""
    parts: dict[str, Any] = {"case": case, "seed": options.seed, "phase": options.phase,
                             "options": options.recorded(), "world_seed": options.world_seed,
                             "drawn_world": drawn,
                             **phases.case_facts(manifest, options)}
    use, learned = phases.learn_to_use(runner, options, wall, say)
    parts.update(learned)
    parts.update(phases.plan_and_evaluate(runner, use, options, wall, say))
    if options.phase in ("create", "all"):
        parts["create"], check = phases.create(runner, use, options, wall, say)
        if check is not None:
            parts["pddl"] = replace(parts["pddl"], create=check)
    return parts


def _stopped_early(exc: BaseException, run: RunFolder, case: str,
                   clips: Optional[ClipKeeper], resumed: bool,
                   say: Callable[[str], None]) -> None:
    """Leave the run folder as a run stopped by ``exc`` should: the clips kept so far
    (Ctrl-C, a lost backend), no empty folder of a new run, how to go on said (Ctrl-C)
    or written in it (a lost backend: ``exc.resume_command``)."""
    interrupted = isinstance(exc, KeyboardInterrupt)
    lost = isinstance(exc, BackendLost)
    if (interrupted or lost) and clips is not None:
        _finish_clips(clips, say)
    # Nothing learned yet (the demonstration failed, the run was interrupted before
    # its first trial): leave no empty folder behind. (A run killed outright leaves
    # run.json: --resume starts it again from there.)
    if not run.trials and not resumed:
        run.release()
        shutil.rmtree(run.path, ignore_errors=True)
        if interrupted:
            say("interrupted before the first trial: nothing was kept")
        elif lost:
            say(f"the backend was lost before the first trial ({exc}): nothing was kept")
    elif interrupted:
        say(f"interrupted after {len(run.trials)} trial(s); to go on: "
            f"{resume_command(case, run.path)}")
    elif lost:
        exc.resume_command = _stopped(run, case, exc, say)


STOPPED = "stopped.json"
"""Written in the run folder when the backend was lost mid-run: why, and how to go on."""


def _stopped(run: RunFolder, case: str, exc: BaseException, say: Callable[[str], None]) -> str:
    """Note in the run folder that the run stopped because the backend went away; return
    the command that resumes the run.

    The trial that was running (``lost_trial``, when the backend went away during one)
    did not go as planned: ``stopped.json`` records it with the skill it was in, but not
    in ``trials.jsonl``, since nothing was learned about the tool from it (it labels no
    example); the resume runs it again."""
    command = resume_command(case, run.path)
    lost = lost_trial(exc)
    note = {"stopped": "the backend was lost", "reason": str(exc),
            "trials_recorded": len(run.trials), "lost_trial": lost, "resume": command}
    try:
        (run.path / STOPPED).write_text(json.dumps(note, indent=1) + "\n", encoding="utf-8")
    except OSError:
        pass  # the message below says it too
    where = ("between trials" if lost is None else
             f"in trial #{lost['trial']} ({lost['tool']} at location {lost['location']}"
             + (f", skill {lost['skill']}" if lost.get("skill") else "")
             + "), which did not go as planned and is run again on resuming")
    say(f"stopped after {len(run.trials)} recorded trial(s): the backend was lost {where} "
        f"({exc}); to go on once it is back: {command}")
    return command


def lost_trial(exc: BaseException) -> Optional[dict[str, Any]]:
    """Return the trial a :class:`BackendLost` interrupted as ``stopped.json`` records
    it (outcome ``not as planned``, ``learned`` false), or None when it came between
    trials."""
    trial = getattr(exc, "trial", None)
    if not trial:
        return None
    return {**trial, "skill": getattr(exc, "skill", None), "outcome": "not as planned",
            "reason": " ".join(str(exc).split()), "learned": False}


def _trial_runner(engine: Engine, world: World, run: RunFolder, options: RunOptions,
                  say: Callable[[str], None], replay: list, lines: list) -> TrialRunner:
    """Return the run's trial runner with its clip keeper (held while a resume's replay
    is checked), replaying ``replay`` (recorded at ``lines`` of ``trials.jsonl``)."""
    # In the GUI the client has a thread of its own: no forking it.
    clips = ClipKeeper(options.video, run.path, world.video, background=not options.gui,
                       new_recorder=backend_for(world.manifest).recorder)
    clips.held = run.sealed
    return TrialRunner(engine, world, run, options.seed, say, replay=replay, clips=clips,
                       gui=options.gui, replay_lines=lines)


def _open_folder(out: Path, case: str, options: RunOptions, world_dir: Optional[Path],
                 drawn: Optional[dict[str, Any]], run_name: Optional[str],
                 resume: Optional[tuple], say: Callable[[str], None]
                 ) -> tuple[RunFolder, list, list, Optional[RunSummary], Optional[Resumed]]:
    """Return the run folder (created and locked with its ``run.json``, or the resumed
    one, sealed until its replay is checked), the trials to replay, their line numbers,
    the summary of a resumed run that had finished (None otherwise) and, for a resume,
    what it replays and the interrupted run's wall time (:class:`Resumed`, its total
    still unknown)."""
    if resume is None:
        waiting = _interrupted_folders(Path(out), case, options.seed)
        run = RunFolder.create(Path(out), case, options.seed, run_name)
        try:
            run.write_json("run.json", run_json(case, options, world_dir, drawn))
        except BaseException:
            run.release()
            shutil.rmtree(run.path, ignore_errors=True)
            raise
        say(f"run folder {run.path}")
        if waiting:
            say(f"a new run; the interrupted run {waiting[-1]} of this case and seed "
                f"can go on with: {resume_command(case, waiting[-1])}")
        return run, [], [], None, None
    run, replay, lines = resume
    resumed = Resumed(replayed=len(replay), earlier_wall_time_s=_earlier_wall(run.path),
                      lost_trial=_stopped_trial(run.path))
    # Nothing is written until the replay is checked (TrialRunner unseals it); with
    # nothing to replay (killed before its first trial) the run starts afresh.
    run.seal(replay)
    if not replay:
        run.unseal()
    say(f"resuming {run.path}: replaying {len(replay)} recorded trials")
    say(f"run folder {run.path}")
    return run, replay, lines, _earlier_summary(run.path), resumed


def _stopped_trial(run_dir: Path) -> Optional[dict[str, Any]]:
    """Return the trial the backend was lost in, from the run's ``stopped.json`` (None
    without one, or when it names none or cannot be read)."""
    try:
        note = json.loads((run_dir / STOPPED).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    lost = note.get("lost_trial") if isinstance(note, dict) else None
    return lost if isinstance(lost, dict) else None


def _interrupted_folders(out: Path, case: str, seed: int) -> list[Path]:
    """Return the run folders under ``out`` of ``case`` and ``seed`` that an interruption
    left unfinished (a ``run.json``, no ``summary.json``, and no process holding its
    lock: a run still going beside the new one is not interrupted), oldest first."""
    try:
        found = [p for p in out.glob(f"{case}-*-s{seed}")
                 if (p / "run.json").is_file() and not (p / "summary.json").exists()
                 and not running_pid(p)]
    except OSError:
        return []
    return sorted(found, key=lambda p: p.name)


def _earlier_wall(run_dir: Path) -> Optional[float]:
    """Return the wall time of an interrupted run: from its ``run.json`` (written as it
    started) to its last recorded trial (``trials.jsonl`` last written), or None when
    one of them is missing."""
    try:
        start = (run_dir / "run.json").stat().st_mtime
        last = (run_dir / "trials.jsonl").stat().st_mtime
    except OSError:
        return None
    return round(max(0.0, last - start), 2)


def _checked_world(case: str, options: RunOptions, world_dir: Optional[Path],
                   drawn: Optional[dict[str, Any]], run_json: Optional[Path] = None
                   ) -> tuple[Engine, Any, Optional[dict[str, Any]]]:
    """Return the engine, the case's world (drawn when ``options.world_seed`` says so,
    or as ``drawn`` read back from a resumed run's ``run_json``) and the drawn world, all
    checked against the ontology, and the display for ``--gui``, before any folder or
    physics."""
    from creative_py.case import get_case, read_manifest
    from creative_py.mesh.slicer import require_slicer

    if options.phase in ("create", "all"):
        require_slicer()  # every created tool is sliced: refuse before any physics
    manifest = get_case(case) if world_dir is None else read_manifest(Path(world_dir))
    if manifest.id != case:
        raise ValueError(f"{Path(world_dir) / 'case.toml'}: declares case {manifest.id!r}, "
                         f"not {case!r}")
    if options.backend is not None and options.backend != manifest.backend:
        manifest = replace(manifest, backend=options.backend)  # --backend: the case unedited
    robot = options.robot or manifest.robot
    if options.robot is not None and manifest.robot is None:
        raise ValueError(f"--robot {options.robot}: the case {case} runs in the "
                         f"{manifest.backend!r} backend, which brings its own arm")
    if robot:
        load_profile(robot)  # a bad profile: one line naming its file and field
    if options.robot is not None:
        manifest = replace(manifest, robot=options.robot)  # --robot: the arm the backend builds
    physics = backend_for(manifest)
    world = physics.load_world(manifest)
    engine = Engine.instance()
    check_manifest(engine, manifest)
    check_catalogue(engine, world)
    if options.world_seed is not None:
        if drawn is None:
            drawn = draw_catalogue_world(engine, world, options.world_seed)
            world = apply_drawn(world, drawn)
        else:  # read back from run.json
            try:
                world = apply_drawn(world, drawn)
            except (KeyError, TypeError, AttributeError, ValueError) as exc:
                raise ValueError(f"{run_json or 'run.json'}: field 'drawn_world' is not a "
                                 f"drawn world of this case ({type(exc).__name__}: {exc})"
                                 ) from None
        check_catalogue(engine, world)
    if options.gui:
        require_display(manifest)  # before the folder exists: an unreachable display aborts
    return engine, world, drawn


def _finish(runner: TrialRunner, clips: ClipKeeper, parts: dict[str, Any],
            wall: dict[str, float], t_start: float, say: Callable[[str], None],
            before: Optional[RunSummary], resumed: Optional[Resumed] = None) -> RunSummary:
    """Wait for the clips, then write ``summary.json`` of the run's ``parts`` (fields of
    :class:`~creative_py.records.summary.RunSummary`) and the reports, and say how long
    it took, the headline (:func:`creative_py.report.headline.headline`) and where the
    report is; ``before`` is the summary of a finished run resumed again, which ran
    nothing (its wall times are kept); ``resumed`` what a resume replayed."""
    run, trials = runner.run_folder, runner.trials
    if clips.children:
        say(f"encoding {len(clips.children)} video clip(s)")
    videos = [VideoEntry.from_dict(v, f"videos[{i}]") for i, v in enumerate(clips.finish())]
    wall["video"] = round(clips.wall_time_s, 2)
    wall["total"] = round(time.perf_counter() - t_start, 2)
    times = WallTimes(**wall)
    if before is not None and before.wall_time_s is not None:
        times = before.wall_time_s
    if before is not None:
        resumed = before.resumed  # nothing ran: the finished run's record stands
    elif resumed is not None and resumed.earlier_wall_time_s is not None:
        resumed = replace(resumed, total_wall_time_s=round(
            resumed.earlier_wall_time_s + times.total, 2))
    summary = RunSummary(**parts, wall_time_s=times, trials=TrialCounts.of(trials),
                         videos=videos, resumed=resumed)
    summary.write(run.path)
    write_reports(run.path, trials, summary)
    say(f"done in {summary.wall_time_s.total} s: {run.path}")
    for line in _headline(run.path):
        say(line)
    say(f"report: {run.path / 'report.html'}")
    return summary


def _headline(run_dir: Path) -> list[str]:
    """The headline's sentences of the finished run (:mod:`creative_py.report.headline`),
    but the first (case, strategy, seed: the run's first lines said them) and the wall
    time (said just before)."""
    from creative_py.report.contents import read_run
    from creative_py.report.headline import headline

    lines = headline(read_run(run_dir)).lines
    return [x for x in lines[1:] if not x.startswith("Wall time ")]


def _readable(say: Callable[[str], None]) -> Callable[[str], None]:
    """Return ``say`` with each line's Prolog variables (``_G3``) written ``A``, ``B``,
    ... as the reports write them (:func:`creative_py.report.contents.readable_term`)."""
    from creative_py.report.contents import readable_term

    return lambda line: say(readable_term(line))


def _finish_clips(clips: ClipKeeper, say: Callable[[str], None]) -> None:
    """After Ctrl-C: wait for the clips being written (their processes ignore it), so
    that no clip of an ended trial is lost; a second Ctrl-C leaves them to finish on
    their own."""
    if not clips.children:
        return
    say(f"interrupted: finishing {len(clips.children)} video clip(s) first")
    try:
        clips.finish()
    except KeyboardInterrupt:
        pass


def _earlier_summary(run_dir: Path) -> Optional[RunSummary]:
    """Return the summary of a run folder that finished before, or None (none, or not
    readable)."""
    try:
        return RunSummary.read(run_dir / "summary.json")
    except (OSError, ValueError):
        return None
