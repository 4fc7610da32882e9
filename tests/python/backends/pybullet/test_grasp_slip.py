"""The grasp-slip guard of the primitives that move a held tool (insert, pull).

pybullet's fixed grasp constraint is soft against contacts with static bodies: a tool
whose prong is stopped by something twists in the hand while the gripper follows its
commands, so the arm's tracking guard does not notice. The guard compares the tool's
pose with the pose the grasp holds it in and stops the motion as ``blocked``.
"""

import math

import pytest

from creative_py.case import get_case
from creative_py.mesh.spec import Box
from creative_py.backends.pybullet import load_world, open_episode
from creative_py.backends.pybullet.bodies import Surface, spawn_parts
from creative_py.backends.pybullet.primitives import PRIMITIVES, slip_guard
from creative_py.backends.pybullet.tools import grasp_slip


def test_the_guard_is_an_option_of_the_moving_primitives_and_off_by_default():
    for name in ("insert_at_pose", "pull_along_axis"):
        opts = PRIMITIVES[name].options
        assert opts["grasp_slip_max_rad"] == 0.0 and opts["grasp_slip_max_m"] == 0.0
    assert slip_guard(None, {"grasp_slip_max_rad": 0.0, "grasp_slip_max_m": 0.0}) is None
    assert slip_guard(None, {}) is None


def _roll_against_a_block(limit_rad):
    """Pick up the hook world's demonstrated tool, put a static block under its flat
    prong, and roll the prong down into it; return the move's outcome and the slip."""
    world = load_world(get_case("hook"))
    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, demo.tool, seed=0) as ep:
        assert ep.run_skill(demo.steps[0]).ok
        assert max(grasp_slip(ep)) < 0.005           # held as the grasp says
        tip = ep.kind.working_point(ep)
        spawn_parts(ep.sim, [Box((0, 0, 0), (0.04, 0.10, 0.02))],
                    ((tip[0], tip[1], tip[2] - 0.025), (0, 0, 0, 1)), 0.0,
                    Surface(0.5, (1, 0, 0, 1)))
        guard = slip_guard(ep, {"grasp_slip_max_rad": limit_rad, "grasp_slip_max_m": 0.0})
        grip = ep.robot.gripper_pose()[0]
        res = ep.kind.move(ep, grip, 0.0, 0.20, guard)
        return res, grasp_slip(ep)


@pytest.mark.sim
def test_a_tool_twisted_by_a_static_block_stops_the_move_as_blocked():
    unguarded, _ = _roll_against_a_block(0.0)
    assert unguarded.ok                              # the arm's own guards see nothing
    guarded, (angle, _) = _roll_against_a_block(0.08)
    assert guarded.status == "blocked"
    assert "slipped in the grasp" in guarded.reason
    assert 0.08 < angle < math.pi / 4
