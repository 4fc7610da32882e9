"""The gripper's straight path, once for every backend that moves an arm by IK.

A skill moves the gripper along a straight line to a target pose: the line cut into
waypoints, the orientation slerped, each waypoint's arm posture solved by the caller's
IK from the one before (:func:`straight_line`). The pybullet backend's arm
(:mod:`creative_py.backends.pybullet.arm`) and the learner's side of an arm over ROS 2
(:mod:`creative_py.backends.ros.motion`, :mod:`creative_py.backends.ros.episode`) cut
their paths here; the IK is theirs. No physics, no robot model: poses are
``(point, quat)``, metres, quaternions ``x, y, z, w``, angles in radians.
"""

from __future__ import annotations

import math
from typing import Callable, Iterator, Sequence

import numpy as np

from creative_py.simulator.types import SkillOutcome

Point = tuple[float, float, float]
Quat = tuple[float, float, float, float]
Pose = tuple[Point, Quat]


def quat_angle(q1: Sequence[float], q2: Sequence[float]) -> float:
    """Return the rotation angle (rad) between two quaternions (x, y, z, w)."""
    d = abs(float(np.dot(q1, q2)))
    return 2.0 * math.acos(min(1.0, d))


def slerp(q1: Sequence[float], q2: Sequence[float], t: float) -> Quat:
    """Return the spherical interpolation between two quaternions at fraction t."""
    a, b = np.asarray(q1, float), np.asarray(q2, float)
    d = float(np.dot(a, b))
    if d < 0:
        b, d = -b, -d
    if d > 0.9995:
        q = a + t * (b - a)
    else:
        th = math.acos(d)
        q = (math.sin((1 - t) * th) * a + math.sin(t * th) * b) / math.sin(th)
    q = q / np.linalg.norm(q)
    return tuple(float(v) for v in q)


def straight_line(solve_ik: Callable[..., list[float] | None], start: Pose, target: Pose,
                  n: int, q: Sequence[float]) -> Iterator[tuple[Point, Quat, list[float]]]:
    """Yield the ``n`` waypoints of a straight gripper move from ``start`` to ``target``:
    each one's position (on the line), orientation (slerped) and arm posture, solved by
    ``solve_ik(pose, seed=...)`` from the posture before it (from ``q`` first).

    Lazily, so that a caller moving the arm as it goes stops where the path does. A
    waypoint without a posture, or one the arm would reach only by flipping (a joint
    jumping more than 0.5 rad), ends the path with :class:`Unreachable`; what
    was yielded before it stands.
    """
    for i in range(1, n + 1):
        t = i / n
        pos = tuple(a + t * (b - a) for a, b in zip(start[0], target[0]))
        quat = slerp(start[1], target[1], t)
        sol = solve_ik((pos, quat), seed=q)
        if sol is None:
            raise Unreachable(SkillOutcome("unreachable", f"IK found no arm posture for "
                                           f"gripper at ({pos[0]:.3f}, {pos[1]:.3f}, "
                                           f"{pos[2]:.3f}) m"))
        if max(abs(a - b) for a, b in zip(sol, q)) > 0.5:
            raise Unreachable(SkillOutcome("unreachable", "the arm would have to flip its "
                                           f"posture (joint jump > 0.5 rad) near ({pos[0]:.3f}"
                                           f", {pos[1]:.3f}, {pos[2]:.3f}) m"))
        q = sol
        yield pos, quat, sol


class Unreachable(Exception):
    """A straight gripper path that the arm cannot follow (:func:`straight_line`):
    ``outcome`` says where and why."""

    def __init__(self, outcome: SkillOutcome) -> None:
        super().__init__(outcome.reason)
        self.outcome = outcome
