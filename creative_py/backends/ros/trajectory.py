"""A joint trajectory executed and judged as ros2_control's joint trajectory controller
does it, without ROS (the stand-in robot runs it; tests run it alone).

The trajectory starts from the arm's current positions at time 0 and is interpolated
linearly in position between its points (the controller's ``linear`` interpolation;
velocities and accelerations in the points are not used). While it runs, every joint
must stay within its path tolerance of the desired position; at the end every joint
must come within its goal tolerance by ``end + goal_time_tolerance``. The outcome codes
are control_msgs' ``FollowJointTrajectory.Result`` codes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Sequence

# control_msgs/action/FollowJointTrajectory Result.error_code
SUCCESSFUL = 0
INVALID_GOAL = -1
INVALID_JOINTS = -2
OLD_HEADER_TIMESTAMP = -3
PATH_TOLERANCE_VIOLATED = -4
GOAL_TOLERANCE_VIOLATED = -5

ERROR_NAMES = {SUCCESSFUL: "SUCCESSFUL", INVALID_GOAL: "INVALID_GOAL",
               INVALID_JOINTS: "INVALID_JOINTS", OLD_HEADER_TIMESTAMP: "OLD_HEADER_TIMESTAMP",
               PATH_TOLERANCE_VIOLATED: "PATH_TOLERANCE_VIOLATED",
               GOAL_TOLERANCE_VIOLATED: "GOAL_TOLERANCE_VIOLATED"}


class InvalidTrajectory(ValueError):
    """A goal the controller refuses: ``code`` is INVALID_JOINTS or INVALID_GOAL."""

    def __init__(self, code: int, message: str) -> None:
        super().__init__(message)
        self.code = code


@dataclass(frozen=True)
class GoalResult:
    """How an executed trajectory ended: ``code`` (SUCCESSFUL or an error) and why."""

    code: int
    message: str


def tolerance_of(given: float, default: float) -> float:
    """Return a joint's tolerance from a goal's value: 0 takes the controller's default,
    a negative value (control_msgs' -1) erases it (no limit)."""
    if given == 0.0:
        return default
    return math.inf if given < 0 else given


class TrajectoryRun:
    """One trajectory goal being executed on the joints ``joints`` (the arm's order).

    Parameters
    ----------
    joints : sequence of str
        The arm's joints, in the order of ``start`` and of the positions it is given.
    start : sequence of float
        The arm's positions when execution starts (time 0).
    names : sequence of str
        The goal's ``joint_names`` (any order; a subset of ``joints``: the others hold).
    points : sequence of (time_from_start s, positions in ``names``' order)
    lower, upper : sequence of float
        The joints' position limits (rad), in ``joints``' order.
    path_tol, goal_tol : dict
        ``name -> tolerance`` given by the goal (0 or absent: ``default_path``/``default_goal``).
    goal_time_tolerance : float
        Seconds after the last point's time by which the goal tolerance must hold
        (0: ``default_goal_time``).

    Raises
    ------
    InvalidTrajectory
        Unknown or repeated joint names (INVALID_JOINTS); no points, a point of the wrong
        length, times not strictly increasing, a non-finite number, a position outside
        the joint's limits (INVALID_GOAL).
    """

    def __init__(self, joints: Sequence[str], start: Sequence[float], names: Sequence[str],
                 points: Sequence[tuple[float, Sequence[float]]], lower: Sequence[float],
                 upper: Sequence[float], path_tol: dict[str, float] | None = None,
                 goal_tol: dict[str, float] | None = None, goal_time_tolerance: float = 0.0,
                 default_path: float = 0.15, default_goal: float = 0.02,
                 default_goal_time: float = 0.5) -> None:
        joints = list(joints)
        unknown = [n for n in names if n not in joints]
        if unknown or len(set(names)) != len(names) or not names:
            raise InvalidTrajectory(INVALID_JOINTS, f"joints {list(names)} are not distinct "
                                    f"joints of the arm {joints}")
        if not points:
            raise InvalidTrajectory(INVALID_GOAL, "the trajectory has no points")
        self.joints = joints
        self.index = [joints.index(n) for n in names]
        self.times: list[float] = []
        self.targets: list[list[float]] = []
        last = 0.0
        full = [float(v) for v in start]
        for k, (t, pos) in enumerate(points):
            if len(pos) != len(names):
                raise InvalidTrajectory(INVALID_GOAL, f"point {k} has {len(pos)} positions "
                                        f"for {len(names)} joints")
            if not math.isfinite(t) or t <= last and not (k == 0 and t == 0.0 == last):
                raise InvalidTrajectory(INVALID_GOAL, f"point {k}: time_from_start {t} s "
                                        "does not increase")
            full = list(full)
            for i, v in zip(self.index, pos):
                if not math.isfinite(v):
                    raise InvalidTrajectory(INVALID_GOAL, f"point {k}: {joints[i]} is {v}")
                if not lower[i] - 1e-9 <= v <= upper[i] + 1e-9:
                    raise InvalidTrajectory(INVALID_GOAL, f"point {k}: {joints[i]} = {v:.4f} "
                                            f"rad is outside its limits [{lower[i]:.4f}, "
                                            f"{upper[i]:.4f}]")
                full[i] = float(v)
            self.times.append(float(t))
            self.targets.append(full)
            last = t
        self.start = [float(v) for v in start]
        path_tol, goal_tol = path_tol or {}, goal_tol or {}
        self.path_tol = [tolerance_of(path_tol.get(n, 0.0), default_path) for n in joints]
        self.goal_tol = [tolerance_of(goal_tol.get(n, 0.0), default_goal) for n in joints]
        self.goal_time = (default_goal_time if goal_time_tolerance == 0.0
                          else max(0.0, goal_time_tolerance))
        self.end = self.times[-1]

    def desired(self, t: float) -> tuple[list[float], int]:
        """Return the desired positions at ``t`` s and the index of the point being
        approached (the last one once the trajectory's time is over)."""
        prev_t, prev_q = 0.0, self.start
        for k, (tk, qk) in enumerate(zip(self.times, self.targets)):
            if t < tk:
                a = (t - prev_t) / (tk - prev_t) if tk > prev_t else 1.0
                return [p + max(0.0, a) * (q - p) for p, q in zip(prev_q, qk)], k
            prev_t, prev_q = tk, qk
        return list(self.targets[-1]), len(self.times) - 1

    def judge(self, t: float, actual: Sequence[float]) -> GoalResult | None:
        """Return the outcome at ``t`` s with the arm at ``actual``, or None while it runs.

        Before the end: PATH_TOLERANCE_VIOLATED if a joint is farther than its path
        tolerance from the desired position. From the end on: SUCCESSFUL once every
        joint is within its goal tolerance; GOAL_TOLERANCE_VIOLATED when
        ``end + goal_time_tolerance`` passes first.
        """
        desired, _ = self.desired(t)
        errors = [abs(a - d) for a, d in zip(actual, desired)]
        if t < self.end:
            for j, (e, tol) in enumerate(zip(errors, self.path_tol)):
                if e > tol:
                    return GoalResult(PATH_TOLERANCE_VIOLATED,
                                   f"{self.joints[j]} is {e:.4f} rad from its desired "
                                   f"position at t = {t:.3f} s (path tolerance {tol:.4f} rad)")
            return None
        worst = max(range(len(errors)), key=lambda j: errors[j] - self.goal_tol[j])
        if errors[worst] <= self.goal_tol[worst]:
            return GoalResult(SUCCESSFUL, "")
        if t > self.end + self.goal_time:
            return GoalResult(GOAL_TOLERANCE_VIOLATED,
                           f"{self.joints[worst]} is {errors[worst]:.4f} rad from its goal "
                           f"{self.goal_time:.3f} s after the trajectory's end (goal tolerance "
                           f"{self.goal_tol[worst]:.4f} rad)")
        return None
