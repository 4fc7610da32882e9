"""The stand-in robot in its own process, driven over ROS 2 by the learner's client.

All ROS traffic runs inside a private network namespace that has only loopback
(``unshare -n``, or ``unshare -rn`` where unprivileged, then ``ip link set lo up``), with
``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`` and a domain id of its own: nothing leaves
the machine. One session (``_session.py``, about 30 s) starts the stand-in of the hook
case and runs every scenario in order; each test checks one part of what it saw.
Skipped, with the reason, without the ``ros`` extra (``make setup-ros``) or where the
namespace is refused.
"""

from __future__ import annotations

import importlib.util
import json
import math
import os
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.sim

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[3]
CASE = "hook"


def ros_missing() -> str | None:
    """Return why the ros extra cannot run here, or None."""
    for module, what in (("rclpy", "the ros extra is not installed"),
                         ("control_msgs", "control_msgs is not built")):
        if importlib.util.find_spec(module) is None:
            return f"{what} (make setup-ros; docs/real-robot.md)"
    return None


def namespace_prefix() -> list[str] | str:
    """Return the command prefix that gives a private network namespace, or why not."""
    for tool in ("unshare", "ip"):
        if shutil.which(tool) is None:
            return f"{tool} is not installed: no private network namespace for ROS traffic"
    why = ""
    for prefix in (["unshare", "-n"], ["unshare", "-rn"]):
        r = subprocess.run([*prefix, "sh", "-c", "ip link set lo up"], capture_output=True,
                           text=True, timeout=20)
        if r.returncode == 0:
            return prefix
        why = r.stderr.strip().splitlines()[-1] if r.stderr.strip() else f"exit {r.returncode}"
    return f"unshare refused a private network namespace ({why}): ROS tests need one"


