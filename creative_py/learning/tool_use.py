"""Learning to use a tool: the demonstration, then experiments (the paper's Algorithm 1).

The loop reads like the paper. Prolog decides (which literal to test, which object,
which spatial constraints; how the version space changes); Python acts (runs the skills
in the physics and reports what the cameras and the arm's proprioception saw). The
physics alone decides whether a trial succeeded.

One trial::

    experiment = engine.next_experiment(case, vs, facts, skip, strategy.term(seed, i))
    record, vs = runner.run(experiment, "use", i, vs, task, t)   # pybullet decides,
                                                                 # Prolog labels

The strategy (a :class:`~creative_py.learning.strategies.Strategy` of
:data:`~creative_py.learning.strategies.STRATEGIES`) is an argument of the loop: its
Prolog clause group chooses the experiment (``experiment:next_experiment/6``), and its
entry says when the loop stops and which experiments are not run again. ``paper`` is
Algorithm 1 (one unknown literal per trial, then K successes in a row once nothing is
left to test); ``informative`` the experiment with the largest expected reduction of the
version space, stopping as soon as no experiment can change it (the certified stop, no
confirmation trials); ``random`` a random experiment that h_g covers, seeded by the
run's seed and the trial's number, stopping when nothing is left to test.
"""

from __future__ import annotations

import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Optional

from creative_py.bridge import Compound, Engine, Term, fact_term
from creative_py.learning.prior import Prior
from creative_py.learning.strategies import Strategy, strategy_named
from creative_py.learning.trials import TrialRecord, TrialRunner
from creative_py.simulator.trial import play_trial
from creative_py.simulator.types import SkillOutcome

if TYPE_CHECKING:
    from creative_py.simulator import PoseTarget, World
    from creative_py.case import SkillBinding


@dataclass(frozen=True)
class LearningOptions:
    """Options of tool-use learning.

    Parameters
    ----------
    max_trials : int
        N: stop after this many tool-use trials.
    consecutive : int
        K: with a strategy that confirms (``paper``), stop once the version space has
        nothing left to test and the last K trials succeeded.
    strategy : str
        A name of :data:`~creative_py.learning.strategies.STRATEGIES`
        (:class:`~creative_py.learning.strategies.UnknownStrategy` otherwise).
    """

    max_trials: int = 12
    consecutive: int = 2
    strategy: str = "informative"

    def __post_init__(self) -> None:
        strategy_named(self.strategy)


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


class DemonstrationFailed(ValueError):
    """The trainer's demonstration did not reach the goal in the physics."""


def run_demonstration(world: World, seed: int = 0, images_dir: Optional[Path] = None,
                      record: Any = None, gui: bool = False,
                      verdict: Optional[Callable[[], None]] = None, *,
                      pose_target: PoseTarget) -> Demonstration:
    """Run the trainer's scripted demonstration and observe after every skill.

    The tool, variant, location, skills and pose come from the manifest's
    ``[demonstration]``. Each step's facts are what the robot perceives (cameras) and
    feels (arm proprioception). It is played and judged as every trial is
    (:func:`creative_py.simulator.trial.play_trial`: the same skill loop, the
    episode's one oracle, the one outcome rule, a non-finite pose ``invalid``); a
    demonstration whose outcome is not ``success`` raises
    :class:`DemonstrationFailed` naming the manifest, or for a drawn world
    (``--world-seed``) its world seed: there is nothing to learn from. ``record`` (a
    :class:`creative_py.simulator.ClipRecorder`) keeps its poses; ``verdict()`` is
    called at the end of a successful demonstration, inside the episode (where its
    clip is rendered); ``gui`` shows the simulator's window. The episode is the
    manifest's backend's (:func:`creative_py.simulator.backend_for`). ``pose_target``
    gives the pose skill its world target (:func:`creative_py.learning.poses.pose_resolver`).
    """
    from creative_py.simulator import backend_for

    m = world.manifest
    demo = m.demonstration
    where = (f"{world.variation} (drawn from {m.folder / 'case.toml'}): the demonstration"
             if world.variation else
             f"{m.folder / 'case.toml'}: field 'demonstration'")
    steps: list[DemoStep] = []
    with backend_for(m).open_episode(world, demo.variant, demo.location, demo.tool,
                                     seed=seed, images_dir=images_dir, gui=gui,
                                     record=record, pose_target=pose_target) as ep:
        seen = [tuple(ep.observe().facts)]
        last = SkillOutcome("ok")

        def observed(skill: SkillBinding, status: SkillOutcome) -> None:
            nonlocal last
            last = status
            seen.append(tuple(ep.observe().facts))
            steps.append(DemoStep(skill.name, m.skill_args(skill, demo.tool), seen[-2],
                                  seen[-1], status.status))

        # A trial like any other (simulator/trial.py): the same skill loop, oracle and
        # outcome rule, the robot observing after every skill instead of before the
        # tool action only.
        played = play_trial(ep, m, demo.pose, observe=False,
                            skills=tuple(m.skill(name) for name in demo.steps),
                            after_skill=observed)
        if played.outcome == "success" and verdict is not None:
            verdict()  # the physics is done with
    if played.outcome != "success" and not last.ok:
        raise DemonstrationFailed(f"{where}: the trainer's skill {steps[-1].skill} ended "
                                  f"{last.status} in the physics: {last.reason}")
    if played.outcome != "success":
        why = (f": {played.reason}" if played.outcome == "invalid" else
               ": nothing to learn from")
        raise DemonstrationFailed(f"{where}: {demo.tool} at location {demo.location} did "
                                  f"not reach the goal in the physics{why}")
    return Demonstration(demo.tool, demo.variant, demo.location, demo.pose, tuple(steps),
                         True)


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
    stop: str = "budget"
    """Why learning stopped: ``certified`` (informative: no experiment could change the
    version space), ``exhausted`` (random: no experiment h_g covers was left),
    ``confirmed`` (paper: nothing left to test and K successes in a row) or ``budget``
    (N trials)."""
    vs_count_initial: int = 0
    """The hypotheses after the demonstration (``version_space:vs_count/3``)."""
    vs_count_initial_exact: bool = True
    prior: Optional[Prior] = None
    """The prior the version space started from (``--prior``), or None."""
    prior_taken: tuple[str, ...] = ()
    """The literals taken from the prior, as text: open predictions at the start."""
    prior_dropped: tuple[tuple[str, int], ...] = ()
    """The prior's literals a trial contradicted (it succeeded though it violated
    them), with that trial's number (0: the demonstration, whose tool lacks them): not
    in h_g, learned afresh."""
    prior_settled: tuple[tuple[str, int], ...] = ()
    """The prior's spatial literals a success satisfied, with its trial number: in h_g
    from then on, untested (the stop is certified relative to them)."""
    prior_confirmed: tuple[tuple[str, int], ...] = ()
    """The prior's literals the physics made necessary (a failure, as without a prior),
    with the trial number."""


