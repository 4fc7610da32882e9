"""The trial loop above the simulator boundary: one trial of any case, whatever its backend.

A backend builds a scene and runs the skills; what a trial *is* (which skills run in
which order, when the robot observes, when the oracle is asked, what each way of
ending means, what the result holds) is decided here, once, for every backend::

    from creative_py.simulator.trial import run_trial
    result = run_trial(world, tool, variant, location, pose, seed,
                       pose_target=poses)                    # TrialResult

``run_trial``     open the manifest's backend's episode, play the trial, return the
                  :class:`~creative_py.simulator.types.TrialResult` (the learner's, the
                  command line's ``creative trial``, the benchmarks')
``play_trial``    its body, for a caller that opens the episode itself (the simulator
                  benchmark: ``by_hand``, ``timings``, no observation)
``trial_outcome`` what each way of ending a trial means: the one place (a motion
                  out of steps or time included)
``judge``         the oracle asked and the outcome given
``verdict_data``  a trial's measured verdict as JSON-ready data
``task_facts``    what the robot perceives of a task before acting, observed once per
                  task through the case's backend (the planner's and the size model's
                  facts)

The physics is the oracle: the outcome comes from how the skills ended
(:class:`~creative_py.simulator.types.SkillOutcome`) and what the episode's oracle
measured (:meth:`creative_py.simulator.Episode.verdict`), never from a tool's
properties.
"""

from __future__ import annotations

import logging
import math
import time
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, NamedTuple, Optional, Sequence

from creative_py.simulator.types import (BackendLost, Fact, NonFiniteState, Observation,
                                         PoseTarget, SkillOutcome, TrialResult, Verdict)

if TYPE_CHECKING:
    from creative_py.case import CaseManifest, SkillBinding
    from creative_py.simulator.protocol import (ClipRecorder, Episode, VerdictCallback,
                                                World)

log = logging.getLogger(__name__)


def run_trial(world: World, tool: str, variant: str, location: int,
              pose: Optional[Sequence[float]] = None, seed: int = 0,
              images_dir: Optional[Path] = None, gui: bool = False,
              pose_target: Optional[PoseTarget] = None,
              record: Optional[ClipRecorder] = None,
              verdict: Optional[VerdictCallback] = None) -> TrialResult:
    """Run one trial in the case's backend: an episode, every skill of the manifest in
    order, then the oracle.

    Parameters
    ----------
    world : World
        The case's world (its manifest names the backend: ``backend_for``).
    tool, variant, location, seed, images_dir, gui, pose_target, record
        As :meth:`creative_py.simulator.Backend.open_episode` takes them.
    pose : sequence of float or None
        The pose skill's numbers, in the order and units of the manifest's
        ``[[pose.param]]``; None: the demonstration's.
    verdict : callable or None
        ``verdict(outcome, reason, measured)`` (``measured`` the result's ``verdict``),
        called once the result is taken, still inside the episode (where a kept
        trial's clip is rendered from ``record``); without it, ``record`` is rendered
        (``record.render()``) at the end.

    Returns
    -------
    TrialResult
        ``outcome`` as :func:`trial_outcome` says (``invalid`` when a true pose is not
        finite); ``facts_before`` what the robot observed just before the tool action
        (or where a blocked motion stopped), the state the learner labels;
        ``verdict`` what the oracle measured (:func:`verdict_data`), asked or not, with
        a guard's measure of a stopped motion; ``max_tool_force_n`` (N) and
        ``tool_load`` the episode's :meth:`~creative_py.simulator.Episode.measured_load`
        once the tool action started (0.0 and None before); ``wall_time_s`` the wall
        time from opening the episode until the trial was judged. A further measure
        goes in ``measures`` under the name of the trial record's field that keeps it
        (a field marked ``measured`` in :mod:`creative_py.records.trial`): the record
        and a replay carry it with no other line.
    """
    from creative_py.simulator.loader import backend_for

    m = world.manifest
    pose = m.demonstration.pose if pose is None else tuple(float(v) for v in pose)
    t0 = time.perf_counter()
    with backend_for(m).open_episode(world, variant, location, tool, seed, gui, images_dir,
                                     pose_target, record=record) as ep:
        played = play_trial(ep, m, pose)
        wall_s = time.perf_counter() - t0
        result = TrialResult(case=m.id, object=tool, variant=variant,
                             location=int(location), pose=tuple(pose), seed=seed,
                             wall_time_s=wall_s, **_measured(ep, played))
        # Everything judged is taken: a clip's rendering may set the state back.
        if verdict is not None:
            verdict(played.outcome, played.reason, played.verdict)
        elif record is not None:
            record.render()
    return result


