"""The learner's bounds: a trajectory too fast or leaving the workspace box is refused
before it is sent (no ROS needed)."""

from __future__ import annotations

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
