"""A joint trajectory judged as a joint trajectory controller does (no ROS needed)."""

from __future__ import annotations

import math

import pytest

from creative_py.backends.ros.trajectory import (GOAL_TOLERANCE_VIOLATED, INVALID_GOAL,
                                                 INVALID_JOINTS, PATH_TOLERANCE_VIOLATED,
                                                 SUCCESSFUL, InvalidTrajectory, TrajectoryRun,
                                                 tolerance_of)

JOINTS = ("a", "b")
LIMITS = dict(lower=[-1.0, -1.0], upper=[1.0, 1.0])


def run(points, names=JOINTS, **kw):
    return TrajectoryRun(JOINTS, [0.0, 0.0], names, points, **LIMITS, **kw)


def test_positions_are_interpolated_from_the_start_and_unnamed_joints_hold():
    r = run([(1.0, [0.5]), (2.0, [1.0])], names=("b",))
    assert r.desired(0.5) == ([0.0, 0.25], 0)
    assert r.desired(1.5) == ([0.0, 0.75], 1)
    assert r.desired(9.0) == ([0.0, 1.0], 1)


def test_success_once_within_goal_tolerance_after_the_end():
    r = run([(1.0, [0.5, 0.5])], default_goal=0.01)
    assert r.judge(0.5, [0.25, 0.25]) is None
    assert r.judge(1.0, [0.48, 0.5]) is None  # not yet within, time left
    assert r.judge(1.1, [0.495, 0.5]).code == SUCCESSFUL


def test_path_and_goal_tolerance_violations_name_the_joint():
    r = run([(1.0, [0.5, 0.5])], default_path=0.1, default_goal=0.01, default_goal_time=0.2)
    out = r.judge(0.5, [0.25, 0.0])
    assert out.code == PATH_TOLERANCE_VIOLATED and out.message.startswith("b is 0.2500 rad")
    out = r.judge(1.3, [0.5, 0.4])
    assert out.code == GOAL_TOLERANCE_VIOLATED and out.message.startswith("b is 0.1000 rad")


def test_a_goals_tolerances_override_the_defaults_and_minus_one_erases():
    r = run([(1.0, [0.5, 0.5])], path_tol={"a": -1.0}, goal_tol={"b": 0.2},
            goal_time_tolerance=2.0, default_path=0.1, default_goal=0.01)
    assert r.path_tol == [math.inf, 0.1] and r.goal_tol == [0.01, 0.2] and r.goal_time == 2.0
    assert r.judge(0.5, [-0.9, 0.25]) is None
    assert tolerance_of(0.0, 0.3) == 0.3 and tolerance_of(0.05, 0.3) == 0.05


@pytest.mark.parametrize("names,points,code", [
    (("a", "c"), [(1.0, [0.0, 0.0])], INVALID_JOINTS),
    (("a", "a"), [(1.0, [0.0, 0.0])], INVALID_JOINTS),
    (JOINTS, [], INVALID_GOAL),
    (JOINTS, [(1.0, [0.0])], INVALID_GOAL),
    (JOINTS, [(1.0, [0.0, 0.0]), (1.0, [0.1, 0.1])], INVALID_GOAL),
    (JOINTS, [(1.0, [0.0, 1.5])], INVALID_GOAL),
    (JOINTS, [(1.0, [0.0, math.nan])], INVALID_GOAL),
])
def test_invalid_goals_carry_the_standard_code(names, points, code):
    with pytest.raises(InvalidTrajectory) as info:
        run(points, names=names)
    assert info.value.code == code
