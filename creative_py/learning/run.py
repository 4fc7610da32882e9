"""One run of a case end to end: demonstration, tool-use learning, tool creation.

:func:`run_case` is what ``creative run hook`` and ``make hook`` call. It writes the run
folder described in :mod:`creative_py.records.folder` as it goes, so an interrupted
run leaves a readable ``trials.jsonl`` of the finished trials.
"""

from __future__ import annotations

import json
import logging
import shutil
import time
from dataclasses import asdict, dataclass, fields
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, Engine, PrologError, fact_term
from creative_py.learning.clips import VIDEO_MODES, ClipKeeper
from creative_py.learning.creation import CreateResult, ToolCreator
from creative_py.records.folder import RunFolder, read_resume
from creative_py.learning.strategies import strategy_named
from creative_py.learning.tool_use import LearningOptions, ToolUseLearner, UseResult
from creative_py.learning.trials import TrialRunner, term_text
from creative_py.report import plot_trials, summarise_trials
from creative_py.report.page import write_html_report
from creative_py.simulator import World, backend_for
from creative_py.simulator.randomise import apply_drawn, draw_world

log = logging.getLogger(__name__)

PHASES = ("use", "create", "all")


@dataclass(frozen=True)
class RunOptions:
    """Options of one run.

    Parameters
    ----------
    seed : int
        Seed of the physics and sensor noise.
    phase : {"use", "create", "all"}
        ``use``: demonstration and tool-use learning only; ``create`` and ``all``: then
        tool creation on the harder variant.
    max_trials : int or None
        N of Algorithm 1, at least 1 (default: the case manifest's ``trial_budget``).
    consecutive : int
        K of Algorithm 1: consecutive successes needed once nothing is left to test.
    eval_trials : int
        Evaluation trials of the learned model after tool-use learning (planner's own
        tool and pose choice), over the predefined locations.
    create_eval_trials : int
        Evaluation trials of a successful created tool (paper: 5).
    video : {"key", "all", "none"}
        Which trials are saved as MP4 clips in ``videos/``
        (:mod:`creative_py.learning.clips`): ``key`` the demonstration, the first
        success, every creation trial and the first trial of each failure reason;
        ``all`` every trial; ``none`` no clip.
    gui : bool
        Show the trials in pybullet's GUI (needs a display).
    strategy : str
        How tool-use learning chooses its experiments: a name of
        :data:`creative_py.learning.strategies.STRATEGIES` (``paper``, ``informative``,
        ``random``); another raises
        :class:`~creative_py.learning.strategies.UnknownStrategy`.
    world_seed : int or None
        None: the world as its files say; N: a world drawn from the case's manifest
        (:func:`creative_py.backends.pybullet.world.draw_world`: the catalogue's numbers inside their
        own qualitative ranges, its order shuffled, the locations jittered), the same
        for the same N.
    catalogue_first : bool or None
        Before manufacturing a tool for the harder task, try in the physics the
        catalogued objects the generalised model admits
        (:meth:`creative_py.learning.creation.ToolCreator._try_catalogue`); a tool is
        made only when none succeeds. None: on, except under the paper's strategy
        (whose Algorithm 2 makes a tool at once, as the parity fixtures record).
    demonstrate_creation : bool
        When a catalogued object solved the harder task, still create a tool afterwards
        as a demonstration of Algorithm 2 (``make hook`` does).
    """

    seed: int = 0
    phase: str = "all"
    max_trials: Optional[int] = None
    consecutive: int = 2
    eval_trials: int = 4
    create_eval_trials: int = 5
    video: str = "key"
    gui: bool = False
    strategy: str = "informative"
    world_seed: Optional[int] = None
    catalogue_first: Optional[bool] = None
    demonstrate_creation: bool = False

    @property
    def tries_catalogue(self) -> bool:
        """Whether tool creation tries the catalogued objects first (``catalogue_first``,
        None meaning what the strategy says: on, except under the paper's)."""
        if self.catalogue_first is None:
            return strategy_named(self.strategy).catalogue_first
        return self.catalogue_first

    def __post_init__(self) -> None:
        checks = [("seed", self.seed, 0), ("max_trials", self.max_trials, 1),
                  ("consecutive", self.consecutive, 1), ("eval_trials", self.eval_trials, 0),
                  ("create_eval_trials", self.create_eval_trials, 0),
                  ("world_seed", self.world_seed, 0)]
        for name, value, least in checks:
            if value is None and name in ("max_trials", "world_seed"):
                continue
            if isinstance(value, bool) or not isinstance(value, int) or value < least:
                raise ValueError(f"option {name} must be a whole number >= {least}, "
                                 f"got {value!r}")
        if self.phase not in PHASES:
            raise ValueError(f"option phase must be one of {', '.join(PHASES)}, "
                             f"got {self.phase!r}")
        if self.video not in VIDEO_MODES:
            raise ValueError(f"option video must be one of {', '.join(VIDEO_MODES)}, "
                             f"got {self.video!r}")
        if not isinstance(self.gui, bool):
            raise ValueError(f"option gui must be true or false, got {self.gui!r}")
        if self.catalogue_first is not None and not isinstance(self.catalogue_first, bool):
            raise ValueError(f"option catalogue_first must be true, false or unset, got "
                             f"{self.catalogue_first!r}")
        if not isinstance(self.demonstrate_creation, bool):
            raise ValueError(f"option demonstrate_creation must be true or false, got "
                             f"{self.demonstrate_creation!r}")
        strategy_named(self.strategy)


