"""The stand-in robot: the pybullet arm of a robot profile with a case's scene, in its own process, behind
exactly the ROS 2 interface a lab's arm offers.

    python -m creative_py.backends.ros.standin --case hook [--variant V] [--location N]
        [--tool NAME] [--profile NAME|PATH.toml] [--seconds S] [--realtime F]

It publishes, with the names of the robot profile (:mod:`.profile`):

* ``sensor_msgs/JointState`` of the arm's joints (and the gripper's gap) at the
  profile's rate;
* ``geometry_msgs/WrenchStamped`` of a wrist force/torque sensor (the profile's
  ``[wrench]``): the contact force on the held tool and its torque about the gripper,
  in the gripper frame, tared, with the joint states, each message the mean over the
  physics steps since the last (a sensor's anti-aliasing filter: a one-step contact
  pulse counts by its impulse, not by the step it fell on);
* ``geometry_msgs/PoseStamped`` of each tracked object of the scene (the case's
  perceived objects, its context and the tool) on its own topic, in the world frame,
  as a motion-capture system publishes rigid bodies;

and serves:

* ``control_msgs/action/FollowJointTrajectory``: the trajectory is executed in the
  physics by the arm's position motors and judged as ros2_control's joint trajectory
  controller judges it (:mod:`.trajectory`): a goal with unknown joints, no points,
  times that do not increase or positions outside the joint limits is rejected; path
  tolerance (a collision makes the arm lag), goal tolerance and goal time tolerance
  abort it with PATH_TOLERANCE_VIOLATED or GOAL_TOLERANCE_VIOLATED; feedback (desired,
  actual, error, index) comes at the joint states' rate; cancelling holds the arm
  where it is;
* ``control_msgs/action/GripperCommand``: a gap at or below the middle of the open and
  closed gaps closes the gripper, above it opens it. The stand-in does not simulate
  fingers: closing holds the tool if the gripper is within ``--grasp-reach`` of where
  the tool's kind is held, with the kind's grasp (a fixed joint that pulls the tool
  into place, exactly as the pybullet backend's grasp holds it: the approach may
  push the tool a few centimetres), and
  the result says so (``stalled`` true, ``reached_goal`` false: the fingers stopped on
  the tool); its reported gap while holding is the middle of the open and closed gaps.

It also answers the trainer's scene requests (``std_msgs/String`` JSON on the profile's
``[trainer]`` topics, :mod:`.trainer`): it rebuilds its scene for the requested variant,
location and tool (a created tool from the request's spec and URDF) in its physics loop,
aborting a running goal, and answers with the request's id.

Physics time runs at ``--realtime`` times the wall clock (1: as fast as a real arm), or
slower where the machine cannot keep up (a lag of up to 0.25 s is caught up, a longer
one is dropped, and a warning gives the real-time factor every 5 s: :class:`Pace`).
The physics time is published as ``rosgraph_msgs/Clock`` on the profile's clock topic
(``/clock``), as Gazebo does; the messages' stamps are that simulated time when the
profile's ``[clock] use_sim_time`` is true, else the node's wall clock. A trajectory's
times are physics time. SIGUSR1 stops the joint states (the clock and everything else
go on) and a second SIGUSR1 resumes them: the fault tests' arm that is alive but
silent. The first line on the standard
output is ``standin ready`` followed by the interface's names as JSON. It stops on
SIGINT/SIGTERM or after ``--seconds``. Bad input: one line naming the option or the
file and field, exit 2.

This module is also a template for a real arm's driver: replace :class:`SimArm`.
"""

from __future__ import annotations

import argparse
import json
import math
import signal
import sys
import threading
import time
from dataclasses import dataclass, field, replace
from typing import Any, Optional, Sequence

import numpy as np
from scipy.spatial.transform import Rotation

from creative_py.backends.ros.profile import RobotProfile, load_profile
from creative_py.backends.ros.trajectory import (INVALID_GOAL, SUCCESSFUL, InvalidTrajectory,
                                                 GoalResult, TrajectoryRun)
from creative_py.world_files import WorldFileError

Pose = tuple[tuple[float, float, float], tuple[float, float, float, float]]


