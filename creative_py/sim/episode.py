"""The simulator's public API: load a case's world, open an episode, run a trial.

Every case is driven the same way, by the skill names of its manifest
(``worlds/<folder>/case.toml``)::

    from creative_py.case import get_case
    from creative_py.sim import load_world, open_episode, run_trial

    world = load_world(get_case("hook"))
    with open_episode(world, "standard", 1, "hook_a2", seed=0) as ep:
        ep.run_skill("pick_up")                      # SkillOutcome
        ep.run_skill("position_tool", pose=(0.03, 0.0, 0.0))
        ep.run_skill("pull")
        ep.goal_reached()                            # the physics oracle
        ep.observe()                                 # Observation(facts, frames, truth)

:func:`run_trial` runs the manifest's skills in order and returns a
:class:`~creative_py.sim.types.TrialResult`. The physics decides the outcome; nothing
here looks at tool properties.
"""

from __future__ import annotations

import math
import time
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable, Iterator, Sequence

from creative_py.sim.types import Fact, Observation, SkillOutcome, TrialResult
from creative_py.sim.world import World

PoseTarget = Callable[[list[Fact], str, tuple[float, ...]], tuple]
"""``(facts, tool, pose) -> world target`` of a pose, e.g. ``("tip", x, y, roll)``."""


def prolog_pose_target(case_id: str, pose_term: str) -> PoseTarget:
    """Return a :data:`PoseTarget` that asks the engine (``api:pose_target``).

    The engine turns the relative pose numbers into the world target of the case's
    pose-taking skill (``abstract_state:pose_world/5``); the answer comes back as a
    tuple ``(name, numbers...)``.
    """

    def target(facts: list[Fact], tool: str, pose: tuple[float, ...]) -> tuple:
        from creative_py.bridge import FAILED, Compound, Engine

        engine = Engine.instance()
        terms = [_fact_term(f) for f in facts]
        answer = engine.call("pose_target", case_id, tool, terms,
                             Compound(pose_term, tuple(float(v) for v in pose)))
        if answer is FAILED:
            return ()
        if isinstance(answer, Compound):
            return (answer.name, *answer.args)
        return (answer,)

    return target


def _fact_term(fact: Fact) -> Any:
    from creative_py.bridge import Compound

    name, *args = fact
    plain = [("true" if a else "false") if isinstance(a, bool)
             else (a.item() if hasattr(a, "item") else a) for a in args]
    return Compound(name, tuple(plain)) if plain else name


@contextmanager
def open_episode(world: World, variant: str, location: int, tool: str, seed: int = 0,
                 gui: bool = False, images_dir: Path | None = None,
                 pose_target: PoseTarget | None = None) -> Iterator["Episode"]:
    """Build the scene and yield an :class:`Episode`; close it on exit.

    Parameters
    ----------
    world : World
        From :func:`creative_py.sim.load_world`.
    variant : str
        A variant of the manifest (its ``set`` values change the scene).
    location : int
        1-based index of the predefined target location (``world.locations``).
    tool : str
        The catalogued object used as a tool; unknown names raise listing the others.
    seed : int
        Seeds every random choice (sensor noise); same seed, same result.
    gui : bool
        Show the pybullet GUI if a display exists.
    images_dir : Path or None
        Save camera snapshots there.
    pose_target : callable or None
        ``(facts, tool, pose) -> target``: the world target of a pose (Prolog's pose
        solution); None asks the engine (:func:`prolog_pose_target`).
    """
    ep = Episode(world, variant, location, tool, seed, gui,
                 None if images_dir is None else Path(images_dir), pose_target)
    try:
        yield ep
    finally:
        ep.close()


class Episode:
    """One scene of a case in its own simulator, driven skill by skill by name."""

    def __init__(self, world: World, variant: str, location: int, tool: str, seed: int = 0,
                 gui: bool = False, images_dir: Path | None = None,
                 pose_target: PoseTarget | None = None) -> None:
        self.world = world
        self.manifest = world.manifest
        self.tool = tool
        self.pose_target = pose_target or prolog_pose_target(world.manifest.id,
                                                             world.manifest.pose_term)
        self._ep = world.impl_open(variant, location, tool, seed, gui, images_dir)

    def run_skill(self, name: str, pose: Sequence[float] | None = None) -> SkillOutcome:
        """Run the manifest's skill ``name`` (with ``pose`` numbers for the pose skill)."""
        skill = self.manifest.skill(name)
        if skill.pose:
            if pose is None:
                raise ValueError(f"skill {name} needs the pose numbers "
                                 f"({', '.join(self.manifest.pose_names)})")
            return self._ep.position_tool(tuple(float(v) for v in pose))
        if skill.tool_action:
            return self._ep.act()
        return self._ep.pick_up()

    def goal_reached(self) -> bool:
        """Return whether the case's goal holds in the simulated state (the oracle)."""
        return bool(self._ep.goal_reached())

    def observe(self) -> Observation:
        """Return the facts the robot perceives now, the frames and the ground truth."""
        return self._ep.observe()

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ground-truth ``name -> (x, y, z, yaw)`` (for error reports only)."""
        return self._ep.truth()

    def sim_time(self) -> float:
        """Return the simulated time so far, seconds."""
        return self._ep.sim_time()

    @property
    def steps(self) -> int:
        """Return the physics steps taken so far."""
        return self._ep.steps

    @property
    def render_time_s(self) -> float:
        """Return the wall time spent rendering camera frames so far, seconds."""
        return self._ep.render_time_s

    def close(self) -> None:
        """Release the simulator (idempotent)."""
        self._ep.close()


def run_trial(world: World, tool: str, variant: str, location: int,
              pose: Sequence[float] | None = None, seed: int = 0,
              images_dir: Path | None = None, gui: bool = False,
              pose_target: PoseTarget | None = None) -> TrialResult:
    """Run one physical trial: every skill of the manifest in order, then the oracle.

    ``pose=None`` uses the demonstration's pose. The outcome comes from the simulated
    state only: ``success``/``failure`` when every skill ran, else the status of the
    skill that stopped (``blocked``, ``unreachable``, ``invalid``).
    """
    m = world.manifest
    pose = m.demonstration.pose if pose is None else tuple(float(v) for v in pose)
    t0 = time.perf_counter()
    with open_episode(world, variant, location, tool, seed, gui, images_dir,
                      pose_target) as ep:
        outcome, reason = "success", ""
        for skill in m.skills:
            res = ep.run_skill(skill.name, pose if skill.pose else None)
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
            case=m.id, object=tool, variant=variant, location=int(location),
            pose=tuple(pose), outcome=outcome, reason=reason, perceived_final=perceived,
            true_final=truth, sim_time_s=ep.sim_time(), wall_time_s=0.0,
            render_time_s=ep.render_time_s, steps=ep.steps, seed=seed)
    return replace(result, wall_time_s=time.perf_counter() - t0)
