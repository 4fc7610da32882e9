"""The learner's bounds on what it sends an arm: joint speed and the gripper's workspace.

A real arm's controller executes what it is sent; these checks run on the learner's side
before a trajectory goal leaves the process (:meth:`.client.ArmClient.send_trajectory`).
A trajectory is refused if a segment moves a joint faster than the profile's
``limits.max_joint_speed``, or if the gripper, by the learner's forward kinematics of the
robot's URDF, leaves the profile's workspace box at a point or between two points
(sampled every ``step`` rad of the fastest joint). No ROS is needed here.
"""

from __future__ import annotations

from typing import Callable, Sequence

from creative_py.backends.ros.profile import RobotProfile

Forward = Callable[[Sequence[float]], Sequence[float]]
"""Forward kinematics: joint positions (profile order) -> the gripper's world position."""


class OutOfBounds(ValueError):
    """A trajectory outside the profile's limits: it is not sent."""


def check_points(profile: RobotProfile, start: Sequence[float],
                 points: Sequence[tuple[float, Sequence[float]]], forward: Forward,
                 step: float = 0.05) -> None:
    """Raise :class:`OutOfBounds` unless the trajectory from ``start`` through ``points``
    (``(time_from_start s, positions in the profile's joint order)``) keeps within the
    profile's joint speed and workspace box."""
    lo, hi = profile.workspace_min, profile.workspace_max
    prev_t, prev_q = 0.0, [float(v) for v in start]
    for k, (t, q) in enumerate(points):
        q = [float(v) for v in q]
        if len(q) != len(profile.joints):
            raise OutOfBounds(f"point {k} has {len(q)} positions for {len(profile.joints)} joints")
        move = max(abs(a - b) for a, b in zip(q, prev_q))
        dt = t - prev_t
        if move > 0 and (dt <= 0 or move / dt > profile.max_joint_speed):
            speed = "instantly" if dt <= 0 else f"at {move / dt:.3f} rad/s"
            raise OutOfBounds(f"point {k}: a joint would move {move:.3f} rad {speed}, above "
                              f"limits.max_joint_speed {profile.max_joint_speed} rad/s of "
                              f"{profile.source}")
        n = max(1, int(move / step) + 1)
        for i in range(1, n + 1):
            a = i / n
            x = forward([p + a * (c - p) for p, c in zip(prev_q, q)])
            if not all(lo[j] <= x[j] <= hi[j] for j in range(3)):
                raise OutOfBounds(f"point {k}: the gripper would reach ({x[0]:.3f}, {x[1]:.3f}, "
                                  f"{x[2]:.3f}) m, outside the workspace box {list(lo)} - "
                                  f"{list(hi)} of {profile.source}")
        prev_t, prev_q = t, q


def urdf_forward(profile: RobotProfile, base=None) -> Forward:
    """Return the forward kinematics of the profile's URDF (the gripper's world position).

    The pybullet backend's arm of the profile, in its kinematics client (DIRECT, no
    scene), its base at ``base`` (a world's placement: position, quaternion; None: the
    profile's ``[base]``), so that the workspace box is checked in the world frame.
    """
    from creative_py.backends.ros.twin import kinematics_model

    model = kinematics_model(profile, base)
    index = [profile.joints.index(n) for n in profile.arm_joints]

    def forward(q: Sequence[float]) -> Sequence[float]:
        model.reset(model.arm, [q[i] for i in index])
        return model.ee_pose()[0]

    return forward


def goal_checker(profile: RobotProfile, start: Callable[[], Sequence[float]],
                 forward: Forward) -> Callable[[object], None]:
    """Return ``check(goal)`` for :meth:`.client.ArmClient.send_trajectory`: the goal's
    points (reordered to the profile's joints) checked from the arm's ``start()``."""

    def check(goal: object) -> None:
        traj = goal.trajectory  # type: ignore[attr-defined]
        names = list(traj.joint_names)
        if sorted(names) != sorted(profile.joints):
            raise OutOfBounds(f"the goal names joints {names}, not the profile's "
                              f"{list(profile.joints)}")
        order = [names.index(j) for j in profile.joints]
        points = [(pt.time_from_start.sec + pt.time_from_start.nanosec * 1e-9,
                   [pt.positions[i] for i in order]) for pt in traj.points]
        check_points(profile, start(), points, forward)

    return check
