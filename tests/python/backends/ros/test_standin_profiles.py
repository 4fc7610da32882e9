"""The stand-in serves any robot profile: the Panda's, with the names of a Franka lab's
ROS 2 set-up, in its own process, driven over ROS 2 by the learner's client.

The ROS traffic runs inside a private network namespace that has only loopback (as
test_standin.py runs it: ``run_in_namespace``). One session (``_profile_session.py``)
starts the stand-in of the hook case with the Panda's profile, checks the interface
and picks the demonstration's tool up through the learner's IK of the Panda. Skipped,
with the reason, without the ``ros`` extra or where the namespace is refused.
"""

from __future__ import annotations

import os

from pathlib import Path

import pytest

pytestmark = pytest.mark.sim

PANDA_JOINTS = [f"panda_joint{i}" for i in range(1, 8)]


@pytest.fixture(scope="module")
def panda() -> dict:
    from test_standin import run_in_namespace

    return run_in_namespace(Path(__file__).parent / "_profile_session.py", "panda", "hook",
                            domain=100 + (os.getpid() + 50) % 100)


def test_the_standin_serves_the_panda_under_franka_names(panda):
    info = panda["interface"]
    assert info["trajectory_action"] == "panda_arm_controller/follow_joint_trajectory"
    assert info["gripper_action"] == "panda_gripper/gripper_action"
    assert info["joints"] == PANDA_JOINTS
    assert info["wrench"] == "franka_robot_state_broadcaster/external_wrench_in_stiffness_frame"
    js = panda["check"]["joint_states"]
    assert js["profile_joints_missing"] == [] and js["rate_hz"] > 0
    # the arm's joints and the gripper's finger joint, its travel open: 4 cm (8 cm gap)
    assert panda["joint_states"]["names"] == [*PANDA_JOINTS, "panda_finger_joint1"]
    assert panda["joint_states"]["position"][-1] == pytest.approx(0.04)
    assert all(o["rate_hz"] > 0 for o in panda["check"]["objects"].values())


def test_the_learner_picks_the_tool_up_with_the_panda_over_ros(panda):
    pick = panda["pick_up"]
    # the learner's kinematics and bounds stand the arm where the scene places it (the
    # hook_tube scene's [robot.panda] base), as the stand-in does
    assert panda["base"][0] == pytest.approx([0.35, -0.75, -0.20])
    assert pick["moves"] == ["ok"] * 4 and pick["goals_sent"] == 4
    # the fingers stopped on the tool: stalled, the travel between open and closed
    assert pick["stalled"] is True and pick["reached_goal"] is False
    assert pick["gap"] == pytest.approx(0.02)
    assert pick["tool_after"][2] - pick["tool_before"][2] == pytest.approx(0.08, abs=0.02)
    assert panda["opened"] == [pytest.approx(0.04), False, True]