def run_in_namespace(script: Path, *args: str, domain: int, timeout: float = 300.0) -> dict:
    """Run ``script`` with this Python inside a loopback-only namespace; return its
    last stdout line as JSON (skip if the namespace or the extra is missing)."""
    missing = ros_missing()
    if missing:
        pytest.skip(missing)
    prefix = namespace_prefix()
    if isinstance(prefix, str):
        pytest.skip(prefix)
    env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST", ROS_DOMAIN_ID=str(domain),
               PYTHONPATH=os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")])))
    command = " ".join(["ip link set lo up && exec", sys.executable, str(script), *args])
    proc = subprocess.Popen([*prefix, "sh", "-c", command], env=env, cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        pytest.fail(f"{script.name} did not end within {timeout:g} s: {err[-2000:]}")
    lines = out.strip().splitlines()
    assert lines, f"{script.name} printed nothing (exit {proc.returncode}): {err[-2000:]}"
    result = json.loads(lines[-1])
    assert "error" not in result, f"{result['error']}\n{err[-3000:]}"
    return result


@pytest.fixture(scope="module")
def session() -> dict:
    return run_in_namespace(HERE / "_session.py", CASE, domain=100 + os.getpid() % 100)


@pytest.fixture(scope="module")
def profile():
    from creative_py.backends.ros.profile import load_profile

    return load_profile("baxter")


def test_the_traffic_stays_in_a_loopback_only_namespace(session):
    assert session["namespace_links"] == ["lo"]
    assert session["discovery_range"] == "LOCALHOST"
    assert 100 <= int(session["domain_id"]) < 200
    # it stopped cleanly on SIGTERM
    assert session["standin_rc"] == 0, session.get("standin_stderr")
    assert session["interface"]["clock"] == "/clock" and session["interface"]["use_sim_time"]


def test_joint_states_arrive_at_the_profile_rate(session, profile):
    js = session["joint_states"]
    assert js["names"] == [*profile.joints, profile.gripper_joint]
    # 50 Hz of physics time; the wall-clock rate depends on the machine and its load, so
    # it is a figure of docs/real-robot.md, not a test's bound
    assert js["per_s"] > 0
    assert js["position"][-1] == pytest.approx(profile.gripper_open)


def test_object_poses_arrive_where_the_scene_has_them(session, profile):
    from creative_py.backends.pybullet import load_world, open_episode
    from creative_py.backends.pybullet.bodies import frame_pose
    from creative_py.case import get_case

    m = get_case(CASE)
    d = m.demonstration
    with open_episode(load_world(m), d.variant, d.location, d.tool) as ep:
        truth = {n: frame_pose(ep.sim, ep.body_id(n)) for n in session["poses"]}
    assert set(session["interface"]["objects"]) == {ep.target_name, ep.context_name, d.tool}
    for name, (pos, quat, frame) in session["poses"].items():
        assert frame == profile.world_frame
        assert session["interface"]["objects"][name] == profile.object_topic_of(name)
        assert math.dist(pos, truth[name][0]) < 0.005, name
        assert abs(sum(a * b for a, b in zip(quat, truth[name][1]))) > 0.999, name


def test_a_trajectory_goal_moves_the_arm_and_succeeds_with_feedback(session, profile):
    trips = session["round_trips"]
    assert len(trips) == 6
    for k, trip in enumerate(trips):
        assert (trip["status"], trip["code"]) == ("succeeded", 0), trip
        assert trip["error_after"] < profile.goal_tolerance
        t = trip["times"]
        # milliseconds on a quiet machine (docs/real-robot.md); bounds for a loaded one
        # the order of the messages, not their timings (which depend on the machine)
        assert 0 < t["accepted"] < t["result"] and 0 < t["first_feedback"] < t["result"]
        assert t["result"] > 0.95  # a 1 s trajectory of physics time cannot end sooner
        assert t["feedbacks"] >= 1
        assert trip["feedback_names"] == list(profile.joints)
    # the last feedback received was on its way to the goal (the result may overtake the
    # feedback messages sent just before it: they travel on a topic, the result does not)
    q1 = session["q1"]
    last = trips[0]["last_feedback_actual"]
    assert max(abs(a - b) for a, b in zip(last, q1)) < 0.15


def test_invalid_goals_are_rejected(session):
    assert session["rejected"] == {"unknown_joint": "rejected", "beyond_limits": "rejected",
                                   "time_not_increasing": "rejected"}


def test_a_goal_outside_the_learners_bounds_is_never_sent(session):
    refused = session["refused"]
    assert "limits.max_joint_speed" in refused["too_fast"]
    assert "outside the workspace box" in refused["outside_workspace"]
    assert session["goals_sent_while_refusing"] == 0
    # the arm stayed where the last round trip left it (its start)
    q_end = session["round_trips"][-1]
    assert q_end["status"] == "succeeded"
    q1, q = session["q1"], session["q_after_refusals"]
    assert max(abs(a - b) for a, b in zip(q, q1)) > 0.1  # not at q1: back at the start


def test_a_blocked_goal_without_path_tolerance_aborts_with_goal_tolerance_violated(session):
    r = session["blocked_no_path_tolerance"]
    assert (r["status"], r["code"]) == ("aborted", -5), r
    assert "goal tolerance" in r["message"]
    assert session["back_to_start"] == {"status": "succeeded", "code": 0}


def test_a_colliding_goal_aborts_with_path_tolerance_violated(session):
    r = session["collision"]
    assert (r["status"], r["code"]) == ("aborted", -4), r
    assert "path tolerance" in r["message"]


def test_the_gripper_answers_and_its_gap_is_published(session, profile):
    g = session["gripper"]
    assert g["closed"] == [profile.gripper_closed, False, True]  # nothing between the fingers
    assert g["opened"] == [profile.gripper_open, False, True]
    assert g["gap_in_joint_states"] == pytest.approx(profile.gripper_open)


def test_without_a_namespace_the_ros_tests_skip_saying_why(monkeypatch):
    monkeypatch.setattr(shutil, "which", lambda name: None)
    assert namespace_prefix() == ("unshare is not installed: no private network namespace "
                                  "for ROS traffic")
    monkeypatch.setattr(importlib.util, "find_spec", lambda name: None)
    assert ros_missing() == "the ros extra is not installed (make setup-ros; docs/real-robot.md)"


def test_the_read_only_check_sees_the_interface_and_names_what_is_absent(session, profile):
    report = session["check"]
    js = report["joint_states"]
    assert js["profile_joints_missing"] == [] and js["rate_hz"] > 0
    assert js["latency_ms"] is None  # simulated stamps: no wall-clock latency
    assert report["clock"]["topic"] == "/clock" and report["clock"]["rate_hz"] > 0
    assert {n: o["frame"] for n, o in report["objects"].items()} == {
        n: profile.world_frame for n in session["interface"]["objects"]}
    assert all(o["rate_hz"] > 0 for o in report["objects"].values())  # 30 Hz nominal
    # a wrong topic or action name: the error lists what the arm does publish
    assert session["check_absent"]["missing"] == (
        "no sensor_msgs/JointState on 'absent/joint_states' within 2 s; the ROS graph has "
        "sensor_msgs/msg/JointState on /joint_states")
    assert session["check_misspelt"]["missing"] == (
        "no action server 'right_gripper_controller/gripper_command' within 2 s; the ROS "
        "graph serves control_msgs/action/GripperCommand on "
        "/right_gripper_controller/gripper_cmd")
    assert session["check_absent_s"] < 8.0


def test_the_learner_moves_the_gripper_through_its_own_ik(session):
    up = session["move_up"]
    assert up["status"] == "ok", up["reason"]
    assert math.dist(up["to"], up["target"]) < 0.01
    assert up["goals_sent"] == 1
    assert session["move_back"]["status"] == "ok"


def test_a_move_below_the_workspace_box_is_unreachable_and_not_sent(session):
    r = session["move_below_the_box"]
    assert r["status"] == "unreachable"
    assert r["reason"].startswith("refused by the learner's bounds: ")
    assert r["goals_sent"] == 1  # still the one of the move up


def test_the_learner_picks_the_tool_up_over_ros(session, profile):
    pick = session["pick_up"]
    assert pick["moves"] == ["ok"] * 4
    assert (pick["stalled"], pick["reached_goal"]) == (True, False)  # closed on the tool
    assert pick["gap"] == pytest.approx((profile.gripper_open + profile.gripper_closed) / 2)
    before, after = pick["tool_before"], pick["tool_after"]
    assert after[2] - before[2] == pytest.approx(0.08, abs=0.01)  # lifted with the gripper
    assert math.dist(after[:2], before[:2]) < 0.01


def test_a_frozen_arm_gives_stale_joint_states_and_a_goal_that_ends_silent(session, profile):
    stale = session["stale"]
    # on the wall clock (a real arm's profile): the joint states' age
    assert stale["arm_q"].startswith(f"joint states on '{profile.joint_states_topic}' are ")
    assert f"(stale after {profile.stale_after_s:g} s)" in stale["arm_q"]
    # on the simulated clock: the clock stopped, naming its topic
    assert stale["sim_arm_q"].startswith("the clock on '/clock' stopped ")
    assert stale["move"]["status"] == "invalid"
    assert stale["move"]["reason"].startswith("the arm went silent: the clock on '/clock'")
    frozen = session["frozen_mid_goal"]
    assert frozen["status"] == "silent"  # not its 30 s timeout
    assert "the clock on '/clock' stopped" in frozen["message"]
    assert frozen["feedbacks"] >= 1  # it was moving when it froze
    assert session["after_thaw"] == {"arm_q_ok": True}


def test_an_absent_arm_names_the_topic_it_waited_for(session):
    absent = session["absent"]
    assert absent["wall"]["message"] == (
        "no sensor_msgs/JointState on 'joint_states' within 2 s; no node of the ROS graph "
        "publishes sensor_msgs/msg/JointState")
    assert absent["sim"]["message"] == (
        "no rosgraph_msgs/Clock on '/clock' within 2 s (the profile's [clock] "
        "use_sim_time); no node of the ROS graph publishes rosgraph_msgs/msg/Clock")


def test_an_arm_killed_mid_goal_gives_an_invalid_motion_and_a_lost_arm(session):
    killed = session["killed_mid_goal"]
    assert killed["rc"] == -9  # SIGKILL while the goal ran
    assert killed["status"] == "invalid"
    assert killed["reason"].startswith("the arm went silent: ")
    assert "the clock on '/clock' stopped " in killed["reason"]
    name, is_lost, message = killed["raised"]
    assert (name, is_lost) == ("ArmUnavailable", True)  # a BackendLost: the run stops
    assert message in killed["reason"]


def test_an_aborted_goal_is_blocked_with_its_error_code(session):
    r = session["learner_blocked"]
    assert r["status"] == "blocked", r
    assert "PATH_TOLERANCE_VIOLATED" in r["reason"]
    assert r["stop"]["measures"]["error_code"] == -4
    assert r["stop"]["threshold_name"] == "path_tolerance_violated"
    assert r["lost"] is False  # an arm that aborts is there: the trial's outcome


def test_stale_joint_states_of_a_live_arm_stop_the_goal_before_it_is_sent(session, profile):
    muted = session["muted"]
    assert muted["clock_ok"]  # the stand-in was alive: its clock went on
    assert muted["move"]["status"] == "invalid"
    assert muted["move"]["reason"].startswith(
        f"the arm went silent: joint states on '{profile.joint_states_topic}' are ")
    assert "in simulated time (stale after 1 s)" in muted["move"]["reason"]
    assert muted["goals_sent"] == 0 and muted["lost"] == "ArmUnavailable"
    assert session["after_unmute"] == {"arm_q_ok": True}