def compose(a: Pose, b: Pose) -> Pose:
    """Return the pose ``a * b`` (b given in a's frame); quaternions x, y, z, w."""
    ra = Rotation.from_quat(a[1])
    pos = np.asarray(a[0]) + ra.apply(b[0])
    return tuple(float(v) for v in pos), tuple(float(v) for v in (ra * Rotation.from_quat(b[1])).as_quat())


def invert(a: Pose) -> Pose:
    """Return the inverse of the pose ``a``."""
    r = Rotation.from_quat(a[1]).inv()
    return (tuple(float(v) for v in -r.apply(a[0])), tuple(float(v) for v in r.as_quat()))


class SimArm:
    """The pybullet arm of an open episode, seen as a lab's arm (no ROS here).

    Parameters
    ----------
    episode : creative_py.backends.pybullet.Episode
        An episode opened with the robot.
    profile : RobotProfile
        The profile the episode's arm was built from (its ``arm.joints`` in any order).
    grasp_reach : float
        How far (m) the gripper may be from where the tool's kind is held for a
        closing gripper to hold the tool.
    """

    def __init__(self, episode: Any, profile: RobotProfile, grasp_reach: float = 0.06) -> None:
        self.ep, self.profile, self.reach = episode, profile, grasp_reach
        self.robot = episode.robot
        arm = self.robot.profile.arm_joints
        if sorted(profile.joints) != sorted(arm):
            raise WorldFileError(f"{profile.source}: field 'arm.joints': the stand-in's arm has "
                                 f"the joints {list(arm)}, got {list(profile.joints)}")
        self.order = [arm.index(n) for n in profile.joints]
        m = self.robot.model
        self.lower = [float(m.arm_lower[i]) for i in self.order]
        self.upper = [float(m.arm_upper[i]) for i in self.order]
        self.time_step = episode.sim.physics.time_step
        names = [n for n, _ in episode.perceived] + [episode.context_name, episode.tool]
        self.tracked = list(dict.fromkeys(names))
        self.closed = False
        self.wrench: tuple = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))  # the last step's
        self._wrench_sum, self._wrench_steps = np.zeros(6), 0
        self.offset = 0.0  # s: the arm's time minus the episode's (scenes rebuilt before)

    def rebind(self, episode: Any) -> None:
        """Take over a newly built scene (the trainer's answer to a scene request); the
        arm's time goes on from where it was (the clock and the stamps never go back)."""
        before = self.time()
        self.__init__(episode, self.profile, self.reach)
        self.offset = before - episode.sim_time()

    def q(self) -> list[float]:
        """Return the arm's joint positions (rad), in the profile's order."""
        q = self.robot.arm_q()
        return [float(q[i]) for i in self.order]

    def command(self, q: Sequence[float]) -> None:
        """Set the position motors' targets (rad, profile order)."""
        full = [0.0] * len(q)
        for k, i in enumerate(self.order):
            full[i] = float(q[k])
        self.robot._command(full)

    def step(self) -> float:
        """Advance the physics one time step; return the simulated time (s)."""
        self.ep.sim.step(1)
        if self.profile.wrench_topic:
            self.wrench = self.measure_wrench()
            self._wrench_sum += np.concatenate(self.wrench)
            self._wrench_steps += 1
        return self.time()

    def take_wrench(self) -> tuple:
        """Return the mean wrench (force, torque; gripper frame) over the physics steps
        since the last call, what the sensor publishes now, and start the next mean."""
        mean = self._wrench_sum / max(1, self._wrench_steps)
        self._wrench_sum, self._wrench_steps = np.zeros(6), 0
        return (tuple(float(v) for v in mean[:3]), tuple(float(v) for v in mean[3:]))

    def measure_wrench(self) -> tuple:
        """Return what a wrist force/torque sensor measures now, tared: the contact
        force on the held tool and its torque about the gripper, in the gripper frame
        (zero when nothing is held)."""
        if not self.holding:
            return ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
        from creative_py.backends.pybullet.loads import contact_wrench

        g_pos, g_quat = self.robot.gripper_pose()
        force, torque = contact_wrench(self.ep.sim, self.ep.tool_body, g_pos)
        inv = Rotation.from_quat(g_quat).inv()
        return (tuple(float(v) for v in inv.apply(force)),
                tuple(float(v) for v in inv.apply(torque)))

    def time(self) -> float:
        """Return the simulated time (s), across the scenes built so far."""
        return self.ep.sim_time() + self.offset

    def poses(self) -> dict[str, Pose]:
        """Return the world pose of each tracked object's own frame."""
        from creative_py.backends.pybullet.bodies import frame_pose

        return {n: frame_pose(self.ep.sim, self.ep.body_id(n)) for n in self.tracked}

    @property
    def holding(self) -> bool:
        """Return whether the gripper holds the tool."""
        return self.robot.held is not None

    def gap(self) -> float:
        """Return the gripper's gap (m) as the profile measures it."""
        p = self.profile
        if not self.closed:
            return p.gripper_open
        return (p.gripper_open + p.gripper_closed) / 2 if self.holding else p.gripper_closed

    def grip(self, close: bool) -> bool:
        """Close or open the gripper; return whether it then holds the tool."""
        ep, robot = self.ep, self.robot
        self.closed = close
        if not close:
            robot.release()
            ep.held = False
            return False
        if self.holding:
            return True
        from creative_py.backends.pybullet.bodies import frame_pose

        gripper = robot.gripper_pose()
        tool = frame_pose(ep.sim, ep.tool_body)
        where = compose(tool, invert(ep.grasp))  # the gripper as the tool's kind holds it
        if math.dist(gripper[0], where[0]) > self.reach:
            return False
        robot.grasp(ep.tool_body, ep.grasp)  # as the pybullet backend's grasp holds it
        ep.held = True
        return True


