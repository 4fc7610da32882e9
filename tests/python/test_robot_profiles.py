"""Robot profiles (robots/<name>.toml, creative_py/robots.py): one file per arm, one
reader, every bad field named in one line with its file."""

from __future__ import annotations

import math
import subprocess
import sys

import pytest

from creative_py.robots import ROBOTS_ROOT, load_profile, profile_names
from creative_py.world_files import WorldFileError

BAXTER = (ROBOTS_ROOT / "baxter.toml").read_text()
PANDA = (ROBOTS_ROOT / "panda.toml").read_text()


def test_three_arms_ship_with_different_grippers():
    assert {"baxter", "panda", "ur5"} <= set(profile_names())
    b, p, u = (load_profile(n) for n in ("baxter", "panda", "ur5"))
    assert len(b.arm_joints) == len(p.arm_joints) == 7 and len(u.arm_joints) == 6
    assert b.hand.driven is False and b.hand.gear_ratio is None
    assert p.hand.driven is True and p.hand.gear_ratio == -1.0 and p.hand.open == (0.04, 0.04)
    assert u.hand is None and u.grasp_mode == "constraint" and u.tool_xyz == (0.0, 0.0, 0.05)
    assert (b.has_ros, p.has_ros, u.has_ros) == (True, True, False)
    assert b.ee_link == "right_gripper" and p.ee_link == "panda_hand_tcp"
    assert set(b.idle) >= {"head_pan", "left_s0"} and p.idle == {} and u.idle == {}
    assert b.urdf_path.is_file() and p.urdf_path.name == "panda.urdf"


@pytest.mark.parametrize("name", profile_names())
def test_every_shipped_profile_reads_with_its_urdf(name):
    """What every profile of robots/ must be (a new arm is checked here, no line
    changes): read without error, its URDF on disk, its joints named, its home posture
    one number per joint."""
    profile = load_profile(name)
    assert profile.urdf_path.is_file(), profile.urdf_path
    assert profile.arm_joints and profile.ee_link
    assert len(profile.home) == len(profile.arm_joints)


def _write(tmp_path, text, name="arm.toml"):
    path = tmp_path / name
    path.write_text(text)
    return path


@pytest.mark.parametrize("old,new,message", [
    ('ee_link = "panda_hand_tcp"', 'ee_lnk = "panda_hand_tcp"', "field 'kinematics.ee_link': missing (is 'ee_lnk' a typo for it?)"),
    ("home = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]", "home = [0.0, -0.785]", "field 'kinematics.home': must be a list of 7 numbers"),
    ('approach_axis = "+z"', 'approach_axis = "z"', "field 'kinematics.approach_axis': must be one of"),
    ("gear_ratio = -1.0", "gear_ratio = 0", "field 'hand.gear_ratio': must be a non-zero number"),
    ("open = [0.04, 0.04]", "open = [0.04]", "field 'hand.open': must be a list of 2 numbers"),
    ('urdf = "example-robot-data:panda_description/urdf/panda.urdf"', 'urdf = "example-robot-data:nope.urdf"', "field 'urdf': no URDF file"),
    ('urdf = "example-robot-data:panda_description/urdf/panda.urdf"', 'urdf = "missing/arm.urdf"', "field 'urdf': no URDF file"),
    ('mode = "constraint"', 'mode = "fingers"', "field 'grasp.mode': must be one of constraint"),
    ("restarts = 40", "restarts = -1", "field 'ik.restarts': must be >= 0"),
    ("[idle]", "[idle]\npanda_joint1 = 0.0", "field 'idle': names an arm joint: 'panda_joint1'"),
    ("position = [0.0, 0.0, 0.0]", "position = [0.0, 0.0, 0.0]\nyaw = 1", "field 'base.yaw': unknown field"),
])
def test_a_bad_field_is_one_line_naming_file_and_field(tmp_path, old, new, message):
    assert old in PANDA
    path = _write(tmp_path, PANDA.replace(old, new, 1))
    with pytest.raises(WorldFileError) as info:
        load_profile(path)
    text = str(info.value)
    assert text.startswith(f"{path}: ") and message in text and "\n" not in text