def _measured(ep: Episode, played: Played) -> dict[str, Any]:
    """Return the :class:`~creative_py.simulator.types.TrialResult` fields that the
    trial ``played`` in episode ``ep`` measured: its outcome and reason, the facts before
    the tool action, the final poses, the episode's time and steps, the tool's load
    (once the tool action started) and the verdict."""
    force, load = ep.measured_load() if played.acted else (0.0, None)
    final = played.final
    return dict(outcome=played.outcome, reason=played.reason,
                perceived_final=(final.perceived_poses() if final is not None and final.frames
                                 else None),
                true_final=played.truth, sim_time_s=ep.sim_time(),
                render_time_s=ep.render_time_s, steps=ep.steps, max_tool_force_n=force,
                tool_load=load, facts_before=played.facts_before, verdict=played.verdict)


class Played(NamedTuple):
    """What :func:`play_trial` did: the outcome and reason, the facts observed before
    the tool action (or where a blocked motion stopped), the last observation (None
    when none was taken), the true poses after the trial, whether the tool action
    started, and the measured verdict (:func:`verdict_data`)."""

    outcome: str
    reason: str
    facts_before: tuple[Fact, ...]
    final: Optional[Observation]
    truth: dict[str, tuple[float, ...]]
    acted: bool
    verdict: Optional[dict[str, Any]] = None


def play_trial(ep: Episode, manifest: CaseManifest, pose: Sequence[float],
               observe: bool = True, by_hand: bool = False,
               timings: Optional[dict[str, float]] = None,
               skills: Optional[Sequence[SkillBinding]] = None,
               after_skill: Optional[Callable[[SkillBinding, SkillOutcome], None]] = None
               ) -> Played:
    """Run the manifest's skills in order in an open episode and judge the trial.

    The body of :func:`run_trial`, for a caller that opens the episode itself (the
    simulator benchmark, the demonstration). Before the tool action the robot observes
    (the state the action model's precondition speaks of); a blocked motion is observed
    where it stopped, a trial whose skills all ran at its end. A skill in which the
    robot struck a scene body (its ``struck``) does not end the trial: the skills go on
    and the judgement carries the first strike. ``observe=False`` takes no observation
    (nothing rendered, no noise drawn). ``by_hand`` lets the trainer put
    the tool at the pose (the pose skill's ``by_hand`` option; the skills before it are
    skipped). ``timings`` receives each skill's wall time (s) as ``<skill>_s``.
    ``skills`` are the skills to run (default: the manifest's; the demonstration's
    ``steps``), and ``after_skill(skill, status)`` is called after each has run (the
    demonstration observes there). The outcome is :func:`trial_outcome`'s, or
    ``invalid`` when a true pose is not finite.
    """
    facts: tuple[Fact, ...] = ()
    final: Optional[Observation] = None
    acted, status = False, SkillOutcome("ok")
    struck: Optional[SkillOutcome] = None
    for skill in manifest.skills if skills is None else skills:
        if by_hand and not (skill.pose or skill.tool_action):
            continue  # the trainer places the tool: no grasp, no carrying
        if skill.tool_action:
            if observe:
                facts = ep.observe().facts  # what the action model's precondition speaks of
            acted = True
        t0 = time.perf_counter()
        options = {"by_hand": True} if by_hand and skill.pose else {}
        try:
            status = ep.run_skill(skill.name, pose if skill.pose else None, **options)
        except BackendLost as exc:
            exc.skill = exc.skill or skill.name  # the skill the backend was lost in
            raise
        if timings is not None:
            timings[f"{skill.name}_s"] = time.perf_counter() - t0
        if struck is None and status.struck is not None:
            struck = status  # the robot's first strike on the scene (trial_outcome)
        if after_skill is not None:
            after_skill(skill, status)
        if not status.ok:
            break
    if struck is not None and struck is not status:
        # The first strike says it; a guard that stopped a later motion keeps its status.
        status = struck if status.ok else replace(status, struck=struck.struck)
    outcome, reason, oracle, asked = judge(ep, status, acted)
    if observe and outcome == "blocked":
        # What the robot sees where the motion stopped: the catalogue and the task's
        # facts still describe the trial (a planned example needs them).
        final = ep.observe()
        facts = final.facts
    elif observe and status.ok:
        final = ep.observe()
    truth = ep.truth()
    bad = [n for n, p in truth.items() if not all(math.isfinite(v) for v in p)]
    if bad and outcome != "invalid":
        outcome, reason = "invalid", f"non-finite pose of {', '.join(bad)}"
    return Played(outcome, reason, tuple(facts), final, truth, acted,
                  verdict_data(oracle, asked, status.stop, status.struck))