class ToolUseLearner:
    """Tool-use learning for one case (paper, Algorithm 1).

    Parameters
    ----------
    runner : TrialRunner
        Runs and records the trials (its world's manifest names the case).
    options : LearningOptions
    prior : Prior or None
        Another case's learned model (:func:`creative_py.learning.prior.load_prior`):
        the literals the ontology maps from it are the version space's open
        predictions, trusted only as far as the trials confirm them.
    """

    def __init__(self, runner: TrialRunner, options: LearningOptions = LearningOptions(),
                 prior: Optional[Prior] = None) -> None:
        self.runner = runner
        self.engine: Engine = runner.engine
        self.case = runner.case
        self.options = options
        self.prior = prior

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

        runner.progress(f"demonstration: the trainer shows the task with {m.tool} "
                        f"(loc {m.location})")
        demo = run_demonstration(runner.world, seed=runner.seed,
                                 images_dir=run.snapshot_dir("demo", 0) if run else None,
                                 record=recorder, gui=runner.gui,
                                 verdict=verdict if recorder is not None else None,
                                 pose_target=runner.pose_target)
        steps = [Compound("step", (s.skill, list(s.args),
                                   [fact_term(f) for f in s.facts_before],
                                   [fact_term(f) for f in s.facts_after]))
                 for s in demo.steps]
        _matched, new, example = self.engine.learn_from_demonstration(self.case, steps)
        return new, example, demo.tool

    def learn(self) -> UseResult:
        """Learn from one demonstration and experiments; return the learned version space.

        Algorithm 1 with the options' strategy as its argument: each trial Prolog
        proposes an experiment under the strategy, the physics runs it, Prolog labels
        it; the strategy's rules say when to stop and what not to run again.
        """
        t0 = time.perf_counter()
        runner, opts = self.runner, self.options
        strategy = strategy_named(opts.strategy)
        models, example, demo_tool = self.observe_demonstration()
        vs, taken, dropped = self._initial_space(example)
        events: list[tuple[str, str, int]] = []
        n0, exact0 = self.engine.vs_count(vs)
        runner.progress(f"demonstration with {demo_tool}: new model {_model_names(models)}; "
                        f"{n0} hypotheses{'' if exact0 else ' at most'}")
        task = runner.task(runner.manifest.demonstration.variant)
        cons = 0
        converged_at = None
        stop = "budget"
        skip: list[Term] = []
        for i in range(1, opts.max_trials + 1):
            td = time.perf_counter()
            exp = self._next(strategy, vs, task, skip, i)
            decision = time.perf_counter() - td
            testing = exp.name == "experiment"
            if not testing:
                # Nothing left that the available objects and poses can test: stop, or,
                # for a strategy that confirms, use the model until K successes in a row.
                if converged_at is None:
                    converged_at = i - 1
                if not strategy.confirm or cons >= opts.consecutive:
                    stop = strategy.stop
                    break
            rec, vs = self._trial(strategy, exp, i, vs, task, decision, skip)
            if self.prior is not None:
                self._note_prior(vs, i, events, dropped)
            if rec.outcome == "success":
                cons += 1
                task.next_location()
            else:
                cons = 0
        else:
            exp = self._next(strategy, vs, task, skip, opts.max_trials + 1)
            if exp.name != "experiment":
                if converged_at is None:
                    converged_at = opts.max_trials
                if not strategy.confirm:
                    stop = strategy.stop
        if strategy.confirm:
            # Converged: nothing is left to test, and the model's last K trials succeeded
            # (a budget spent on trials the arm could not carry out is not convergence).
            converged = converged_at is not None and cons >= opts.consecutive
        else:
            converged = stop == strategy.stop
        return UseResult(vs, models, list(runner.trials), converged, converged_at,
                         demo_tool, time.perf_counter() - t0, stop, n0, exact0,
                         self.prior, tuple(str(t) for t in taken), tuple(dropped),
                         tuple((lit, i) for kind, lit, i in events if kind == "settled"),
                         tuple((lit, i) for kind, lit, i in events if kind == "confirmed"))

    def _initial_space(self, example: Term) -> tuple[Term, list[Term], list[tuple[str, int]]]:
        """Return the version space the demonstration ``example`` starts (from the prior,
        when there is one), the prior's literals taken (open until the physics settles
        them) and those the demonstration contradicts (at trial 0)."""
        runner = self.runner
        taken: list[Term] = []
        if self.prior is not None:
            taken = list(self.engine.prior_literals(self.case, self.prior.term, example))
            vs = self.engine.vs_init_prior(self.case, example, taken)
            runner.progress(f"prior from case {self.prior.case} ({self.prior.source}): "
                            f"{len(taken)} literal(s) predicted necessary, open until the "
                            "physics settles them: "
                            + (", ".join(str(t) for t in taken) or "none"))
        else:
            vs = self.engine.vs_init(example)
        dropped: list[tuple[str, int]] = []
        if self.prior is not None:
            # The demonstration is the first trial the prior can be wrong about: a
            # literal it violates is contradicted there (trial 0) and not taken.
            for lit in self.engine.prior_contradicted(self.case, self.prior.term, example):
                dropped.append((str(lit), 0))
                runner.progress(f"the demonstration contradicted the prior: {lit} "
                                "not taken, learned afresh")
        return vs, taken, dropped

    def _note_prior(self, vs: Term, i: int, events: list[tuple[str, str, int]],
                    dropped: list[tuple[str, int]]) -> None:
        """Record what trial ``i`` did to the prior's literals
        (``version_space:vs_prior_events/2``): settled by a success consistent with it,
        confirmed by the physics as without a prior, or dropped (contradicted)."""
        now = self.engine.vs_prior_events(vs)
        for ev in now[len(events):]:
            kind, lit = str(ev.name), str(ev.args[0])
            events.append((kind, lit, i))
            if kind == "dropped":
                dropped.append((lit, i))
                self.runner.progress(f"trial {i} contradicted the prior: {lit} dropped, "
                                     "learned afresh")
            elif kind == "settled":
                self.runner.progress(f"trial {i} succeeded as the prior predicted: {lit} "
                                     "settled")
            else:
                self.runner.progress(f"trial {i}: the physics made {lit} necessary, as "
                                     "the prior predicted")

    def _trial(self, strategy: Strategy, exp: Term, i: int, vs: Term, task: Any,
               decision: float, skip: list[Term]) -> tuple[TrialRecord, Term]:
        """Run tool-use trial ``i`` and add to ``skip`` what the strategy will not run
        again; return its record and the version space after it."""
        testing = exp.name == "experiment"
        before = self._bounds(vs) if strategy.repeat_taught and testing else None
        rec, vs = self.runner.run(exp, "use", i, vs, task, decision)
        taught = rec.outcome in ("success", "failure", "blocked")
        # Algorithm 1 repeats the task after a failure; it does not repeat an experiment
        # whose trial left h_s and h_g as they were (what the robot observed was already
        # excluded: a stick seen outside the tube), which would give the same answer
        # until the budget is spent. An experiment the arm could not carry out taught
        # nothing and is not repeated either.
        idle = taught and before is not None and self._bounds(vs) == before
        if testing:
            done = strategy.skip(exp, taught, idle)
            if done is not None:
                skip.append(done)
        return rec, vs

    def _bounds(self, vs: Term) -> tuple[str, str]:
        """Return h_s and h_g as text, to tell whether a trial changed them."""
        hs, hg = self.engine.vs_bounds(vs)
        return str(hs), str(hg)

    def _next(self, strategy: Strategy, vs: Term, task: Any, skip: list[Term],
              i: int) -> Term:
        """Return Prolog's choice for trial ``i`` under ``strategy``."""
        facts = self.runner.task_facts(task)
        return self.engine.next_experiment(self.case, vs, facts, skip,
                                           strategy.term(self.runner.seed, i))


def _model_names(models: Term) -> str:
    if isinstance(models, list):
        return ", ".join(str(m.args[0]) if isinstance(m, Compound) else str(m)
                         for m in models)
    return str(models)
