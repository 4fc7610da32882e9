"""The ``ros`` backend of the simulator boundary: a case run on an arm over ROS 2.

Its functions are the :class:`creative_py.simulator.Backend` protocol. A case runs on it
without editing the case: ``creative run hook --backend ros [--robot NAME|PATH]``
(or ``make run CASE=hook BACKEND=ros``); the robot profile is the manifest's ``robot``
(the case's, or ``--robot``'s in a run's manifest).

* :func:`load_world`: the world files, read for the learner's twin of the scene
  (:mod:`.twin`: the learner knows the apparatus as its world files describe it; only
  the tracked objects' poses come from the topics), without a clip camera (no clips of
  a real arm). It connects to the arm of the manifest's profile once per process
  (:func:`connection`) and refuses a case that binds a primitive this backend does not
  run, both in one line.
* :func:`open_episode`: asks the trainer for the scene (:mod:`.trainer`) and yields a
  :class:`~creative_py.backends.ros.episode.RosEpisode`.

Importing this module imports rclpy and control_msgs: without the ``ros`` extra the
loader says what installs it (:func:`creative_py.simulator.loader.backend`).
"""

from __future__ import annotations

import atexit
import json
import logging
import os
import threading
import time
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Any, Iterator, Optional

import rclpy  # noqa: F401  (the ros extra: the loader names it when missing)
from control_msgs.action import FollowJointTrajectory  # noqa: F401  (make setup-ros)

from creative_py.backends.ros.client import ArmClient, ArmUnavailable, discovery_warning
from creative_py.backends.ros.episode import (RosEpisode, SceneRefused, unjudged_oracle,
                                             unsupported_skills)
from creative_py.backends.ros.motion import Kinematics, LearnerArm
from creative_py.backends.ros.profile import RobotProfile, load_profile
from creative_py.world_files import WorldFileError

log = logging.getLogger(__name__)

WAIT_ENV = "CREATIVE_ROS_WAIT_S"
"""The environment variable of the seconds to wait for the arm at the start (20)."""


class ArmAbsent(WorldFileError):
    """The arm did not answer at the start (one line naming the topic or action)."""


class Connection:
    """The learner's one connection to the arm, kept for every episode of the process:
    the client (:class:`ArmClient`), the learner's kinematics and arm, and the
    trainer's request and answer topics."""

    def __init__(self, profile: RobotProfile, wait: float, base: Any = None) -> None:
        from std_msgs.msg import String

        self.profile, self.base = profile, base
        self.client = ArmClient(profile, (), name="creative_learner")
        self.kin: Optional[Kinematics] = None
        try:
            self.client.wait_for_arm(wait)
            self.kin = Kinematics(profile, base)
        except BaseException:
            self.close()
            raise
        self.arm = LearnerArm(self.client, self.kin)
        self._answers: dict[str, dict] = {}
        self._answered = threading.Condition()
        self._String = String
        self.requests = self.client.node.create_publisher(String, profile.trainer_request_topic, 10)
        self.client.node.create_subscription(String, profile.trainer_done_topic,
                                             self._on_answer, 10)
        self.scene_s: list[float] = []
        self.wrenches: Optional[list] = None  # recording: (force, torque), gripper frame
        if profile.wrench_topic:
            from geometry_msgs.msg import WrenchStamped

            self.client.node.create_subscription(WrenchStamped, profile.wrench_topic,
                                                 self._on_wrench, 50)

    def _on_wrench(self, msg: Any) -> None:
        samples = self.wrenches
        if samples is not None:
            f, t = msg.wrench.force, msg.wrench.torque
            samples.append(((f.x, f.y, f.z), (t.x, t.y, t.z)))

    def record_wrenches(self) -> None:
        """Start keeping the wrist sensor's samples (a tool action begins)."""
        self.wrenches = []

    def recorded_wrenches(self) -> list:
        """Stop keeping them; return the samples kept."""
        samples, self.wrenches = self.wrenches or [], None
        return samples

    def _on_answer(self, msg: Any) -> None:
        try:
            data = json.loads(msg.data)
        except json.JSONDecodeError:
            return
        if isinstance(data, dict) and isinstance(data.get("id"), str):
            with self._answered:
                self._answers[data["id"]] = data
                self._answered.notify_all()

    def request_scene(self, rid: str, text: str) -> None:
        """Publish a scene request and wait for its answer (the profile's
        ``trainer.timeout_s``).

        Raises
        ------
        ArmUnavailable
            No trainer listens on the request topic, or none answered in time.
        SceneRefused
            The trainer answered with an error.
        """
        p = self.profile
        t0 = time.monotonic()
        end = t0 + p.trainer_timeout_s
        while self.requests.get_subscription_count() == 0:
            if time.monotonic() > end:
                raise ArmUnavailable(f"no trainer subscribes to std_msgs/String on "
                                     f"{p.trainer_request_topic!r} within "
                                     f"{p.trainer_timeout_s:g} s")
            time.sleep(0.02)
        self.requests.publish(self._String(data=text))
        with self._answered:
            while rid not in self._answers:
                left = end - time.monotonic()
                if left <= 0:
                    raise ArmUnavailable(f"no answer to scene request {rid} on "
                                         f"{p.trainer_done_topic!r} within "
                                         f"{p.trainer_timeout_s:g} s")
                self._answered.wait(min(left, 0.5))
            answer = self._answers.pop(rid)
        self.scene_s.append(time.monotonic() - t0)
        if not answer.get("ok"):
            raise SceneRefused(f"{p.source}: the trainer on {p.trainer_done_topic!r} refused "
                               f"the scene: {answer.get('error') or 'no reason given'}")

    def rebase(self, base: Any) -> None:
        """Put the learner's model of the arm's base at ``base`` (another world places
        the same arm elsewhere): new kinematics and learner arm over the same client,
        so one process keeps one node per arm."""
        if base == self.base:
            return
        kin = Kinematics(self.profile, base)
        if self.kin is not None:
            self.kin.close()
        log, self.base, self.kin = self.arm.log, base, kin
        self.arm = LearnerArm(self.client, kin)
        self.arm.log = log  # every goal of the process (GOAL_LOG_ENV)

    def close(self) -> None:
        """Release the kinematics and the node (idempotent)."""
        if self.kin is not None:
            self.kin.close()
            self.kin = None
        if self.client is not None:
            self.client.close()
            self.client = None