def test_a_lab_urdf_path_is_relative_to_the_profile(tmp_path):
    urdf = load_profile("panda").urdf_path
    (tmp_path / "mine.urdf").write_text(urdf.read_text())
    text = PANDA.replace('urdf = "example-robot-data:panda_description/urdf/panda.urdf"',
                         'urdf = "mine.urdf"')
    assert load_profile(_write(tmp_path, text)).urdf_path == tmp_path / "mine.urdf"


def test_a_case_names_its_robot_and_a_typo_is_one_line(tmp_path):
    from creative_py.case import get_case, read_manifest

    assert get_case("hook").robot == "baxter"
    src = get_case("hook").folder
    for f in src.iterdir():
        (tmp_path / f.name).write_text(f.read_text())
    text = (tmp_path / "case.toml").read_text().replace('robot = "baxter"', 'robot = "baxtr"')
    (tmp_path / "case.toml").write_text(text)
    with pytest.raises(WorldFileError, match=r"case.toml: field 'robot': no robot profile 'baxtr'"):
        read_manifest(tmp_path)


@pytest.mark.sim
def test_every_shipped_profile_builds_an_arm_that_reaches_its_home():
    from creative_py.backends.pybullet import check_profile

    for name in profile_names():
        line = check_profile(name)
        assert line.startswith("ok: ") and "home reachable" in line, line


@pytest.mark.sim
def test_the_check_names_a_joint_the_urdf_lacks(tmp_path):
    from creative_py.backends.pybullet import check_profile

    path = _write(tmp_path, PANDA.replace('"panda_joint7"]', '"panda_joint8"]'))
    with pytest.raises(WorldFileError, match=r"field 'kinematics.joints': 'panda_joint8' is "
                                             r"no moving joint of panda.urdf"):
        check_profile(load_profile(path))
    path = _write(tmp_path, PANDA.replace("home = [0.0, -0.785, 0.0, -2.356",
                                          "home = [0.0, -0.785, 0.0, 0.5"))
    with pytest.raises(WorldFileError, match=r"field 'kinematics.home': panda_joint4 = 0.5 "
                                             "lies outside"):
        check_profile(load_profile(path))


@pytest.mark.sim
def test_the_tool_frame_and_approach_axis_move_the_ik_target():
    """A tool frame 5 cm out of the flange: IK puts that point, not the flange, at the
    target; the approach axis turns the frame."""
    import pybullet as pb

    from creative_py.backends.pybullet.arm import Arm, gripper_down
    from creative_py.backends.pybullet.core import Sim
    from creative_py.world_files import PhysicsSettings

    ur5 = load_profile("ur5")
    with Sim(PhysicsSettings()) as sim:
        arm = Arm(sim, ur5)
        target = ((0.45, 0.1, 0.2), gripper_down(0.3))
        q = arm.solve_ik_global(target)
        assert q is not None
        arm.reset_posture(q)
        pos, quat = arm.gripper_pose()
        assert math.dist(pos, target[0]) < 0.002
        flange = pb.getLinkState(arm.body, arm.model.ee, physicsClientId=sim.client)[4]
        assert flange[2] == pytest.approx(0.25, abs=0.003)  # 5 cm above, pointing down
        arm.close()


def test_the_robots_command_lists_every_profile_with_its_check():
    r = subprocess.run([sys.executable, "-m", "creative_py.cli", "robots"], capture_output=True,
                       text=True, timeout=600)
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert [ln.split()[0] for ln in lines] == profile_names()
    assert all(" ok: " in ln and "home reachable" in ln for ln in lines), lines


def test_the_robots_command_fails_in_one_line_on_a_bad_profile(tmp_path):
    path = _write(tmp_path, PANDA.replace('ee_link = "panda_hand_tcp"', 'ee_link = "hand"'))
    r = subprocess.run([sys.executable, "-m", "creative_py.cli", "robots", str(path)],
                       capture_output=True, text=True, timeout=600)
    assert r.returncode == 2
    assert r.stdout.count("\n") == 1 and "FAILED" in r.stdout
    assert f"{path}: field 'kinematics.ee_link': 'hand' is no link of panda.urdf" in r.stdout


@pytest.mark.sim
def test_the_demonstration_trial_succeeds_on_the_panda():
    """The hook world places the Panda by data ([robot.panda] of scene.toml); the same
    demonstration trial the Baxter makes reaches the goal."""
    import json

    r = subprocess.run([sys.executable, "-m", "creative_py.cli", "trial", "hook", "--tool",
                        "hook_a2", "--robot", "panda", "--json"], capture_output=True,
                       text=True, timeout=900)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["outcome"] == "success"


