"""The simulated arm of a robot profile: loading, IK, guarded position control, grasping.

Everything the code knows of an arm comes from its profile (:mod:`creative_py.robots`,
``robots/<name>.toml``): the URDF (example-robot-data's or a lab's; its
``package://`` mesh paths are rewritten once into a cached copy, with or without
``<visual>`` elements), the base pose, the arm's joints, the end-effector link and the
tool frame on it, the home posture, the idle joints, the hand, the collision links and
the IK settings. The tool frame's +z axis points out of the gripper (the profile's
``approach_axis`` says which axis of its ``ee_link`` that is), so the attitudes below
(:func:`gripper_forward`, :func:`gripper_down`) mean the same for every arm.

IK is solved in a second DIRECT client holding a kinematics-only model, so trying a
target never disturbs the physics.

How heavy the robot is (:data:`ROBOT`): the ``light`` robot (the default) has in the
physics a model whose idle joints (the profile's ``[idle]``: another arm, a head) are
fixed at the posture they are held in and whose idle links are merged into the link
they hang from, so that a physics step simulates only the joints that act. In every
mode but ``heavy`` the kinematics client holds only the chain from the base to the
end-effector link, is loaded once per process and profile and kept for every robot
after (an episode loads one URDF), and the start posture's via solution is searched
once per target; IK answers are bit for bit those of the full model. Fewer joints
change the rows of pybullet's constraint solver, and with them the rounding of the
arm's motion: the ``light`` gripper's path differs from the full model's by about
0.01 mm, so a trial that is borderline for a guard can end differently. The ``exact``
mode keeps the full physics model and so the heavy robot's results bit for bit.

Moves are Cartesian straight lines sampled every ``steps_per_waypoint`` physics steps;
each waypoint is an IK solution seeded from the previous one, sent as position targets
at the URDF effort limits. A move ends ``blocked`` when the gripper lags its target by
more than ``max_tracking_error`` (it hit something), ``unreachable`` when IK cannot
reach a waypoint, ``invalid`` when the physics produces NaN. After every waypoint the
arm also measures where its own links strike the scene bodies it was given
(:meth:`Arm.watch_strikes`, :meth:`Arm.take_strikes`): a strike stops nothing (the
physics goes on as without it); the episode reports it with the skill
(``SkillOutcome.struck``) and the trial's outcome rule reads it.
"""

from __future__ import annotations

import hashlib
import logging
import math
import os
import re
import tempfile
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterator, Sequence

import numpy as np
import pybullet as pb

from creative_py.backends.pybullet.core import Point, Pose, Quat, Sim
from creative_py.robots import RobotProfile, erd_share_dir, load_profile
from creative_py.simulator.paths import Unreachable, quat_angle, slerp, straight_line
from creative_py.simulator.types import SkillOutcome, Verdict

log = logging.getLogger(__name__)

ROBOT_MODES = ("light", "exact", "heavy")
"""How heavy the robot is: ``light`` (idle joints fixed and merged in the physics, a
shared kinematics client with the arm's chain, the via solution cached),
``exact`` (the same but every joint simulated: results bit for bit the heavy ones),
``heavy`` (every joint simulated, a kinematics client with the full model and a
second URDF load per robot, no via cache)."""

ROBOT_ENV = "CREATIVE_ROBOT"
"""Environment variable read at import into :data:`ROBOT` (one of :data:`ROBOT_MODES`)."""

ROBOT: str = os.environ.get(ROBOT_ENV, "").strip() or "light"
"""The mode of every :class:`Arm` built without one (default ``light``); the
per-trial CPU benchmark (``bench/robot_cost_bench.py``) sets it to run all three."""

_URDF_EDITS = "v4: meshes, root inertial, optional visuals, light and arm models"
"""Changes with the edits below, so that a stale cached URDF is never reused."""

URDF_MODELS = ("full", "light", "arm")
"""The models :func:`arm_urdf` writes: every joint; the profile's idle joints fixed
and merged; the chain from the base to the end-effector link only (kinematics)."""

_APPROACH: dict[str, tuple[float, float, float]] = {
    "+z": (0.0, 0.0, 0.0), "-z": (math.pi, 0.0, 0.0),
    "+x": (0.0, math.pi / 2, 0.0), "-x": (0.0, -math.pi / 2, 0.0),
    "+y": (-math.pi / 2, 0.0, 0.0), "-y": (math.pi / 2, 0.0, 0.0)}
"""The rotation (rpy) that turns each approach axis of the tool frame into its +z."""


def tool_frame(profile: RobotProfile) -> Pose | None:
    """Return the tool frame in the end-effector link's frame (+z out of the gripper),
    or None where it is the link's own frame (the pose is then never composed, so that
    such an arm's numbers are exactly its link's)."""
    if profile.tool_xyz == (0.0, 0.0, 0.0) and profile.tool_rpy == (0.0, 0.0, 0.0) \
            and profile.approach_axis == "+z":
        return None
    pos, quat = pb.multiplyTransforms(profile.tool_xyz,
                                      pb.getQuaternionFromEuler(profile.tool_rpy), (0, 0, 0),
                                      pb.getQuaternionFromEuler(_APPROACH[profile.approach_axis]))
    return tuple(pos), tuple(quat)


def _rewrite_packages(text: str, profile: RobotProfile) -> str:
    """Return the URDF text with every ``package://NAME/`` replaced by a folder: the
    profile's ``[packages]`` entry, else example-robot-data's share folder."""
    dirs = dict(profile.packages)

    def folder(m: re.Match) -> str:
        name = m.group(1)
        if name in dirs:
            return dirs[name].rstrip("/") + "/"
        try:
            return str(erd_share_dir()) + "/" + name + "/"
        except FileNotFoundError:
            raise FileNotFoundError(f"{profile.source}: field 'packages': the URDF needs "
                                    f"package://{name}/, which no folder names") from None

    return re.sub(r"package://([^/\"']+)/", folder, text)


