"""The simulated arm of a robot profile: URDF rewriting, IK, guarded moves, the grasp
(on the Baxter profile, whose figures the parity fixtures pin)."""

import math

import pybullet as pb
import pytest

from creative_py.mesh.spec import Box

from creative_py.kinds.hook_like import HookSpec
from creative_py.backends.pybullet.arm import Arm, arm_urdf
from creative_py.backends.pybullet.bodies import Surface, frame_pose, spawn_parts, spawn_spec
from creative_py.backends.pybullet.core import Sim
from creative_py.backends.pybullet.arm import gripper_forward as gripper_orientation
from creative_py.backends.pybullet.tools import tool_in_gripper
from creative_py.robots import load_profile
from creative_py.world_files import PhysicsSettings

BAXTER = load_profile("baxter")


def Baxter(sim, **kw):
    return Arm(sim, BAXTER, **kw)


def baxter_urdf(visuals=False, model="full"):
    return arm_urdf(BAXTER, visuals, model)

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


def _movable(urdf) -> list[str]:
    with Sim(PhysicsSettings()) as sim:
        body = pb.loadURDF(str(urdf), useFixedBase=True, physicsClientId=sim.client)
        return [pb.getJointInfo(body, j, physicsClientId=sim.client)[1].decode()
                for j in range(pb.getNumJoints(body, physicsClientId=sim.client))
                if pb.getJointInfo(body, j, physicsClientId=sim.client)[2] != pb.JOINT_FIXED]


def test_the_light_model_fixes_the_idle_joints_and_keeps_every_shape():
    import xml.etree.ElementTree as ET

    IDLE_HOLD, RIGHT_ARM = BAXTER.idle, BAXTER.arm_joints

    full, light = baxter_urdf(model="full"), baxter_urdf(model="light")
    assert set(_movable(full)) - set(_movable(light)) == set(IDLE_HOLD)
    assert set(RIGHT_ARM) <= set(_movable(light))
    # The merged links' shapes moved to the link their part hangs from, none lost.
    count = [len(ET.parse(u).getroot().findall("link/collision")) for u in (full, light)]
    assert count[0] == count[1] > 0
    assert _movable(baxter_urdf(model="arm")) == list(RIGHT_ARM)
    with pytest.raises(ValueError, match="model"):
        baxter_urdf(model="tiny")


def test_the_arm_chain_solves_ik_bit_for_bit_like_the_full_model():
    with Sim(PhysicsSettings()) as sim:
        light, heavy = Baxter(sim, mode="exact"), Baxter(sim, mode="heavy")
        assert len(light.kin.movable) == 7 < len(heavy.kin.movable)
        for target in [((0.7, -0.3, -0.02), gripper_orientation(0.5)),
                       ((0.55, -0.5, 0.1), gripper_orientation(-1.5))]:
            assert light.ik_candidates(target, keep=2, restarts=3) == \
                heavy.ik_candidates(target, keep=2, restarts=3)
        heavy.close()
        light.close()


def test_the_kinematics_client_outlives_a_robot_and_a_bad_mode_is_refused():
    with Sim(PhysicsSettings()) as sim:
        a = Baxter(sim, mode="light")
        a.close()
        b = Baxter(sim, mode="light")
        assert b.kin is a.kin and pb.isConnected(b.kin.client)
        assert b.model.idle == [] and len(b.model.movable) == 9
        with pytest.raises(ValueError, match="CREATIVE_ROBOT"):
            Baxter(sim, mode="feather")


@pytest.mark.parametrize("mode, searches", [("light", 1), ("heavy", 2)])
def test_the_via_posture_is_searched_once_per_target(monkeypatch, mode, searches):
    from creative_py.case import get_case
    from creative_py.backends.pybullet import arm, load_world, open_episode

    world = load_world(get_case("hook"))
    via = world.scene.robot.via
    assert via is not None
    calls = []
    search = Arm.solve_ik_global

    def counted(self, target, *args, **kw):
        calls.append(kw.get("keep", 6))
        return search(self, target, *args, **kw)

    monkeypatch.setattr(Arm, "solve_ik_global", counted)
    monkeypatch.setattr(arm, "ROBOT", mode)
    # Two tools of different reach: two start poses, one via target.
    for tool in ("hook_a2", "hook_b2"):
        with open_episode(world, "standard", 1, tool, robot=True):
            pass
    assert len(world.postures) == 2 + (mode != "heavy")
    assert calls.count(6) == searches  # the via search (the start pose's keeps 1)


def test_a_straight_line_is_solved_lazily_and_ends_where_the_arm_cannot_follow():
    from creative_py.backends.pybullet.arm import Unreachable, straight_line

    start, target = ((0.0, 0.0, 0.0), FORWARD), ((0.4, 0.0, 0.0), FORWARD)
    asked = []

    def ik(pose, seed):  # one "joint" per metre of x; no posture beyond x = 0.25
        asked.append(pose[0][0])
        return None if pose[0][0] > 0.25 else [pose[0][0]]

    line = straight_line(ik, start, target, 4, [0.0])
    pos, quat, q = next(line)
    assert pos == pytest.approx((0.1, 0.0, 0.0)) and q == pytest.approx([0.1])
    assert quat == pytest.approx(FORWARD) and asked == pytest.approx([0.1])  # lazily
    assert next(line)[2] == pytest.approx([0.2])
    with pytest.raises(Unreachable) as err:
        next(line)
    assert err.value.outcome.status == "unreachable"
    assert err.value.outcome.reason == ("IK found no arm posture for gripper at "
                                        "(0.300, 0.000, 0.000) m")
    # a posture that jumps more than 0.5 rad from the one before it is a flip
    flip = straight_line(lambda pose, seed: [seed[0] + 0.6], start, target, 4, [0.0])
    with pytest.raises(Unreachable, match=r"flip its posture \(joint jump > 0.5 rad\) near "
                                          r"\(0.100, 0.000, 0.000\) m"):
        next(flip)
