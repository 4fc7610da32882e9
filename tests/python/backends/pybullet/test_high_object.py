"""RoboToolBench's HighObject on the Panda: what the physics decides, scored by the
benchmark's reward (worlds/high_object/, docs/robotoolbench.md).

The physics is the oracle: a few real trials (the Panda at the origin, IK, contacts)
check the discrimination the learner and the creator rely on (objects.toml): in the
trainer's nearer shelf the demonstrated medium hook pulls the cube into the box
(reward 1); a short handle cannot be carried along the insertion; a stick passes over
the cube (reward 0). In the benchmark's scene a medium handle cannot reach behind the
cube, the catalogue's long stick does not pull it, and a 0.68 m hook, the size the
creator makes, puts it in the box.
"""

from functools import lru_cache

import pytest

from creative_py.case import get_case
from creative_py.kinds.hook_like import HookSpec
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses

pytestmark = pytest.mark.sim


@lru_cache(maxsize=None)
def _world():
    world = load_world(get_case("high_object"))
    created = HookSpec(name="hook_long", handle_length=0.68, handle_width=0.018,
                       hook_length=0.030, hook_width=0.014, hook_side="right", mass=None)
    return world.with_tool(created)


@pytest.mark.parametrize("tool, variant, outcome, reward, why", [
    ("hook_a1", "standard", "success", 1.0, ""),
    ("hook_a2", "standard", "unreachable", 0.0, "position_tool"),
    ("stick_a5", "standard", "failure", 0.0, ""),
    ("hook_a1", "benchmark", "unreachable", 0.0, "position_tool"),
    ("stick_a4", "benchmark", "failure", 0.0, ""),
    ("hook_long", "benchmark", "success", 1.0, ""),
])
def test_the_physics_discriminates_the_tools_by_the_benchmarks_reward(
        tool, variant, outcome, reward, why):
    result = run_trial(_world(), tool, variant, 1, pose=(0.05, 0.0, 0.0),
                       pose_target=poses(_world()))
    assert result.outcome == outcome, result.reason
    assert why in result.reason
    verdict = result.verdict
    assert verdict["quantity"] == "reward"
    assert verdict["value"] == pytest.approx(reward, abs=1e-6)
    assert verdict["holds"] is (reward > 0.99)


def test_a_slow_pull_drops_the_cube_between_the_box_and_the_shelf():
    # The carry past the edge is the pull's speed: at 0.05 m/s the cube leaves the edge
    # without the speed to clear the box's far wall; it falls short of the box and
    # earns the benchmark's drop bonus only.
    world = _world()
    from creative_py.backends.pybullet.episode import open_episode

    with open_episode(world, "benchmark", 1, "hook_long", pose_target=poses(world)) as ep:
        for name, pose in (("pick_up", None), ("position_tool", (0.05, 0.0, 0.0))):
            assert ep.run_skill(name, pose).ok
        assert ep.run_skill("pull", speed=0.05).ok
        verdict = ep.verdict()
    assert not verdict.measures["in_box"]
    assert verdict.measures["below_bonus_z"]
    assert 0.2 <= verdict.value < 0.99