_CONNECTION: dict[str, Connection] = {}
"""This process's connections, one per robot profile (one node per arm)."""


def profile_name(manifest: Any) -> str:
    """Return the robot profile ``manifest`` names (a name under ``robots/`` or a
    ``.toml`` path: the case's robot, or ``--robot``'s in a run's manifest)."""
    m = manifest
    if not m.robot:
        raise WorldFileError(f"{m.folder / 'case.toml'}: field 'robot': missing (the ros "
                             "backend drives the arm of a robot profile: --robot NAME|PATH)")
    return m.robot


def world_base(world: Any) -> Any:
    """Return the arm's base pose (position, quaternion) where ``world`` places it
    (its scene's ``[robot.NAME] base``), or None for the profile's ``[base]``."""
    rs = getattr(getattr(world, "scene", None), "robot", None)
    if rs is None or rs.base is None:
        return None
    from creative_py.backends.ros.twin import base_pose

    return base_pose(rs.profile, *rs.base)


def connection(world: Any) -> Connection:
    """Return this process's connection to the arm of the profile ``world``'s manifest
    names (:func:`profile_name`), made on first use and kept, one per profile; the
    learner's kinematics and bounds put the arm's base where ``world`` places it
    (:func:`world_base`; :meth:`Connection.rebase` when another world placed it
    elsewhere).

    Raises
    ------
    WorldFileError
        A bad profile (naming its file and field).
    ArmAbsent
        The arm did not answer within :data:`WAIT_ENV` seconds (naming the topic or
        action it waited for).
    WorldFileError
        ``ROS_SECURITY_ENABLE=true`` with a Fast DDS built without DDS Security (the
        PyPI wheels'), in one line.

    Warns (logging) when discovery reaches beyond the host without DDS Security
    (:func:`~creative_py.backends.ros.client.discovery_warning`).
    """
    name = profile_name(world.manifest)
    base = world_base(world)
    conn = _CONNECTION.get(name)
    if conn is not None and conn.client is not None:
        conn.rebase(base)
        return conn
    profile = load_profile(name)
    warning = discovery_warning(os.environ)
    if warning:
        log.warning("%s", warning)
    try:
        wait = float(os.environ.get(WAIT_ENV) or 20.0)
    except ValueError:
        raise WorldFileError(f"environment variable {WAIT_ENV}: must be a number of "
                             f"seconds, got {os.environ[WAIT_ENV]!r}") from None
    try:
        conn = Connection(profile, wait, base)
    except ArmUnavailable as exc:
        raise ArmAbsent(f"{profile.source}: {exc}: no arm answers (start the arm or the "
                        f"stand-in first, docs/real-robot.md)") from None
    except RuntimeError as exc:  # rclpy's RCLError: the node could not be made
        said = " ".join(str(exc).split())
        if "SECURITY=ON" not in said:
            raise
        raise WorldFileError(
            "ROS_SECURITY_ENABLE=true: this ROS 2's Fast DDS is built without DDS Security "
            "(it said: 'Please compile Fast DDS using the -DSECURITY=ON CMake option'; the "
            "PyPI wheels' is): run the learner with the lab's own ROS 2 install and SROS2, "
            "or on an isolated robot network (docs/real-robot.md, Network safety)") from None
    _CONNECTION[name] = conn
    return conn


