"""The learner's side of an arm's motion over ROS 2.

:class:`LearnerArm` moves the gripper the way the learner's skills do, with the
kinematics on the learner's side:

1. a target pose of the gripper is cut into waypoints along a straight line;
2. each waypoint goes through IK from the robot's URDF, computed in the learner's own
   process (the pybullet backend's arm of the profile in a DIRECT client without the
   scene);
3. the waypoints are sent as one ``FollowJointTrajectory`` goal, timed so that no joint
   exceeds the profile's speed, after the learner's bounds (:mod:`.limits`) passed.

Its outcome is a :class:`~creative_py.simulator.types.SkillOutcome`, as the pybullet
backend's motions give:

* ``ok``: the goal succeeded;
* ``blocked``: the arm aborted the goal on a path or goal tolerance, with the lag as
  the stop's :class:`~creative_py.simulator.types.Verdict`;
* ``unreachable``: no IK solution, or the learner's bounds refused the motion, which
  is then never sent;
* ``out_of_time``: the arm accepted the goal but gave no result within its duration
  plus :attr:`LearnerArm.timeout` (the trial loop judges it as a ManiSkill episode out
  of control steps: :func:`creative_py.simulator.trial.trial_outcome`);
* ``invalid``: the arm rejected the goal, did not accept it in time, or went silent (its
  joint states stale or its clock stopped, before the goal or while it ran). A silent
  arm is also kept as :attr:`LearnerArm.lost` (an :class:`ArmUnavailable`, which is a
  :class:`~creative_py.simulator.types.BackendLost`): an episode raises it through the
  boundary so that the run stops resumably instead of recording a failed trial.

:class:`creative_py.backends.ros.episode.RosEpisode` (the backend's episode) moves
the arm through :meth:`LearnerArm.send` and :meth:`LearnerArm.grip`; ``log`` keeps each
goal's timings.
"""

from __future__ import annotations

import math
from typing import Any, Optional, Sequence

from creative_py.backends.ros.client import ArmClient, ArmUnavailable
from creative_py.backends.ros.limits import OutOfBounds, goal_checker, urdf_forward
from creative_py.backends.ros.profile import RobotProfile
from creative_py.backends.ros.trajectory import GOAL_TOLERANCE_VIOLATED
from creative_py.simulator.paths import Unreachable, straight_line
from creative_py.simulator.types import SkillOutcome, Verdict

Pose = tuple[tuple[float, float, float], tuple[float, float, float, float]]

SPEED_MARGIN = 0.9
"""The learner times its trajectories at this fraction of the profile's joint speed."""

EASE_STEP = 0.05
"""Radians of the fastest joint between the points of an eased joint-space move."""


class Kinematics:
    """The robot's kinematics on the learner's side, from the profile's URDF (no scene).

    The pybullet backend's arm of the profile, in a pybullet DIRECT client of its own
    (:func:`creative_py.backends.ros.twin.kinematics_arm`),
    its base at ``base`` (the world's placement of the arm, ``[robot.NAME] base`` of a
    scene: position, quaternion; None: the profile's ``[base]``). Joint positions are
    in the profile's ``[arm]`` order.
    """

    def __init__(self, profile: RobotProfile, base=None) -> None:
        from creative_py.backends.ros.twin import kinematics_arm

        self.profile = profile
        self._sim, self._robot = kinematics_arm(profile, base)
        arm = profile.arm_joints
        self._to_arm = [profile.joints.index(n) for n in arm]
        self._to_profile = [arm.index(n) for n in profile.joints]
        self.forward_position = urdf_forward(profile, base)

    def ik(self, target: Pose, seed: Sequence[float]) -> Optional[list[float]]:
        """Return joint positions putting the gripper at ``target``, from ``seed``."""
        q = self._robot.solve_ik(target, seed=[seed[i] for i in self._to_arm])
        return None if q is None else [q[i] for i in self._to_profile]

    def forward(self, q: Sequence[float]) -> Pose:
        """Return the gripper's world pose at joint positions ``q``."""
        self._robot.reset_posture([q[i] for i in self._to_arm])
        return self._robot.gripper_pose()

    def close(self) -> None:
        """Release the kinematics' physics client."""
        self._robot.close()
        self._sim.close()