@pytest.mark.sim
def test_the_panda_pulls_the_cube_out_with_the_short_prong_hook_as_the_baxter_does():
    """The Baxter's seed-0 hook run pulls the cube out with hook_a3 at this pose; so does
    the Panda. With its fingers held open around the tool, the Panda's finger struck the
    tube's mouth and riser (blocked)."""
    import json

    r = subprocess.run([sys.executable, "-m", "creative_py.cli", "trial", "hook", "--tool",
                        "hook_a3", "--pose", "0.0375,0,0", "--seed", "5", "--robot",
                        "panda", "--json"], capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["outcome"] == "success"


@pytest.mark.sim
def test_the_panda_pulls_the_cube_through_the_long_tube_with_a_created_hook():
    """The Panda's created hook of the seed-0 run (a 0.6 m handle) pulls the cube out of
    the long tube in the evaluations it failed at 8 physics steps per IK waypoint (the
    arm shook the tool sideways and walked the cube off the prong); the hook world's
    [robot.panda] moves the Panda with one step per waypoint."""
    from creative_py.bridge import Engine
    from creative_py.case import get_case
    from creative_py.kinds import spec_from_dict
    from dataclasses import replace

    from creative_py.learning.poses import pose_resolver
    from creative_py.simulator import backend_for
    from creative_py.simulator.trial import run_trial

    m = replace(get_case("hook"), robot="panda")  # what --robot panda makes of the case
    spec = spec_from_dict({"kind": "hook", "name": "hook_new1", "handle_length": 0.6,
                           "handle_width": 0.009, "hook_length": 0.0375, "hook_width": 0.014,
                           "hook_side": "right", "hook_angle_deg": 90, "grip_offset": 0.04,
                           "mass": None})
    world = backend_for(m).load_world(m).with_tool(spec)
    poses = pose_resolver(Engine.instance(), m)
    for location, seed, dx in ((1, 17, 0.0377), (4, 16, 0.0326)):
        r = run_trial(world, "hook_new1", "long_tube", location, (dx, 0.0, 0.0), seed,
                      pose_target=poses)
        assert r.outcome == "success", (location, seed, r.verdict)


@pytest.mark.sim
def test_a_driven_hand_closes_over_a_held_tool_and_opens_at_release():
    """The Panda's fingers (a driven hand) stay open while free, close to ``closed``
    over a held tool (held open, they stuck out 4 cm around it and struck a tube's
    mouth) and open again at release."""
    import pybullet as pb

    from creative_py.backends.pybullet.arm import Arm
    from creative_py.backends.pybullet.core import Sim
    from creative_py.world_files import PhysicsSettings

    with Sim(PhysicsSettings()) as sim:
        arm = Arm(sim, "panda")
        hand = arm.profile.hand
        box = pb.createMultiBody(0.05, pb.createCollisionShape(
            pb.GEOM_BOX, halfExtents=(0.1, 0.005, 0.005), physicsClientId=sim.client),
            basePosition=arm.gripper_pose()[0], physicsClientId=sim.client)

        def fingers():
            return [pb.getJointState(arm.body, j, physicsClientId=sim.client)[0]
                    for j in arm.fingers]

        sim.step(60)
        assert fingers() == pytest.approx(list(hand.open), abs=1e-3)
        arm.grasp(box, ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
        sim.step(120)
        assert fingers() == pytest.approx(list(hand.closed), abs=1e-3)
        arm.release()
        sim.step(120)
        assert fingers() == pytest.approx(list(hand.open), abs=1e-3)
        arm.close()


def test_a_placement_for_an_unknown_robot_is_one_line(tmp_path):
    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case, read_manifest

    src = get_case("hook").folder
    for f in src.iterdir():
        (tmp_path / f.name).write_text(f.read_text())
    scene = (tmp_path / "scene.toml").read_text().replace("[robot.panda]", "[robot.pandaa]")
    (tmp_path / "scene.toml").write_text(scene)
    with pytest.raises(WorldFileError, match=r"scene.toml: field 'robot.pandaa': names no "
                                             r"robot profile"):
        load_world(read_manifest(tmp_path))


def test_a_world_places_the_arm_it_runs():
    from dataclasses import replace

    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case

    baxter = load_world(get_case("hook")).scene.robot
    assert baxter.profile.name == "baxter" and baxter.base is None
    panda = load_world(replace(get_case("hook"), robot="panda")).scene.robot
    assert panda.profile.name == "panda" and panda.base[0] == (0.35, -0.75, -0.2)
    assert panda.start == baxter.start  # the start poses are the world's own


@pytest.mark.parametrize("key", ["robot", "robot_profile"])
def test_a_resume_keeps_the_robot_run_json_recorded(tmp_path, key):
    """run.json names the robot (``robot``; ``robot_profile`` before --robot existed),
    and the options a resume reads back carry it."""
    import json

    from creative_py.learning.options import read_run_json, run_json_check

    meta = {"case": "hook", "options": {"seed": 0, key: "panda"}, "world": None,
            "drawn_world": None}
    meta["check"] = run_json_check(meta)
    (tmp_path / "run.json").write_text(json.dumps(meta))
    case, options, _, _ = read_run_json(tmp_path)
    assert (case, options.robot) == ("hook", "panda")


@pytest.mark.sim
@pytest.mark.parametrize("axis, direction", [("+z", (0, 0, 1)), ("+x", (1, 0, 0)),
                                             ("-y", (0, -1, 0))])
def test_the_approach_axis_becomes_the_tool_frames_z(axis, direction):
    """The attitudes turn the tool frame's +z: the profile's approach axis of the link."""
    import dataclasses

    import numpy as np
    import pybullet as pb

    from creative_py.backends.pybullet.arm import tool_frame

    p = dataclasses.replace(load_profile("panda"), approach_axis=axis)
    frame = tool_frame(p) or ((0, 0, 0), (0, 0, 0, 1))
    z = np.array(pb.getMatrixFromQuaternion(frame[1])).reshape(3, 3)[:, 2]
    assert z == pytest.approx(direction, abs=1e-9)


# ------------------------------------------------- a run's robot does not outlive it
def _loads_worlds_for(monkeypatch) -> list:
    """Spy on the pybullet backend's load_world: return the list of the robot profile
    name of each world it loads."""
    import creative_py.backends.pybullet as pybullet_backend

    loaded, real = [], pybullet_backend.load_world

    def spy(manifest, *args, **kwargs):
        world = real(manifest, *args, **kwargs)
        loaded.append(world.scene.robot.profile.name)
        return world

    monkeypatch.setattr(pybullet_backend, "load_world", spy)
    return loaded


def test_a_command_passes_its_robot_to_the_backend_and_no_further(monkeypatch):
    """`creative trial --robot panda` builds the Panda's world; in-process (a test, a
    notebook) the next command and the next world loaded read their own case's robot
    (the choice travels in the command's manifest, nowhere else)."""
    from typer.testing import CliRunner

    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case
    from creative_py.cli import app

    loaded = _loads_worlds_for(monkeypatch)
    result = CliRunner().invoke(app, ["trial", "hook", "--robot", "panda", "--list"])
    assert result.exit_code == 0, result.output
    result = CliRunner().invoke(app, ["trial", "hook", "--list"])
    assert result.exit_code == 0, result.output
    assert loaded == ["panda", "baxter"]
    assert load_world(get_case("hook")).scene.robot.profile.name == "baxter"


def test_a_run_builds_its_robot_and_the_next_world_its_own():
    """A Baxter run's world, then a Panda run's, then the case's world in the same
    process: each gets its own arm (--robot is the run's manifest's robot, which
    load_world reads; nothing of a run outlives it)."""
    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case
    from creative_py.learning.options import RunOptions
    from creative_py.learning.run import _checked_world

    def run_arm(**options) -> tuple[str, str]:
        _, world, _ = _checked_world("hook", RunOptions(phase="use", **options), None, None)
        return world.manifest.robot, world.scene.robot.profile.name

    assert run_arm() == ("baxter", "baxter")
    assert run_arm(robot="panda") == ("panda", "panda")
    assert load_world(get_case("hook")).scene.robot.profile.name == "baxter"
    assert get_case("hook").robot == "baxter"
    assert run_arm() == ("baxter", "baxter")
