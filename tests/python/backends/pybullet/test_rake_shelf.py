"""The rake-under-a-shelf world: what the physics decides at the demonstration's pose.

The physics is the oracle: a handful of real trials (Baxter, IK, contacts) check the
discrimination the learner relies on (worlds/rake_shelf/objects.toml): the demonstrated
medium rake pulls the box out; a short handle stops at the shelf's front edge; a tall
prong jams under the plate (the grasp-slip guard); a stick slides past the box; a long
rake with a short prong, the size the creator makes, works under the deep shelf.
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
    world = load_world(get_case("rake"))
    created = HookSpec(name="rake_long", handle_length=0.60, handle_width=0.008,
                       hook_length=0.016, hook_width=0.012, hook_side="right")
    return world.with_tool(created)


@pytest.mark.parametrize("tool, variant, location, outcome, why", [
    ("rake_a2", "standard", 1, "success", ""),
    ("rake_a2", "standard", 3, "success", ""),
    ("rake_a1", "standard", 1, "blocked", "gripper lagged"),
    ("hook_a3", "standard", 1, "blocked", "slipped in the grasp"),
    ("stick_a5", "standard", 1, "failure", ""),
    ("rake_a2", "deep_shelf", 1, "blocked", "gripper lagged"),
    ("rake_long", "deep_shelf", 3, "success", ""),
])
def test_the_physics_discriminates_the_tools_at_the_demonstration_pose(
        tool, variant, location, outcome, why):
    result = run_trial(_world(), tool, variant, location, pose_target=poses(_world()))
    assert result.outcome == outcome, result.reason
    assert why in result.reason


@pytest.mark.parametrize("pose, why", [
    ((0.035, 0.0, -1.5707963267948966), "prong laid flat passes over the box"),
    ((0.035, 0.0, 0.96), "prong half-raised passes over the box"),
    ((-0.04, 0.0, 0.0), "prong lowered in front of the box pushes it deeper"),
    ((0.035, 0.01, 0.0), "1 cm off centre the box turns off the prong"),
])
def test_the_demonstrated_rake_fails_at_the_wrong_poses(pose, why):
    result = run_trial(_world(), "rake_a2", "standard", 1, pose=pose,
                       pose_target=poses(_world()))
    assert result.outcome == "failure", f"{why}: {result.outcome} {result.reason}"
