"""Learning to use a tool: the demonstration, then the paper's Algorithm 1.

The loop reads like the paper. Prolog decides (which literal to test, which object,
which spatial constraints; how the version space changes); Python acts (runs the skills
in the physics and reports what the cameras and the arm's proprioception saw). The
physics alone decides whether a trial succeeded.

One trial::

    experiment = engine.next_experiment(case, vs, facts, skip)  # literal, object, pose
    record, vs = runner.run(experiment, "use", i, vs, task, t)   # pybullet decides,
                                                                 # Prolog labels
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, Engine, Term, fact_term
from creative_py.learning.trials import TrialRecord, TrialRunner


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
    """

    max_trials: int = 12
    consecutive: int = 2


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
    pose: tuple[float, ...]
    steps: tuple[DemoStep, ...]
    goal_reached: bool


def run_demonstration(world: Any, seed: int = 0, images_dir: Optional[Path] = None,
                      record: Any = None, gui: bool = False,
                      verdict: Optional[Callable[[], None]] = None) -> Demonstration:
    """Run the trainer's scripted demonstration and observe after every skill.

    The tool, variant, location, skills and pose come from the manifest's
    ``[demonstration]``. Each step's facts are what the robot perceives (cameras) and
    feels (arm proprioception). A demonstration that fails in the physics raises
    ValueError naming the manifest: there is nothing to learn from. ``record`` (a
    :class:`creative_py.sim.recorder.Recorder`) keeps its poses; ``verdict()`` is
    called at the end of a successful demonstration, inside the episode (where its
    clip is rendered); ``gui`` shows the pybullet GUI.
    """
    from creative_py.sim import open_episode

    m = world.manifest
    demo = m.demonstration
    steps: list[DemoStep] = []
    with open_episode(world, demo.variant, demo.location, demo.tool, seed=seed,
                      images_dir=images_dir, gui=gui, record=record) as ep:
        before = tuple(ep.observe().facts)
        for name in demo.steps:
            skill = m.skill(name)
            res = ep.run_skill(name, pose=demo.pose if skill.pose else None)
            after = tuple(ep.observe().facts)
            steps.append(DemoStep(name, m.skill_args(skill, demo.tool), before, after,
                                  res.status))
            if res.status != "ok":
                raise ValueError(f"{m.folder / 'case.toml'}: field 'demonstration': the "
                                 f"trainer's skill {name} ended {res.status} in the physics: "
                                 f"{res.reason}")
            before = after
        reached = ep.goal_reached()
        if reached and verdict is not None:
            verdict()  # the physics is done with
    if not reached:
        raise ValueError(f"{m.folder / 'case.toml'}: field 'demonstration': {demo.tool} at "
                         f"location {demo.location} did not reach the goal in the physics: "
                         "nothing to learn from")
    return Demonstration(demo.tool, demo.variant, demo.location, demo.pose, tuple(steps),
                         reached)


@dataclass
class UseResult:
    """The outcome of tool-use learning."""

    vs: Term
    models: Term
    trials: list[TrialRecord]
    converged: bool
    trials_to_converge: Optional[int]
    """The trials after which nothing was left to test (None: something still was)."""
    demo_tool: str
    wall_time_s: float


class ToolUseLearner:
    """Tool-use learning for one case (paper, Algorithm 1).

    Parameters
    ----------
    runner : TrialRunner
        Runs and records the trials (its world's manifest names the case).
    options : LearningOptions
    """

    def __init__(self, runner: TrialRunner, options: LearningOptions = LearningOptions()) -> None:
        self.runner = runner
        self.engine: Engine = runner.engine
        self.case = runner.case
        self.options = options

    def observe_demonstration(self) -> tuple[Term, Term, str]:
        """Run the trainer's demonstration and build the new action model from it.

        Returns the new models, the example clause for the version space and the
        demonstrated tool.
        """
        runner = self.runner
        run = runner.run_folder
        clips = runner.clips
        recorder = clips.recorder() if clips is not None else None
        m = runner.manifest.demonstration

        def verdict() -> None:
            why = clips.why("demo", "success", "goal reached")
            if why is not None:
                clips.write(recorder, why, 0, "demo", 0, m.tool, [], "success",
                            "goal reached", m.location)

        demo = run_demonstration(runner.world, seed=runner.seed,
                                 images_dir=run.snapshot_dir("demo", 0) if run else None,
                                 record=recorder, gui=runner.gui,
                                 verdict=verdict if recorder is not None else None)
        steps = [Compound("step", (s.skill, list(s.args),
                                   [fact_term(f) for f in s.facts_before],
                                   [fact_term(f) for f in s.facts_after]))
                 for s in demo.steps]
        _matched, new, example = self.engine.learn_from_demonstration(self.case, steps)
        return new, example, demo.tool

    def learn(self) -> UseResult:
        """Run Algorithm 1 from one demonstration; return the learned version space."""
        t0 = time.perf_counter()
        runner, opts = self.runner, self.options
        models, example, demo_tool = self.observe_demonstration()
        vs = self.engine.vs_init(example)
        runner.progress(f"demonstration with {demo_tool}: new model {_model_names(models)}")
        task = runner.task(runner.manifest.demonstration.variant)
        cons = 0
        converged_at = None
        skip: list[Term] = []
        for i in range(1, opts.max_trials + 1):
            td = time.perf_counter()
            exp = self.engine.next_experiment(self.case, vs, runner.task_facts(task), skip)
            decision = time.perf_counter() - td
            if exp.name != "experiment":
                # Nothing left that the available objects and poses can test.
                if converged_at is None:
                    converged_at = i - 1
                if cons >= opts.consecutive:
                    break
            rec, vs = runner.run(exp, "use", i, vs, task, decision)
            if rec.outcome == "success":
                cons += 1
                task.next_location()
            else:
                cons = 0
                if rec.outcome not in ("failure", "blocked") and exp.name == "experiment":
                    # The arm could not carry it out: it taught nothing; do not repeat
                    # it. A pose test (a negated spatial literal) is skipped whatever
                    # the tool.
                    who = "any" if exp.args[5] else exp.args[0]
                    skip.append(Compound("skip", (who, exp.args[1])))
        else:
            exp = self.engine.next_experiment(self.case, vs, runner.task_facts(task), skip)
            if exp.name != "experiment" and converged_at is None:
                converged_at = opts.max_trials
        # Converged: nothing is left to test, and the model's last K trials succeeded
        # (a budget spent on trials the arm could not carry out is not convergence).
        converged = converged_at is not None and cons >= opts.consecutive
        return UseResult(vs, models, list(runner.trials), converged, converged_at,
                         demo_tool, time.perf_counter() - t0)


def _model_names(models: Term) -> str:
    if isinstance(models, list):
        return ", ".join(str(m.args[0]) if isinstance(m, Compound) else str(m)
                         for m in models)
    return str(models)
