"""The ROS 2 backend's episode: a case's skills run on an arm over ROS 2, the case's facts
and oracle measured from the pose topics.

The learner keeps a *twin* of the scene (:mod:`.twin`): the pybullet backend's episode
of the same world files (variant, location, tool), built in a DIRECT client of the
learner's own process, whose physics never runs once built. Before anything reads it, the tracked
objects (the case's perceived objects, its context and the tool) are put where the
motion-capture topics (``geometry_msgs/PoseStamped``) last said, and the twin's arm
where the joint states say. So the pybullet backend's code runs unchanged on what the
topics give:

* the primitives the hook-like cases bind (:data:`PRIMITIVES`: ``grasp``,
  ``insert_at_pose``, ``pull_along_axis``), whose arm is :class:`RosRobot`: its
  kinematics queries (IK, forward kinematics, the posture search's dry runs) run in
  the learner's kinematics client, its motions are straight gripper paths solved
  there and sent as ``FollowJointTrajectory`` goals through the learner's bounds
  (:class:`~creative_py.backends.ros.motion.LearnerArm`), its grasp is a
  ``GripperCommand``;
* the facts (:meth:`RosEpisode.observe`): the perceived objects' ``pose``/``size``
  from the pose topics (motion capture gives poses, not images: the estimate is the
  object's box in its yaw frame with the perception's symmetry rules), the held
  tool by proprioception, the scene's fixed facts, the catalogue;
* the oracle (:meth:`RosEpisode.verdict`), measured on the poses the topics gave.

A motion that did not go as planned is reported as the arm reported it
(:class:`~creative_py.backends.ros.motion.LearnerArm`): aborted on a path or goal
tolerance (a jammed tool makes the arm lag: the role of the pybullet backend's
tracking guard) is ``blocked``; rejected or not answered in time is ``invalid``; no
IK solution or outside the learner's bounds is ``unreachable``. An arm gone silent
(stale joint states, a stopped clock) is no outcome: its
:class:`~creative_py.backends.ros.client.ArmUnavailable` (a
:class:`~creative_py.simulator.types.BackendLost`) goes through the boundary and the
run stops resumably.
The trial's outcome is labelled above the boundary (:mod:`creative_py.simulator.trial`).

The contact load on the tool during the tool action comes from a wrist force/torque
sensor's ``geometry_msgs/WrenchStamped`` topic (the profile's ``[wrench]``;
:func:`wrench_load`); without one it is not measured (``(0.0, None)``: a created tool's
strength check then says ``unmeasured``). What the arm side does not tell is not made
up: no camera frames, no touching bodies in a stopped motion's verdict. Time is the
wall's since the episode opened; steps are the trajectory goals sent.
"""

from __future__ import annotations

import math
import time
import uuid
from typing import Any, Callable, Optional, Sequence

from creative_py.backends.ros.client import ArmUnavailable
from creative_py.backends.ros.twin import TwinEpisode, local_extents, set_frame_pose
from creative_py.simulator.load import ToolLoad
from creative_py.simulator.paths import Unreachable, quat_angle, straight_line
from creative_py.simulator.types import SkillOutcome
from creative_py.world_files import WorldFileError

PRIMITIVES = ("grasp", "insert_at_pose", "pull_along_axis")
"""The primitives the ROS 2 backend runs (a case binding another is refused at load)."""

WAYPOINT_M = 0.01
"""Metres between the waypoints of a straight gripper path (IK solved at each)."""

WAYPOINT_RAD = 0.1
"""Radians of gripper turn between waypoints."""


class GripMissed(Exception):
    """The grasp did not hold the tool: the gripper closed on nothing (``blocked``) or
    did not answer (``invalid``), as the arm's GripperCommand said."""

    def __init__(self, reason: str, status: str = "blocked") -> None:
        super().__init__(reason)
        self.status = status


class SceneRefused(WorldFileError):
    """The trainer answered a scene request with an error."""


def unsupported_skills(world: Any) -> list[str]:
    """Return one line per skill of the world's manifest whose primitive this backend
    does not run (naming the case file and the skill)."""
    m = world.manifest
    where = f"{m.folder}/case.toml"
    return [f"{where}: skill {s.name!r} binds primitive {world.skills[s.name].primitive!r}, "
            f"which the ros backend does not run (it runs {', '.join(PRIMITIVES)})"
            for s in m.skills if world.skills[s.name].primitive not in PRIMITIVES]


