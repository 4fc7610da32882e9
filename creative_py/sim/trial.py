"""The case interface: load a case's world, run it step by step, or run one whole trial.

A *case* (``hook``, ``wedge``) is registered in :data:`creative_py.sim.cases.CASES`
and implements :class:`Case`. Its episodes implement :class:`Episode`: the learning
loop drives one skill at a time and observes in between::

    world = load_case_world("hook")
    with open_episode("hook", world, "standard", 1, "hook_a2", seed=0) as ep:
        ep.pick_up()                          # SkillOutcome
        ep.position_tool(HookPose(0.03, 0.0, 0.0))
        ep.act()                              # hook: pull; wedge: release the door
        ep.goal_reached()                     # from the simulated state
        ep.observe()                          # Observation(facts, frames, truth)

:func:`run_trial` does all of that and returns a :class:`TrialResult`. The physics
decides the outcome; nothing here looks at tool properties.

Outcomes: ``success`` / ``failure`` (every skill ran; the goal was or was not reached),
``blocked`` (a move was stopped by a collision: the tracking-error guard),
``unreachable`` (no arm posture reaches a waypoint), ``invalid`` (the physics blew up:
NaN, an object thrown out of the scene).
"""

from __future__ import annotations

import math
import time
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Any, Iterator, Protocol

from creative_py.sim.types import (TRIAL_OUTCOMES, Fact, Observation, SkillOutcome,  # noqa: F401
                                   SkillStatus, TrialOutcome, TrialResult)


class Episode(Protocol):
    """One scene of a case, driven skill by skill (see the module docstring)."""

    steps: int
    render_time_s: float

    def pick_up(self) -> SkillOutcome: ...

    def position_tool(self, pose: Any) -> SkillOutcome: ...

    def act(self) -> SkillOutcome: ...

    def goal_reached(self) -> bool: ...

    def observe(self) -> Observation: ...

    def truth(self) -> dict[str, tuple[float, float, float, float]]: ...

    def sim_time(self) -> float: ...

    def close(self) -> None: ...


class Case(Protocol):
    """A task family with its world, objects, locations and variants."""

    name: str
    object_option: str  # the CLI option naming the object: "tool" or "object"

    def load_world(self, world_dir: Path | None) -> Any: ...

    def open_episode(self, world: Any, variant: str, location: int, object_name: str,
                     seed: int, gui: bool, images_dir: Path | None) -> Episode: ...

    def listing(self, world: Any) -> dict[str, Any]: ...

    def default_pose(self, world: Any) -> Any: ...

    def parse_pose(self, text: str) -> Any: ...


def get_case(case: str) -> Case:
    """Return the registered case ``case``; raise listing the known ones."""
    from creative_py.sim.cases import CASES

    if case not in CASES:
        raise KeyError(f"unknown case {case!r}; known cases: {', '.join(sorted(CASES))}")
    return CASES[case]


def load_case_world(case: str, world_dir: Path | None = None) -> Any:
    """Return the world of ``case`` read from ``world_dir`` (default: the shipped one).

    Errors name the world file and the field (:class:`creative_py.world.WorldFileError`).
    """
    return get_case(case).load_world(None if world_dir is None else Path(world_dir))


@contextmanager
def open_episode(case: str, world: Any, variant: str, location: int, object_name: str,
                 seed: int = 0, gui: bool = False,
                 images_dir: Path | None = None) -> Iterator[Episode]:
    """Build the scene and yield an :class:`Episode`; close it on exit.

    Parameters
    ----------
    case : str
        Registered case name.
    world : object
        From :func:`load_case_world`.
    variant : str
        Task variant name (hook: ``standard`` or ``long_tube``).
    location : int
        1-based index of the predefined target location.
    object_name : str
        The object used as a tool; unknown names raise listing the available ones.
    seed : int
        Seeds every random choice (sensor noise); same seed, same result.
    gui : bool
        Show the pybullet GUI if a display exists.
    images_dir : Path or None
        Save camera snapshots there.
    """
    ep = get_case(case).open_episode(world, variant, location, object_name, seed, gui,
                                     None if images_dir is None else Path(images_dir))
    try:
        yield ep
    finally:
        ep.close()


def list_case(case: str, world: Any) -> dict[str, Any]:
    """Return the case's objects (names and spec fields), locations, variants and default pose."""
    return get_case(case).listing(world)


def _pose_tuple(pose: Any) -> tuple[float, ...]:
    return tuple(float(v) for v in pose)


def run_trial(case: str, world: Any, object_name: str, variant: str, location: int,
              pose: Any = None, seed: int = 0, images_dir: Path | None = None,
              gui: bool = False) -> TrialResult:
    """Run one physical trial: pick up the object, position it, act, judge the goal.

    ``pose=None`` uses the demonstration's pose. The outcome comes from the simulated
    state only (see the module docstring for the outcome names).
    """
    c = get_case(case)
    if pose is None:
        pose = c.default_pose(world)
    t0 = time.perf_counter()
    with open_episode(case, world, variant, location, object_name, seed, gui,
                      images_dir) as ep:
        outcome, reason = "success", ""
        for skill in (ep.pick_up, lambda: ep.position_tool(pose), ep.act):
            res = skill()
            if not res.ok:
                outcome, reason = res.status, res.reason
                break
        else:
            if not ep.goal_reached():
                outcome, reason = "failure", "the goal was not reached"
        obs = ep.observe()
        perceived = obs.perceived_poses() if obs.frames else None
        truth = ep.truth()
        bad = [n for n, p in truth.items() if not all(math.isfinite(v) for v in p)]
        if bad and outcome != "invalid":
            outcome, reason = "invalid", f"non-finite pose of {', '.join(bad)}"
        result = TrialResult(
            case=case, object=object_name, variant=variant, location=int(location),
            pose=_pose_tuple(pose), outcome=outcome, reason=reason,
            perceived_final=perceived, true_final=truth, sim_time_s=ep.sim_time(),
            wall_time_s=0.0, render_time_s=ep.render_time_s, steps=ep.steps, seed=seed)
    return replace(result, wall_time_s=time.perf_counter() - t0)
