"""Learning to use a tool: the demonstration, then the paper's Algorithm 1.

The loop reads like the paper. Prolog decides (which literal to test, which object,
which spatial constraints; how the version space changes); Python acts (runs the skills
in the physics and reports what the cameras and the arm's proprioception saw). The
physics alone decides whether a trial succeeded.

One trial::

    experiment = prolog.next_experiment(vs, objects, task)       # literal, object, pose
    outcome, facts = execute(object, pose)                       # pybullet decides
    example = prolog.trial_example(object, facts)                # ground clause
    vs = prolog.vs_update(vs, pos(example) | neg(example))

Outcomes ``blocked`` (the arm could not carry out the motion, e.g. a short handle whose
gripper hits the tube mouth before the prong is behind the cube) count as failures of
the *planned* example, so they are evidence about the tested literal only; outcomes
``unreachable`` and ``invalid`` are recorded with their reason and leave the version
space unchanged.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, Engine, Term, Var, clause_parts
from creative_py.learning.run_folder import RunFolder

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class LearningOptions:
    """Options of tool-use learning (paper, Algorithm 1).

    Parameters
    ----------
    max_trials : int
        N: stop after this many tool-use trials.
    consecutive : int
        K: stop once the version space has nothing left to test and the last K trials
        succeeded.
    seed : int
        Seed of the run; trial i uses seed ``seed * 1000 + i`` in the physics.
    """

    max_trials: int = 12
    consecutive: int = 2
    seed: int = 0


@dataclass
class TaskState:
    """The current task: variant and cube location (or door placement index)."""

    variant: str
    location: int
    locations: tuple[int, ...]

    def next_location(self) -> None:
        """Move to the next predefined location (the task changes after a success)."""
        i = self.locations.index(self.location)
        self.location = self.locations[(i + 1) % len(self.locations)]


@dataclass
class TrialRecord:
    """One executed trial, as written to ``trials.jsonl``."""

    trial: int
    phase: str
    phase_trial: int
    variant: str
    location: int
    tool: str
    kind: str
    tested: list[str]
    violated: list[str]
    pose: dict[str, float]
    outcome: str
    reason: str
    hs: str = ""
    hg: str = ""
    wall_time_s: float = 0.0
    sim_time_s: float = 0.0
    decision_time_s: float = 0.0
    extra: dict[str, Any] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        """Return the record as a JSON-ready dict."""
        d = dict(self.__dict__)
        d.update(d.pop("extra"))
        return d


def fact_term(fact: tuple) -> Term:
    """Return a primitive fact given as a tuple ``("pose", "cube1", x, ...)`` as a term."""
    name, *args = fact
    return Compound(name, tuple(_plain(a) for a in args)) if args else name


def _plain(a: Any) -> Any:
    if isinstance(a, bool):
        return "true" if a else "false"
    if hasattr(a, "item"):  # numpy scalars
        return a.item()
    return a


def term_text(t: Term) -> str:
    """Return a term as Prolog text (for logs and JSON)."""
    return str(t)


# --------------------------------------------------------------------------------------
# The demonstration and the task's facts, from the simulator
# --------------------------------------------------------------------------------------

CASE_ROLES = {"hook": ("cube1", "tube1"), "wedge": ("door1", "floor1")}
"""The target and the context object of each case (the head's 2nd and 3rd arguments)."""

DEMO_STEPS = {"hook": ("pick_up", "position_tool", "pull"),
              "wedge": ("pick_up", "place", "release_door")}
"""The trainer's skills, when the world's demonstration.toml does not list them."""


def demonstration_info(case: str, world: Any) -> dict[str, Any]:
    """Return the demonstration's tool, variant, location and skills from the world."""
    from creative_py.sim.trial import list_case

    info = list_case(case, world)["demonstration"]
    return {"tool": info.get("tool") or info["object"],
            "variant": info.get("variant", "standard"),
            "location": int(info.get("location", 1)),
            "steps": tuple(info.get("steps") or DEMO_STEPS[case])}


@dataclass(frozen=True)
class DemoStep:
    """One skill of the trainer's demonstration with the facts seen before and after."""

    skill: str
    args: tuple[str, ...]
    facts_before: tuple[tuple, ...]
    facts_after: tuple[tuple, ...]
    outcome: str


@dataclass(frozen=True)
class Demonstration:
    """The trainer's demonstration as run in the simulator."""

    tool: str
    variant: str
    location: int
    pose: Any
    steps: tuple[DemoStep, ...]
    goal_reached: bool


def run_demonstration(case: str, world: Any, variant: Optional[str] = None, seed: int = 0,
                      images_dir: Optional[Path] = None) -> Demonstration:
    """Run the trainer's scripted demonstration and observe after every skill.

    The skills and the pose come from the world's ``demonstration.toml``. Each step's
    facts are what the robot perceives (cameras) and feels (arm proprioception).
    """
    from creative_py.sim.trial import get_case, open_episode

    info = demonstration_info(case, world)
    variant = variant or info["variant"]
    tool, location = info["tool"], int(info["location"])
    pose = get_case(case).default_pose(world)
    target, ctx = CASE_ROLES[case]
    steps: list[DemoStep] = []
    with open_episode(case, world, variant, location, tool, seed=seed,
                      images_dir=images_dir) as ep:
        before = tuple(ep.observe().facts)
        for skill in info["steps"]:
            if skill == "pick_up":
                res, args = ep.pick_up(), (tool,)
            elif skill in ("position_tool", "place"):
                res = ep.position_tool(pose)
                args = (tool, target, ctx)
            elif skill == "pull":
                res, args = ep.act(), (tool, target, ctx)
            elif skill == "release_door":
                res, args = ep.act(), (target,)
            else:
                raise ValueError(f"{case} demonstration: unknown skill {skill!r}")
            after = tuple(ep.observe().facts)
            steps.append(DemoStep(skill, args, before, after, res.status))
            if res.status != "ok":
                raise RuntimeError(f"{case} demonstration: skill {skill} ended "
                                   f"{res.status}: {res.reason}")
            before = after
        reached = ep.goal_reached()
    if not reached:
        raise RuntimeError(f"{case} demonstration with {tool} at location {location} did "
                           "not reach the goal in the physics: nothing to learn from")
    return Demonstration(tool, variant, location, pose, tuple(steps), reached)


_TASK_FACTS: dict[tuple, list[tuple]] = {}


def task_facts(case: str, world: Any, variant: str, location: int) -> list[tuple]:
    """Return what the robot perceives of a task before acting: the catalogue of
    available objects, the apparatus (tube or door) and the target's pose.

    The scene is built and observed once per (world folder, available objects, variant,
    location); nothing moves.
    """
    from creative_py.sim.trial import list_case, open_episode

    names = tuple(sorted(list_case(case, world)["objects"]))
    key = (case, str(getattr(world, "directory", "")), names, variant, int(location))
    if key not in _TASK_FACTS:
        tool = demonstration_info(case, world)["tool"]
        with open_episode(case, world, variant, int(location), tool, seed=0) as ep:
            _TASK_FACTS[key] = list(ep.observe().facts)
    return _TASK_FACTS[key]


# --------------------------------------------------------------------------------------
# Executing one trial in the physics
# --------------------------------------------------------------------------------------


@dataclass
class Executed:
    """What the physics did with one planned trial."""

    outcome: str
    reason: str
    facts_before: list[tuple]
    sim_time_s: float
    wall_time_s: float
    perceived_final: dict[str, Any] = field(default_factory=dict)


def execute_trial(case: str, world: Any, tool: str, variant: str, location: int,
                  pose: Any, seed: int, images_dir: Optional[Path]) -> Executed:
    """Run one tool-use trial in pybullet and report the outcome the physics gave.

    The skills run in order (pick up, position the tool at ``pose`` relative to the
    target, act: pull or release the door). The observation used for learning is taken
    after positioning, before the tool action: the state the action model's
    precondition speaks of.
    """
    from creative_py.sim.trial import open_episode

    t0 = time.perf_counter()
    facts: list[tuple] = []
    with open_episode(case, world, variant, location, tool, seed=seed,
                      images_dir=images_dir) as ep:
        steps = (("pick_up", ep.pick_up), ("position_tool", lambda: ep.position_tool(pose)))
        for name, skill in steps:
            res = skill()
            if res.status != "ok":
                # What the robot sees where the motion stopped: the catalogue and the
                # task's facts still describe the trial (a planned example needs them).
                facts = list(ep.observe().facts) if res.status == "blocked" else facts
                return Executed(res.status, f"{name}: {res.reason}", facts,
                                ep.sim_time(), time.perf_counter() - t0)
        facts = list(ep.observe().facts)
        res = ep.act()
        if res.status not in ("ok",):
            if res.status == "blocked":
                # Blocked while acting: the tool could not carry out the action; the
                # physics says the goal was not reached with this tool and pose.
                outcome = "success" if ep.goal_reached() else "failure"
                return Executed(outcome, f"act: {res.reason}", facts, ep.sim_time(),
                                time.perf_counter() - t0)
            return Executed(res.status, f"act: {res.reason}", facts, ep.sim_time(),
                            time.perf_counter() - t0)
        ok = ep.goal_reached()
        final = ep.observe()
        return Executed("success" if ok else "failure",
                        "goal reached" if ok else "goal not reached", facts,
                        ep.sim_time(), time.perf_counter() - t0,
                        perceived_final=final.perceived_poses() if final.frames else {})


# --------------------------------------------------------------------------------------
# Algorithm 1
# --------------------------------------------------------------------------------------


@dataclass
class UseResult:
    """The outcome of tool-use learning."""

    vs: Term
    models: Term
    trials: list[TrialRecord]
    converged: bool
    trials_to_converge: Optional[int]
    demo_tool: str
    wall_time_s: float


class ToolUseLearner:
    """Tool-use learning for one case (paper, Algorithm 1).

    Parameters
    ----------
    engine : Engine
        The Prolog engine (bridge).
    case : str
        ``"hook"`` or ``"wedge"``.
    world : object
        The case's world, as loaded by :func:`creative_py.sim.trial.load_case_world`.
    run : RunFolder or None
        Where trials are logged; None logs nowhere.
    options : LearningOptions
    progress : callable or None
        Called with one line of text per trial.
    """

    def __init__(self, engine: Engine, case: str, world: Any, run: Optional[RunFolder],
                 options: LearningOptions = LearningOptions(),
                 progress: Optional[Callable[[str], None]] = None) -> None:
        self.engine = engine
        self.case = case
        self.world = world
        self.run = run
        self.options = options
        self.progress = progress or (lambda _msg: None)
        self.trials: list[TrialRecord] = []

    # -- the demonstration (learning by observation) ---------------------------------

    def observe_demonstration(self, variant: str = "standard") -> tuple[Term, Term, str]:
        """Run the trainer's demonstration and build the new action model from it.

        Returns the Prolog ``models(Matched, New, Example)`` term's parts: the new
        models, the example clause for the version space and the demonstrated tool.
        """
        images = self.run.snapshot_dir("demo", 0) if self.run else None
        demo = run_demonstration(self.case, self.world, variant=variant,
                                 seed=self.options.seed, images_dir=images)
        steps = [Compound("step", (s.skill, [_plain(a) for a in s.args],
                                   [fact_term(f) for f in s.facts_before],
                                   [fact_term(f) for f in s.facts_after]))
                 for s in demo.steps]
        reply = self.engine.call("learn_from_demonstration", self.case, steps)
        if not isinstance(reply, Compound) or reply.name != "models":
            raise RuntimeError(f"demonstration of {self.case}: {reply}")
        _matched, new, example = reply.args
        return new, example, demo.tool

    # -- the loop ---------------------------------------------------------------------

    def learn(self, variant: str = "standard") -> UseResult:
        """Run Algorithm 1 from one demonstration; return the learned version space."""
        t0 = time.perf_counter()
        models, example, demo_tool = self.observe_demonstration(variant)
        vs = self.engine.call("vs_init", example)
        self.progress(f"demonstration with {demo_tool}: new model {_model_names(models)}")
        task = TaskState(variant, *self._locations())
        cons = 0
        converged_at = None
        opts = self.options
        skip: list[Term] = []
        for i in range(1, opts.max_trials + 1):
            facts = self.task_facts(task)
            td = time.perf_counter()
            exp = self.engine.call("next_experiment", self.case, vs, facts, skip)
            decision = time.perf_counter() - td
            if exp.name != "experiment":
                # Nothing left that the available objects and poses can test.
                if converged_at is None:
                    converged_at = i - 1
                if cons >= opts.consecutive:
                    break
            rec, vs = self._run_experiment(i, "use", i, exp, vs, task, decision)
            if rec.outcome == "success":
                cons += 1
                task.next_location()
            elif rec.outcome in ("failure", "blocked"):
                cons = 0
            elif exp.name == "experiment":
                # The arm could not carry it out: it taught nothing; do not repeat it. A
                # pose test (a negated spatial literal) is skipped whatever the tool.
                who = "any" if exp.args[5] else exp.args[0]
                skip.append(Compound("skip", (who, exp.args[1])))
        else:
            exp = self.engine.call("next_experiment", self.case, vs, self.task_facts(task),
                                   skip)
            if exp.name != "experiment" and converged_at is None:
                converged_at = opts.max_trials
        return UseResult(vs, models, self.trials, converged_at is not None, converged_at,
                         demo_tool, time.perf_counter() - t0)

    def task_facts(self, task: TaskState) -> list[Term]:
        """Return the primitive facts the planner needs before a trial: the catalogue
        of available objects and the task's geometry."""
        return [fact_term(f) for f in task_facts(self.case, self.world, task.variant,
                                                  task.location)]

    def _locations(self) -> tuple[int, tuple[int, ...]]:
        from creative_py.sim.trial import list_case

        info = list_case(self.case, self.world)
        locs = tuple(int(x["index"]) if isinstance(x, dict) else int(x)
                     for x in info["locations"])
        return locs[0], locs

    def _run_experiment(self, n: int, phase: str, phase_trial: int, exp: Term, vs: Term,
                        task: TaskState, decision: float, label: bool = True,
                        label_failures: bool = True) -> tuple[TrialRecord, Term]:
        """Execute a planned experiment, label it and update the version space.

        ``label=False`` leaves the version space unchanged (evaluation trials);
        ``label_failures=False`` learns from successes only (a created tool that fails
        is Marvin's search state, not evidence about the learned model).
        """
        kind = exp.name if isinstance(exp, Compound) else str(exp)
        if kind == "no_experiment":
            raise RuntimeError(f"{self.case}: no experiment is possible: {exp.args[0]}")
        if kind == "experiment":
            tool, tested, violated, pose, _req, _neg = exp.args
            tested_l = [term_text(tested)]
        else:  # exploit
            tool, violated, pose, _req = exp.args
            tested_l = []
        images = self.run.snapshot_dir(phase, n) if self.run else None
        seed = self.options.seed * 1000 + n
        ex = execute_trial(self.case, self.world, tool, task.variant, task.location,
                           _pose_from_term(self.case, pose), seed, images)
        td = time.perf_counter()
        lab = {"success": "pos", "failure": "neg", "blocked": "neg"}.get(ex.outcome)
        if lab == "neg" and not label_failures:
            lab = None
        if lab is not None and label:
            facts = [fact_term(f) for f in ex.facts_before]
            planned = ex.outcome == "blocked"
            if planned and not facts:
                facts = self.task_facts(task)
            vs1 = self.engine.call("label_trial", self.case, vs, exp, facts, lab,
                                   "planned" if planned else "observed")
            if not isinstance(vs1, Compound):
                raise RuntimeError(f"{self.case} trial {n}: Prolog could not label the "
                                   f"{ex.outcome} of {tool} ({term_text(exp)})")
            vs = vs1
        hs, hg = self._bounds(vs)
        decision += time.perf_counter() - td
        rec = TrialRecord(
            trial=len(self.trials) + 1, phase=phase, phase_trial=phase_trial,
            variant=task.variant, location=task.location, tool=str(tool), kind=kind,
            tested=tested_l, violated=[term_text(v) for v in violated],
            pose=_pose_dict(pose), outcome=ex.outcome, reason=ex.reason,
            hs=hs, hg=hg, wall_time_s=round(ex.wall_time_s, 3),
            sim_time_s=round(ex.sim_time_s, 3), decision_time_s=round(decision, 4))
        self.trials.append(rec)
        if self.run:
            self.run.append_trial(rec.as_dict())
        tag = {"use": "TUL", "create": "TC", "eval": "EVAL"}[phase]
        self.progress(f"{tag:<4} {phase_trial:2d}  {tool:<14} "
                      f"loc {task.location}  {ex.outcome:<11} tested {', '.join(tested_l) or '-'}")
        return rec, vs

    def _bounds(self, vs: Term) -> tuple[str, str]:
        b = self.engine.call("vs_bounds", vs)
        return term_text(b.args[0]), term_text(b.args[1])


def _model_names(models: Term) -> str:
    if isinstance(models, list):
        return ", ".join(term_text(m.args[0]) if isinstance(m, Compound) else str(m)
                         for m in models)
    return term_text(models)


def _pose_from_term(case: str, pose: Term) -> Any:
    """Return the sim's pose object for a ground pose term of the constraint solver."""
    from creative_py.sim.trial import get_case

    text = ",".join(repr(float(a)) for a in pose.args)
    return get_case(case).parse_pose(text)


def _pose_dict(pose: Term) -> dict[str, float]:
    names = {"hook_pose": ("dx", "dy", "roll"), "wedge_pose": ("r", "gap", "yaw")}
    if isinstance(pose, Compound) and pose.name in names:
        return dict(zip(names[pose.name], (round(float(a), 5) for a in pose.args)))
    return {"pose": term_text(pose)}
