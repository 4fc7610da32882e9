"""The simulated Baxter: loading, right-arm IK, guarded position control, grasping.

The URDF comes from the ``example-robot-data`` package; its ``package://`` mesh paths
are rewritten once into a cached copy (with or without ``<visual>`` elements). The
base frame of the robot is the world frame (the floor is at z = -0.926 m).

IK is solved in a second DIRECT client holding a kinematics-only Baxter, so trying a
target never disturbs the physics. The tool frame is the link ``right_gripper`` (the
point between the finger tips; its +z axis points out of the gripper).

How heavy the robot is (:data:`ROBOT`): the ``light`` robot (the default) has in the
physics a Baxter whose idle joints (left arm, head, left gripper) are fixed at the
posture they are held in and whose idle links are merged into the link they hang from,
so that a physics step simulates the 9 joints that act instead of 19 (less than half
the CPU time per step). In every mode but ``heavy`` the kinematics client holds only
the right arm's chain, is loaded once per process and kept for every robot after (an
episode loads one URDF), and the start posture's via solution is searched once per
target; IK answers are bit for bit those of the full model. Fewer joints change the
rows of pybullet's constraint solver, and with them the rounding of the arm's motion
(even fixing only the head, which cannot touch the arm, does): the ``light`` gripper's
path differs from the full model's by about 0.01 mm, so a trial that is borderline for
a guard (a gripper lag of 3.0 cm against the 3 cm limit) can end differently. The
``exact`` mode keeps the full physics model and so the heavy robot's results bit for
bit.

Moves are Cartesian straight lines sampled every ``steps_per_waypoint`` physics steps;
each waypoint is an IK solution seeded from the previous one, sent as position targets
at the URDF effort limits. A move ends ``blocked`` when the gripper lags its target by
more than ``max_tracking_error`` (it hit something), ``unreachable`` when IK cannot
reach a waypoint, ``invalid`` when the physics produces NaN.
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
from creative_py.simulator.types import SkillOutcome, Verdict

log = logging.getLogger(__name__)

RIGHT_ARM = ("right_s0", "right_s1", "right_e0", "right_e1", "right_w0", "right_w1",
             "right_w2")
"""The seven joints of the right arm, shoulder to wrist."""

LEFT_ARM = tuple(n.replace("right", "left") for n in RIGHT_ARM)

TUCKED_LEFT = (0.6, -1.0, -0.3, 2.2, 0.0, 0.4, 0.0)
"""Left-arm joint angles (rad) that keep the idle arm out of the workspace."""

IDLE_HOLD: dict[str, float] = {**dict(zip(LEFT_ARM, TUCKED_LEFT)), "head_pan": 0.0,
                               "l_gripper_l_finger_joint": 0.0,
                               "l_gripper_r_finger_joint": 0.0}
"""The idle joints (rad or m) and the values they are held at: the light robot fixes
them there (the left arm tucked, the head straight, the left gripper closed)."""

ROBOT_MODES = ("light", "exact", "heavy")
"""How heavy the robot is: ``light`` (idle joints fixed and merged in the physics, a
shared kinematics client with the right arm's chain, the via solution cached),
``exact`` (the same but every joint simulated: results bit for bit the heavy ones),
``heavy`` (the robot of before: every joint simulated, a kinematics client with the
full model and a second URDF load per robot, no via cache)."""

ROBOT_ENV = "CREATIVE_ROBOT"
"""Environment variable read at import into :data:`ROBOT` (one of :data:`ROBOT_MODES`)."""

ROBOT: str = os.environ.get(ROBOT_ENV, "").strip() or "light"
"""The mode of every :class:`Baxter` built without one (default ``light``); the
per-trial CPU benchmark (``bench/robot_cost_bench.py``) sets it to run all three."""

READY_RIGHT = (0.3, -0.6, 0.4, 1.6, -0.3, 0.6, 0.0)
"""Right-arm joint angles (rad) of the start posture, gripper in front of the robot."""

EE_LINK = "right_gripper"

WORKSPACE_LINK_PREFIXES = ("right_lower_elbow", "right_upper_forearm", "right_lower_forearm",
                           "right_wrist", "right_hand", "right_gripper", "r_gripper")
"""Links that keep their collision shapes: the right arm from the elbow on."""

def baxter_share_dir() -> Path:
    """Return ``.../cmeel.prefix/share`` of the installed example-robot-data package."""
    import site
    import sys

    for base in map(Path, [*site.getsitepackages(), *sys.path]):
        share = base / "cmeel.prefix" / "share"
        if (share / "example-robot-data" / "robots" / "baxter_description").is_dir():
            return share
    raise FileNotFoundError("the Baxter URDF needs the package example-robot-data "
                            "(pip install --no-deps example-robot-data)")


_URDF_EDITS = "v3: absolute meshes, base inertial, optional visuals, light and arm models"
"""Changes with the edits below, so that a stale cached URDF is never reused."""

URDF_MODELS = ("full", "light", "arm")
"""The Baxter models :func:`baxter_urdf` writes: every joint; the idle joints of
:data:`IDLE_HOLD` fixed and merged; the right arm's chain only (kinematics)."""


def baxter_urdf(visuals: bool = False, model: str = "full") -> Path:
    """Return a cached Baxter URDF with absolute mesh paths.

    Parameters
    ----------
    visuals : bool
        Keep the ``<visual>`` elements (slow to load); never for ``arm``.
    model : {"full", "light", "arm"}
        ``full``: the robot as shipped. ``light``: the idle joints of
        :data:`IDLE_HOLD` fixed at their values and every link below them merged
        into the link the idle part hangs from (its shapes kept where the held
        posture puts them, its mass dropped: those links hang from the fixed torso).
        ``arm``: only the links from the base to ``right_gripper`` (kinematics).
    """
    if model not in URDF_MODELS:
        raise ValueError(f"Baxter model must be one of {', '.join(URDF_MODELS)}, "
                         f"got {model!r}")
    share = baxter_share_dir()
    src = share / "example-robot-data" / "robots" / "baxter_description" / "urdf" / "baxter.urdf"
    text = src.read_text()
    key = hashlib.sha1((str(src) + text + str(visuals) + model + repr(sorted(IDLE_HOLD.items()))
                        + _URDF_EDITS).encode()).hexdigest()[:12]
    out = Path(tempfile.gettempdir()) / f"creative_py_baxter_{key}.urdf"
    if not out.is_file():
        text = text.replace("package://", str(share) + "/")
        # The fixed base link has no inertial element; give it one so that pybullet
        # does not print a warning on every load (its mass is irrelevant: it is fixed).
        text = text.replace('<link name="base">\n  </link>',
                            '<link name="base"><inertial><mass value="0.001"/><inertia '
                            'ixx="1e-6" ixy="0" ixz="0" iyy="1e-6" iyz="0" izz="1e-6"/>'
                            '</inertial></link>')
        if not visuals or model == "arm":
            text = re.sub(r"<visual>.*?</visual>", "", text, flags=re.S)
        if model != "full":
            root = ET.fromstring(text)
            if model == "light":
                _merge_idle(root, IDLE_HOLD)
            else:
                _keep_chain(root, EE_LINK)
            text = ET.tostring(root, encoding="unicode")
        tmp = out.with_suffix(f".{os.getpid()}.{id(text)}.tmp")
        tmp.write_text(text)
        tmp.replace(out)
    return out


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
            raise ValueError(f"the Baxter URDF has no joint {name}")
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
class BaxterConfig:
    """Settings of the robot model and its controller.

    Attributes
    ----------
    visuals : bool
        Load the visual meshes (slow, 1.2 s) so cameras see the robot.
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
    ik_position_tolerance : float
        Position error (m) an IK solution must reach to count as reachable.
    ik_orientation_tolerance : float
        Orientation error (rad) an IK solution must reach.
    ik_centring : float
        Gain (per iteration) of the null-space drift of the joints towards the
        middle of their ranges.
    grasp_max_force : float
        Maximum force of the fixed grasp constraint, N.
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
    ik_position_tolerance: float = 0.002
    ik_orientation_tolerance: float = 0.02
    ik_centring: float = 0.05
    grasp_max_force: float = 500.0
    settle_steps: int = 120
    max_body_speed: float = 5.0


GRIPPER_FORWARD: Quat = tuple(pb.getQuaternionFromEuler((0.0, math.pi / 2, 0.0)))
"""Orientation of ``right_gripper`` pointing along +x world (its +z axis), roll 0."""


def gripper_forward(roll: float) -> Quat:
    """Return the gripper orientation pointing +x world, turned by ``roll`` (rad) about x."""
    return tuple(pb.multiplyTransforms((0, 0, 0), pb.getQuaternionFromEuler((roll, 0, 0)),
                                       (0, 0, 0), GRIPPER_FORWARD)[1])


def gripper_down(yaw: float) -> Quat:
    """Return the gripper orientation pointing down (-z) with its x axis at ``yaw`` (rad)."""
    return tuple(pb.getQuaternionFromEuler((math.pi, 0.0, yaw)))


GRIPPER_ATTITUDES = {"forward": gripper_forward, "down": gripper_down}
"""Gripper orientations by name, each a function of one angle (rad)."""


def quat_angle(q1: Sequence[float], q2: Sequence[float]) -> float:
    """Return the rotation angle (rad) between two quaternions (x, y, z, w)."""
    d = abs(float(np.dot(q1, q2)))
    return 2.0 * math.acos(min(1.0, d))


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


class _Model:
    """A loaded Baxter in one client: joint tables and helpers."""

    def __init__(self, client: int, urdf: Path) -> None:
        self.client = client
        self.body = pb.loadURDF(str(urdf), (0, 0, 0), (0, 0, 0, 1), useFixedBase=True,
                                physicsClientId=client)
        if self.body < 0:
            raise RuntimeError(f"{urdf}: pybullet could not load the Baxter URDF")
        self.joint: dict[str, int] = {}
        self.link: dict[str, int] = {}
        self.movable: list[int] = []
        self.lower: list[float] = []
        self.upper: list[float] = []
        self.effort: dict[int, float] = {}
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
        self.arm = [self.joint[n] for n in RIGHT_ARM]
        self.left = [self.joint[n] for n in LEFT_ARM if n in self.joint
                     and self.joint[n] in self.movable]
        """The left arm's joints, if it moves (none in the light robot)."""
        self.ee = self.link[EE_LINK]
        self.arm_in_movable = [self.movable.index(j) for j in self.arm]
        self.arm_lower = np.array([self.lower[i] for i in self.arm_in_movable])
        self.arm_upper = np.array([self.upper[i] for i in self.arm_in_movable])

    def reset(self, joints: Sequence[int], q: Sequence[float]) -> None:
        pb.resetJointStatesMultiDof(self.body, list(joints), [[float(v)] for v in q],
                                    targetVelocities=[[0.0]] * len(joints),
                                    physicsClientId=self.client)

    def ee_pose(self) -> Pose:
        st = pb.getLinkState(self.body, self.ee, computeForwardKinematics=True,
                             physicsClientId=self.client)
        return tuple(st[4]), tuple(st[5])

    def arm_q(self) -> list[float]:
        return [pb.getJointState(self.body, j, physicsClientId=self.client)[0]
                for j in self.arm]


_KINEMATICS: list = []
"""``[(pid, model)]``: this process's kinematics model (a fork loads its own)."""


def kinematics_model() -> _Model:
    """Return this process's kinematics-only Baxter (the right arm's chain).

    It lives in its own DIRECT client, loaded on first use and kept for every robot
    after: IK resets the arm before each query, so no robot sees another's state.
    """
    pid = os.getpid()
    if _KINEMATICS and _KINEMATICS[0][0] == pid and pb.isConnected(_KINEMATICS[0][1].client):
        return _KINEMATICS[0][1]
    client = pb.connect(pb.DIRECT)
    if client < 0:
        raise RuntimeError("pybullet: could not connect the kinematics client")
    model = _Model(client, baxter_urdf(False, "arm"))
    _KINEMATICS[:] = [(pid, model)]
    return model


class Baxter:
    """A Baxter robot in a :class:`Sim`, with a private kinematics client for IK.

    Parameters
    ----------
    sim : Sim
        The physics client to load the robot into (base at the world origin).
    config : BaxterConfig
        Controller settings.
    mode : str or None
        One of :data:`ROBOT_MODES`; None takes :data:`ROBOT`.
    """

    def __init__(self, sim: Sim, config: BaxterConfig = BaxterConfig(),
                 mode: str | None = None) -> None:
        self.sim = sim
        self.config = config
        self.mode = ROBOT if mode is None else mode
        if self.mode not in ROBOT_MODES:
            raise ValueError(f"robot mode (environment variable {ROBOT_ENV}) must be one of "
                             f"{', '.join(ROBOT_MODES)}, got {self.mode!r}")
        self.light = self.mode != "heavy"
        """Shared kinematics client, cached via solution (every mode but ``heavy``)."""
        self.urdf = baxter_urdf(config.visuals, "light" if self.mode == "light" else "full")
        """The URDF file the robot was loaded from."""
        self.model = _Model(sim.client, self.urdf)
        self.body = self.model.body
        if self.light:
            self._kin_client = -1  # the shared one: not this robot's to close
            self.kin = kinematics_model()
        else:
            self._kin_client = pb.connect(pb.DIRECT)
            self.kin = _Model(self._kin_client, baxter_urdf(False))
        self.grasp_constraint: int | None = None
        self.held: int | None = None
        self.reset_posture(READY_RIGHT)
        self._limit_collisions()

    def _limit_collisions(self) -> None:
        """Let only the links that can reach the workspace collide (a speed-up).

        The torso, head, pedestal, left arm and right shoulder cannot touch anything
        on the table; their collision meshes only cost time in every step.
        """
        m = self.model
        for name, link in [("base", -1), *m.link.items()]:
            if not name.startswith(WORKSPACE_LINK_PREFIXES):
                pb.setCollisionFilterGroupMask(m.body, link, 0, 0, physicsClientId=m.client)

    # ------------------------------------------------------------------ state
    def reset_posture(self, right_q: Sequence[float]) -> None:
        """Teleport the right arm to ``right_q`` (rad) and tuck the left arm; hold them.

        The light robot's left arm is tucked for good (its joints are fixed).
        """
        m = self.model
        m.reset(m.arm, right_q)
        if m.left:
            m.reset(m.left, TUCKED_LEFT)
        self._command(list(right_q))
        if m.left:
            pb.setJointMotorControlArray(m.body, m.left, pb.POSITION_CONTROL,
                                         targetPositions=list(TUCKED_LEFT),
                                         forces=[m.effort[j] for j in m.left],
                                         physicsClientId=self.sim.client)

    def arm_q(self) -> list[float]:
        """Return the right-arm joint angles (rad)."""
        return self.model.arm_q()

    def gripper_pose(self) -> Pose:
        """Return the world pose of ``right_gripper`` by forward kinematics (proprioception)."""
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
        """Return right-arm joint angles (rad) putting ``right_gripper`` at ``target``.

        Damped least squares on the arm's 6 x 7 Jacobian (from pybullet, in the
        kinematics client), started from ``seed`` (default: the current arm) and
        clamped to the joint limits. Returns None unless the position error ends
        under ``ik_position_tolerance`` (m) and the orientation error under
        ``ik_orientation_tolerance`` (rad): the target is then unreachable from
        this seed (out of reach, or a joint limit in the way).
        """
        k = self.kin
        q = np.array(seed if seed is not None else self.arm_q(), dtype=float)
        lo, hi = k.arm_lower, k.arm_upper
        q = np.clip(q, lo, hi)
        mid = (lo + hi) / 2
        tpos = np.asarray(target[0], float)
        tquat = target[1]
        zeros = [0.0] * len(k.movable)
        full = [0.0] * len(k.movable)
        perr = oerr = math.inf
        damped = 1e-4 * np.eye(6)
        eye7 = np.eye(7)
        for _ in range(max_iterations):
            k.reset(k.arm, q)
            pos, quat = k.ee_pose()
            e_pos = tpos - np.asarray(pos)
            e_rot = rotation_vector(quat, tquat)
            perr, oerr = float(np.linalg.norm(e_pos)), float(np.linalg.norm(e_rot))
            if perr < 1e-4 and oerr < 1e-3:
                break
            for i, v in zip(k.arm_in_movable, q):
                full[i] = float(v)
            lin, ang = pb.calculateJacobian(k.body, k.ee, (0, 0, 0), full, zeros, zeros,
                                            physicsClientId=k.client)
            jac = np.vstack([np.asarray(lin)[:, k.arm_in_movable],
                             np.asarray(ang)[:, k.arm_in_movable]])
            err = np.concatenate([e_pos, e_rot])
            # Joints pinned at a limit and pushed beyond it are taken out of the
            # Jacobian (an active set), so the others do the work instead of the
            # solver stalling against the clamp.
            free = np.ones(7)
            for _ in range(3):
                jf = jac * free
                pinv = jf.T @ np.linalg.inv(jf @ jf.T + damped)
                dq = pinv @ err
                # Secondary task in the null space: drift towards mid-range, so that
                # long Cartesian paths do not run the arm into a joint limit.
                dq += (eye7 - pinv @ jf) @ (self.config.ik_centring * (mid - q) * free)
                pinned = ((q <= lo + 1e-6) & (dq < 0)) | ((q >= hi - 1e-6) & (dq > 0))
                if not np.any(pinned & (free > 0)):
                    break
                free[pinned] = 0.0
            biggest = float(np.max(np.abs(dq)))
            if biggest > 0.2:
                dq *= 0.2 / biggest
            q = np.clip(q + dq, lo, hi)
        if perr > self.config.ik_position_tolerance or oerr > self.config.ik_orientation_tolerance:
            return None
        return [float(v) for v in q]

    def ik_candidates(self, target: Pose, keep: int = 6, restarts: int = 40,
                      seeds: Sequence[Sequence[float]] = ()) -> list[list[float]]:
        """Return up to ``keep`` arm postures (rad) reaching ``target``.

        Solves from ``seeds``, the ready posture, the current posture and ``restarts``
        random postures of a fixed-seed generator (deterministic), in that order.
        """
        k = self.kin
        lo, hi = k.arm_lower, k.arm_upper
        rng = np.random.default_rng(0)
        tries = [*map(list, seeds), list(READY_RIGHT), self.arm_q()]
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

    def solve_ik_global(self, target: Pose, restarts: int = 40, keep: int = 6,
                        seeds: Sequence[Sequence[float]] = ()) -> list[float] | None:
        """Return an arm posture (rad) reaching ``target``, chosen among several.

        Among :meth:`ik_candidates` returns the one farthest from the joint limits
        (the largest smallest margin, as a fraction of each joint's range), or None.
        Margins matter: a joint at its limit cannot help against gravity or contact.
        """
        found = self.ik_candidates(target, keep, restarts, seeds)
        if not found:
            return None
        lo, hi = self.kin.arm_lower, self.kin.arm_upper

        def margin(q: list[float]) -> float:
            qa = np.array(q)
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

    def move_joints(self, q_goal: Sequence[float], joint_speed: float = 0.8,
                    check: bool = True, watch: Sequence[int] = ()) -> SkillOutcome:
        """Move the arm in joint space to ``q_goal`` (rad), fastest joint at ``joint_speed`` rad/s.

        The tracking guard compares the gripper with the forward kinematics of the
        commanded posture.
        """
        cfg = self.config
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

    def reach(self, target: Pose, joint_speed: float = 0.8,
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
            World pose of ``right_gripper``.
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

    def _check(self, commanded: Point, check: bool,
               watch: Sequence[int] = ()) -> SkillOutcome | None:
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
        not its centre of mass) in the ``right_gripper`` frame. The constraint is
        fixed, with ``grasp_max_force`` N; collisions between the body and every
        robot link are switched off (the fingers are not simulated closing).
        """
        c = self.sim.client
        for link in range(-1, pb.getNumJoints(self.body, physicsClientId=c)):
            for blink in range(-1, pb.getNumJoints(body, physicsClientId=c)):
                pb.setCollisionFilterPair(self.body, body, link, blink, 0, physicsClientId=c)
        info = pb.getDynamicsInfo(body, -1, physicsClientId=c)
        # The child frame is given relative to the body's centre-of-mass frame.
        child_pos, child_quat = pb.invertTransform(info[3], info[4])
        self.grasp_constraint = pb.createConstraint(
            self.body, self.model.ee, body, -1, pb.JOINT_FIXED, (0, 0, 0),
            parentFramePosition=frame_in_gripper[0], childFramePosition=child_pos,
            parentFrameOrientation=frame_in_gripper[1], childFrameOrientation=child_quat,
            physicsClientId=c)
        pb.changeConstraint(self.grasp_constraint, maxForce=self.config.grasp_max_force,
                            physicsClientId=c)
        self.held = body

    def release(self) -> None:
        """Remove the grasp constraint, if any."""
        if self.grasp_constraint is not None:
            pb.removeConstraint(self.grasp_constraint, physicsClientId=self.sim.client)
        self.grasp_constraint = None
        self.held = None

    def close(self) -> None:
        """Disconnect the heavy robot's kinematics client (the physics client belongs
        to the Sim; the light robot's kinematics client is shared and stays)."""
        if self._kin_client >= 0:
            pb.disconnect(physicsClientId=self._kin_client)
            self._kin_client = -1
