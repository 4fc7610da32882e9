"""The learner's side of the ROS 2 interface: an arm observed by subscribing and moved by
trajectory and gripper goals, with the names of a robot profile.

:class:`ArmClient` owns one rclpy node spun in a background thread. It keeps the latest
``JointState`` and each tracked object's ``PoseStamped``, and sends
``FollowJointTrajectory`` and ``GripperCommand`` goals, waiting for their results with a
bound; every goal's messages are timed (:class:`GoalTimes`). A trajectory goes through
:func:`creative_py.backends.ros.limits.check_trajectory` first: one outside the
profile's speed or workspace bounds raises :class:`~.limits.OutOfBounds` and is never
sent.

**Whose clock.** With the profile's ``[clock] use_sim_time`` (a simulated arm: the
stand-in, Gazebo), the client follows ``rosgraph_msgs/Clock`` on the clock topic, as a
ROS node with ``use_sim_time`` does: the joint states' age is the clock minus their
stamp, and a goal's timeout counts simulated seconds, so an arm simulated slower than
real time on a loaded machine is neither stale nor late. A clock that stops for
``silent_after_s`` of wall-clock time means the simulator died or froze. Without it
(a real arm) ages and timeouts are wall-clock seconds.

**An arm that goes silent** (its joint states stale, or its clock stopped) while a goal
or a gripper command is waited for ends the wait at once: status ``silent``, naming
what stopped, instead of waiting for the goal's whole timeout.

Needs the ``ros`` extra (``make setup-ros``); rclpy is imported when a client is made.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Optional, Sequence

from creative_py.backends.ros.profile import RobotProfile
from creative_py.backends.ros.trajectory import ERROR_NAMES
from creative_py.simulator.types import BackendLost


def discovery_warning(env: Mapping[str, str]) -> Optional[str]:
    """Return a warning when ROS 2 discovery reaches beyond this host while DDS Security
    is off (None otherwise): then any machine on the network, on the same domain id, can
    see the arm's topics and send it goals.

    Discovery reaches beyond the host unless ``ROS_AUTOMATIC_DISCOVERY_RANGE`` is
    ``LOCALHOST`` or ``OFF`` (unset, ``SUBNET`` and ``SYSTEM_DEFAULT`` reach the subnet;
    the deprecated ``ROS_LOCALHOST_ONLY=1`` counts as ``LOCALHOST`` when the range is
    unset) and ``ROS_STATIC_PEERS`` names no peer. Security is on when
    ``ROS_SECURITY_ENABLE`` is ``true`` (SROS2; docs/real-robot.md, "Network safety").
    """
    scope = env.get("ROS_AUTOMATIC_DISCOVERY_RANGE", "").strip().upper()
    if not scope and env.get("ROS_LOCALHOST_ONLY", "").strip() == "1":
        scope = "LOCALHOST"
    peers = env.get("ROS_STATIC_PEERS", "").strip()
    if scope in ("LOCALHOST", "OFF") and not peers:
        return None
    if env.get("ROS_SECURITY_ENABLE", "").strip().lower() == "true":
        return None
    reach = (f"ROS_STATIC_PEERS={peers}" if scope in ("LOCALHOST", "OFF") else
             f"ROS_AUTOMATIC_DISCOVERY_RANGE={scope or 'unset, so SUBNET'}")
    return (f"ROS 2 discovery reaches beyond this host ({reach}) and DDS Security is off "
            f"(ROS_SECURITY_ENABLE is not true): any machine on the network on domain "
            f"{env.get('ROS_DOMAIN_ID', '0') or '0'} can see the arm's topics and send it "
            f"goals; use the lab's ROS 2 with SROS2 or an isolated robot network, or set "
            f"ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST (docs/real-robot.md, Network safety)")


class ArmUnavailable(BackendLost):
    """The arm did not answer in time or went silent (no joint states, stale joint
    states, a stopped clock, no action server). A :class:`BackendLost`: raised through
    the boundary, it stops a run resumably."""


@dataclass
class GoalTimes:
    """Wall-clock seconds from sending a goal to each of its messages."""

    accepted: Optional[float] = None
    first_feedback: Optional[float] = None
    result: Optional[float] = None
    feedbacks: int = 0


@dataclass
class TrajectoryResult:
    """How a trajectory goal ended: ``status`` is ``rejected``, ``succeeded``,
    ``aborted``, ``canceled``, ``timeout`` or ``silent`` (the arm's joint states or
    clock stopped while the goal ran: ``error_string`` names them); ``error_code`` is
    control_msgs' code."""

    status: str
    error_code: Optional[int]
    error_string: str
    times: GoalTimes
    last_feedback: Any = None

    @property
    def error_name(self) -> str:
        """Return the error code's name (``SUCCESSFUL``, ``PATH_TOLERANCE_VIOLATED``, ...)."""
        return ERROR_NAMES.get(self.error_code, str(self.error_code))