def judge(ep: Episode, status: SkillOutcome, acted: bool
          ) -> tuple[str, str, Optional[Verdict], bool]:
    """Return ``(outcome, reason, oracle, asked)`` of a trial whose last skill ended
    ``status``: the episode's oracle measured (:meth:`Episode.verdict`, the one oracle
    of every backend) and :func:`trial_outcome`'s judgement.

    The oracle is asked when the goal can have been reached: every skill ran, or the
    tool acted until it was stopped or ran out of time. It measures every trial (the
    measure is reported) but decides only when asked; a physics blow-up may leave
    nothing finite to measure (``oracle`` None): asked, a :class:`NonFiniteState` (a
    body the oracle reads thrown to NaN, tracked by the cameras or not) makes the trial
    ``invalid``, any other error is raised.
    """
    asked = status.ok or (acted and status.status in STOPPED)
    try:
        oracle: Optional[Verdict] = ep.verdict()
    except (ValueError, ArithmeticError) as exc:
        if asked and not isinstance(exc, NonFiniteState):
            raise
        log.debug("no oracle measure after %s: %s", status.status, exc)
        if asked:
            return "invalid", str(exc), None, asked
        oracle = None
    reached = asked and oracle is not None and oracle.holds
    outcome, reason = trial_outcome(status, acted, reached)
    return outcome, reason, oracle, asked


def verdict_data(oracle: Optional[Verdict], asked: bool, stop: Optional[Verdict],
                 struck: Optional[Verdict] = None) -> Optional[dict[str, Any]]:
    """Return a trial's measured verdict as JSON-ready data: the oracle's
    (:meth:`Verdict.to_dict`) with ``asked`` (whether the outcome rests on it: every
    skill ran, or the tool acted until stopped), for a motion a guard stopped,
    ``stop`` (the guard's verdict: what it measured and what was touching), and for
    a robot that struck a scene body, ``struck`` (which link struck which body,
    where, how hard: :attr:`SkillOutcome.struck`)."""
    if oracle is None and stop is None and struck is None:
        return None
    data = oracle.to_dict() if oracle is not None else {}
    data["asked"] = bool(asked)
    if stop is not None:
        data["stop"] = stop.to_dict()
    if struck is not None:
        data["struck"] = struck.to_dict()
    return data


STOPPED = ("blocked", "out_of_time")
"""The skill statuses of a motion that stopped before its end with the scene intact: a
guard stopped it, or its step or time budget ran out (the goal is asked after either
once the tool acted)."""

