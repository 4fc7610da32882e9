"""The robot profile (robots/<name>.toml): read without ROS, bad fields named in one line."""

from __future__ import annotations

import pytest

from creative_py.backends.ros.profile import ROBOTS_ROOT, load_profile
from creative_py.world_files import WorldFileError

SHIPPED = (ROBOTS_ROOT / "baxter.toml").read_text()


def test_the_shipped_profile_names_the_stand_ins_interface():
    p = load_profile("baxter")
    assert p.joints == ("right_s0", "right_s1", "right_e0", "right_e1", "right_w0", "right_w1",
                        "right_w2")
    assert p.arm_action.endswith("/follow_joint_trajectory")
    assert p.object_topic_of("thing") == "mocap/thing/pose"
    assert p.max_joint_speed == 0.8 and p.workspace_min[2] == -0.19


def test_the_panda_profile_has_the_names_of_a_franka_labs_ros2_set_up():
    # franka_ros2 with arm_id panda: the arm's joint trajectory controller, the
    # franka_gripper node's GripperCommand (one finger's travel: half the gap), the
    # state broadcaster's estimated external wrench
    p = load_profile("panda")
    assert p.joints == tuple(f"panda_joint{i}" for i in range(1, 8))
    assert p.arm_action == "panda_arm_controller/follow_joint_trajectory"
    assert p.gripper_action == "panda_gripper/gripper_action"
    assert (p.gripper_joint, p.gripper_open, p.gripper_closed) == ("panda_finger_joint1", 0.04, 0.0)
    assert p.base_frame == "panda_link0" and p.joint_states_topic == "joint_states"
    assert p.wrench_topic == "franka_robot_state_broadcaster/external_wrench_in_stiffness_frame"
    assert p.wrench_frame == "panda_hand_tcp"


def _write(tmp_path, text):
    path = tmp_path / "arm.toml"
    path.write_text(text)
    return path


def test_a_lab_remaps_names_by_a_file(tmp_path):
    text = (SHIPPED.replace('topic = "joint_states"', 'topic = "/robot/joint_states"')
            .replace("names = {}", 'names = { thing = "Thing_01" }'))
    p = load_profile(_write(tmp_path, text))
    assert p.joint_states_topic == "/robot/joint_states"
    assert p.object_topic_of("thing") == "mocap/Thing_01/pose"


# The ROS tables' bad fields are rows of the one table of bad profiles, read by this
# reader: tests/python/test_robot_profiles.py, test_a_bad_field_is_one_line_naming_file_and_field.


def test_an_unknown_profile_lists_the_shipped_ones():
    with pytest.raises(WorldFileError, match="shipped profiles: baxter, panda, ur5"):
        load_profile("nosuch")


def test_a_profile_without_the_ros_tables_is_refused_for_ros(tmp_path):
    path = _write(tmp_path, SHIPPED.split("\n[frames]")[0] + "\n")
    with pytest.raises(WorldFileError, match=r"field 'arm': missing: the profile has no ROS 2"):
        load_profile(path)


def test_the_clock_table_is_optional_and_checked(tmp_path):
    p = load_profile("baxter")
    assert (p.use_sim_time, p.clock_topic, p.clock_silent_after_s) == (False, "/clock", 3.0)
    assert p.now_source() == "wall-clock time"
    without = _write(tmp_path, SHIPPED.split("\n[clock]")[0] + "\n")
    assert load_profile(without).use_sim_time is False  # a real arm's profile leaves it out
    sim = load_profile(_write(tmp_path, SHIPPED.replace("use_sim_time = false",
                                                        "use_sim_time = true")))
    assert sim.use_sim_time and sim.now_source() == "simulated time on '/clock'"
    with pytest.raises(WorldFileError, match=r"clock\.silent_after_s"):
        load_profile(_write(tmp_path, SHIPPED.replace("silent_after_s = 3.0",
                                                      "silent_after_s = 0")))
    with pytest.raises(WorldFileError, match=r"'clock.use_sim_tme': unknown field"):
        load_profile(_write(tmp_path, SHIPPED.replace("use_sim_time = false",
                                                      "use_sim_tme = false")))