def arm_urdf(profile: RobotProfile, visuals: bool = False, model: str = "full") -> Path:
    """Return a cached copy of the profile's URDF with absolute mesh paths.

    Parameters
    ----------
    profile : RobotProfile
        The arm.
    visuals : bool
        Keep the ``<visual>`` elements (slow to load); never for ``arm``.
    model : {"full", "light", "arm"}
        ``full``: the robot as shipped. ``light``: the profile's idle joints fixed at
        their values and every link below them merged into the link the idle part
        hangs from (its shapes kept where the held posture puts them, its mass
        dropped). ``arm``: only the links from the base to the end-effector link
        (kinematics).
    """
    if model not in URDF_MODELS:
        raise ValueError(f"URDF model must be one of {', '.join(URDF_MODELS)}, got {model!r}")
    src = profile.urdf_path
    text = src.read_text()
    key = hashlib.sha1((str(src) + text + str(visuals) + model + repr(sorted(profile.idle.items()))
                        + profile.ee_link + repr(sorted(profile.packages.items()))
                        + _URDF_EDITS).encode()).hexdigest()[:12]
    out = Path(tempfile.gettempdir()) / f"creative_py_{profile.name}_{key}.urdf"
    if not out.is_file():
        text = _rewrite_packages(text, profile)
        if not visuals or model == "arm":
            text = re.sub(r"<visual>.*?</visual>", "", text, flags=re.S)
        if model == "full":  # the text as shipped, but for the root's inertial
            text = _root_inertial_text(text)
        else:
            root = ET.fromstring(text)
            _root_inertial(root)
            if model == "light":
                _merge_idle(root, profile.idle)
            else:
                _keep_chain(root, profile.ee_link)
            text = ET.tostring(root, encoding="unicode")
        tmp = out.with_suffix(f".{os.getpid()}.{id(text)}.tmp")
        tmp.write_text(text)
        tmp.replace(out)
    return out


def _root_link(root: ET.Element) -> str:
    children = {j.find("child").get("link") for j in root.findall("joint")}
    return next(e.get("name") for e in root.findall("link") if e.get("name") not in children)


_TINY_INERTIAL = ('<inertial><mass value="0.001"/><inertia ixx="1e-6" ixy="0" ixz="0" '
                  'iyy="1e-6" iyz="0" izz="1e-6"/></inertial>')


def _root_inertial(root: ET.Element) -> None:
    """Give a fixed root link without ``<inertial>`` a tiny one, so that pybullet does not
    print a warning on every load (its mass is irrelevant: it is fixed)."""
    name = _root_link(root)
    link = next(e for e in root.findall("link") if e.get("name") == name)
    if link.find("inertial") is None:
        link.append(ET.fromstring(_TINY_INERTIAL))


def _root_inertial_text(text: str) -> str:
    """The same edit in the text of the full model (kept as shipped otherwise)."""
    name = _root_link(ET.fromstring(text))
    m = re.search(r'<link\s+name="%s"\s*>\s*</link>' % re.escape(name), text)
    if m is None:
        m = re.search(r'<link\s+name="%s"\s*/>' % re.escape(name), text)
    if m is None:
        return text
    return text[:m.start()] + f'<link name="{name}">{_TINY_INERTIAL}</link>' + text[m.end():]


def _floats(text: str) -> tuple[float, ...]:
    return tuple(float(v) for v in text.split())


def _origin(element: ET.Element) -> Pose:
    """Return the ``<origin>`` of a URDF joint, visual or collision as a pose."""
    o = element.find("origin")
    xyz = _floats(o.get("xyz", "0 0 0")) if o is not None else (0.0, 0.0, 0.0)
    rpy = _floats(o.get("rpy", "0 0 0")) if o is not None else (0.0, 0.0, 0.0)
    return xyz, tuple(pb.getQuaternionFromEuler(rpy))


def _set_origin(element: ET.Element, pose: Pose) -> None:
    o = element.find("origin")
    if o is None:
        o = ET.SubElement(element, "origin")
    o.set("xyz", " ".join(repr(float(v)) for v in pose[0]))
    o.set("rpy", " ".join(repr(float(v)) for v in pb.getEulerFromQuaternion(pose[1])))


def _joint_pose(joint: ET.Element, value: float) -> Pose:
    """Return the child link's frame in the parent link's frame at joint ``value``."""
    origin = _origin(joint)
    kind = joint.get("type")
    axis_el = joint.find("axis")
    axis = _floats(axis_el.get("xyz")) if axis_el is not None else (1.0, 0.0, 0.0)
    if kind == "fixed" or value == 0.0:
        motion: Pose = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
    elif kind in ("revolute", "continuous"):
        motion = ((0.0, 0.0, 0.0), tuple(pb.getQuaternionFromAxisAngle(axis, value)))
    elif kind == "prismatic":
        motion = (tuple(a * value for a in axis), (0.0, 0.0, 0.0, 1.0))
    else:
        raise ValueError(f"joint {joint.get('name')}: cannot hold a {kind} joint")
    pos, quat = pb.multiplyTransforms(origin[0], origin[1], motion[0], motion[1])
    return tuple(pos), tuple(quat)