@dataclass
class Job:
    """A goal handed from an action server's thread to the physics loop."""

    handle: Any
    kind: str                      # "trajectory" or "gripper"
    request: Any
    done: threading.Event = field(default_factory=threading.Event)
    result: Any = None
    run: Optional[TrajectoryRun] = None
    t0: float = 0.0


def _duration(d: Any) -> float:
    return d.sec + d.nanosec * 1e-9


def _trajectory_run(goal: Any, arm: SimArm, start: Sequence[float]) -> TrajectoryRun:
    """Return the run of a FollowJointTrajectory goal from ``start`` (raises InvalidTrajectory)."""
    p = arm.profile
    traj = goal.trajectory
    if goal.multi_dof_trajectory.points:
        raise InvalidTrajectory(INVALID_GOAL, "multi-DOF trajectories are not supported")
    points = [(_duration(pt.time_from_start), list(pt.positions)) for pt in traj.points]
    return TrajectoryRun(p.joints, start, list(traj.joint_names), points, arm.lower, arm.upper,
                         {t.name: t.position for t in goal.path_tolerance},
                         {t.name: t.position for t in goal.goal_tolerance},
                         _duration(goal.goal_time_tolerance), p.path_tolerance,
                         p.goal_tolerance, p.goal_time_tolerance)


def _sim_stamp(t: float) -> Any:
    """Return physics time ``t`` (s) as a ``builtin_interfaces/Time``."""
    from builtin_interfaces.msg import Time

    sec = int(t)
    return Time(sec=sec, nanosec=min(999_999_999, int(round((t - sec) * 1e9))))


class Pace:
    """Keeps physics time at ``realtime`` times the wall clock, and says when it cannot.

    :meth:`wait` is called once a publication period (not every physics step: each
    sleep is a wake-up the scheduler may serve late on a loaded machine, and the GIL
    must be won back after it). A lag behind the wall clock is caught up, by stepping
    without sleeping, up to :attr:`CATCH_UP` s; a longer one is dropped (the physics
    never races to make up for a stall). Every :attr:`REPORT_EVERY` s of wall time the
    real-time factor of that window is measured (:attr:`factor`) and a warning is
    logged when it is below 0.9 of ``realtime``.
    """

    CATCH_UP = 0.25
    REPORT_EVERY = 5.0

    def __init__(self, realtime: float, sim0: float, logger: Any = None,
                 clock=time.monotonic, sleep=time.sleep) -> None:
        self.realtime, self.logger, self.clock, self.sleep = realtime, logger, clock, sleep
        self.wall0 = self.win_wall = clock()
        self.sim0 = self.win_sim = sim0
        self.factor: Optional[float] = None
        self.dropped = 0.0  # wall seconds of lag dropped

    def wait(self, now: float) -> None:
        """Sleep until the wall clock reaches physics time ``now`` (s)."""
        wall = self.clock()
        ahead = self.wall0 + (now - self.sim0) / self.realtime - wall
        if ahead > 0:
            self.sleep(ahead)
        elif ahead < -self.CATCH_UP:
            self.dropped -= ahead
            self.wall0, self.sim0 = wall, now
        span = wall - self.win_wall
        if span >= self.REPORT_EVERY:
            self.factor = (now - self.win_sim) / span
            if self.factor < 0.9 * self.realtime and self.logger is not None:
                self.logger.warning(f"physics ran at {self.factor:.2f} x real time over the "
                                    f"last {span:.1f} s: this machine cannot keep up (the "
                                    "simulated time is on the clock topic)")
            self.win_wall, self.win_sim = wall, now


