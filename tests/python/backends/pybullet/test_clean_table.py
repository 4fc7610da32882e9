"""RoboToolBench's CleanTable on the Panda: what the physics decides at the demonstration's
pose (worlds/clean_table/).

Eight cubes drawn by the scatter (location 1: seed 1) are swept along +x into the goal
circle; the verdict is the benchmark's reward (the mean over the cubes of 1 within 0.16,
L1, of (1.1, 0), else their progress). In the standard band (y within 0.08 m) the
trainer's shallow U gathers all eight; at the benchmark's spread (y within 0.2 m) it
leaves the cubes beside it, and a plate as wide as the spread pushes them straight on,
some beyond the goal's reach across; a funnel (its wings spread 0.13 m each: the
sizes the case's size model gives a created pusher) gathers them all.
"""

from functools import lru_cache

import pytest

from creative_py.case import get_case
from creative_py.kinds.pusher import PusherSpec
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses

pytestmark = pytest.mark.sim


@lru_cache(maxsize=None)
def _world():
    world = load_world(get_case("clean_table"))
    funnel = PusherSpec(name="funnel_new", pole_length=0.23, pole_width=0.021,
                        plate_width=0.23, wing_length=0.07, wing_spread=0.13, mass=None)
    return world.with_tool(funnel)


@pytest.mark.parametrize("tool, variant, outcome, inside", [
    ("rake_c1", "standard", "success", 8),
    ("rake_c1", "benchmark", "failure", 4),
    ("rake_c5", "benchmark", "failure", 5),
    ("funnel_new", "benchmark", "success", 8),
])
def test_the_physics_discriminates_the_heads(tool, variant, outcome, inside):
    result = run_trial(_world(), tool, variant, 1, pose_target=poses(_world()))
    assert result.outcome == outcome, result.reason
    verdict = result.verdict
    # the load on the tool is its contacts with every cube (the target's bodies)
    assert result.max_tool_force_n > 1.0
    assert result.tool_load["bodies"] == ["cubes"]
    assert verdict["quantity"] == "reward"
    assert verdict["measures"]["objects"] == 8
    assert verdict["measures"]["inside"] == inside
    if outcome == "success":
        assert verdict["value"] == pytest.approx(1.0)
    else:
        assert verdict["value"] < 0.99