def _merge_idle(root: ET.Element, hold: dict[str, float]) -> None:
    """Fix the joints of ``hold`` at their values; merge every link below them.

    Each idle part's links are removed with their joints; their visual and collision
    elements move to the link the part hangs from, with origins composed along the
    held joints. Raises ValueError if a joint below an idle one moves and is not idle.
    """
    links = {e.get("name"): e for e in root.findall("link")}
    joints = {e.get("name"): e for e in root.findall("joint")}
    below: dict[str, list[ET.Element]] = {}
    for j in joints.values():
        below.setdefault(j.find("parent").get("link"), []).append(j)
    merged: set[str] = set()

    def absorb(target: ET.Element, joint: ET.Element, frame: Pose) -> None:
        name = joint.get("name")
        if joint.get("type") != "fixed" and name not in hold:
            raise ValueError(f"joint {name} moves below an idle joint but is not idle")
        child = joint.find("child").get("link")
        f = _joint_pose(joint, hold.get(name, 0.0))
        pose = tuple(map(tuple, pb.multiplyTransforms(frame[0], frame[1], f[0], f[1])))
        link = links[child]
        for tag in ("visual", "collision"):
            for e in link.findall(tag):
                o = _origin(e)
                _set_origin(e, pb.multiplyTransforms(pose[0], pose[1], o[0], o[1]))
                target.append(e)
        root.remove(link)
        root.remove(joint)
        merged.add(name)
        for j in below.get(child, []):
            absorb(target, j, pose)

    idle_children = {joints[n].find("child").get("link") for n in hold}
    for name in hold:
        if name not in joints:
            raise ValueError(f"the URDF has no idle joint {name}")
    for name in hold:
        parent = joints[name].find("parent").get("link")
        if name not in merged and not _below_any(parent, idle_children, joints):
            absorb(links[parent], joints[name], ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
    for t in root.findall("transmission"):
        if any(j.get("name") in merged for j in t.iter("joint")):
            root.remove(t)


def _below_any(link: str, tops: set[str], joints: dict[str, ET.Element]) -> bool:
    """Return whether ``link`` is one of ``tops`` or hangs below one of them."""
    parent_of = {j.find("child").get("link"): j.find("parent").get("link")
                 for j in joints.values()}
    while link is not None:
        if link in tops:
            return True
        link = parent_of.get(link)
    return False


def _keep_chain(root: ET.Element, tip: str) -> None:
    """Remove every link (and joint) that is not on the way from the root to ``tip``."""
    parent_of = {j.find("child").get("link"): j.find("parent").get("link")
                 for j in root.findall("joint")}
    keep, link = set(), tip
    while link is not None:
        keep.add(link)
        link = parent_of.get(link)
    for e in root.findall("link"):
        if e.get("name") not in keep:
            root.remove(e)
    for e in root.findall("joint"):
        if e.find("child").get("link") not in keep:
            root.remove(e)
    for e in root.findall("transmission"):
        root.remove(e)


@dataclass(frozen=True)
class ArmConfig:
    """Settings of the arm's controller (the profile holds the arm's own facts).

    Attributes
    ----------
    visuals : bool
        Load the visual meshes (slow) so cameras see the robot.
    speed : float
        Default Cartesian speed of the gripper, m/s.
    turn_speed : float
        Fastest rotation of the gripper during a move, rad/s.
    steps_per_waypoint : int
        Physics steps between two IK waypoints.
    max_tracking_error : float
        Gripper lag (m) beyond which a move stops as ``blocked``.
    max_turn_error : float
        Gripper orientation lag (rad) beyond which a move stops as ``blocked``.
    settle_steps : int
        Most physics steps spent at the end of a move waiting for the arm to converge.
    max_body_speed : float
        A held or watched body moving faster than this (m/s) is a physics blow-up.
    """

    visuals: bool = False
    speed: float = 0.10
    turn_speed: float = 1.0
    steps_per_waypoint: int = 4
    max_tracking_error: float = 0.03
    max_turn_error: float = 0.3
    settle_steps: int = 120
    max_body_speed: float = 5.0


GRIPPER_FORWARD: Quat = tuple(pb.getQuaternionFromEuler((0.0, math.pi / 2, 0.0)))
"""Orientation of the tool frame pointing along +x world (its +z axis), roll 0."""


def gripper_forward(roll: float) -> Quat:
    """Return the gripper orientation pointing +x world, turned by ``roll`` (rad) about x."""
    return tuple(pb.multiplyTransforms((0, 0, 0), pb.getQuaternionFromEuler((roll, 0, 0)),
                                       (0, 0, 0), GRIPPER_FORWARD)[1])


def gripper_down(yaw: float) -> Quat:
    """Return the gripper orientation pointing down (-z) with its x axis at ``yaw`` (rad)."""
    return tuple(pb.getQuaternionFromEuler((math.pi, 0.0, yaw)))


GRIPPER_ATTITUDES = {"forward": gripper_forward, "down": gripper_down}
"""Gripper orientations by name, each a function of one angle (rad)."""


def rotation_vector(q_from: Sequence[float], q_to: Sequence[float]) -> np.ndarray:
    """Return the rotation vector (axis * angle, rad, world frame) taking q_from to q_to."""
    x, y, z, w = pb.multiplyTransforms((0, 0, 0), q_to, (0, 0, 0),
                                       pb.invertTransform((0, 0, 0), q_from)[1])[1]
    if w < 0:
        x, y, z, w = -x, -y, -z, -w
    s = math.sqrt(x * x + y * y + z * z)
    if s < 1e-12:
        return np.zeros(3)
    angle = 2.0 * math.atan2(s, w)
    return np.array([x, y, z]) * (angle / s)


def _ik_step(jac: np.ndarray, err: np.ndarray, q: np.ndarray, lo: np.ndarray,
             hi: np.ndarray, drift: np.ndarray) -> np.ndarray:
    """Return one damped-least-squares step of the arm's joints (rad) that reduces
    ``err`` (the tool frame's position then orientation error, m and rad) through the
    6 x n Jacobian ``jac``, with ``drift`` (rad, towards mid-range) in the null space,
    at most 0.2 rad per joint.

    Joints pinned at a limit (``lo``, ``hi``) and pushed beyond it are taken out of the
    Jacobian (an active set), so the others do the work instead of the solver stalling
    against the clamp.
    """
    n = len(q)
    damped = 1e-4 * np.eye(6)
    eye = np.eye(n)
    free = np.ones(n)
    for _ in range(3):
        jf = jac * free
        pinv = jf.T @ np.linalg.inv(jf @ jf.T + damped)
        dq = pinv @ err
        # Secondary task in the null space: drift towards mid-range, so that
        # long Cartesian paths do not run the arm into a joint limit.
        dq += (eye - pinv @ jf) @ (drift * free)
        pinned = ((q <= lo + 1e-6) & (dq < 0)) | ((q >= hi - 1e-6) & (dq > 0))
        if not np.any(pinned & (free > 0)):
            break
        free[pinned] = 0.0
    biggest = float(np.max(np.abs(dq)))
    if biggest > 0.2:
        dq *= 0.2 / biggest
    return dq


class _Model:
    """A loaded arm in one client: joint tables and helpers."""

    def __init__(self, client: int, urdf: Path, profile: RobotProfile,
                 base: Pose = ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))) -> None:
        self.client = client
        self.profile = profile
        self.body = pb.loadURDF(str(urdf), base[0], base[1], useFixedBase=True,
                                physicsClientId=client)
        if self.body < 0:
            raise RuntimeError(f"{urdf}: pybullet could not load the URDF of {profile.source}")
        self._read_joints()
        self._check_names()
        self.arm = [self.joint[n] for n in profile.arm_joints]
        self.idle = [self.joint[n] for n in profile.idle if n in self.joint
                     and self.joint[n] in self.movable]
        """The idle joints that move in this model (none in the light robot)."""
        self.idle_q = [profile.idle[n] for n in profile.idle if n in self.joint
                       and self.joint[n] in self.movable]
        self.ee = self.link[profile.ee_link]
        self.tool = tool_frame(profile)
        self._jacobian_frames(base)
        self._arm_limits()

    def _read_joints(self) -> None:
        """Read the URDF's joint table: joint and child-link names to joint indices, the
        moving joints with their limits (rad or m) and efforts (N m or N)."""
        client = self.client
        self.joint: dict[str, int] = {}
        self.link: dict[str, int] = {}
        self.movable: list[int] = []
        self.lower: list[float] = []
        self.upper: list[float] = []
        self.effort: dict[int, float] = {}
        self.base_link = pb.getBodyInfo(self.body, physicsClientId=client)[0].decode()
        for j in range(pb.getNumJoints(self.body, physicsClientId=client)):
            info = pb.getJointInfo(self.body, j, physicsClientId=client)
            name = info[1].decode()
            self.joint[name] = j
            self.link[info[12].decode()] = j
            if info[2] != pb.JOINT_FIXED:
                self.movable.append(j)
                self.lower.append(info[8])
                self.upper.append(info[9])
                self.effort[j] = info[10]

    def _check_names(self) -> None:
        """Raise the profile's error unless its arm joints move in the URDF and its
        end-effector link is one of the URDF's links."""
        profile = self.profile
        missing = [n for n in profile.arm_joints if n not in self.joint
                   or self.joint[n] not in self.movable]
        if missing:
            raise profile.error("kinematics.joints", f"{missing[0]!r} is no moving joint of "
                                f"{profile.urdf_path.name}")
        if profile.ee_link not in self.link:
            raise profile.error("kinematics.ee_link", f"{profile.ee_link!r} is no link of "
                                f"{profile.urdf_path.name}")

    def _jacobian_frames(self, base: Pose) -> None:
        """Set what the Jacobians need: the base's rotation, the end-effector link's
        centre-of-mass frame and the tool frame's origin in it."""
        self.base_rotation: np.ndarray | None = None
        """The base's rotation matrix where it is turned: pybullet's Jacobians are in the
        base's frame, IK's errors in the world's."""
        if tuple(base[1]) != (0.0, 0.0, 0.0, 1.0):
            self.base_rotation = np.array(pb.getMatrixFromQuaternion(base[1])).reshape(3, 3)
        st = pb.getLinkState(self.body, self.ee, physicsClientId=self.client)
        self.ee_com: Pose | None = None
        """The end-effector link's centre-of-mass frame in its link frame, None where
        they coincide (pybullet's Jacobians and constraints are taken there)."""
        if tuple(st[2]) != (0.0, 0.0, 0.0) or tuple(st[3]) != (0.0, 0.0, 0.0, 1.0):
            self.ee_com = (tuple(st[2]), tuple(st[3]))
        self.jacobian_point: tuple[float, float, float] = (0.0, 0.0, 0.0)
        """The tool frame's origin in the end-effector link's centre-of-mass frame."""
        if self.tool is not None or self.ee_com is not None:
            self.jacobian_point = self.in_ee_com(((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))[0]

    def _arm_limits(self) -> None:
        """Set the arm joints' limits (rad; infinite for a continuous joint)."""
        self.arm_in_movable = [self.movable.index(j) for j in self.arm]
        lower = np.array([self.lower[i] for i in self.arm_in_movable])
        upper = np.array([self.upper[i] for i in self.arm_in_movable])
        # pybullet reports a continuous joint with lower > upper: no limits, no centring.
        self.continuous = lower > upper
        self.arm_lower = np.where(self.continuous, -np.inf, lower)
        self.arm_upper = np.where(self.continuous, np.inf, upper)

    def in_ee_com(self, pose: Pose) -> Pose:
        """Return a pose given in the tool frame in the end-effector link's
        centre-of-mass frame."""
        tool = self.tool or ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
        com = self.ee_com or ((0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))
        inv = pb.invertTransform(com[0], com[1])
        p, q = pb.multiplyTransforms(inv[0], inv[1], tool[0], tool[1])
        p, q = pb.multiplyTransforms(p, q, pose[0], pose[1])
        return tuple(p), tuple(q)

    def reset(self, joints: Sequence[int], q: Sequence[float]) -> None:
        pb.resetJointStatesMultiDof(self.body, list(joints), [[float(v)] for v in q],
                                    targetVelocities=[[0.0]] * len(joints),
                                    physicsClientId=self.client)

    def ee_pose(self) -> Pose:
        """Return the world pose of the tool frame."""
        st = pb.getLinkState(self.body, self.ee, computeForwardKinematics=True,
                             physicsClientId=self.client)
        if self.tool is None:
            return tuple(st[4]), tuple(st[5])
        pos, quat = pb.multiplyTransforms(st[4], st[5], self.tool[0], self.tool[1])
        return tuple(pos), tuple(quat)

    def arm_jacobian(self, q: np.ndarray) -> np.ndarray:
        """Return the tool frame's 6 x n Jacobian (linear then angular rows, world
        frame) at the arm's joint angles ``q`` (rad), the model being posed at ``q``."""
        zeros = [0.0] * len(self.movable)
        full = [0.0] * len(self.movable)
        for i, v in zip(self.arm_in_movable, q):
            full[i] = float(v)
        lin, ang = pb.calculateJacobian(self.body, self.ee, self.jacobian_point, full, zeros,
                                        zeros, physicsClientId=self.client)
        cols = self.arm_in_movable
        lin, ang = np.asarray(lin)[:, cols], np.asarray(ang)[:, cols]
        if self.base_rotation is not None:
            lin, ang = self.base_rotation @ lin, self.base_rotation @ ang
        return np.vstack([lin, ang])

    def arm_q(self) -> list[float]:
        return [pb.getJointState(self.body, j, physicsClientId=self.client)[0]
                for j in self.arm]


_KINEMATICS: dict = {}
"""``(profile file, base pose) -> (pid, model)``: this process's kinematics models (a
fork loads its own)."""


def base_pose(profile: RobotProfile, position=None, rpy=None) -> Pose:
    """Return the arm's base pose in the world: the profile's, or the given one."""
    pos = tuple(float(v) for v in (profile.base_position if position is None else position))
    ang = profile.base_rpy if rpy is None else rpy
    return pos, tuple(pb.getQuaternionFromEuler(ang))


def kinematics_model(profile: RobotProfile, base: Pose | None = None) -> _Model:
    """Return this process's kinematics-only model of the profile's arm (its chain).

    It lives in its own DIRECT client, loaded on first use and kept for every robot
    after: IK resets the arm before each query, so no robot sees another's state.
    """
    base = base_pose(profile) if base is None else base
    key = (profile.source, str(profile.urdf_path), base)
    pid = os.getpid()
    got = _KINEMATICS.get(key)
    if got and got[0] == pid and pb.isConnected(got[1].client):
        return got[1]
    client = pb.connect(pb.DIRECT)
    if client < 0:
        raise RuntimeError("pybullet: could not connect the kinematics client")
    model = _Model(client, arm_urdf(profile, False, "arm"), profile, base)
    _KINEMATICS[key] = (pid, model)
    return model


class Arm:
    """The arm of a robot profile in a :class:`Sim`, with a kinematics client for IK.

    Parameters
    ----------
    sim : Sim
        The physics client to load the robot into.
    profile : RobotProfile or str
        The arm (a profile or its name).
    config : ArmConfig
        Controller settings.
    mode : str or None
        One of :data:`ROBOT_MODES`; None takes :data:`ROBOT`.
    base : Pose or None
        The base link's world pose (a world's placement); None: the profile's.
    """

    def __init__(self, sim: Sim, profile: RobotProfile | str, config: ArmConfig = ArmConfig(),
                 mode: str | None = None, base: Pose | None = None) -> None:
        self.sim = sim
        self.profile = load_profile(profile) if isinstance(profile, str) else profile
        self.config = config
        self.mode = ROBOT if mode is None else mode
        if self.mode not in ROBOT_MODES:
            raise ValueError(f"robot mode (environment variable {ROBOT_ENV}) must be one of "
                             f"{', '.join(ROBOT_MODES)}, got {self.mode!r}")
        self.base = base_pose(self.profile) if base is None else base
        self.light = self.mode != "heavy"
        """Shared kinematics client, cached via solution (every mode but ``heavy``)."""
        self.urdf = arm_urdf(self.profile, config.visuals,
                             "light" if self.mode == "light" else "full")
        """The URDF file the robot was loaded from."""
        self.model = _Model(sim.client, self.urdf, self.profile, self.base)
        self.body = self.model.body
        if self.light:
            self._kin_client = -1  # the shared one: not this robot's to close
            self.kin = kinematics_model(self.profile, self.base)
        else:
            self._kin_client = pb.connect(pb.DIRECT)
            self.kin = _Model(self._kin_client, arm_urdf(self.profile, False), self.profile,
                              self.base)
        self.grasp_constraint: int | None = None
        self.held: int | None = None
        self.fingers: list[int] = []
        """A driven hand's finger joints (none without one)."""
        self._hand()
        self.reset_posture(self.profile.home)
        self._limit_collisions()
        self.strike_bodies: dict[int, str] = {}
        """The scene bodies whose strikes by a robot link are measured (id -> name)."""
        self._mount: set[tuple[int, int]] = set()
        self._strikes: dict[tuple[int, int], tuple[float, tuple[float, ...]]] = {}

    def _hand(self) -> None:
        """Set a driven hand up: fingers open, held by motors, coupled by a gear."""
        hand, m, c = self.profile.hand, self.model, self.sim.client
        if hand is None or not hand.driven:
            return
        missing = [n for n in hand.joints if n not in m.joint or m.joint[n] not in m.movable]
        if missing:
            raise self.profile.error("hand.joints", f"{missing[0]!r} is no moving joint of "
                                     f"{self.profile.urdf_path.name}")
        fingers = [m.joint[n] for n in hand.joints]
        m.reset(fingers, hand.open)
        self.fingers = fingers
        self._fingers_to(hand.open)
        if hand.gear_ratio is not None:
            gear = pb.createConstraint(m.body, fingers[0], m.body, fingers[1], pb.JOINT_GEAR,
                                       (1, 0, 0), (0, 0, 0), (0, 0, 0), physicsClientId=c)
            pb.changeConstraint(gear, gearRatio=hand.gear_ratio, erp=0.1,
                                maxForce=hand.max_force, physicsClientId=c)

    def _fingers_to(self, values: Sequence[float]) -> None:
        """Drive a driven hand's fingers to ``values`` (the profile's ``open`` or
        ``closed``), with the hand's ``max_force``."""
        pb.setJointMotorControlArray(self.body, self.fingers, pb.POSITION_CONTROL,
                                     targetPositions=list(values),
                                     forces=[self.profile.hand.max_force] * len(self.fingers),
                                     physicsClientId=self.sim.client)

    def _limit_collisions(self) -> None:
        """Let only the profile's ``collision_links`` collide (a speed-up): the links
        that cannot touch anything on the table only cost time in every step."""
        m = self.model
        prefixes = self.profile.collision_links
        if not prefixes:
            return
        for name, link in [(m.base_link, -1), *m.link.items()]:
            if not name.startswith(prefixes):
                pb.setCollisionFilterGroupMask(m.body, link, 0, 0, physicsClientId=m.client)

    # ------------------------------------------------------------------ state
    def reset_posture(self, arm_q: Sequence[float]) -> None:
        """Teleport the arm to ``arm_q`` (rad) and the idle joints to their values; hold them.

        The light robot's idle joints are held for good (they are fixed).
        """
        m = self.model
        m.reset(m.arm, arm_q)
        if m.idle:
            m.reset(m.idle, m.idle_q)
        self._command(list(arm_q))
        if m.idle:
            pb.setJointMotorControlArray(m.body, m.idle, pb.POSITION_CONTROL,
                                         targetPositions=list(m.idle_q),
                                         forces=[m.effort[j] for j in m.idle],
                                         physicsClientId=self.sim.client)

    def arm_q(self) -> list[float]:
        """Return the arm's joint angles (rad)."""
        return self.model.arm_q()

    def gripper_pose(self) -> Pose:
        """Return the world pose of the tool frame by forward kinematics (proprioception)."""
        return self.model.ee_pose()

    def _command(self, q: Sequence[float]) -> None:
        m = self.model
        pb.setJointMotorControlArray(m.body, m.arm, pb.POSITION_CONTROL,
                                     targetPositions=list(q),
                                     forces=[m.effort[j] for j in m.arm],
                                     physicsClientId=self.sim.client)

    # --------------------------------------------------------------------- IK
    def solve_ik(self, target: Pose, seed: Sequence[float] | None = None,
                 max_iterations: int = 150) -> list[float] | None:
        """Return arm joint angles (rad) putting the tool frame at ``target``.

        Damped least squares on the arm's 6 x n Jacobian (from pybullet, in the
        kinematics client), started from ``seed`` (default: the current arm) and
        clamped to the joint limits. Returns None unless the position error ends
        under the profile's ``ik.position_tolerance`` (m) and the orientation error
        under ``ik.orientation_tolerance`` (rad): the target is then unreachable from
        this seed (out of reach, or a joint limit in the way).
        """
        k = self.kin
        q = np.array(seed if seed is not None else self.arm_q(), dtype=float)
        lo, hi = k.arm_lower, k.arm_upper
        q = np.clip(q, lo, hi)
        # A continuous joint has no mid-range: its drift target is where it is.
        mid = np.where(k.continuous, q, (lo + hi) / 2) if k.continuous.any() else (lo + hi) / 2
        ik = self.profile.ik
        tpos = np.asarray(target[0], float)
        tquat = target[1]
        perr = oerr = math.inf
        for _ in range(max_iterations):
            k.reset(k.arm, q)
            pos, quat = k.ee_pose()
            e_pos = tpos - np.asarray(pos)
            e_rot = rotation_vector(quat, tquat)
            perr, oerr = float(np.linalg.norm(e_pos)), float(np.linalg.norm(e_rot))
            if perr < 1e-4 and oerr < 1e-3:
                break
            if k.continuous.any():
                mid = np.where(k.continuous, q, mid)
            dq = _ik_step(k.arm_jacobian(q), np.concatenate([e_pos, e_rot]), q, lo, hi,
                          ik.centring * (mid - q))
            q = np.clip(q + dq, lo, hi)
        if perr > ik.position_tolerance or oerr > ik.orientation_tolerance:
            return None
        return [float(v) for v in q]

    def ik_candidates(self, target: Pose, keep: int = 6, restarts: int | None = None,
                      seeds: Sequence[Sequence[float]] = ()) -> list[list[float]]:
        """Return up to ``keep`` arm postures (rad) reaching ``target``.

        Solves from ``seeds``, the profile's home posture, the current posture and
        ``restarts`` (default: the profile's ``ik.restarts``) random postures of a
        fixed-seed generator (deterministic), in that order; a continuous joint's
        random angle is drawn within +-pi.
        """
        k = self.kin
        restarts = self.profile.ik.restarts if restarts is None else restarts
        lo = np.where(k.continuous, -math.pi, k.arm_lower)
        hi = np.where(k.continuous, math.pi, k.arm_upper)
        rng = np.random.default_rng(0)
        tries = [*map(list, seeds), list(self.profile.home), self.arm_q()]
        tries += [list(rng.uniform(lo, hi)) for _ in range(restarts)]
        found: list[list[float]] = []
        for seed in tries:
            sol = self.solve_ik(target, seed=seed)
            if sol is not None and all(max(abs(a - b) for a, b in zip(sol, f)) > 0.05
                                       for f in found):
                found.append(sol)
                if len(found) >= keep:
                    break
        return found

    def solve_ik_global(self, target: Pose, restarts: int | None = None, keep: int = 6,
                        seeds: Sequence[Sequence[float]] = ()) -> list[float] | None:
        """Return an arm posture (rad) reaching ``target``, chosen among several.

        Among :meth:`ik_candidates` returns the one farthest from the joint limits
        (the largest smallest margin, as a fraction of each joint's range), or None.
        Margins matter: a joint at its limit cannot help against gravity or contact.
        """
        found = self.ik_candidates(target, keep, restarts, seeds)
        if not found:
            return None
        limited = ~self.kin.continuous  # a continuous joint has no limit to keep from
        lo, hi = self.kin.arm_lower[limited], self.kin.arm_upper[limited]
        if not limited.any():
            return found[0]

        def margin(q: list[float]) -> float:
            qa = np.array(q)[limited]
            return float(np.min(np.minimum(qa - lo, hi - qa) / (hi - lo)))

        return max(found, key=margin)

    def dry_run(self, q_start: Sequence[float], path: Sequence[Pose],
                max_step: float = 0.01) -> list[float] | None:
        """Follow ``path`` (gripper poses joined by straight lines) in the kinematics client.

        Starts at ``q_start``; returns the final posture, or None where IK loses the
        path or the arm would have to jump (> 0.5 rad). Nothing moves in the physics.
        """
        q = list(q_start)
        k = self.kin
        k.reset(k.arm, q)
        prev = k.ee_pose()
        for target in path:
            dist = math.dist(prev[0], target[0])
            ang = quat_angle(prev[1], target[1])
            n = max(1, math.ceil(max(dist / max_step, ang / (10 * max_step))))
            for i in range(1, n + 1):
                t = i / n
                pos = tuple(a + t * (b - a) for a, b in zip(prev[0], target[0]))
                sol = self.solve_ik((pos, slerp(prev[1], target[1], t)), seed=q)
                if sol is None or max(abs(a - b) for a, b in zip(sol, q)) > 0.5:
                    return None
                q = sol
            prev = target
        return q

    def move_joints(self, q_goal: Sequence[float], joint_speed: float | None = None,
                    check: bool = True, watch: Sequence[int] = ()) -> SkillOutcome:
        """Move the arm in joint space to ``q_goal`` (rad), fastest joint at ``joint_speed``
        rad/s (default: the profile's ``kinematics.max_joint_speed``).

        The tracking guard compares the gripper with the forward kinematics of the
        commanded posture.
        """
        cfg = self.config
        joint_speed = self.profile.joint_speed if joint_speed is None else joint_speed
        q0 = np.array(self.arm_q())
        q1 = np.array(q_goal, dtype=float)
        step = joint_speed * cfg.steps_per_waypoint * self.sim.physics.time_step
        n = max(1, math.ceil(float(np.max(np.abs(q1 - q0))) / step))
        k = self.kin
        for i in range(1, n + cfg.settle_steps // cfg.steps_per_waypoint + 1):
            q = q0 + min(1.0, i / n) * (q1 - q0)
            self._command(q)
            self.sim.step(cfg.steps_per_waypoint)
            k.reset(k.arm, q)
            commanded = k.ee_pose()[0]
            bad = self._check(commanded, check, watch)
            if bad is not None:
                return bad
            if i >= n and math.dist(self.gripper_pose()[0], commanded) < 0.001:
                break
        return SkillOutcome("ok")

    def reach(self, target: Pose, joint_speed: float | None = None,
              watch: Sequence[int] = ()) -> SkillOutcome:
        """Go to ``target`` (gripper pose) through joint space: for moves in free space."""
        q = self.solve_ik_global(target)
        if q is None:
            p = target[0]
            return SkillOutcome("unreachable", f"IK found no arm posture for gripper at "
                              f"({p[0]:.3f}, {p[1]:.3f}, {p[2]:.3f}) m")
        return self.move_joints(q, joint_speed, watch=watch)

    # ----------------------------------------------------------------- motion
    def move_to(self, target: Pose, speed: float | None = None, check: bool = True,
                watch: Sequence[int] = (),
                guard: Callable[[], SkillOutcome | None] | None = None) -> SkillOutcome:
        """Move the gripper in a straight line (slerped orientation) to ``target``.

        Parameters
        ----------
        target : Pose
            World pose of the tool frame.
        speed : float or None
            Cartesian speed, m/s (default ``config.speed``); the orientation turns at
            most at ``config.turn_speed`` rad/s.
        check : bool
            Apply the tracking-error guard.
        watch : sequence of int
            Further bodies whose blow-up (NaN, thrown out of the scene, faster than
            ``max_body_speed``) ends the move as ``invalid``.
        guard : callable or None
            A further check run after every guarded step (with ``check``): a
            :class:`SkillOutcome` it returns ends the move (e.g. a grasp-slip guard).
        """
        cfg = self.config
        speed = speed or cfg.speed
        start_pos, start_quat = self.gripper_pose()
        dist = math.dist(start_pos, target[0])
        ang = quat_angle(start_quat, target[1])
        step_len = speed * cfg.steps_per_waypoint * self.sim.physics.time_step
        turn_len = cfg.turn_speed * cfg.steps_per_waypoint * self.sim.physics.time_step
        n = max(1, math.ceil(max(dist / step_len, ang / turn_len)))
        # Each waypoint's IK starts from the one before it, to avoid wrist flips.
        try:
            for pos, quat, q in straight_line(self.solve_ik, (start_pos, start_quat), target,
                                              n, self.arm_q()):
                self._command(q)
                self.sim.step(cfg.steps_per_waypoint)
                bad = self._check(pos, check, watch) or self._check_turn(quat, check)
                if bad is None and check and guard is not None:
                    bad = guard()
                if bad is not None:
                    return bad
        except Unreachable as exc:
            return exc.outcome
        for _ in range(cfg.settle_steps // cfg.steps_per_waypoint):
            actual = self.gripper_pose()[0]
            if math.dist(actual, target[0]) < 0.001:
                break
            self.sim.step(cfg.steps_per_waypoint)
            bad = self._check(target[0], check, watch)
            if bad is None and check and guard is not None:
                bad = guard()
            if bad is not None:
                return bad
        return SkillOutcome("ok")

    def _check_turn(self, commanded: Quat, check: bool) -> SkillOutcome | None:
        err = quat_angle(self.gripper_pose()[1], commanded)
        if check and err > self.config.max_turn_error:
            stop = Verdict("gripper twist", math.degrees(err),
                           math.degrees(self.config.max_turn_error), "deg", "<=", False,
                           threshold_name="max_turn_error",
                           measures={"touching_ids": self.touching()})
            return SkillOutcome("blocked", f"the gripper was twisted {math.degrees(err):.0f} "
                              "degrees away from its commanded orientation: something is "
                              "in the way", stop)
        return None

    def touching(self) -> list[tuple[int, int]]:
        """Return the pairs of bodies ``(robot or held body, other)`` in contact after
        the last physics step (what a stopped motion ran into)."""
        c = self.sim.client
        mine = [self.body] + ([self.held] if self.held is not None else [])
        pairs = set()
        for body in mine:
            for cp in pb.getContactPoints(bodyA=body, physicsClientId=c):
                if cp[2] not in mine:  # not the arm on itself or on what it holds
                    pairs.add((int(body), int(cp[2])))
        return sorted(pairs)

    # --------------------------------------------------------------- strikes
    def watch_strikes(self, bodies: dict[int, str]) -> None:
        """Measure from now on where the robot's own links strike ``bodies`` (scene
        body id -> name), after every waypoint of a move (:meth:`take_strikes`).

        A strike is a contact point of a robot link with one of them that carries a
        normal force (pybullet also reports points a contact margin apart, with
        none). The held tool is no scene body, and its contacts with the fingers are
        switched off while held (:meth:`grasp`). A link touching one of the bodies
        now, before any move (what the robot stands on), is left out with that body.
        """
        self.strike_bodies = dict(bodies)
        self._mount = {(int(cp[3]), int(cp[2])) for cp in
                       pb.getContactPoints(bodyA=self.body, physicsClientId=self.sim.client)
                       if cp[2] in self.strike_bodies}
        self._strikes = {}

    def _measure_strikes(self) -> None:
        """Keep, per robot link and scene body, the largest normal force of a strike
        in the contacts after the last physics step, and where on the body."""
        if not self.strike_bodies:
            return
        for cp in pb.getContactPoints(bodyA=self.body, physicsClientId=self.sim.client):
            key = (int(cp[3]), int(cp[2]))
            if cp[2] in self.strike_bodies and cp[9] > 0.0 and key not in self._mount:
                if key not in self._strikes or cp[9] > self._strikes[key][0]:
                    self._strikes[key] = (float(cp[9]), tuple(float(v) for v in cp[6]))

    def take_strikes(self) -> list[dict]:
        """Return the strikes measured since the last call and forget them, strongest
        first: each ``{"link", "body", "force_n", "point"}`` (the robot link's and the
        scene body's names, the largest normal force in N, where on the body it
        acted, world frame, m)."""
        names = {j: n for n, j in self.model.link.items()}
        names[-1] = self.model.base_link
        out = [{"link": names.get(link, f"link{link}"), "body": self.strike_bodies[body],
                "force_n": round(force, 3), "point": [round(v, 4) for v in point]}
               for (link, body), (force, point) in self._strikes.items()]
        self._strikes = {}
        return sorted(out, key=lambda s: (-s["force_n"], s["link"], s["body"]))

    def _check(self, commanded: Point, check: bool,
               watch: Sequence[int] = ()) -> SkillOutcome | None:
        self._measure_strikes()
        actual = self.gripper_pose()[0]
        if not all(math.isfinite(v) for v in actual):
            return SkillOutcome("invalid", "the physics produced NaN in the arm's state")
        bodies = ([self.held] if self.held is not None else []) + list(watch)
        for body in bodies:
            why = self.sim.blow_up(body, self.config.max_body_speed)
            if why:
                return SkillOutcome("invalid", why)
        err = math.dist(actual, commanded)
        if check and err > self.config.max_tracking_error:
            stop = Verdict("gripper lag", err, self.config.max_tracking_error, "m", "<=",
                           False, threshold_name="max_tracking_error",
                           measures={"touching_ids": self.touching()})
            return SkillOutcome("blocked", f"gripper lagged its target by {err * 100:.1f} cm "
                              f"at ({commanded[0]:.3f}, {commanded[1]:.3f}, "
                              f"{commanded[2]:.3f}) m: something is in the way", stop)
        return None

    # ----------------------------------------------------------------- grasp
    def grasp(self, body: int, frame_in_gripper: Pose) -> None:
        """Fix ``body`` to the gripper so that its own frame sits at ``frame_in_gripper``.

        ``frame_in_gripper`` is the pose of the body's link frame (spec or URDF frame,
        not its centre of mass) in the tool frame. The constraint is fixed, with the
        profile's ``grasp.max_force`` N; collisions between the body and every robot
        link are switched off (the fingers, if any, do not hold it). A driven hand
        closes its fingers over the body (to the profile's ``hand.closed``) as a hand
        holding it would: held open, a wide gripper's fingers stick out around the
        tool and strike what the tool passes close to (a tube's mouth).
        """
        c = self.sim.client
        for link in range(-1, pb.getNumJoints(self.body, physicsClientId=c)):
            for blink in range(-1, pb.getNumJoints(body, physicsClientId=c)):
                pb.setCollisionFilterPair(self.body, body, link, blink, 0, physicsClientId=c)
        info = pb.getDynamicsInfo(body, -1, physicsClientId=c)
        # The child frame is given relative to the body's centre-of-mass frame.
        child_pos, child_quat = pb.invertTransform(info[3], info[4])
        # The parent frame too: the tool frame in the end-effector link's
        # centre-of-mass frame (an identity for an arm whose tool frame is its link's).
        if self.model.tool is not None or self.model.ee_com is not None:
            frame_in_gripper = self.model.in_ee_com(frame_in_gripper)
        self.grasp_constraint = pb.createConstraint(
            self.body, self.model.ee, body, -1, pb.JOINT_FIXED, (0, 0, 0),
            parentFramePosition=frame_in_gripper[0], childFramePosition=child_pos,
            parentFrameOrientation=frame_in_gripper[1], childFrameOrientation=child_quat,
            physicsClientId=c)
        pb.changeConstraint(self.grasp_constraint, maxForce=self.profile.grasp_max_force,
                            physicsClientId=c)
        self.held = body
        if self.fingers:
            self._fingers_to(self.profile.hand.closed)

    def release(self) -> None:
        """Remove the grasp constraint, if any, and open a driven hand's fingers."""
        if self.grasp_constraint is not None:
            pb.removeConstraint(self.grasp_constraint, physicsClientId=self.sim.client)
        self.grasp_constraint = None
        self.held = None
        if self.fingers:
            self._fingers_to(self.profile.hand.open)

    def close(self) -> None:
        """Disconnect the heavy robot's kinematics client (the physics client belongs
        to the Sim; the light robot's kinematics client is shared and stays)."""
        if self._kin_client >= 0:
            pb.disconnect(physicsClientId=self._kin_client)
            self._kin_client = -1


def check_profile(profile: RobotProfile | str) -> str:
    """Check that a robot profile builds a working arm; return one line saying what
    was found (raise :class:`~creative_py.world_files.WorldFileError` naming the
    profile's file and field otherwise).

    Loads the URDF (the light and the kinematics models too), finds the arm's joints,
    the end-effector link, the idle joints and the hand's fingers, checks that the home
    posture lies within the joint limits and that IK reaches the home posture's tool
    pose from mid-range (so the solver works on this arm), and measures the cost of a
    physics step with the arm at rest (the best of three runs of 480 steps).
    """
    from creative_py.world_files import PhysicsSettings

    p = load_profile(profile) if isinstance(profile, str) else profile
    sim = Sim(PhysicsSettings(1 / 240, 50, (0.0, 0.0, -9.81)))
    try:
        arm = _load_checked(sim, p)
        k = arm.kin
        pose = _check_home(arm, p)
        step_us = _step_cost_us(sim)
        hand = ("no hand" if p.hand is None else
                f"{len(p.hand.joints)} fingers" + (" gear-coupled" if p.hand.gear_ratio else ""))
        x, y, z = pose[0]
        return (f"ok: {p.urdf_path.name} loads; {len(p.arm_joints)} arm joints"
                + (f" ({int(k.continuous.sum())} continuous)" if k.continuous.any() else "")
                + f", ee {p.ee_link}, {hand}, {len(p.idle)} idle joints; home reachable "
                f"(tool at {x:.3f}, {y:.3f}, {z:.3f} m); {step_us:.0f} us per step")
    finally:
        sim.close()


def _load_checked(sim: Sim, p: RobotProfile) -> Arm:
    """Load profile ``p``'s full model (checking its idle joints, then removing it) and
    its light arm in ``sim``; raise the profile's error naming the field at fault."""
    from creative_py.world_files import WorldFileError

    try:
        full = _Model(sim.client, arm_urdf(p, False, "full"), p)
        for name in p.idle:
            if name not in full.joint:
                raise p.error("idle", f"{name!r} is no joint of {p.urdf_path.name}")
        pb.removeBody(full.body, physicsClientId=sim.client)
        return Arm(sim, p, mode="light")
    except ValueError as exc:
        if isinstance(exc, WorldFileError):
            raise
        raise p.error("urdf", str(exc)) from None
    except (RuntimeError, pb.error) as exc:
        raise p.error("urdf", f"pybullet cannot load {p.urdf_path}: {exc}") from None


def _check_home(arm: Arm, p: RobotProfile) -> Pose:
    """Return the tool pose of profile ``p``'s home posture; raise the profile's error
    unless the posture lies within the joint limits and IK reaches its tool pose from
    mid-range."""
    k = arm.kin
    home = np.array(p.home)
    bad = [(n, v) for n, v, lo, hi in zip(p.arm_joints, home, k.arm_lower, k.arm_upper)
           if not lo - 1e-9 <= v <= hi + 1e-9]
    if bad:
        raise p.error("kinematics.home", f"{bad[0][0]} = {bad[0][1]} lies outside the "
                      "joint's limits")
    pose = arm.gripper_pose()
    mid = np.where(k.continuous, 0.0, (k.arm_lower + k.arm_upper) / 2)
    q = arm.solve_ik(pose, seed=list(np.where(k.continuous, 0.0, mid)))
    if q is None:
        q = arm.solve_ik_global(pose)
    if q is None:
        raise p.error("kinematics.home", "IK does not reach the home posture's tool pose "
                      "(check ee_link, the tool frame and the joints)")
    return pose


def _step_cost_us(sim: Sim) -> float:
    """Return the cost of one physics step of ``sim`` (microseconds): the best of three
    480-step runs (a shared machine is noisy)."""
    import time

    best = math.inf
    for _ in range(3):
        t0 = time.perf_counter()
        sim.step(480)
        best = min(best, time.perf_counter() - t0)
    return best / 480 * 1e6