class StandinNode:
    """The stand-in's ROS 2 node around a :class:`SimArm`: its action servers, publishers
    and the trainer's subscription, the goals handed to the physics loop, and one
    method for each thing the loop does (``rclpy`` must be initialised first).

    The action servers' callbacks run on the executor's threads; every other method runs
    in the physics loop (:func:`serve`), which alone touches the arm.

    Parameters
    ----------
    arm : SimArm
        The simulated arm, with its profile's names.
    stop, muted : threading.Event
        Set when the stand-in stops; set while the joint states are silent (SIGUSR1).
    scenes : creative_py.backends.ros.trainer.SceneKeeper, optional
        With it, the trainer's scene requests are answered.
    """

    def __init__(self, arm: SimArm, stop: threading.Event, muted: threading.Event,
                 scenes: Any = None) -> None:
        from rclpy.action import ActionServer, CancelResponse
        from rclpy.callback_groups import ReentrantCallbackGroup
        from rclpy.node import Node

        from control_msgs.action import FollowJointTrajectory, GripperCommand
        from geometry_msgs.msg import PoseStamped
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import JointState

        p = self.profile = arm.profile
        self.arm, self.stop, self.muted, self.scenes = arm, stop, muted, scenes
        node = self.node = Node("creative_standin")
        group = ReentrantCallbackGroup()
        self.lock = threading.Lock()
        self.jobs: list[Job] = []  # goals accepted, not yet taken by the physics loop
        self.latest_q = arm.q()  # the arm's last positions, read by the goal check
        ActionServer(node, FollowJointTrajectory, p.arm_action,
                     execute_callback=lambda handle: self.execute(handle, "trajectory"),
                     goal_callback=self.on_trajectory,
                     cancel_callback=lambda _: CancelResponse.ACCEPT, callback_group=group)
        ActionServer(node, GripperCommand, p.gripper_action,
                     execute_callback=lambda handle: self.execute(handle, "gripper"),
                     cancel_callback=lambda _: CancelResponse.REJECT, callback_group=group)
        self.js_pub = node.create_publisher(JointState, p.joint_states_topic, 10)
        self.clock_pub = node.create_publisher(Clock, p.clock_topic, 10)
        self.pose_pubs = {n: node.create_publisher(PoseStamped, p.object_topic_of(n), 10)
                          for n in arm.tracked}
        self.wrench_pub = None
        if p.wrench_topic:
            from geometry_msgs.msg import WrenchStamped

            self.wrench_pub = node.create_publisher(WrenchStamped, p.wrench_topic, 10)
        self.trainer_done = None
        if scenes is not None:
            from std_msgs.msg import String

            node.create_subscription(String, p.trainer_request_topic,
                                     lambda m: scenes.requests.put(m.data), 10,
                                     callback_group=group)
            self.trainer_done = node.create_publisher(String, p.trainer_done_topic, 10)
        # The physics loop's state.
        self.js_period, self.pose_period = 1.0 / p.joint_states_rate_hz, 1.0 / p.object_rate_hz
        self.active: Optional[Job] = None  # the trajectory being executed
        self.hold = arm.q()  # the posture held between trajectories
        self.next_js = self.next_pose = arm.time()
        self.last_fb = -math.inf
        self.prev_q, self.prev_t = arm.q(), arm.time()

    def interface(self) -> dict:
        """Return the interface's names, as the ready line gives them."""
        p, arm = self.profile, self.arm
        interface = {"joint_states": p.joint_states_topic, "trajectory_action": p.arm_action,
                     "gripper_action": p.gripper_action, "joints": list(p.joints),
                     "objects": {n: p.object_topic_of(n) for n in arm.tracked},
                     "frame": p.world_frame, "clock": p.clock_topic,
                     "use_sim_time": p.use_sim_time}
        if self.scenes is not None:
            interface["trainer"] = {"request": p.trainer_request_topic,
                                    "done": p.trainer_done_topic}
        if self.wrench_pub is not None:
            interface["wrench"] = p.wrench_topic
        return interface

    # The action servers' threads.

    def on_trajectory(self, goal: Any) -> Any:
        """Accept a FollowJointTrajectory goal, or reject it (logged) as the controller
        would from the arm's last positions."""
        from rclpy.action import GoalResponse

        try:
            _trajectory_run(goal, self.arm, list(self.latest_q))
        except InvalidTrajectory as exc:
            self.node.get_logger().warning(f"rejected a trajectory: {exc}")
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def execute(self, handle: Any, kind: str) -> Any:
        """Hand an accepted goal (``kind`` "trajectory" or "gripper") to the physics loop
        and wait for its result; end it here if the stand-in stops first."""
        job = Job(handle, kind, handle.request)
        with self.lock:
            self.jobs.append(job)  # the physics loop takes it at its next step
        while not job.done.wait(0.05):
            if self.stop.is_set():  # the loop ends: it may still finish the job itself
                self.settle(job, INVALID_GOAL, "the stand-in stopped", None)
        return job.result

    def settle(self, job: Job, code: int, message: str, succeeded: Optional[bool]) -> None:
        """End a job once, whichever thread comes first (the physics loop, or the
        action server's thread when the stand-in stops): succeed or abort its goal
        (``succeeded`` None: abort), set its result, wake its thread. A goal the client
        already ended (cancelled while the stand-in was stopped) is only logged."""
        with self.lock:
            if job.done.is_set():
                return
            job.result = self.result_of(job.kind, SUCCESSFUL if job.kind == "gripper" else code,
                                     message)
            try:
                (job.handle.succeed if succeeded else job.handle.abort)()
            except Exception as exc:  # rclpy refuses a transition from a terminal state
                self.node.get_logger().warning(f"goal ended as {message!r}: {exc}")
            job.done.set()

    def result_of(self, kind: str, code: int, message: str) -> Any:
        """Return the action's result: the gripper's gap, or a trajectory's error code
        and string."""
        from control_msgs.action import FollowJointTrajectory, GripperCommand

        if kind == "gripper":
            r = GripperCommand.Result()
            r.position, r.effort = self.arm.gap(), 0.0
            return r
        r = FollowJointTrajectory.Result()
        r.error_code, r.error_string = code, message
        return r

    # The physics loop, in the order serve calls them.

    def answer_scene_request(self) -> None:
        """Answer the trainer's next scene request, if any (trainer.py): rebuild the
        scene here, in the physics loop, aborting the running goal; the arm's time goes
        on from where it was (SimArm.rebind)."""
        scenes, arm = self.scenes, self.arm
        if scenes is None or scenes.requests.empty():
            return
        rid, error, episode = scenes.apply(scenes.requests.get())
        if episode is not None:
            if self.active is not None:
                self.settle(self.active, INVALID_GOAL, "the trainer reset the scene", False)
                self.active = None
            arm.rebind(episode)
            from geometry_msgs.msg import PoseStamped

            for name in arm.tracked:
                if name not in self.pose_pubs:
                    self.pose_pubs[name] = self.node.create_publisher(
                        PoseStamped, self.profile.object_topic_of(name), 10)
            self.hold = arm.q()
            self.prev_q = self.hold
            self.latest_q = self.hold
        if rid is not None:
            from std_msgs.msg import String

            self.trainer_done.publish(String(data=json.dumps(
                {"id": rid, "ok": error is None, "error": error or ""})))
        if error is not None:
            self.node.get_logger().warning(f"scene request {rid}: {error}")

    def take_jobs(self) -> list[Job]:
        """Return the goals handed over since the last call, oldest first."""
        if not self.jobs:
            return []
        with self.lock:
            pending, self.jobs[:] = list(self.jobs), []
        return pending

    def run_gripper(self, job: Job) -> None:
        """Close or open the gripper at once; its feedback and result say whether it
        holds the tool (stalled on it)."""
        from control_msgs.action import GripperCommand

        p, arm = self.profile, self.arm
        close = job.request.command.position <= (p.gripper_open + p.gripper_closed) / 2
        holds = arm.grip(close)
        r = GripperCommand.Result()
        r.position = arm.gap()
        r.effort = job.request.command.max_effort if holds else 0.0
        r.stalled, r.reached_goal = holds, not holds
        fb = GripperCommand.Feedback()
        fb.position, fb.effort, fb.stalled, fb.reached_goal = (
            r.position, r.effort, r.stalled, r.reached_goal)
        job.handle.publish_feedback(fb)
        with self.lock:
            if not job.done.is_set():  # not ended by a stop meanwhile
                job.handle.succeed()
                job.result = r
                job.done.set()

    def start_trajectory(self, job: Job) -> None:
        """Make a trajectory goal the active one from the arm's positions now,
        preempting the active one (aborted if it has become invalid)."""
        if self.active is not None:
            self.settle(self.active, INVALID_GOAL, "preempted by a newer goal", False)
        try:
            job.run = _trajectory_run(job.request, self.arm, self.arm.q())
        except InvalidTrajectory as exc:  # the arm moved since the goal was accepted
            self.settle(job, exc.code, str(exc), False)
            return
        job.t0, self.active = self.arm.time(), job

    def command_trajectory(self) -> None:
        """Set the motors to the active trajectory's desired positions now, if any."""
        if self.active is not None:
            t = self.arm.time() - self.active.t0
            desired, index = self.active.run.desired(t)
            self.arm.command(desired)

    def advance_trajectory(self, now: float, q: list[float]) -> None:
        """Judge the active trajectory at physics time ``now`` and positions ``q``, after a
        physics step: end it if cancelled, else send feedback at the joint states'
        rate and end it when judged."""
        active = self.active
        if active is None:
            return
        if active.handle.is_cancel_requested:
            with self.lock:
                if not active.done.is_set():
                    active.handle.canceled()
                    active.result = self.result_of("trajectory", SUCCESSFUL, "canceled")
                    active.done.set()
            self.hold, self.active = q, None
            self.arm.command(self.hold)
            return
        t = now - active.t0
        result = active.run.judge(t, q)
        if now - self.last_fb >= self.js_period or result is not None:
            self.last_fb = now
            self.trajectory_feedback(now, t, q)
        if result is not None:
            self.finish_trajectory(result, q)

    def trajectory_feedback(self, now: float, t: float, q: list[float]) -> None:
        """Publish the active trajectory's feedback: desired, actual, error, index at
        ``t`` s into it."""
        from control_msgs.action import FollowJointTrajectory

        desired, index = self.active.run.desired(t)
        fb = FollowJointTrajectory.Feedback()
        fb.header.stamp = self.stamp(now)
        fb.joint_names = list(self.profile.joints)
        fb.desired.positions = desired
        fb.actual.positions = q
        fb.error.positions = [d - a for d, a in zip(desired, q)]
        fb.index = index
        self.active.handle.publish_feedback(fb)

    def finish_trajectory(self, result: GoalResult, q: list[float]) -> None:
        """End the active trajectory as judged: succeeded, holding its last point, or
        aborted, stopping where it is (as a controller does on an abort)."""
        ok = result.code == SUCCESSFUL
        if not ok:
            self.hold = q
            self.arm.command(self.hold)
        else:
            self.hold = self.active.run.targets[-1]
        self.settle(self.active, result.code, result.message, ok)
        self.active = None

    def stamp(self, now: float) -> Any:
        """The header stamp of a message about physics time ``now``: that simulated time
        when the profile says use_sim_time (as Gazebo stamps), else the wall clock."""
        if self.profile.use_sim_time:
            return _sim_stamp(now)
        return self.node.get_clock().now().to_msg()

    def publish_states(self, now: float, q: list[float]) -> None:
        """Publish the clock, and (unless muted) the joint states with the velocities
        since the last and the wrench; schedule the next."""
        from rosgraph_msgs.msg import Clock
        from sensor_msgs.msg import JointState

        p, arm = self.profile, self.arm
        clock_msg = Clock()
        clock_msg.clock = _sim_stamp(now)
        self.clock_pub.publish(clock_msg)
        if not self.muted.is_set():
            msg = JointState()
            msg.header.stamp = self.stamp(now)
            msg.name = [*p.joints, p.gripper_joint]
            msg.position = [*q, arm.gap()]
            dt = now - self.prev_t
            msg.velocity = ([*((a - b) / dt for a, b in zip(q, self.prev_q)), 0.0]
                            if dt > 0 else [])
            self.js_pub.publish(msg)
            if self.wrench_pub is not None:
                self.publish_wrench(msg.header.stamp)
        self.prev_q, self.prev_t = q, now
        self.next_js = max(self.next_js + self.js_period, now)

    def publish_wrench(self, stamp: Any) -> None:
        """Publish the wrist sensor's mean wrench since the last, with the joint states'
        ``stamp``."""
        from geometry_msgs.msg import WrenchStamped

        w = WrenchStamped()
        w.header.stamp, w.header.frame_id = stamp, self.profile.wrench_frame
        force, torque = self.arm.take_wrench()
        (w.wrench.force.x, w.wrench.force.y, w.wrench.force.z) = force
        (w.wrench.torque.x, w.wrench.torque.y, w.wrench.torque.z) = torque
        self.wrench_pub.publish(w)

    def publish_poses(self, now: float) -> None:
        """Publish each tracked object's pose when its period is due; schedule the next."""
        if now < self.next_pose:
            return
        from geometry_msgs.msg import PoseStamped

        pose_stamp = self.stamp(now)
        for name, (pos, quat) in self.arm.poses().items():
            msg = PoseStamped()
            msg.header.stamp, msg.header.frame_id = pose_stamp, self.profile.world_frame
            msg.pose.position.x, msg.pose.position.y, msg.pose.position.z = pos
            (msg.pose.orientation.x, msg.pose.orientation.y, msg.pose.orientation.z,
             msg.pose.orientation.w) = quat
            self.pose_pubs[name].publish(msg)
        self.next_pose = max(self.next_pose + self.pose_period, now)

    def abort_jobs(self) -> None:
        """Abort the active goal and those not yet taken: the stand-in stopped."""
        for job in [*([self.active] if self.active is not None else []), *self.jobs]:
            self.settle(job, INVALID_GOAL, "the stand-in stopped", False)