RUN_JSON_KEYS = ("case", "options", "world", "drawn_world")
"""The keys of a run folder's ``run.json`` (:func:`read_run_json`)."""


def read_run_json(run_dir: Path) -> tuple[str, RunOptions, Optional[Path],
                                          Optional[dict[str, Any]]]:
    """Return the case, options, world folder and drawn world of a run folder's
    ``run.json``, checked.

    A run recorded before there were strategies ran the paper's Algorithm 1, and one
    recorded before catalogued objects were tried first made a tool at once; other
    missing options take their defaults. A resumed run shows no GUI (the display it
    was started on may be gone).

    Raises
    ------
    ValueError
        One line naming ``run.json`` and the field: no ``run.json``, not JSON, not an
        object, a missing key, an unknown option or a bad option value, a
        ``drawn_world`` that is not an object.
    """
    meta_path = Path(run_dir) / "run.json"
    if not meta_path.is_file():
        raise ValueError(f"{run_dir}: not a resumable run folder (no run.json)")
    try:
        meta = json.loads(meta_path.read_text(encoding="utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise ValueError(f"{meta_path}: not JSON ({getattr(exc, 'msg', exc)})") from None
    if not isinstance(meta, dict):
        raise ValueError(f"{meta_path}: a JSON object with keys {', '.join(RUN_JSON_KEYS)} "
                         f"was expected, not a {type(meta).__name__}")
    for key in ("case", "options"):
        if key not in meta:
            raise ValueError(f"{meta_path}: field {key!r} is missing")
    if not isinstance(meta["case"], str):
        raise ValueError(f"{meta_path}: field 'case' must be text, got {meta['case']!r}")
    opts = meta["options"]
    if not isinstance(opts, dict):
        raise ValueError(f"{meta_path}: field 'options' must be an object, got "
                         f"{type(opts).__name__}")
    names = {f.name for f in fields(RunOptions)}
    unknown = sorted(set(opts) - names)
    if unknown:
        raise ValueError(f"{meta_path}: field 'options.{unknown[0]}' is not an option "
                         f"({', '.join(sorted(names))})")
    try:
        options = RunOptions(**{"strategy": "paper", "catalogue_first": False,
                                **opts, "gui": False})
    except ValueError as exc:
        raise ValueError(f"{meta_path}: field 'options': {exc}") from None
    world = meta.get("world")
    if world is not None and not isinstance(world, str):
        raise ValueError(f"{meta_path}: field 'world' must be a folder or null, got "
                         f"{world!r}")
    drawn = meta.get("drawn_world")
    if drawn is not None and not isinstance(drawn, dict):
        raise ValueError(f"{meta_path}: field 'drawn_world' must be an object or null, "
                         f"got {type(drawn).__name__}")
    return meta["case"], options, Path(world) if world else None, drawn


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
        ``logging``), so a caller that configures logging sees the run go on.
    world_dir : Path or None
        A world folder other than the shipped one (with its own ``case.toml``).
    resume : (RunFolder, list of TrialRecord, list of int) or None
        Used by :func:`resume_run`: the run folder (locked), its recorded trials and
        their line numbers in ``trials.jsonl``.
    drawn : dict or None
        Used by :func:`resume_run`: the randomised world recorded in ``run.json``
        (otherwise drawn from ``options.world_seed``).
    """
    say = progress or log.info
    t_start = time.perf_counter()
    engine, world, drawn = _checked_world(case, options, world_dir, drawn,
                                          resume[0].path / "run.json" if resume else None)
    run, replay, lines, before = _open_folder(out, case, options, world_dir, drawn,
                                              run_name, resume, say)
    try:
        runner = _trial_runner(engine, world, run, options, say, replay, lines)
        clips = runner.clips
        summary: dict[str, Any] = {"case": case, "seed": options.seed, "phase": options.phase,
                                   "options": asdict(options), "wall_time_s": {},
                                   "world_seed": options.world_seed, "drawn_world": drawn,
                                   **_case_facts(world.manifest, options)}
        use = _learn_to_use(runner, options, summary, say)
        _plan_and_evaluate(runner, use, options, summary, say)
        if options.phase in ("create", "all"):
            _create(runner, use, options, summary, say)
        runner.end_replay()  # a resume with nothing left to run: the replay was checked
        _finish(runner, clips, options, summary, t_start, say,
                before if resume is not None and runner.physical == 0 else {})
    except BaseException:
        # Nothing learned yet (the demonstration failed, the run was interrupted before
        # its first trial): leave no empty folder behind. (A run killed outright leaves
        # run.json: --resume starts it again from there.)
        if not run.trials and resume is None:
            run.release()
            shutil.rmtree(run.path, ignore_errors=True)
        raise
    finally:
        if resume is None:
            run.release()  # a resumed folder's lock is resume_run's
    return run


def _case_facts(manifest: Any, options: RunOptions) -> dict[str, Any]:
    """What the reports need of the case, written into ``summary.json`` so that they read
    the run folder alone: the unit of each pose number (``pose_units``), N of Algorithm 1
    as this run used it (``trial_budget``) and the paper's count of tool-use trials
    (``paper_trials``, None when the paper has no such case)."""
    return {"pose_units": {p.name: p.unit for p in manifest.pose_params},
            "trial_budget": options.max_trials or manifest.trial_budget,
            "paper_trials": manifest.paper_trials}


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
                 ) -> tuple[RunFolder, list, list, dict[str, Any]]:
    """Return the run folder (created and locked with its ``run.json``, or the resumed
    one, sealed until its replay is checked), the trials to replay, their line numbers
    and the summary of a resumed run that had finished ({} otherwise)."""
    if resume is None:
        run = RunFolder.create(Path(out), case, options.seed, run_name)
        try:
            run.write_json("run.json", {"case": case, "options": asdict(options),
                                        "world": str(world_dir) if world_dir else None,
                                        "drawn_world": drawn})
        except BaseException:
            run.release()
            shutil.rmtree(run.path, ignore_errors=True)
            raise
        say(f"run folder {run.path}")
        return run, [], [], {}
    run, replay, lines = resume
    # Nothing is written until the replay is checked (TrialRunner unseals it); with
    # nothing to replay (killed before its first trial) the run starts afresh.
    run.seal(replay)
    if not replay:
        run.unseal()
    say(f"resuming {run.path}: replaying {len(replay)} recorded trials")
    say(f"run folder {run.path}")
    return run, replay, lines, _earlier_summary(run.path)


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


def _learn_to_use(runner: TrialRunner, options: RunOptions, summary: dict[str, Any],
                  say: Callable[[str], None]) -> UseResult:
    """The demonstration and tool-use learning (Algorithm 1); write ``model.pl`` and the
    phase's part of the summary."""
    engine, run = runner.engine, runner.run_folder
    lopts = LearningOptions(max_trials=options.max_trials or runner.manifest.trial_budget,
                            consecutive=options.consecutive, strategy=options.strategy)
    t0 = time.perf_counter()
    use = ToolUseLearner(runner, lopts).learn()
    summary["wall_time_s"]["use"] = round(time.perf_counter() - t0, 2)
    summary["demonstration"] = {"tool": use.demo_tool}
    summary["use"] = {"trials": len(use.trials), "converged": use.converged,
                      "trials_to_converge": use.trials_to_converge,
                      "strategy": options.strategy, "stop": use.stop}
    # The version space after the demonstration, and the information-theoretic bound:
    # with binary outcomes, telling N0 hypotheses apart in the worst case takes
    # ceil(log2 N0) trials.
    summary["vs_count_initial"] = use.vs_count_initial
    summary["vs_count_initial_exact"] = use.vs_count_initial_exact
    summary["info_bound_trials"] = (use.vs_count_initial - 1).bit_length()
    summary["vs_count_final"] = (use.trials[-1].vs_count
                                 if use.trials else use.vs_count_initial)
    engine.write_model_file(run.path / "model.pl", runner.case, use.models, use.vs)
    hs, hg = runner.bounds(use.vs)
    summary["hypotheses"] = {"hs": hs, "hg": hg}
    say(f"h_s: {hs}")
    say(f"h_g: {hg}")
    return use


def _plan_and_evaluate(runner: TrialRunner, use: UseResult, options: RunOptions,
                       summary: dict[str, Any], say: Callable[[str], None]) -> None:
    """Plan the task with the learned model (``domain.pddl``/``problem.pddl``, solved by
    pyperplan and compared), then evaluate the model on fresh trials."""
    engine, path = runner.engine, runner.run_folder.path
    # Tool-use learning runs every trial on the demonstration's variant.
    task = runner.task(runner.manifest.demonstration.variant)
    plan = engine.plan_task(runner.case, use.models, use.vs, runner.task_facts(task),
                            [Compound("pddl", (str(path / "domain.pddl"),
                                               str(path / "problem.pddl")))])
    summary["plan"] = term_text(plan)
    say(f"plan: {term_text(plan)}")
    summary["pddl"] = {"use": _check_pddl(path, "domain.pddl", "problem.pddl",
                                          plan, task.variant, say)}
    # Evaluation of the learned model: the planner's own tool and pose choice.
    t0 = time.perf_counter()
    summary["eval"] = _evaluate(runner, use, options.eval_trials)
    summary["wall_time_s"]["eval"] = round(time.perf_counter() - t0, 2)


def _create(runner: TrialRunner, use: UseResult, options: RunOptions,
            summary: dict[str, Any], say: Callable[[str], None]) -> None:
    """Tool creation (Algorithm 2) on the harder variant; the harder task's model in
    ``model.pl`` and its PDDL when a tool (catalogued or made) solved it."""
    engine, path = runner.engine, runner.run_folder.path
    t0 = time.perf_counter()
    creator = ToolCreator(runner, eval_trials=options.create_eval_trials,
                          catalogue_first=options.tries_catalogue,
                          demonstrate=options.demonstrate_creation)
    created = creator.create(use.vs, runner.manifest.harder_variant)
    summary["wall_time_s"]["create"] = round(time.perf_counter() - t0, 2)
    summary["create"] = _creation_summary(created, path)
    if created.instance is not None:
        models = engine.created_models(use.models, use.vs, created.replaced,
                                       created.instance)
        engine.write_model_file(path / "model.pl", runner.case, use.models, use.vs,
                                [Compound("created", (created.variant, models))])
        summary["create"]["model"] = [term_text(m) for m in models]
        summary["pddl"]["create"] = _created_pddl(runner, path, created, models, say)


def _finish(runner: TrialRunner, clips: ClipKeeper, options: RunOptions,
            summary: dict[str, Any], t_start: float, say: Callable[[str], None],
            before: dict[str, Any]) -> None:
    """Wait for the clips, then write ``trials.png``, ``summary.json`` and, last,
    ``report.html``; ``before`` is the summary of a finished run resumed again, which
    ran nothing (its wall times are kept)."""
    run, trials = runner.run_folder, runner.trials
    summary["trials"] = summarise_trials(trials)
    if clips.children:
        say(f"encoding {len(clips.children)} video clip(s)")
    summary["videos"] = clips.finish()
    summary["wall_time_s"]["video"] = round(clips.wall_time_s, 2)
    summary["wall_time_s"]["total"] = round(time.perf_counter() - t_start, 2)
    if "wall_time_s" in before:
        summary["wall_time_s"] = before["wall_time_s"]
    plot_trials(trials, run.path / "trials.png",
                title=f"CREATIVE-py, {runner.case} case, seed {options.seed}")
    run.write_json("summary.json", summary)
    write_html_report(run.path)
    say(f"done in {summary['wall_time_s']['total']} s: {run.path}")


def catalogue_ranges(engine: Engine, world: World) -> dict[str, dict[str, tuple]]:
    """Return ``object -> {catalogue fact -> (low, high, bounds, value)}``: the
    qualitative range of each catalogued number and the value it stands for (the
    engine's ``catalogue_ranges``; what the backend's ``draw_world`` draws inside)."""
    facts = [fact_term(f) for spec in world.catalogue.values() for f in spec.catalogue_facts()]
    ranges: dict[str, dict[str, tuple[float, float, str, str]]] = {}
    for r in engine.catalogue_ranges(world.manifest.id, facts):
        obj, fact, _x, _prop, value, lo, hi, bounds = r.args
        ranges.setdefault(str(obj), {})[str(fact)] = (float(lo), float(hi), str(bounds),
                                                      str(value))
    return ranges


DEMO_CHECK_SEED = 0
"""The seed of the sensor noise in the demonstration that checks a drawn world (the
world must not depend on a run's seed; runs of seed 0 see that very demonstration)."""


def _earlier_summary(run_dir: Path) -> dict[str, Any]:
    """Return the ``summary.json`` of a run folder that finished before, or {}."""
    try:
        data = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    return data if isinstance(data, dict) else {}


def require_display(manifest: Optional[Any] = None) -> None:
    """Raise ValueError unless the simulator's window (``--gui``) can open on the
    display: the window of ``manifest``'s backend, or, without a manifest (the command
    line's check before it reads one), the default backend's (its
    ``display_reachable``)."""
    from creative_py.simulator import backend

    physics = backend() if manifest is None else backend_for(manifest)
    why = physics.display_reachable()
    if why:
        raise ValueError(f"--gui: {why}; run without --gui, or under a display "
                         f"(e.g. xvfb-run)")


def draw_catalogue_world(engine: Engine, world: World, seed: int,
                         check_demonstration: bool = True) -> dict[str, Any]:
    """Draw a randomised world of ``world`` for world seed ``seed`` (its backend's
    ``draw_world``): the engine gives each catalogued number's own qualitative range
    (``catalogue_ranges``) and checks that every drawn object keeps its structural
    literals; the physics checks that it lies still where the scene puts it (the
    backend's ``tool_rests``), else it is drawn again.
    With ``check_demonstration``, the trainer's demonstration runs in the drawn world
    (sensor noise of :data:`DEMO_CHECK_SEED`) and the demonstration's location is
    drawn again until it reaches the goal (the drawn world's ``redraws`` counts the
    times)."""
    from creative_py.learning.poses import pose_resolver
    from creative_py.learning.tool_use import DemonstrationFailed, run_demonstration

    physics = backend_for(world.manifest)
    case = world.manifest.id
    ranges = catalogue_ranges(engine, world)

    def literals(spec: Any) -> set[str]:
        state = engine.abstract_state(case, [fact_term(f) for f in spec.catalogue_facts()])
        return {str(lit) for lit in state}

    originals = {name: literals(spec) for name, spec in world.catalogue.items()}
    def keeps(name: str, spec: Any) -> bool:
        if literals(spec) != originals[name]:
            return False
        return physics.tool_rests(world.with_spec(name, spec), name)

    def demonstrates(drawn: dict[str, Any]) -> bool:
        new = apply_drawn(world, drawn)
        try:
            run_demonstration(new, seed=DEMO_CHECK_SEED,
                              pose_target=pose_resolver(engine, new.manifest))
        except DemonstrationFailed:
            return False
        return True

    return draw_world(world, seed, ranges, keeps=keeps,
                      demonstrates=demonstrates if check_demonstration else None)


def check_manifest(engine: Engine, manifest: Any) -> None:
    """Check that a case manifest agrees with its ontology file; raise ValueError naming
    the manifest's file and field where they differ.

    The manifest binds the skills to simulator primitives and names the goal, the roles
    and the pose; the ontology (``ontology/cases/<case>.pl``) holds the knowledge behind
    the same names, so the two must say the same.
    """
    where = manifest.folder / "case.toml"
    try:
        info = engine.case_info(manifest.id)
    except PrologError as exc:
        raise ValueError(f"{where}: field 'id': the ontology does not know case "
                         f"{manifest.id!r} (add ontology/cases/{manifest.ontology}.pl): "
                         f"{exc}") from None
    missing = [f"{i.args[0]}/{i.args[1]}" for i in engine.case_missing_hooks(manifest.id)]
    if missing:
        raise ValueError(f"ontology/cases/{manifest.ontology}.pl: case {manifest.id} does "
                         f"not answer the engine's hook predicate(s) {', '.join(missing)} "
                         f"(ontology/README.md lists them)")
    skills, goal, target, context, pose_term = info.args
    checks = [
        ("skill", [s.name for s in manifest.skills], [str(s) for s in skills]),
        ("goal", [str(engine.parse(g)) for g in manifest.goal], [str(g) for g in goal]),
        ("roles.target", manifest.target, str(target)),
        ("roles.context", manifest.context, str(context)),
        ("pose.term", manifest.pose_term, str(pose_term)),
    ]
    for field, mine, theirs in checks:
        if mine != theirs:
            raise ValueError(f"{where}: field {field!r}: {mine} differs from the ontology's "
                             f"{theirs} (ontology/cases/{manifest.ontology}.pl)")


def check_catalogue(engine: Engine, world: World) -> None:
    """Check that every catalogued object's facts (its kind's, as the robot perceives
    them) are in the ontology's vocabulary (the catalogue predicates of the case's tool
    class); raise ValueError naming the object and the fact otherwise."""
    from creative_py.fabrication.manufacture import tool_vocabulary

    m = world.manifest
    known = {(str(i.args[0]), int(i.args[1])) for i in engine.catalogue_predicates(m.id)}
    kinds = tool_vocabulary(engine, m.id).kinds
    for kind, (_classes, properties) in kinds.items():
        for prop, values in properties.items():
            if not values:
                raise ValueError(f"ontology: the property {prop} of a {kind} has no values "
                                 f"(no qualitative_range/5 in ontology/ranges.pl, nor a "
                                 f"size_choice/4 in ontology/kinds/)")
    where = m.folder / "objects.toml"
    for name, spec in world.catalogue.items():
        facts = spec.catalogue_facts()
        for fact in facts:
            if (fact[0], len(fact) - 1) not in known:
                raise ValueError(
                    f"{where}: {name}: the catalogue fact {fact[0]}/{len(fact) - 1} is not "
                    f"in the ontology's vocabulary of the case's tools "
                    f"({', '.join(f'{n}/{a}' for n, a in sorted(known))})")
        # Every property of the object's kind must take a qualitative value: a number
        # outside every range of the ontology would leave the learner blind to it.
        literals = engine.abstract_state(m.id, [fact_term(f) for f in facts])
        have = {lit.name for lit in literals
                if isinstance(lit, Compound) and lit.args and lit.args[0] == name}
        kind = str(facts[0][2]) if facts and facts[0][0] == "object_kind" else None
        missing = [p for p in kinds.get(kind, ((), {}))[1] if p not in have]
        if missing and not world.items[name].outside_ranges:
            raise ValueError(
                f"{where}: {name}: {', '.join(missing)} outside every qualitative range of "
                f"the ontology (ontology/ranges.pl); the learner could not tell its value "
                f"(write outside_ranges = true in its table if that is meant)")


def _evaluate(runner: TrialRunner, use: UseResult, n: int) -> dict[str, Any]:
    """Run ``n`` trials of the learned model over the locations, no learning."""
    outcomes = []
    task = runner.task(runner.manifest.demonstration.variant)
    for i in range(1, n + 1):
        plan = runner.engine.plan_use(runner.case, use.vs, runner.task_facts(task))
        if not isinstance(plan, Compound) or plan.name != "exploit":
            outcomes.append("no_plan")
            continue
        rec, _ = runner.run(plan, "eval", i, use.vs, task, 0.0, label=False)
        outcomes.append(rec.outcome)
        task.next_location()
    return {"trials": n, "successes": outcomes.count("success"), "outcomes": outcomes}


def _plan_steps(plan: Any) -> Optional[list[tuple[str, list[str]]]]:
    """Return the steps of the engine's ``plan(Steps)`` as (name, [args]), or None for a
    ``no_plan(Reason)``."""
    if not (isinstance(plan, Compound) and plan.name == "plan"):
        return None
    steps = []
    for step in plan.args[0]:
        if isinstance(step, Compound):
            steps.append((step.name, [str(a) for a in step.args]))
        else:
            steps.append((str(step), []))
    return steps


def _check_pddl(folder: Path, domain: str, problem: str, plan: Any, variant: str,
                say: Callable[[str], None]) -> dict[str, Any]:
    """Solve the run's own PDDL files with pyperplan and compare with Prolog's plan
    (:func:`creative_py.learning.pddl_check.check_files`); the record of
    ``summary.json``'s ``pddl`` key for one task."""
    from creative_py.learning.pddl_check import check_files

    record = check_files(folder / domain, folder / problem, _plan_steps(plan))
    record["variant"] = variant
    record["prolog"] = term_text(plan)
    same = "equals Prolog's" if record["equals_prolog"] else "DIFFERS from Prolog's"
    say(f"pddl {problem}: {record['status']} by {record['planner']} "
        f"{' '.join(record['plan'])} ({same})")
    return record


def _created_pddl(runner: TrialRunner, folder: Path, created: CreateResult,
                  models: Any, say: Callable[[str], None]) -> dict[str, Any]:
    """Write and check the harder task's PDDL: the created tool's model (the learned one
    with the replaced literal swapped for the created tool's value, or for the value of
    the catalogued object that solved the task) planning the harder variant, with the
    created tools in the catalogue, as ``domain_<variant>.pddl`` and
    ``problem_<variant>.pddl``.
    """
    from creative_py.learning.pddl_check import PLANNER_NAME

    task = runner.task(created.variant)
    domain, problem = f"domain_{created.variant}.pddl", f"problem_{created.variant}.pddl"
    names = [Compound("domain_name", (f"creative_{created.variant}",)),
             Compound("problem_name", (f"task_{created.variant}",))]
    try:
        plan = runner.engine.plan_models(
            runner.case, models, runner.task_facts(task),
            [Compound("pddl", (str(folder / domain), str(folder / problem))), *names])
    except PrologError as exc:
        log.warning("%s: the harder task's PDDL was not written: %s", folder, exc)
        return {"domain": domain, "problem": problem, "status": "error", "plan": [],
                "equals_prolog": False, "planner": PLANNER_NAME, "variant": created.variant,
                "error": str(exc)}
    say(f"plan ({created.variant}, created model): {term_text(plan)}")
    return _check_pddl(folder, domain, problem, plan, created.variant, say)


def _creation_summary(res: CreateResult, run_dir: Path) -> dict[str, Any]:
    """``summary.json``'s ``create``; the created tools' file names relative to the run
    folder (the folder can be moved)."""
    created = [asdict(c) for c in res.created]
    for c in created:
        if isinstance(c.get("files"), dict):
            c["files"] = {k: _relative(run_dir, v) for k, v in c["files"].items()}
    return {
        "variant": res.variant,
        "needed": res.needed,
        "predicted": res.predicted,
        # The learned model's best tool was not tried: the geometry predicted its failure.
        "predicted_failure_skipped": bool(res.predicted and res.predicted["feasible"] is False),
        "trials": len([t for t in res.trials if t.phase == "create"]),
        "failed_trials": len([t for t in res.trials
                              if t.phase == "create" and t.outcome != "success"]),
        "created_tools": created,
        "slice_wall_time_s": round(sum(p.get("slice_wall_time_s", 0.0)
                                       for c in res.created
                                       for p in c.print.get("pieces", [])), 2),
        "print_wall_time_s": round(sum(c.print.get("wall_time_s", 0.0)
                                       for c in res.created), 2),
        "success": res.success.name if res.success else None,
        "eval": res.success.eval_outcomes if res.success else [],
        "exhausted": res.exhausted,
        # What solved the harder task: learned (TC trial 1), catalogue (an available
        # object the generalised model admits, tried before manufacturing), created or
        # None; the catalogued objects tried (or skipped), best first, with why.
        "solved_by": res.solved_by,
        "catalogue": res.catalogue,
        "catalogue_trials": len([c for c in res.catalogue if c["trial"] is not None]),
        "catalogue_success": next((c["tool"] for c in res.catalogue
                                   if c["outcome"] == "success"), None),
    }


def _relative(run_dir: Path, name: Any) -> Any:
    """A file name as a POSIX path relative to the run folder when it is inside it; any
    other value as it is."""
    if not isinstance(name, (str, Path)):
        return name
    path = Path(name)
    try:
        return path.resolve().relative_to(Path(run_dir).resolve()).as_posix()
    except ValueError:
        return str(name)
