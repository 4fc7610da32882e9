"""The paddle-and-tube world (worlds/paddle_tube, a case of the paddle kind): what the
physics decides for the trials the learner relies on."""

from functools import lru_cache

import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses

pytestmark = pytest.mark.sim


@lru_cache(maxsize=None)
def paddle_world():
    """Return the shipped paddle world."""
    return load_world(get_case("paddle_tube"))


def test_the_catalogue_is_paddles_of_the_paddle_kind():
    world = paddle_world()
    assert {item.spec.kind for item in world.items.values()} == {"paddle"}


@pytest.mark.parametrize("tool, pose, outcome", [
    ("paddle_a2", None, "success"),                    # the demonstration
    ("paddle_a3", None, "failure"),                    # a wide blade cannot stand upright
    ("paddle_a2", (0.03, 0.0, -1.5707963), "failure"),  # the blade flat slides over the cube
    ("paddle_a2", (-0.04, 0.0, 0.0), "failure"),       # the blade in front of the cube
])
def test_the_physics_decides_the_blade_s_width_roll_and_place(tool, pose, outcome):
    result = run_trial(paddle_world(), tool, "standard", 1, pose=pose,
                       pose_target=poses(paddle_world()))
    assert result.outcome == outcome, result.reason


def test_a_short_shaft_cannot_put_the_blade_behind_the_cube():
    assert run_trial(paddle_world(), "paddle_a1", "standard", 1,
                     pose_target=poses(paddle_world())).outcome == "blocked"