def _stop_signals() -> tuple[threading.Event, threading.Event]:
    """Return the events that SIGINT/SIGTERM set (stop) and SIGUSR1 toggles (mute the
    joint states: a live arm whose joint states stop)."""
    stop, muted = threading.Event(), threading.Event()
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda *_: stop.set())
    signal.signal(signal.SIGUSR1,
                  lambda *_: muted.clear() if muted.is_set() else muted.set())
    return stop, muted


def _spin(node: Any) -> tuple[Any, threading.Thread]:
    """Spin ``node`` on a multi-threaded executor in a daemon thread; return both."""
    from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor

    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)

    def spin() -> None:
        try:
            executor.spin()
        except ExternalShutdownException:
            pass

    spinner = threading.Thread(target=spin, daemon=True)
    spinner.start()
    return executor, spinner


def serve(arm: SimArm, realtime: float = 1.0, seconds: float = math.inf,
          out=sys.stdout, scenes: Any = None) -> int:
    """Run the stand-in's node until SIGINT/SIGTERM or ``seconds``; return 0.

    With ``scenes`` (a :class:`~creative_py.backends.ros.trainer.SceneKeeper`) it also
    answers the trainer's scene requests: the scene is rebuilt in the physics loop.
    """
    import rclpy
    from rclpy.signals import SignalHandlerOptions

    stop, muted = _stop_signals()
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)  # ours stop the loop
    standin = StandinNode(arm, stop, muted, scenes)
    executor, spinner = _spin(standin.node)
    print("standin ready " + json.dumps(standin.interface()), file=out, flush=True)
    pace = Pace(realtime, arm.time(), standin.node.get_logger())
    deadline = time.monotonic() + seconds
    while not stop.is_set() and time.monotonic() < deadline:
        standin.answer_scene_request()
        for job in standin.take_jobs():
            if job.kind == "gripper":
                standin.run_gripper(job)
            else:
                standin.start_trajectory(job)
        standin.command_trajectory()
        now = arm.step()
        q = arm.q()
        standin.advance_trajectory(now, q)
        standin.latest_q = q  # one reference swapped: atomic under the GIL
        if now < standin.next_js:
            continue  # the physics runs ahead, at most one publication period
        standin.publish_states(now, q)
        standin.publish_poses(now)
        pace.wait(now)  # once a publication period: wall time catches up with physics
    stop.set()
    standin.abort_jobs()
    executor.shutdown(timeout_sec=2.0)
    spinner.join(timeout=2.0)
    standin.node.destroy_node()
    rclpy.try_shutdown()
    return 0