GOAL_LOG_ENV = "CREATIVE_ROS_GOAL_LOG"
"""The environment variable of a JSON file to write, at the process's end, every goal's
timings (:attr:`~creative_py.backends.ros.motion.LearnerArm.log`) and the scene set-ups'
seconds: the benchmark's (``bench/ros_hook_bench.py``)."""


def _close_connections() -> None:
    path = os.environ.get(GOAL_LOG_ENV)
    if path and _CONNECTION:
        data = {name: {"goals": conn.arm.log, "scene_s": conn.scene_s}
                for name, conn in _CONNECTION.items()}
        Path(path).write_text(json.dumps(data), encoding="utf-8")
    for conn in _CONNECTION.values():
        try:
            conn.close()
        except Exception:  # noqa: BLE001  (the process is ending)
            pass
    _CONNECTION.clear()


# Close the node before the interpreter's thread pools refuse new work (their exit
# hook runs at threading's shutdown, before atexit's, in reverse order of registration:
# this one, registered later, runs first); atexit as well, where that hook is missing.
try:
    threading._register_atexit(_close_connections)  # type: ignore[attr-defined]
except (AttributeError, RuntimeError):
    pass
atexit.register(_close_connections)


# ------------------------------------------------------------------ the protocol
def load_world(manifest: Any) -> Any:
    """Return the case's world as its files describe it for the manifest's robot, without
    a clip camera; connect to the arm (:func:`connection`). Raise WorldFileError for a
    case that binds a primitive this backend does not run, an oracle that reads an
    object it does not follow (or a velocity), a bad profile, or an absent arm."""
    from creative_py.world.read import load_world as read_world

    profile_name(manifest)  # no robot: one line naming the case file
    world = read_world(manifest)
    world = replace(world, scene=replace(world.scene, video=None))
    bad = unsupported_skills(world) or unjudged_oracle(world)
    if bad:
        raise WorldFileError(bad[0])
    connection(world)
    return world


@contextmanager
def open_episode(world: Any, variant: str, location: int, tool: str, seed: int = 0,
                 gui: bool = False, images_dir: Optional[Path] = None,
                 pose_target: Any = None, *, robot: bool = True,
                 record: Any = None) -> Iterator[RosEpisode]:
    """Ask the trainer for the scene and yield its :class:`RosEpisode`.

    ``gui`` and ``record`` are refused (a real arm has no simulator window and no
    clip); ``images_dir`` is ignored (no camera frames: motion capture).
    """
    if gui:
        raise ValueError(display_reachable())
    if record is not None:
        raise ValueError("the ros backend records no clips (its world has no video camera)")
    if world.variation:
        raise WorldFileError(f"{world.variation}: the ros backend runs the world as its files "
                             "say; a drawn world (--world-seed) is not one the trainer's "
                             "scene requests can set up")
    conn = connection(world)
    ep = RosEpisode(conn, world, variant, location, tool, seed, pose_target, robot=robot)
    try:
        ep.set_up()
        yield ep
    finally:
        ep.close()


def tool_rests(world: Any, tool: str) -> bool:
    """Return whether the tool rests where the world puts it, as the world files'
    physics says (the learner's model: a drawn world is checked before a person sets
    it up; the twin's answer, :mod:`.twin`)."""
    from creative_py.backends.ros.twin import tool_rests as model_rests

    return model_rests(world, tool)


def display_reachable() -> Optional[str]:
    """The ros backend has no simulator window."""
    return "the ros backend drives an arm over ROS 2: it has no simulator window (drop --gui)"


def recorder(camera: Any) -> Any:
    """No clips: the ros backend's worlds have no video camera."""
    raise ValueError("the ros backend records no clips")


Episode = RosEpisode
"""The backend's episode class (:class:`creative_py.simulator.Episode`)."""

__all__ = ["ArmAbsent", "Connection", "Episode", "SceneRefused", "connection",
           "display_reachable", "load_world", "open_episode", "recorder", "tool_rests"]