class LearnerArm:
    """An arm driven over ROS 2 by gripper poses, with IK and bounds on the learner's side.

    Parameters
    ----------
    client : ArmClient
        Connected to the arm (:meth:`ArmClient.wait_for_arm` done).
    kinematics : Kinematics
        From the profile's URDF.
    step : float
        Metres between the waypoints of a straight move.
    timeout : float
        Seconds a goal may take beyond its trajectory's duration.
    """

    def __init__(self, client: ArmClient, kinematics: Kinematics, step: float = 0.01,
                 timeout: float = 10.0) -> None:
        self.client, self.kin, self.profile = client, kinematics, client.profile
        self.step, self.timeout = step, timeout
        self.check = goal_checker(self.profile, client.arm_q, kinematics.forward_position)
        self.goals_sent = 0
        self.log: list[dict] = []
        """One entry per goal sent: its planned duration, status and the seconds from
        sending it to its acceptance, first feedback and result (``GoalTimes``)."""
        self.lost: Optional[ArmUnavailable] = None

    def _silent(self, why: str) -> SkillOutcome:
        """Note that the arm went silent; return the motion's ``invalid`` outcome."""
        self.lost = ArmUnavailable(why)
        return SkillOutcome("invalid", f"the arm went silent: {why}")

    def raise_if_lost(self) -> None:
        """Raise the :class:`ArmUnavailable` of a motion that found the arm silent (an
        episode calls it after a motion: the run then stops resumably)."""
        if self.lost is not None:
            raise self.lost

    def gripper_pose(self) -> Pose:
        """Return the gripper's pose by forward kinematics of the joint states."""
        return self.kin.forward(self.client.arm_q())

    def _timed(self, start: Sequence[float], path: Sequence[Sequence[float]],
               min_duration: float) -> list[tuple[float, list[float]]]:
        """Time the joint path: each segment at most the margin of the joint speed.

        The first segment is timed as if each joint had the profile's goal tolerance
        more to move: after a goal succeeded the arm may still settle that far (the
        controller judged it within the tolerance), and the bounds are checked from
        where the joint states say the arm is when the goal is sent."""
        speed = SPEED_MARGIN * self.profile.max_joint_speed
        t, prev, points = 0.0, list(start), []
        per = min_duration / max(1, len(path))
        slack = self.profile.goal_tolerance
        for q in path:
            move = max(abs(a - b) for a, b in zip(q, prev)) + slack
            slack = 0.0
            t += max(per, move / speed, 1e-3)
            points.append((t, list(q)))
            prev = list(q)
        return points

    def send_path(self, path: Sequence[Sequence[float]], min_duration: float = 0.0
                  ) -> SkillOutcome:
        """Send a joint path (profile order; waypoints planned from where the arm was),
        timed from where the joint states say the arm is now.

        The path was planned from an earlier reading (IK of its waypoints takes a
        while); the arm may have gone on settling after its last goal since. Timing
        from a fresh reading, just before the bounds check it, keeps the first
        segment within the joint speed the bounds hold it to."""
        try:
            start = self.client.arm_q()
        except ArmUnavailable as exc:
            return self._silent(str(exc))
        return self.send(self._timed(start, path, min_duration))

    def send(self, points: Sequence[tuple[float, Sequence[float]]]) -> SkillOutcome:
        """Send a trajectory (profile joint order) through the bounds; return its outcome."""
        goal = self.client.make_goal(points)
        try:
            self.check(goal)
        except OutOfBounds as exc:
            return SkillOutcome("unreachable", f"refused by the learner's bounds: {exc}")
        except ArmUnavailable as exc:
            return self._silent(str(exc))
        self.goals_sent += 1
        timeout = points[-1][0] + self.timeout
        r = self.client.send_trajectory(goal, timeout=timeout)
        self.log.append({"planned_s": points[-1][0], "points": len(points),
                         "status": r.status, "error_code": r.error_code,
                         **vars(r.times)})
        if r.status == "succeeded":
            return SkillOutcome("ok")
        if r.status == "aborted":
            fb = r.last_feedback
            lag = (max(abs(e) for e in fb.error.positions)
                   if fb is not None and len(fb.error.positions) else None)
            tol = (self.profile.goal_tolerance if r.error_code == GOAL_TOLERANCE_VIOLATED
                   else self.profile.path_tolerance)
            stop = Verdict("joint lag", lag, tol, "rad", "<=", False,
                           threshold_name=r.error_name.lower(),
                           measures={"error_code": r.error_code})
            return SkillOutcome("blocked", f"the arm aborted the goal ({r.error_name}): "
                                f"{r.error_string}", stop)
        if r.status == "silent":
            return self._silent(r.error_string)
        if r.status == "timeout" and r.times.accepted is not None:
            # Accepted, then no result in its time: the motion ran out of time, which
            # the trial loop judges as every backend's (simulator/trial.py).
            stop = Verdict("time without the goal's result", timeout, timeout, "s", "<",
                           False, threshold_name="the trajectory's duration + the timeout",
                           measures={"planned_s": points[-1][0], "timeout_s": self.timeout})
            return SkillOutcome("out_of_time", f"the arm's goal ran out of time: "
                                f"{r.error_string}", stop)
        return SkillOutcome("invalid", f"the goal was {r.status}: {r.error_string}")

    def move_joints(self, q: Sequence[float], min_duration: float = 0.0) -> SkillOutcome:
        """Move to joint positions ``q`` (profile order) in joint space, easing in and out.

        A single segment would ask the arm to be at full speed at once: the controller
        interpolates linearly from where the arm is, and an arm under load lags that
        step past the path tolerance (seen on the stand-in carrying a tool). The move
        is cut into points on a half-cosine of time (at rest at both ends, at most the
        margin of the joint speed in the middle: ``pi / 2`` times the average)."""
        try:
            start = self.client.arm_q()
        except ArmUnavailable as exc:
            return self._silent(str(exc))
        move = max((abs(a - b) for a, b in zip(q, start)), default=0.0)
        speed = SPEED_MARGIN * self.profile.max_joint_speed
        k = max(1, math.ceil(move / EASE_STEP))
        path = [[a + (1 - math.cos(math.pi * i / k)) / 2 * (b - a) for a, b in zip(start, q)]
                for i in range(1, k + 1)]
        return self.send_path(path, max(min_duration, math.pi / 2 * move / speed))

    def move_to(self, target: Pose, speed: float = 0.1) -> SkillOutcome:
        """Move the gripper in a straight line to ``target`` at most at ``speed`` m/s, the
        orientation slerped (the waypoints of
        :func:`creative_py.simulator.paths.straight_line`, every ``step`` m)."""

        try:
            start = self.client.arm_q()
        except ArmUnavailable as exc:
            return self._silent(str(exc))
        here = self.kin.forward(start)
        dist = math.dist(here[0], target[0])
        n = max(1, math.ceil(dist / self.step))
        try:
            path = [q for _, _, q in straight_line(self.kin.ik, here, target, n, start)]
        except Unreachable as exc:
            return exc.outcome
        return self.send_path(path, dist / speed)

    def grip(self, close: bool) -> SkillOutcome:
        """Close or open the gripper; ``ok`` when it answered (``holding`` says more)."""
        r = self.client.grip(close)
        if r is None:
            try:
                self.client.check_fresh()
            except ArmUnavailable as exc:
                return self._silent(str(exc))
            return SkillOutcome("invalid", f"the gripper {self.profile.gripper_action!r} did "
                                "not answer")
        self.holding = bool(close and r.stalled and not r.reached_goal)
        return SkillOutcome("ok")