def _parser() -> argparse.ArgumentParser:
    ap = argparse.ArgumentParser(prog="python -m creative_py.backends.ros.standin",
                                 description="The pybullet arm of a robot profile with a case's scene behind "
                                             "a lab arm's ROS 2 interface.")
    ap.add_argument("--case", required=True, help="the case id (creative cases)")
    ap.add_argument("--variant", help="a variant of the case (default: the demonstration's)")
    ap.add_argument("--location", type=int, help="1-based target location (default: the "
                                                 "demonstration's)")
    ap.add_argument("--tool", help="the catalogued tool in the scene (default: the "
                                   "demonstration's)")
    ap.add_argument("--profile", default=None, help="robot profile: a name under robots/ "
                                                     "or a .toml path (default: the case's robot)")
    ap.add_argument("--seconds", type=float, default=math.inf,
                    help="stop after this many seconds (default: run until stopped)")
    ap.add_argument("--realtime", type=float, default=1.0,
                    help="physics time per wall-clock time (default 1)")
    ap.add_argument("--grasp-reach", type=float, default=0.06,
                    help="m: how close the gripper must be to the tool's grasp to hold it")
    return ap


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the stand-in; return the exit code (2 on bad input, one line on stderr)."""
    args = _parser().parse_args(argv)
    prog = "creative_py.backends.ros.standin"
    for name, value, low, high in (("--realtime", args.realtime, 0.01, 100.0),
                                   ("--grasp-reach", args.grasp_reach, 0.0, 1.0)):
        if not low <= value <= high:
            print(f"{prog}: option {name}: must be in [{low}, {high}], got {value}",
                  file=sys.stderr)
            return 2
    if not args.seconds > 0:
        print(f"{prog}: option --seconds: must be > 0, got {args.seconds}", file=sys.stderr)
        return 2
    from creative_py.backends.pybullet import open_episode
    from creative_py.world.read import load_world
    from creative_py.case import get_case

    try:  # every input is checked before ROS or the physics start
        manifest = get_case(args.case)
        if manifest.backend != "pybullet":
            raise WorldFileError(f"option --case: {args.case} runs in the {manifest.backend!r} "
                                 "backend; the stand-in builds pybullet scenes")
        profile = load_profile(args.profile or manifest.robot or "")
        manifest = replace(manifest, robot=profile.source)  # the scene's arm is the profile's
        demo = manifest.demonstration
        variant = args.variant or demo.variant
        location = demo.location if args.location is None else args.location
        tool = args.tool or demo.tool
        variants = [v.name for v in manifest.variants]
        if variant not in variants:
            raise WorldFileError(f"option --variant: {variant!r} is not a variant of "
                                 f"{args.case} ({', '.join(variants)})")
        world = load_world(manifest)
        if location not in world.locations:
            raise WorldFileError(f"option --location: {location} is not a location of "
                                 f"{args.case} ({', '.join(map(str, world.locations))})")
        world.item(tool)
    except (WorldFileError, KeyError) as exc:
        msg = exc.args[0] if isinstance(exc, KeyError) and exc.args else exc
        print(f"{prog}: {msg}", file=sys.stderr)
        return 2
    try:
        import rclpy  # noqa: F401
        from control_msgs.action import FollowJointTrajectory  # noqa: F401
    except ImportError as exc:
        print(f"{prog}: {exc.name or 'rclpy'} is not installed: run make setup-ros "
              "(docs/real-robot.md)", file=sys.stderr)
        return 2
    from creative_py.backends.ros.trainer import SceneKeeper

    scenes = SceneKeeper(world, open_episode)
    try:
        ep = scenes.open(variant, location, tool)
        arm = SimArm(ep, profile, args.grasp_reach)
        return serve(arm, args.realtime, args.seconds, scenes=scenes)
    except WorldFileError as exc:
        print(f"{prog}: {exc}", file=sys.stderr)
        return 2
    finally:
        scenes.close()


if __name__ == "__main__":
    sys.exit(main())