GOAL_REACHED, GOAL_NOT_REACHED = "goal reached", "goal not reached"
"""The reasons of a trial whose skills all ran (:func:`trial_outcome`): any other
reason says how the trial did not go as planned, and every line that shows a trial's
outcome shows it too (:func:`plain_reason`)."""


def plain_reason(reason: str) -> bool:
    """Return whether ``reason`` is only the goal's judgement of a trial whose skills
    all ran (nothing more to say beside the outcome)."""
    return reason in ("", GOAL_REACHED, GOAL_NOT_REACHED)


def trial_outcome(status: SkillOutcome, acted: bool, reached: bool) -> tuple[str, str]:
    """Return a trial's ``(outcome, reason)``: the one place that says what each way of
    ending a trial means, for every backend.

    Parameters
    ----------
    status : SkillOutcome
        How the last skill run ended (``ok`` when every skill ran).
    acted : bool
        Whether the tool action started (the motion that stopped, if any, was the tool
        action or a skill after it).
    reached : bool
        Whether the goal holds (the oracle), asked when the skills ran or the tool acted.

    Returns
    -------
    (str, str)
        Every skill ran: ``success`` / ``failure`` as the goal was or was not reached.
        Blocked before the tool action: ``blocked`` (the arm could not carry out the
        planned motion). Blocked while the tool acted: the tool could not carry out the
        action to its end, and the physics says ``success`` or ``failure`` by the goal.
        Out of time (``out_of_time``: the episode's control steps, a goal's seconds),
        wherever it ran out, in every backend: ``success`` if the tool acted and the
        goal holds when the time is up (the physics judges the state the budget left),
        ``blocked`` otherwise: the plan did not fit the budget, so the trial says
        nothing of what the tool would have done at its end (a ``failure`` would say
        the tool did all of it and missed). The reason is the skill's.
        Otherwise the skill's status (``unreachable``, ``invalid``) with its reason.
        Before all of these, a trial in which the robot itself (a link, not the tool
        it holds) struck a scene body (``status.struck``, measured by the backend),
        before or during the tool action, unless the physics blew up (``invalid``):
        ``success`` if the tool acted and the goal holds (the physics judges the
        state, as for a trial out of time), ``blocked`` otherwise: the arm, not the
        tool, met the scene, so a goal not reached says nothing of what the tool
        does where it was planned to be (a hand that strikes a tube's mouth pushes
        the held tool aside; a ``failure`` would be read as the tool's). The reason
        is the skill's (which link struck which body, where; or its guard's, when
        one stopped the motion too).
    """
    if status.struck is not None and status.status != "invalid":
        return ("success" if acted and reached else "blocked"), status.reason
    if status.ok:
        return ("success", GOAL_REACHED) if reached else ("failure", GOAL_NOT_REACHED)
    if status.status == "out_of_time":
        return ("success" if acted and reached else "blocked"), status.reason
    if status.status == "blocked" and acted:
        return ("success" if reached else "failure"), status.reason
    return status.status, status.reason


_TASK_FACTS: dict[tuple, list[tuple]] = {}


def task_facts(world: World, variant: str, location: int) -> list[tuple]:
    """Return what the robot perceives of a task before acting: the catalogue of
    available objects, the apparatus and the target's pose.

    The scene is built and observed once per (world folder, available objects, variant,
    location) by the manifest's backend; nothing moves.
    """
    from creative_py.simulator.loader import backend_for

    m: CaseManifest = world.manifest
    key = (m.id, str(m.folder), world.variation,
           tuple(sorted(world.catalogue)), variant, int(location))
    if key not in _TASK_FACTS:
        # The robot is not built: it is invisible to the cameras and holds nothing yet,
        # so the facts are the same (checked for every case, variant and location) and
        # the scene builds seven times faster.
        with backend_for(m).open_episode(world, variant, int(location),
                                         m.demonstration.tool, seed=0, robot=False) as ep:
            _TASK_FACTS[key] = list(ep.observe().facts)
    return _TASK_FACTS[key]