def unjudged_oracle(world: Any) -> list[str]:
    """Return one line per reason this backend cannot judge the world's oracle as the
    pybullet backend does: the learner follows the poses of the perceived objects, the
    context and the tool alone (its twin's other bodies stay where the scene put them)
    and measures no velocity. Checked for the demonstration's variant, location and
    tool; each line names ``tasks.toml`` and the field."""
    from creative_py.world.read import object_name, oracle_reads

    m, demo = world.manifest, world.manifest.demonstration
    where = f"{world.directory / 'tasks.toml'}: field 'oracle'"
    reads, velocity = oracle_reads(world, demo.variant, demo.location, demo.tool)
    followed = {object_name(m, p.name, demo.tool) for p in world.scene.perceived}
    followed |= {m.context, demo.tool}
    out = [f"{where}: the {world.oracle.kind} oracle reads {name}, whose pose the ros "
           f"backend does not follow (it follows {', '.join(sorted(followed))})"
           for name in reads if name not in followed]
    if velocity:
        out.append(f"{where}: the {world.oracle.kind} oracle weighs a velocity "
                   "(speed_weight > 0), which the ros backend does not measure")
    return out


def wrench_load(samples: Sequence[tuple], grasp: Any, rate_hz: float,
                working_point: Sequence[float] = (0.0, 0.0, 0.0)) -> Any:
    """Return the tool action's contact load (a
    :class:`~creative_py.simulator.load.ToolLoad`, every backend's) from a wrist sensor's
    samples ``(force, torque)`` (gripper frame, tared; torque about the gripper, which
    holds the tool at the grasp) at ``rate_hz``.

    The force of a sample is its magnitude (the net force: a sensor cannot tell the
    target's contact from the others, where the pybullet backend counts the target's
    alone). The robust force follows the rule of every backend
    (:func:`creative_py.simulator.load.robust_force`): the 95th percentile of the force
    averaged over each 0.1 s, over the windows with contact. The torque about the grasp
    places the force: a sensor gives its line of action (``torque = r x force``), and
    the point is the peak sample's line's point nearest the tool's ``working_point``
    (tool frame; a hook's prong), in the tool frame through the grasp (the tool frame
    in the gripper frame); the strength check's lever arm runs from the grasp to it.
    """
    import numpy as np

    from creative_py.backends.ros.standin import compose, invert
    from creative_py.simulator.load import LOAD_WINDOW_S, robust_force, samples_per_window

    norms = [float(np.linalg.norm(f)) for f, _ in samples]
    contact = [n for n in norms if n > 1e-6]
    if not contact:
        return ToolLoad(steps=len(samples), window_s=LOAD_WINDOW_S)
    k = int(np.argmax(norms))
    f, t = np.asarray(samples[k][0]), np.asarray(samples[k][1])
    tool_in_gripper = (tuple(grasp[0]), tuple(grasp[1]))
    gripper_in_tool = invert(tool_in_gripper)
    on_line = np.cross(f, t) / float(f @ f)  # the line's point nearest the gripper
    unit = f / np.linalg.norm(f)
    work = np.asarray(compose(tool_in_gripper, (tuple(working_point), (0, 0, 0, 1)))[0])
    point_g = on_line + float((work - on_line) @ unit) * unit
    point = compose(gripper_in_tool, (tuple(point_g), (0.0, 0.0, 0.0, 1.0)))[0]
    force = compose(((0.0, 0.0, 0.0), gripper_in_tool[1]), (tuple(f), (0.0, 0.0, 0.0, 1.0)))[0]
    robust = robust_force([n if n > 1e-6 else 0.0 for n in norms],
                          samples_per_window(rate_hz))
    return ToolLoad(max_force_n=norms[k], point=point, force=force,
                    grasp_point=gripper_in_tool[0], contacts=0, bodies=(), step=k,
                    steps=len(samples), robust_force_n=robust,
                    contact_steps=len(contact), impulse_ns=sum(contact) / rate_hz,
                    window_s=LOAD_WINDOW_S)