@dataclass
class Latest:
    """The newest message of a topic, its arrival (``at``: ``time.monotonic()``;
    ``wall``: ``time.time()``, to compare with the header's stamp) and how many came."""

    msg: Any = None
    at: float = field(default=-1.0)
    count: int = 0
    wall: float = 0.0

    @property
    def stamp(self) -> float:
        """Return the header's stamp (s), or the clock's time for a Clock message."""
        t = self.msg.clock if hasattr(self.msg, "clock") else self.msg.header.stamp
        return t.sec + t.nanosec * 1e-9


_STATUS = {4: "succeeded", 5: "canceled", 6: "aborted"}


class ArmClient:
    """A node that observes and moves the arm a :class:`RobotProfile` describes.

    Parameters
    ----------
    profile : RobotProfile
    objects : sequence of str
        The case's objects whose poses to follow (topics from the profile).
    name : str
        The node's name.
    """

    def __init__(self, profile: RobotProfile, objects: Sequence[str] = (),
                 name: str = "creative_learner") -> None:
        import rclpy
        from rclpy.action import ActionClient
        from rclpy.executors import MultiThreadedExecutor
        from rclpy.node import Node

        from control_msgs.action import FollowJointTrajectory, GripperCommand
        from geometry_msgs.msg import PoseStamped
        from sensor_msgs.msg import JointState

        self.profile = profile
        self._closing = False
        self._own_context = not rclpy.ok()
        if self._own_context:
            rclpy.init()
        self.node = Node(name)
        self.joint_state = Latest()
        self.poses: dict[str, Latest] = {n: Latest() for n in objects}
        self._lock = threading.Lock()
        self.node.create_subscription(JointState, profile.joint_states_topic,
                                      self._on_joints, 10)
        self._pose_type = PoseStamped
        for n in objects:
            self.node.create_subscription(PoseStamped, profile.object_topic_of(n),
                                          lambda m, n=n: self._on_pose(n, m), 10)
        self.clock = Latest()
        if profile.use_sim_time:
            from rosgraph_msgs.msg import Clock

            self.node.create_subscription(Clock, profile.clock_topic, self._on_clock, 10)
        self.trajectory = ActionClient(self.node, FollowJointTrajectory, profile.arm_action)
        self.gripper = ActionClient(self.node, GripperCommand, profile.gripper_action)
        self._fjt, self._grip = FollowJointTrajectory, GripperCommand
        self.executor = MultiThreadedExecutor(num_threads=2)
        self.executor.add_node(self.node)
        self._spinner = threading.Thread(target=self._spin, daemon=True)
        self._spinner.start()

    def _spin(self) -> None:
        from rclpy.executors import ExternalShutdownException

        try:
            self.executor.spin()
        except ExternalShutdownException:
            pass
        except RuntimeError:  # the executor's pool refused work: it is being shut down
            if not self._closing:
                raise

    def _on_joints(self, msg: Any) -> None:
        with self._lock:
            self.joint_state = Latest(msg, time.monotonic(), self.joint_state.count + 1,
                                      time.time())

    def _on_clock(self, msg: Any) -> None:
        with self._lock:
            self.clock = Latest(msg, time.monotonic(), self.clock.count + 1, time.time())

    def _on_pose(self, name: str, msg: Any) -> None:
        with self._lock:
            self.poses[name] = Latest(msg, time.monotonic(), self.poses[name].count + 1,
                                     time.time())

    def follow(self, name: str) -> None:
        """Also follow the pose topic of object ``name`` (a tool of a later episode)."""
        with self._lock:
            if name in self.poses:
                return
            self.poses[name] = Latest()
        self.node.create_subscription(self._pose_type, self.profile.object_topic_of(name),
                                      lambda m: self._on_pose(name, m), 10)

    # ---------------------------------------------------------------- observation
    def wait_for_arm(self, timeout: float) -> None:
        """Wait until joint states arrive and both action servers answer.

        Raises
        ------
        ArmUnavailable
            Naming the topic or action that stayed silent for ``timeout`` s.
        """
        end = time.monotonic() + timeout
        p = self.profile
        while p.use_sim_time and self.clock.msg is None:
            if time.monotonic() > end:
                raise ArmUnavailable(f"no rosgraph_msgs/Clock on {p.clock_topic!r} within "
                                     f"{timeout:g} s (the profile's [clock] use_sim_time); "
                                     + self.published("rosgraph_msgs/msg/Clock"))
            time.sleep(0.02)
        while self.joint_state.msg is None:
            if time.monotonic() > end:
                raise ArmUnavailable(f"no sensor_msgs/JointState on "
                                     f"{self.profile.joint_states_topic!r} within {timeout:g} s; "
                                     + self.published("sensor_msgs/msg/JointState"))
            time.sleep(0.02)
        for client, name, kind in (
                (self.trajectory, self.profile.arm_action,
                 "control_msgs/action/FollowJointTrajectory"),
                (self.gripper, self.profile.gripper_action, "control_msgs/action/GripperCommand")):
            if not client.wait_for_server(timeout_sec=max(0.0, end - time.monotonic())):
                raise ArmUnavailable(f"no action server {name!r} within {timeout:g} s; "
                                     + self.served(kind))

    def _others(self) -> list[tuple[str, str]]:
        """Return the ROS graph's nodes other than this one, ``(name, namespace)``."""
        me = (self.node.get_name(), self.node.get_namespace())
        return [n for n in self.node.get_node_names_and_namespaces() if n != me]

    def published(self, type_name: str) -> str:
        """Return, in words, the topics on which another node of the ROS graph publishes
        messages of ``type_name`` (``sensor_msgs/msg/JointState``) now: what the arm does
        publish, for an error that a profile's topic name is wrong."""
        topics = set()
        for name, ns in self._others():
            try:
                found = self.node.get_publisher_names_and_types_by_node(name, ns)
            except Exception:  # noqa: BLE001  (the node left the graph meanwhile)
                continue
            topics.update(t for t, types in found if type_name in types)
        return (f"the ROS graph has {type_name} on {', '.join(sorted(topics))}" if topics
                else f"no node of the ROS graph publishes {type_name}")

    def served(self, type_name: str) -> str:
        """Return, in words, the action servers of ``type_name``
        (``control_msgs/action/GripperCommand``) other nodes of the ROS graph offer."""
        from rclpy.action.graph import get_action_server_names_and_types_by_node

        names = set()
        for name, ns in self._others():
            try:
                found = get_action_server_names_and_types_by_node(self.node, name, ns)
            except Exception:  # noqa: BLE001  (the node left the graph meanwhile)
                continue
            names.update(a for a, types in found if type_name in types)
        return (f"the ROS graph serves {type_name} on {', '.join(sorted(names))}" if names
                else f"no node of the ROS graph serves {type_name}")

    def now(self) -> float:
        """Return the time staleness and timeouts count (s): the simulated clock's last
        time with ``use_sim_time``, else ``time.monotonic()``.

        Raises
        ------
        ArmUnavailable
            With ``use_sim_time``: no clock yet, or none for ``silent_after_s`` of
            wall-clock time (the simulator died or froze).
        """
        p = self.profile
        if not p.use_sim_time:
            return time.monotonic()
        with self._lock:
            clock = self.clock
        if clock.msg is None:
            raise ArmUnavailable(f"no rosgraph_msgs/Clock on {p.clock_topic!r}")
        silent = time.monotonic() - clock.at
        if silent > p.clock_silent_after_s:
            raise ArmUnavailable(f"the clock on {p.clock_topic!r} stopped {silent:.2f} s ago "
                                 f"(silent after {p.clock_silent_after_s:g} s of wall-clock "
                                 "time): the simulated arm died or froze")
        return clock.stamp

    def joint_state_age(self) -> float:
        """Return the age (s) of the latest joint states, on :meth:`now`'s clock.

        Raises
        ------
        ArmUnavailable
            None yet, or the clock stopped (:meth:`now`).
        """
        with self._lock:
            latest = self.joint_state
        if latest.msg is None:
            raise ArmUnavailable(f"no joint states on {self.profile.joint_states_topic!r}")
        now = self.now()
        return now - latest.stamp if self.profile.use_sim_time else now - latest.at

    def check_fresh(self, max_age: Optional[float] = None) -> None:
        """Raise :class:`ArmUnavailable` naming the topic if the joint states are older
        than ``max_age`` s (default: the profile's ``stale_after_s``) or the clock
        stopped."""
        limit = self.profile.stale_after_s if max_age is None else max_age
        age = self.joint_state_age()
        if age > limit:
            where = " in simulated time" if self.profile.use_sim_time else ""
            raise ArmUnavailable(f"joint states on {self.profile.joint_states_topic!r} are "
                                 f"{age:.2f} s old{where} (stale after {limit:g} s)")

    def joints(self, max_age: Optional[float] = None) -> dict[str, float]:
        """Return the latest joint positions by name.

        Raises
        ------
        ArmUnavailable
            None yet, older than ``max_age`` s (default: the profile's
            ``stale_after_s``), or the clock stopped (:meth:`check_fresh`).
        """
        self.check_fresh(max_age)
        with self._lock:
            latest = self.joint_state
        return dict(zip(latest.msg.name, latest.msg.position))

    def arm_q(self, max_age: Optional[float] = None) -> list[float]:
        """Return the arm's joint positions in the profile's order."""
        by_name = self.joints(max_age)
        return [by_name[j] for j in self.profile.joints]

    def pose(self, name: str) -> Optional[tuple[tuple[float, ...], tuple[float, ...], str]]:
        """Return the latest ``(position, quaternion xyzw, frame)`` of object ``name``."""
        with self._lock:
            latest = self.poses[name]
        if latest.msg is None:
            return None
        p, o = latest.msg.pose.position, latest.msg.pose.orientation
        return (p.x, p.y, p.z), (o.x, o.y, o.z, o.w), latest.msg.header.frame_id

    # --------------------------------------------------------------------- motion
    def make_goal(self, points: Sequence[tuple[float, Sequence[float]]],
                  path_tolerance: Optional[dict[str, float]] = None,
                  goal_tolerance: Optional[dict[str, float]] = None,
                  goal_time_tolerance: float = 0.0,
                  joint_names: Optional[Sequence[str]] = None) -> Any:
        """Return a FollowJointTrajectory goal of ``(time_from_start s, positions)``."""
        from builtin_interfaces.msg import Duration
        from control_msgs.msg import JointTolerance
        from trajectory_msgs.msg import JointTrajectoryPoint

        def duration(s: float) -> Any:
            sec = int(s)
            return Duration(sec=sec, nanosec=int(round((s - sec) * 1e9)))

        goal = self._fjt.Goal()
        goal.trajectory.joint_names = list(joint_names or self.profile.joints)
        for t, q in points:
            pt = JointTrajectoryPoint()
            pt.positions = [float(v) for v in q]
            pt.time_from_start = duration(t)
            goal.trajectory.points.append(pt)
        goal.path_tolerance = [JointTolerance(name=n, position=float(v))
                               for n, v in (path_tolerance or {}).items()]
        goal.goal_tolerance = [JointTolerance(name=n, position=float(v))
                               for n, v in (goal_tolerance or {}).items()]
        goal.goal_time_tolerance = duration(goal_time_tolerance)
        return goal

    def send_trajectory(self, goal: Any, timeout: float = 30.0,
                        check: Optional[Callable[[Any], None]] = None,
                        on_feedback: Optional[Callable[[Any], None]] = None) -> TrajectoryResult:
        """Send a FollowJointTrajectory goal and wait for its end (at most ``timeout`` s
        of :meth:`now`'s clock, simulated time with ``use_sim_time``).

        ``check(goal)`` runs first and raises to stop the goal from being sent (the
        learner's bounds, :mod:`.limits`). While waiting, joint states that go stale or
        a clock that stops end the wait with status ``silent``.
        """
        if check is not None:
            check(goal)
        times = GoalTimes()
        last: list[Any] = [None]
        t0 = time.monotonic()

        def feedback(msg: Any) -> None:
            if times.first_feedback is None:
                times.first_feedback = time.monotonic() - t0
            times.feedbacks += 1
            last[0] = msg.feedback
            if on_feedback is not None:
                on_feedback(msg.feedback)

        try:
            deadline = self.now() + timeout
        except ArmUnavailable as exc:
            return TrajectoryResult("silent", None, str(exc), times)
        sent = self.trajectory.send_goal_async(goal, feedback_callback=feedback)
        handle, at, why = self._wait(sent, deadline)
        if handle is None:
            if why:
                return TrajectoryResult("silent", None, f"before the goal was accepted: {why}",
                                        times)
            return TrajectoryResult("timeout", None, "no answer to the goal", times)
        times.accepted = at - t0
        if not handle.accepted:
            return TrajectoryResult("rejected", None, "the arm rejected the goal", times)
        res, at, why = self._wait(handle.get_result_async(), deadline)
        if res is None:
            handle.cancel_goal_async()
            if why:
                return TrajectoryResult("silent", None, f"while the goal ran: {why}", times,
                                        last[0])
            return TrajectoryResult("timeout", None, f"no result within {timeout:g} s "
                                    f"({self.profile.now_source()})", times, last[0])
        times.result = at - t0
        return TrajectoryResult(_STATUS.get(res.status, f"status {res.status}"),
                                res.result.error_code, res.result.error_string, times, last[0])

    def grip(self, close: bool, timeout: float = 10.0) -> Any:
        """Close or open the gripper; return its GripperCommand result (None on timeout)."""
        goal = self._grip.Goal()
        p = self.profile
        goal.command.position = p.gripper_closed if close else p.gripper_open
        goal.command.max_effort = p.gripper_max_effort
        try:
            end = self.now() + timeout
        except ArmUnavailable:
            return None
        handle, _, _ = self._wait(self.gripper.send_goal_async(goal), end)
        if handle is None or not handle.accepted:
            return None
        res, _, _ = self._wait(handle.get_result_async(), end)
        return None if res is None else res.result

    def close(self) -> None:
        """Destroy the node (and the rclpy context if this client made it)."""
        import rclpy

        self._closing = True
        self.executor.shutdown(timeout_sec=1.0)
        self.trajectory.destroy()
        self.gripper.destroy()
        self.node.destroy_node()
        if self._own_context:
            rclpy.try_shutdown()

    def __enter__(self) -> "ArmClient":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def _wait(self, future: Any, deadline: float, poll: float = 0.02
              ) -> tuple[Any, Optional[float], str]:
        """Wait for ``future``: return its result, when it was done (``time.monotonic()``)
        and ``""``; or ``(None, None, "")`` once :meth:`now` passes ``deadline``; or
        ``(None, None, why)`` as soon as the arm goes silent (:meth:`check_fresh`)."""
        done = threading.Event()
        at: list[float] = []

        def finished(_: Any) -> None:
            at.append(time.monotonic())
            done.set()

        future.add_done_callback(finished)
        while not done.wait(poll):
            try:
                self.check_fresh()
                if self.now() > deadline:
                    return None, None, ""
            except ArmUnavailable as exc:
                if done.is_set():
                    break
                return None, None, str(exc)
        return future.result(), at[0] if at else time.monotonic(), ""
