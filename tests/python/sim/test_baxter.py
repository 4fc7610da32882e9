"""The simulated Baxter: URDF rewriting, IK, guarded moves, the grasp."""

import math

import pybullet as pb
import pytest

from creative_py.mesh.spec import Box

from creative_py.kinds.hook_like import HookSpec
from creative_py.sim.baxter import Baxter, baxter_urdf
from creative_py.sim.bodies import Surface, frame_pose, spawn_parts, spawn_spec
from creative_py.sim.core import Sim
from creative_py.sim.baxter import gripper_forward as gripper_orientation
from creative_py.sim.tools import tool_in_gripper
from creative_py.world import PhysicsSettings

pytestmark = pytest.mark.sim

FORWARD = gripper_orientation(0.0)


@pytest.fixture
def robot():
    with Sim(PhysicsSettings()) as sim:
        b = Baxter(sim)
        q = b.solve_ik_global(((0.5, -0.25, 0.0), FORWARD))
        assert q is not None
        b.reset_posture(q)
        sim.step(50)
        yield b
        b.close()


def test_urdf_has_absolute_meshes_and_no_visuals():
    text = baxter_urdf(visuals=False).read_text()
    assert "package://" not in text
    assert "<visual>" not in text
    assert "<visual>" in baxter_urdf(visuals=True).read_text()


def test_ik_reaches_a_gripper_pose_to_sub_millimetre(robot):
    target = ((0.7, -0.3, -0.02), gripper_orientation(0.5))
    q = robot.solve_ik(target)
    assert q is not None
    k = robot.kin
    k.reset(k.arm, q)
    pos, quat = k.ee_pose()
    assert math.dist(pos, target[0]) < 1e-3


def test_ik_says_no_to_a_target_out_of_reach(robot):
    assert robot.solve_ik(((2.0, -0.3, 0.0), FORWARD)) is None
    res = robot.move_to(((2.0, -0.3, 0.0), FORWARD))
    assert res.status == "unreachable", res
    assert robot.gripper_pose()[0][0] < 1.3


def test_a_free_move_ends_where_it_was_sent(robot):
    res = robot.move_to(((0.75, -0.2, 0.05), FORWARD), speed=0.3)
    assert res.ok, res.reason
    assert math.dist(robot.gripper_pose()[0], (0.75, -0.2, 0.05)) < 0.003


def test_a_move_into_a_wall_is_blocked(robot):
    spawn_parts(robot.sim, [Box((0, 0, 0), (0.05, 0.6, 0.6))], ((0.65, -0.25, 0.0), (0, 0, 0, 1)),
                0.0, Surface())
    res = robot.move_to(((0.9, -0.25, 0.0), FORWARD), speed=0.2)
    assert res.status == "blocked", res
    assert "cm" in res.reason
    assert robot.gripper_pose()[0][0] < 0.66


def test_a_grasped_tool_follows_the_gripper(robot):
    spec = HookSpec("hook_t", 0.3)
    g = robot.gripper_pose()
    grasp = tool_in_gripper(spec)
    body = spawn_spec(robot.sim, spec, pb.multiplyTransforms(g[0], g[1], *grasp))
    robot.grasp(body, grasp)
    assert robot.move_to(((0.6, -0.3, 0.1), FORWARD), speed=0.3).ok
    g = robot.gripper_pose()
    expected = pb.multiplyTransforms(g[0], g[1], *grasp)[0]
    assert math.dist(frame_pose(robot.sim, body)[0], expected) < 0.003
    robot.release()
    robot.sim.step(120)
    assert frame_pose(robot.sim, body)[0][2] < expected[2] - 0.05  # it falls when released