class RosRobot:
    """The arm over ROS 2, shaped as the pybullet backend's arm is to a primitive.

    Kinematics on the learner's side (the twin's arm and its kinematics client, at
    the posture the joint states give); motions as trajectory goals
    (:class:`~creative_py.backends.ros.motion.LearnerArm`); the grasp as a gripper
    command. Attributes it does not define (``config``, ``model``, ``kin``,
    ``light``, ``body``, ``urdf``) are the twin arm's.
    """

    def __init__(self, ep: "RosEpisode") -> None:
        self.ep, self.twin = ep, ep.twin_robot
        self.conn = ep.conn
        self.arm = ep.conn.arm
        kin = ep.conn.kin
        self._to_arm, self._to_profile = kin._to_arm, kin._to_profile
        self.held: Optional[int] = None
        self.grasp_constraint = None

    def __getattr__(self, name: str) -> Any:
        return getattr(self.__dict__["twin"], name)

    # ------------------------------------------------------------------ state
    def arm_q(self) -> list[float]:
        """Return the arm's joint positions (rad, the profile's kinematics order) from the joint
        states (ArmUnavailable if stale)."""
        q = self.conn.client.arm_q()
        return [q[i] for i in self._to_arm]

    def _profile_q(self, q: Sequence[float]) -> list[float]:
        return [float(q[i]) for i in self._to_profile]

    def sync(self) -> list[float]:
        """Put the twin's arm where the joint states say; return that posture."""
        q = self.arm_q()
        self.twin.model.reset(self.twin.model.arm, q)
        return q

    def gripper_pose(self):
        """Return the gripper's world pose by forward kinematics of the joint states."""
        self.sync()
        return self.twin.gripper_pose()

    def reset_posture(self, right_q: Sequence[float]) -> None:
        raise RuntimeError("the arm over ROS 2 is moved by goals, not teleported")

    # --------------------------------------------------------------------- IK
    def solve_ik(self, target, seed=None, max_iterations: int = 150):
        return self.twin.solve_ik(target, seed=self.arm_q() if seed is None else seed,
                                  max_iterations=max_iterations)

    def ik_candidates(self, target, keep: int = 6, restarts: int = 40, seeds=()):
        self.sync()
        return self.twin.ik_candidates(target, keep, restarts, seeds)

    def solve_ik_global(self, target, restarts: int = 40, keep: int = 6, seeds=()):
        self.sync()
        return self.twin.solve_ik_global(target, restarts, keep, seeds)

    def dry_run(self, q_start, path, max_step: float = 0.01):
        return self.twin.dry_run(q_start, path, max_step)

    # ----------------------------------------------------------------- motion
    def _send(self, path: Sequence[Sequence[float]], duration: float) -> SkillOutcome:
        """Send a joint path (the kinematics order), timed from where the arm is as it leaves."""
        return self.arm.send_path([self._profile_q(q) for q in path], duration)

    def move_to(self, target, speed: Optional[float] = None, check: bool = True,
                watch: Sequence[int] = (),
                guard: Optional[Callable[[], Optional[SkillOutcome]]] = None) -> SkillOutcome:
        """Move the gripper in a straight line (slerped orientation) to ``target``: the
        waypoints solved by the learner's IK, sent as one trajectory goal timed by
        ``speed`` (m/s) and the turn speed. ``guard`` runs once the goal ended."""
        cfg = self.twin.config
        speed = speed or cfg.speed
        q = self.sync()
        start_pos, start_quat = self.twin.gripper_pose()
        dist = math.dist(start_pos, target[0])
        ang = quat_angle(start_quat, target[1])
        n = max(1, math.ceil(max(dist / WAYPOINT_M, ang / WAYPOINT_RAD)))
        try:
            path = [sol for _, _, sol in straight_line(self.twin.solve_ik,
                                                       (start_pos, start_quat), target, n, q)]
        except Unreachable as exc:
            return exc.outcome
        res = self._send(path, max(dist / speed, ang / cfg.turn_speed))
        if res.ok and check and guard is not None:
            self.ep.sync()
            res = guard() or res
        return res

    def move_joints(self, q_goal: Sequence[float], joint_speed: float = 0.8,
                    check: bool = True, watch: Sequence[int] = ()) -> SkillOutcome:
        """Move the arm in joint space to ``q_goal`` (rad, the kinematics order), easing in and
        out (:meth:`LearnerArm.move_joints`), the fastest joint at most at
        ``joint_speed`` on average."""
        q0 = self.arm_q()
        move = max(abs(a - b) for a, b in zip(q_goal, q0))
        return self.arm.move_joints(self._profile_q(q_goal), move / joint_speed)

    def reach(self, target, joint_speed: float = 0.8, watch: Sequence[int] = ()) -> SkillOutcome:
        q = self.solve_ik_global(target)
        if q is None:
            p = target[0]
            return SkillOutcome("unreachable", f"IK found no arm posture for gripper at "
                                f"({p[0]:.3f}, {p[1]:.3f}, {p[2]:.3f}) m")
        return self.move_joints(q, joint_speed, watch=watch)

    # ----------------------------------------------------------------- grasp
    def grasp(self, body: int, frame_in_gripper) -> None:
        """Close the gripper; raise GripMissed unless it then holds something."""
        res = self.arm.grip(True)
        if not res.ok:
            raise GripMissed(res.reason, res.status)
        if not getattr(self.arm, "holding", False):
            raise GripMissed("the gripper closed on nothing (GripperCommand on "
                             f"{self.conn.profile.gripper_action!r}: not stalled on an object)")
        self.held = body

    def release(self) -> None:
        """Open the gripper."""
        self.arm.grip(False)
        self.held = None

    def touching(self) -> list[tuple[int, int]]:
        """Nothing: the arm's interface does not say what it touches."""
        return []

    def close(self) -> None:
        self.twin.close()


