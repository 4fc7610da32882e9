"""Hook trials shared by several test files, each run once per test session."""

from __future__ import annotations

from functools import lru_cache

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator import TrialResult
from creative_py.simulator.trial import run_trial

from _poses import poses


@lru_cache(maxsize=None)
def hook_world():
    """Return the shipped hook world."""
    return load_world(get_case("hook"))


@lru_cache(maxsize=None)
def hook_trial(tool: str, variant: str, location: int,
               pose: tuple[float, float, float] | None = None, seed: int = 0) -> TrialResult:
    """Return the result of one hook trial (cached: trials are deterministic)."""
    return run_trial(hook_world(), tool, variant, location, pose=pose, seed=seed,
                     pose_target=poses(hook_world()))


def tube(world):
    """Return the tube body's mouth x (m) in the world's standard variant."""
    from creative_py.backends.pybullet.scene import make_bodies

    ns = world.namespace("standard", 1, world.manifest.demonstration.tool)
    return make_bodies(world.scene.bodies, ns)[world.manifest.context]
