"""The learner's bounds: a trajectory too fast or leaving the workspace box is refused
before it is sent (no ROS needed)."""

from __future__ import annotations

import math

import pytest

from creative_py.backends.ros.limits import OutOfBounds, check_points, goal_checker
from creative_py.backends.ros.profile import load_profile

PROFILE = load_profile("baxter")
N = len(PROFILE.joints)


def toy_forward(q):
    """A made-up forward kinematics: the gripper at (0.5 + q0, q1, q2)."""
    return (0.5 + q[0], q[1], q[2])


def test_a_trajectory_inside_the_bounds_passes():
    check_points(PROFILE, [0.0] * N, [(1.0, [0.3, 0.0, 0.1] + [0.0] * (N - 3))], toy_forward)


def test_a_joint_too_fast_is_refused():
    with pytest.raises(OutOfBounds, match="above limits.max_joint_speed 0.8 rad/s"):
        check_points(PROFILE, [0.0] * N, [(0.1, [0.3] + [0.0] * (N - 1))], toy_forward)
    with pytest.raises(OutOfBounds, match="instantly"):
        check_points(PROFILE, [0.0] * N, [(0.0, [0.3] + [0.0] * (N - 1))], toy_forward)


def test_leaving_the_box_between_two_points_is_refused():
    # both ends inside (z = 0.1), the middle would dip below workspace_min z = -0.19
    dip = lambda q: (0.5, 0.0, 0.1 - 0.6 * (1 - abs(1 - q[0])))  # noqa: E731
    with pytest.raises(OutOfBounds, match="outside the workspace box"):
        check_points(PROFILE, [0.0] * N, [(4.0, [2.0] + [0.0] * (N - 1))], dip)


def test_the_goal_checker_reads_a_goal_in_any_joint_order():
    class Stamp:
        def __init__(self, t):
            self.sec, self.nanosec = int(t), int(round((t - int(t)) * 1e9))

    class Point:
        def __init__(self, t, q):
            self.time_from_start, self.positions = Stamp(t), q

    class Goal:
        class trajectory:
            joint_names = list(reversed(PROFILE.joints))
            points = [Point(0.5, [0.0] * (N - 1) + [0.9])]  # the first joint, last here

    check = goal_checker(PROFILE, lambda: [0.0] * N, toy_forward)
    with pytest.raises(OutOfBounds, match="1.800 rad/s"):
        check(Goal)


def test_a_joint_space_move_eases_in_and_out_within_the_bounds():
    from creative_py.backends.ros.client import GoalTimes, TrajectoryResult
    from creative_py.backends.ros.motion import SPEED_MARGIN, LearnerArm

    start, goal = [0.0] * N, [0.8, -0.4] + [0.0] * (N - 2)
    sent = []

    class Client:  # the arm's side of LearnerArm, without ROS: the points it would send
        profile = PROFILE

        def arm_q(self):
            return list(start)

        def make_goal(self, points):
            return points

        def send_trajectory(self, points, timeout):
            sent.append(points)
            return TrajectoryResult("succeeded", 0, "", GoalTimes())

    class Kinematics:
        forward_position = staticmethod(toy_forward)

    arm = LearnerArm(Client(), Kinematics())
    arm.check = lambda points: check_points(PROFILE, start, points, toy_forward)
    assert arm.move_joints(goal).status == "ok"
    (points,) = sent
    assert points[-1][1] == pytest.approx(goal)
    speeds, prev_t, prev_q = [], 0.0, start
    for t, q in points:
        speeds.append(max(abs(a - b) for a, b in zip(q, prev_q)) / (t - prev_t))
        prev_t, prev_q = t, q
    peak = SPEED_MARGIN * PROFILE.max_joint_speed
    # at rest at both ends, the margin of the joint speed in the middle
    assert max(speeds) <= peak + 1e-9 and max(speeds) > 0.95 * peak
    assert speeds[0] < 0.2 * peak and speeds[-1] < 0.2 * peak
    assert points[-1][0] == pytest.approx(math.pi / 2 * 0.8 / peak, rel=0.02)


@pytest.mark.parametrize("accepted, want", [(0.01, "out_of_time"), (None, "invalid")])
def test_a_goal_without_a_result_in_its_time_is_a_motion_out_of_time(accepted, want):
    # Accepted and then no result within its duration plus the timeout: out of time,
    # judged above the boundary as a ManiSkill episode out of control steps. Never
    # accepted: the arm did not answer, not a motion that ran long.
    from creative_py.backends.ros.client import GoalTimes, TrajectoryResult
    from creative_py.backends.ros.motion import LearnerArm
    from creative_py.simulator.trial import trial_outcome

    class Client:
        profile = PROFILE

        def arm_q(self):
            return [0.0] * N

        def make_goal(self, points):
            return points

        def send_trajectory(self, points, timeout):
            why = "no result within 12.5 s (simulated time)" if accepted else "no answer"
            return TrajectoryResult("timeout", None, why, GoalTimes(accepted=accepted))

    class Kinematics:
        forward_position = staticmethod(toy_forward)

    arm = LearnerArm(Client(), Kinematics(), timeout=10.0)
    arm.check = lambda points: None
    out = arm.send([(2.5, [0.1] + [0.0] * (N - 1))])
    assert out.status == want
    if want == "out_of_time":
        assert out.reason == ("the arm's goal ran out of time: no result within 12.5 s "
                              "(simulated time)")
        assert (out.stop.value, out.stop.threshold, out.stop.unit) == (12.5, 12.5, "s")
        assert trial_outcome(out, acted=True, reached=False)[0] == "blocked"