class RosEpisode(TwinEpisode):
    """One scene of a case on the arm over ROS 2 (see the module docstring).

    Built as the pybullet backend's episode of the same world files (the twin), then
    the trainer is asked for the scene (:meth:`set_up`), and the twin follows the
    topics from then on.
    """

    def __init__(self, conn: Any, world: Any, variant: str, location: int, tool: str,
                 seed: int = 0, pose_target: Any = None, *, robot: bool = True) -> None:
        super().__init__(world, variant, location, tool, seed, False, None, pose_target,
                         robot=robot)
        self.conn = conn
        self.sim.step = self._wait_steps  # the twin's physics never runs: the arm's does
        self.tracked = list(dict.fromkeys(
            [n for n, _ in self.perceived] + [self.context_name, self.spec.name]))
        self.twin_robot = self.robot
        if self.robot is not None:
            self.robot = RosRobot(self)
        self._extents: dict[str, tuple[float, float, float]] = {}
        self.ros_load: Any = None  # the last tool action's ToolLoad, from the wrench topic
        self._t0 = time.monotonic()
        self._goals0 = conn.arm.goals_sent

    # ------------------------------------------------------------ the scene
    def set_up(self) -> None:
        """Ask the trainer for this episode's scene and wait for it: the answer, then
        fresh poses of every tracked object and fresh joint states."""
        from creative_py.backends.ros.trainer import scene_request

        conn, item = self.conn, self.item
        created = self.spec.name not in self.manifest_catalogue()
        rid = f"{uuid.uuid4().hex[:12]}"
        text = scene_request(rid, self.manifest.id, self.variant, self.location,
                             self.spec.name, self.spec if created else None,
                             item.urdf if created else None)
        for name in self.tracked:
            conn.client.follow(name)
        conn.request_scene(rid, text)
        # Two messages of each after the answer: the first may have left before it
        # (another topic: DDS keeps no order between topics).
        counts = {n: conn.client.poses[n].count for n in self.tracked}
        js = conn.client.joint_state.count
        end = time.monotonic() + conn.profile.trainer_timeout_s
        while (any(conn.client.poses[n].count < counts[n] + 2 for n in self.tracked)
               or conn.client.joint_state.count < js + 2):
            if time.monotonic() > end:
                late = [conn.profile.object_topic_of(n) for n in self.tracked
                        if conn.client.poses[n].count < counts[n] + 2]
                if late:
                    raise ArmUnavailable(
                        f"no fresh geometry_msgs/PoseStamped on {', '.join(late)} after the "
                        f"scene was set up; "
                        + conn.client.published("geometry_msgs/msg/PoseStamped"))
                raise ArmUnavailable(f"no fresh sensor_msgs/JointState on "
                                     f"{conn.profile.joint_states_topic!r} after the scene "
                                     "was set up")
            time.sleep(0.02)
        self.sync()
        self.start_centres = {n: self.true_centre(n) for n, _ in self.perceived}
        self.held = False
        conn.arm.lost = None  # the arm answered again: a new scene, a new start
        self._t0 = time.monotonic()
        self._goals0 = conn.arm.goals_sent

    def manifest_catalogue(self) -> set[str]:
        """Return the names of the world files' catalogued objects (not created)."""
        return {n for n, it in self.world.items.items() if getattr(it, "urdf", None) is None}

    def sync(self) -> None:
        """Put the twin's tracked objects where the pose topics last said, and its arm
        where the joint states say."""
        client = self.conn.client
        for name in self.tracked:
            pose = client.pose(name)
            if pose is not None:
                set_frame_pose(self.sim, self.body_id(name), (pose[0], pose[1]))
        if isinstance(self.robot, RosRobot):
            self.robot.sync()

    def _wait_steps(self, n: int = 1) -> None:
        """Let ``n`` of the twin's time steps pass on the arm: as many joint-state
        messages as the arm publishes in that time (its own clock)."""
        client, p = self.conn.client, self.conn.profile
        wanted = math.ceil(n * self.sim.physics.time_step * p.joint_states_rate_hz)
        start = client.joint_state.count
        end = time.monotonic() + 10 * n * self.sim.physics.time_step + 2 * p.stale_after_s
        while client.joint_state.count < start + wanted and time.monotonic() < end:
            time.sleep(0.005)

    # ------------------------------------------------------------------ skills
    def run_skill(self, name: str, pose: Optional[Sequence[float]] = None,
                  **options: Any) -> SkillOutcome:
        """Run the manifest's skill ``name`` on the arm (see the module docstring)."""
        prim = self.world.skills[name].primitive
        if prim not in PRIMITIVES:
            raise WorldFileError(f"{self.manifest.folder}/case.toml: skill {name!r} binds "
                                 f"primitive {prim!r}, which the ros backend does not run")
        acting = self.manifest.skill(name).tool_action and bool(self.conn.profile.wrench_topic)
        if acting:
            self.conn.record_wrenches()
        try:
            res = super().run_skill(name, pose, **options)
            # An arm gone silent is no outcome of the trial: BackendLost (ArmUnavailable)
            # goes through the boundary, the run stops resumably.
            self.conn.arm.raise_if_lost()
            return res
        except GripMissed as exc:
            self.conn.arm.raise_if_lost()  # a silent gripper is no miss
            return SkillOutcome(exc.status, f"{name}: {exc}")
        finally:
            if acting:
                work = (self.spec.working_point() if hasattr(self.spec, "working_point")
                        else self.kind.centre(self.spec))
                self.ros_load = wrench_load(self.conn.recorded_wrenches(), self.grasp,
                                        self.conn.profile.joint_states_rate_hz, work)

    def run_primitive(self, primitive: str, pose: Optional[Sequence[float]] = None,
                      **options: Any) -> SkillOutcome:
        self.sync()
        return super().run_primitive(primitive, pose, **options)

    # -------------------------------------------------------------- perception
    def _extent(self, name: str) -> tuple[float, float, float]:
        """Return the object's box extents (m) in its own frame, from the world files'
        geometry (the twin's body, turned to the identity for a moment)."""
        if name not in self._extents:
            self._extents[name] = local_extents(self.sim, self.body_id(name))
        return self._extents[name]

    def _estimates(self):
        """The perceived objects as motion capture gives them: each one's centre and
        heading from its pose topic, its size from the world files, the heading put
        in the perception's range for its footprint (square: modulo pi/2; oblong: x
        the longer side, modulo pi). No frames."""
        from creative_py.perception.estimate import ObjectEstimate

        self.sync()
        client, est = self.conn.client, {}
        for name, _ in self.perceived:
            if client.pose(name) is None:
                continue  # not seen: no facts, as a camera that does not see it
            x, y, z, yaw = self.true_centre(name)
            dx, dy, dz = self._extent(name)
            if abs(dx - dy) < 0.002:
                period, symmetry = math.pi / 2, "half_pi"
            else:
                if dx < dy:
                    dx, dy, yaw = dy, dx, yaw + math.pi / 2
                period, symmetry = math.pi, "pi"
            yaw = yaw - period * math.floor((yaw + period / 2) / period)
            if yaw <= -period / 2 + 1e-12:
                yaw += period
            est[name] = ObjectEstimate(name, x, y, z, yaw, (dx, dy, dz), 0, ("mocap",),
                                       symmetry)
        return est, ()

    def observe(self, cameras: bool = True):
        """Return the facts from the pose topics and the joint states (no frames: with
        or without ``cameras``, the perceived objects come from motion capture)."""
        return super().observe(cameras=True)

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ``name -> (x, y, z, yaw)`` of the tracked objects and the tool, as the
        pose topics last gave them."""
        self.sync()
        return super().truth()

    # ------------------------------------------------------------------- oracle
    def verdict(self):
        """Return the case's oracle measured on the poses the topics last gave."""
        self.sync()
        return super().verdict()

    def sim_time(self) -> float:
        """Return the wall seconds since the scene was set up (the arm's time)."""
        return time.monotonic() - self._t0

    @property
    def steps(self) -> int:
        """Return the trajectory goals sent in this episode."""
        return self.conn.arm.goals_sent - self._goals0

    def measured_load(self):
        """Return the contact load on the tool during the last tool action, from the
        wrist sensor's topic (:func:`wrench_load`); ``(0.0, None)`` without one (a
        created tool's strength check is then ``unmeasured``)."""
        if self.ros_load is None:
            return 0.0, None
        return self.ros_load.max_force_n, self.ros_load.to_dict()
