"""Robot profiles: one TOML file per arm (``robots/<name>.toml``), read here and only here.

A profile is the one place an arm's facts live, for every backend (docs/robots.md):

``name``, ``urdf``
    The profile's name and its URDF: ``example-robot-data:<path>`` (a file of the
    example-robot-data package, under its ``robots/`` folder) or a path (relative to
    the profile's folder). ``[packages]`` maps a ``package://NAME`` of the URDF to a
    folder (example-robot-data's packages are found without it).
``[base]``
    Where the arm's base link stands in the world frame (``position`` m, ``rpy`` rad);
    a world file may place it elsewhere for its scene (``[robot.NAME]`` of
    ``scene.toml``).
``[kinematics]``
    The arm's ``joints`` (shoulder to wrist; continuous ones are found in the URDF),
    the ``ee_link``, the tool frame on it (``tool_xyz`` m, ``tool_rpy`` rad) and the
    tool frame's ``approach_axis`` (the axis that points out of the gripper), the
    ``home`` posture (start, reset, IK seed), the joint-space ``max_joint_speed``
    (rad/s) and the ``collision_links`` (name prefixes of the links that keep their
    collision shapes; every link if empty).
``[idle]``
    Joints that never move (another arm, a head), each held at its value; the light
    robot fixes them and merges their links.
``[hand]`` (optional)
    The gripper's finger ``joints``, their ``open`` and ``closed`` values, ``max_force``
    (N), ``gear_ratio`` (couples the fingers: pybullet ignores a URDF ``<mimic>``) and
    ``driven`` (motors hold them open, and closed over a held tool; false leaves them
    to the physics). No table: the arm has no actuated gripper.
``[grasp]``
    How a tool is held: ``mode = "constraint"`` (a fixed constraint between the tool
    frame and the tool, ``max_force`` N; the fingers, if any, do not hold it).
``[ik]``
    The IK's ``position_tolerance`` (m), ``orientation_tolerance`` (rad), ``centring``
    (the null-space drift to mid-range) and ``restarts`` (random seeds).

The ROS 2 interface tables (``[frames]``, ``[joint_states]``, ``[arm]``, ``[gripper]``,
``[objects]``, ``[limits]``, optional ``[clock]``, ``[trainer]``, ``[wrench]``; see
docs/real-robot.md) stay in the same file; a profile without ``[arm]`` has no ROS 2
interface. Every error names the file and the field (:class:`WorldFileError`).
"""

from __future__ import annotations

import math
import site
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from creative_py.world_files import Fields, WorldFileError, load_toml

ROBOTS_ROOT = Path(__file__).resolve().parents[1] / "robots"
"""The folder holding the shipped robot profiles (``robots/<name>.toml``)."""

ERD_PREFIX = "example-robot-data:"
"""A ``urdf`` starting so names a file under example-robot-data's ``robots/`` folder."""

APPROACH_AXES = ("+x", "-x", "+y", "-y", "+z", "-z")


@dataclass(frozen=True)
class HandSpec:
    """A parallel gripper's finger joints (``[hand]``)."""

    joints: tuple[str, ...]
    open: tuple[float, ...]
    closed: tuple[float, ...]
    max_force: float
    gear_ratio: Optional[float]
    driven: bool


@dataclass(frozen=True)
class IkSpec:
    """The IK settings (``[ik]``)."""

    position_tolerance: float = 0.002
    orientation_tolerance: float = 0.02
    centring: float = 0.05
    restarts: int = 40


@dataclass(frozen=True)
class RobotProfile:
    """An arm: its model and kinematics for every backend, and its ROS 2 interface.

    The ROS 2 fields keep the names the ROS 2 backend reads (``joints`` are the
    ``[arm]`` table's, in the controller's order); ``has_ros`` is False for a profile
    without those tables.
    """

    source: str
    name: str
    urdf: str
    urdf_path: Path = Path()
    packages: dict[str, str] = field(default_factory=dict)
    base_position: tuple[float, float, float] = (0.0, 0.0, 0.0)
    base_rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    arm_joints: tuple[str, ...] = ()
    ee_link: str = ""
    tool_xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    tool_rpy: tuple[float, float, float] = (0.0, 0.0, 0.0)
    approach_axis: str = "+z"
    home: tuple[float, ...] = ()
    joint_speed: float = 0.8
    collision_links: tuple[str, ...] = ()
    idle: dict[str, float] = field(default_factory=dict)
    hand: Optional[HandSpec] = None
    grasp_mode: str = "constraint"
    grasp_max_force: float = 500.0
    ik: IkSpec = IkSpec()
    description: str = ""

    has_ros: bool = False
    world_frame: str = "world"
    base_frame: str = "base"
    joint_states_topic: str = "joint_states"
    joint_states_rate_hz: float = 50.0
    stale_after_s: float = 1.0
    arm_action: str = ""
    joints: tuple[str, ...] = ()
    path_tolerance: float = 0.15
    goal_tolerance: float = 0.02
    goal_time_tolerance: float = 0.5
    gripper_action: str = ""
    gripper_joint: str = ""
    gripper_open: float = 0.04
    gripper_closed: float = 0.0
    gripper_max_effort: float = 40.0
    object_topic: str = "mocap/{name}/pose"
    object_rate_hz: float = 30.0
    object_names: dict[str, str] = field(default_factory=dict)
    max_joint_speed: float = 0.8
    workspace_min: tuple[float, float, float] = (-10.0, -10.0, -10.0)
    workspace_max: tuple[float, float, float] = (10.0, 10.0, 10.0)
    use_sim_time: bool = False
    clock_topic: str = "/clock"
    clock_silent_after_s: float = 3.0
    trainer_request_topic: str = "trainer/scene_request"
    trainer_done_topic: str = "trainer/scene_done"
    trainer_timeout_s: float = 120.0
    wrench_topic: str = ""
    wrench_frame: str = ""

    def now_source(self) -> str:
        """Return what the learner's staleness and timeouts count: ``simulated time on
        '/clock'`` or ``wall-clock time``."""
        return f"simulated time on {self.clock_topic!r}" if self.use_sim_time else "wall-clock time"

    def object_topic_of(self, name: str) -> str:
        """Return the pose topic of the case's object ``name`` (its mocap name mapped)."""
        return self.object_topic.format(name=self.object_names.get(name, name))

    def error(self, field_name: str, cause: str) -> WorldFileError:
        """Return an error naming this profile's file and ``field_name``."""
        return WorldFileError(f"{self.source}: field {field_name!r}: {cause}")


def erd_share_dir() -> Path:
    """Return ``.../cmeel.prefix/share`` of the installed example-robot-data package."""
    for base in map(Path, [*site.getsitepackages(), *sys.path]):
        share = base / "cmeel.prefix" / "share"
        if (share / "example-robot-data" / "robots").is_dir():
            return share
    raise FileNotFoundError("example-robot-data is not installed "
                            "(pip install --no-deps example-robot-data)")


def profile_names() -> list[str]:
    """Return the names of the shipped profiles (``robots/*.toml``), sorted."""
    return sorted(p.stem for p in ROBOTS_ROOT.glob("*.toml"))


def profile_path(spec: str | Path) -> Path:
    """Return the file of profile ``spec`` (a shipped name or a ``.toml`` path)."""
    path = Path(spec)
    if path.suffix != ".toml":
        path = ROBOTS_ROOT / f"{spec}.toml"
        if not path.is_file():
            raise WorldFileError(f"{path}: no robot profile {str(spec)!r}; shipped profiles: "
                                 f"{', '.join(profile_names())} (or give a .toml path)")
    elif not path.is_file():
        raise WorldFileError(f"{path}: no such robot profile file")
    return path


def _ros_name(f: Fields, name: str) -> str:
    value = f.str(name)
    if not value or any(c.isspace() for c in value):
        raise f.error(name, f"must be a ROS name without spaces, got {value!r}")
    return value


def _names(f: Fields, name: str, default=None, *, empty: bool = False) -> tuple[str, ...]:
    value = f.raw(name, default) if default is not None else f.raw(name)
    if (not isinstance(value, list) or (not value and not empty)
            or not all(isinstance(j, str) and j for j in value) or len(set(value)) != len(value)):
        raise f.error(name, f"must be a list of distinct names, got {value!r}")
    return tuple(value)


def _resolve_urdf(f: Fields, spec: str, path: Path) -> Path:
    if spec.startswith(ERD_PREFIX):
        try:
            share = erd_share_dir()
        except FileNotFoundError as exc:
            raise f.error("urdf", str(exc)) from None
        out = share / "example-robot-data" / "robots" / spec[len(ERD_PREFIX):]
    else:
        out = Path(spec).expanduser()
        if not out.is_absolute():
            out = path.parent / out
    if not out.is_file():
        raise f.error("urdf", f"no URDF file {str(out)!r}")
    return out


def load_profile(spec: str | Path) -> RobotProfile:
    """Return the profile ``spec``: a shipped profile's name or a ``.toml`` path.

    Raises
    ------
    WorldFileError
        The file is missing or a field is missing, mistyped, out of bounds or unknown
        (one line naming the file and the field).
    """
    path = profile_path(spec)
    f = Fields(load_toml(path), path)
    out: dict = {"source": str(path)}
    out.update(_read_identity(f, path))
    out.update(_read_base(f))
    out.update(_read_kinematics(f))
    joints = out["arm_joints"]
    out.update(_read_idle(f, joints))
    if f.has("hand"):
        out["hand"] = _read_hand(f, joints, out["idle"])
    out.update(_read_grasp_and_ik(f))
    if f.has("arm"):
        out.update(_read_ros(f, joints))
    f.done()
    return RobotProfile(**out)


def _read_identity(f: Fields, path: Path) -> dict:
    """Read the profile's name, description, URDF (resolved against ``path``) and ROS
    package folders."""
    out: dict = {}
    name = f.str("name")
    if not name or not name.replace("_", "").replace("-", "").isalnum():
        raise f.error("name", f"must be a name of letters, digits, - and _, got {name!r}")
    out["name"] = name
    out["description"] = f.str("description", "")
    urdf = f.str("urdf")
    out["urdf"] = urdf
    out["urdf_path"] = _resolve_urdf(f, urdf, path)
    packages = f.raw("packages", {})
    if not isinstance(packages, dict) or not all(isinstance(v, str) and v
                                                 for v in packages.values()):
        raise f.error("packages", f"must be a table of package name = folder, got {packages!r}")
    out["packages"] = {k: str((path.parent / Path(v).expanduser()).resolve())
                       for k, v in packages.items()}
    return out


def _read_base(f: Fields) -> dict:
    """Read the ``[base]`` table: the arm's base position (m) and roll, pitch, yaw (rad)."""
    b = f.table("base", {})
    out = {"base_position": b.vec("position", 3, (0.0, 0.0, 0.0), minimum=-10.0, maximum=10.0),
           "base_rpy": b.vec("rpy", 3, (0.0, 0.0, 0.0), minimum=-7.0, maximum=7.0)}
    b.done()
    return out


def _read_kinematics(f: Fields) -> dict:
    """Read the ``[kinematics]`` table: the arm's joints, end-effector link and tool
    offset, approach axis, home posture, joint speed and collision links."""
    out: dict = {}
    k = f.table("kinematics")
    joints = _names(k, "joints")
    out["arm_joints"] = joints
    out["ee_link"] = k.str("ee_link")
    if not out["ee_link"]:
        raise k.error("ee_link", "must name a link of the URDF")
    out["tool_xyz"] = k.vec("tool_xyz", 3, (0.0, 0.0, 0.0), minimum=-2.0, maximum=2.0)
    out["tool_rpy"] = k.vec("tool_rpy", 3, (0.0, 0.0, 0.0), minimum=-7.0, maximum=7.0)
    out["approach_axis"] = k.str("approach_axis", "+z", choices=APPROACH_AXES)
    out["home"] = k.vec("home", len(joints), minimum=-50.0, maximum=50.0)
    out["joint_speed"] = k.float("max_joint_speed", 0.8, minimum=0.01, maximum=10.0)
    out["collision_links"] = _names(k, "collision_links", [], empty=True)
    k.done()
    return out


def _read_idle(f: Fields, joints: tuple[str, ...]) -> dict:
    """Read the ``idle`` table: where the joints that are not the arm's stay (rad or m)."""
    idle = f.raw("idle", {})
    if not isinstance(idle, dict) or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in idle.values()):
        raise f.error("idle", f"must be a table of joint name = value (rad or m), got {idle!r}")
    if set(idle) & set(joints):
        raise f.error("idle", f"names an arm joint: {sorted(set(idle) & set(joints))[0]!r}")
    return {"idle": {n: float(v) for n, v in idle.items()}}


def _read_hand(f: Fields, joints: tuple[str, ...], idle: dict[str, float]) -> HandSpec:
    """Read the ``[hand]`` table: the finger joints (none of the arm's or idle ones),
    their open and closed positions, force, gear ratio and whether they are driven."""
    h = f.table("hand")
    fingers = _names(h, "joints")
    opened = h.vec("open", len(fingers), minimum=-7.0, maximum=7.0)
    closed = h.vec("closed", len(fingers), minimum=-7.0, maximum=7.0)
    ratio = h.raw("gear_ratio", None)
    if ratio is not None and (isinstance(ratio, bool) or not isinstance(ratio, (int, float))
                              or ratio == 0 or not math.isfinite(ratio)):
        raise h.error("gear_ratio", f"must be a non-zero number, got {ratio!r}")
    if ratio is not None and len(fingers) != 2:
        raise h.error("gear_ratio", "couples two finger joints; the hand names "
                      f"{len(fingers)}")
    hand = HandSpec(fingers, opened, closed,
                    h.float("max_force", 20.0, minimum=0.0, maximum=1e4),
                    None if ratio is None else float(ratio),
                    h.bool("driven", True))
    h.done()
    if set(fingers) & (set(joints) | set(idle)):
        raise f.error("hand.joints", "names an arm or idle joint")
    return hand


def _read_grasp_and_ik(f: Fields) -> dict:
    """Read the ``[grasp]`` table (how a tool is held, the hold's force, N) and the
    ``[ik]`` table (the IK's tolerances, centring and restarts)."""
    g = f.table("grasp", {})
    out = {"grasp_mode": g.str("mode", "constraint", choices=("constraint",)),
           "grasp_max_force": g.float("max_force", 500.0, minimum=1.0, maximum=1e5)}
    g.done()
    ik = f.table("ik", {})
    out["ik"] = IkSpec(ik.float("position_tolerance", 0.002, minimum=1e-6, maximum=0.05),
                       ik.float("orientation_tolerance", 0.02, minimum=1e-5, maximum=0.5),
                       ik.float("centring", 0.05, minimum=0.0, maximum=1.0),
                       ik.int("restarts", 40, minimum=0, maximum=1000))
    ik.done()
    return out


def _read_ros(f: Fields, arm_joints: tuple[str, ...]) -> dict:
    """Read the ROS 2 interface tables into the profile's ROS fields."""
    out: dict = {"has_ros": True}
    out.update(_read_ros_frames(f))
    out.update(_read_ros_arm(f, arm_joints))
    out.update(_read_ros_gripper(f))
    out.update(_read_ros_objects(f))
    out.update(_read_ros_limits(f))
    out.update(_read_ros_optional(f))
    return out


def _read_ros_frames(f: Fields) -> dict:
    """Read ``[frames]`` (the world and base frames) and ``[joint_states]`` (the topic,
    its rate, Hz, and when it is stale, s)."""
    out: dict = {}
    fr = f.table("frames")
    out["world_frame"], out["base_frame"] = _ros_name(fr, "world"), _ros_name(fr, "base")
    fr.done()
    js = f.table("joint_states")
    out["joint_states_topic"] = _ros_name(js, "topic")
    out["joint_states_rate_hz"] = js.float("rate_hz", minimum=1.0, maximum=1000.0)
    out["stale_after_s"] = js.float("stale_after_s", minimum=0.01, maximum=10.0)
    js.done()
    return out


def _read_ros_arm(f: Fields, arm_joints: tuple[str, ...]) -> dict:
    """Read ``[arm]``: the trajectory action, its joints (those of
    ``kinematics.joints``, in any order) and its tolerances (rad, s)."""
    out: dict = {}
    arm = f.table("arm")
    out["arm_action"] = _ros_name(arm, "action")
    joints = arm.raw("joints")
    if (not isinstance(joints, list) or not joints
            or not all(isinstance(j, str) and j for j in joints) or len(set(joints)) != len(joints)):
        raise arm.error("joints", f"must be a list of distinct joint names, got {joints!r}")
    if sorted(joints) != sorted(arm_joints):
        raise arm.error("joints", f"must be the joints of kinematics.joints {list(arm_joints)} "
                        f"(in any order), got {joints!r}")
    out["joints"] = tuple(joints)
    out["path_tolerance"] = arm.float("path_tolerance", minimum=1e-4, maximum=3.2)
    out["goal_tolerance"] = arm.float("goal_tolerance", minimum=1e-5, maximum=3.2)
    out["goal_time_tolerance"] = arm.float("goal_time_tolerance", minimum=0.0, maximum=60.0)
    arm.done()
    return out


def _read_ros_gripper(f: Fields) -> dict:
    """Read ``[gripper]``: its action and joint, its open and closed positions (closed
    below open) and its effort."""
    out: dict = {}
    g = f.table("gripper")
    out["gripper_action"], out["gripper_joint"] = _ros_name(g, "action"), _ros_name(g, "joint")
    out["gripper_open"] = g.float("open_position", minimum=0.0, maximum=1.0)
    out["gripper_closed"] = g.float("closed_position", minimum=0.0, maximum=1.0)
    out["gripper_max_effort"] = g.float("max_effort", minimum=0.0, maximum=1e4)
    if out["gripper_closed"] >= out["gripper_open"]:
        raise g.error("closed_position", f"must be below open_position "
                      f"({out['gripper_open']}), got {out['gripper_closed']}")
    g.done()
    return out


def _read_ros_objects(f: Fields) -> dict:
    """Read ``[objects]``: the motion-capture topic (one per object, ``{name}`` in
    it), its rate (Hz) and the objects' mocap names."""
    out: dict = {}
    o = f.table("objects")
    topic = _ros_name(o, "topic")
    if "{name}" not in topic:
        raise o.error("topic", f"must contain {{name}} (one topic per object), got {topic!r}")
    out["object_topic"] = topic
    out["object_rate_hz"] = o.float("rate_hz", minimum=1.0, maximum=1000.0)
    names = o.raw("names", {})
    if not isinstance(names, dict) or not all(isinstance(v, str) and v for v in names.values()):
        raise o.error("names", f"must be a table of object name = mocap name, got {names!r}")
    out["object_names"] = dict(names)
    o.done()
    return out


def _read_ros_limits(f: Fields) -> dict:
    """Read ``[limits]``: the joint speed (rad/s) and the workspace box (m), its
    maximum above its minimum on every axis."""
    out: dict = {}
    lim = f.table("limits")
    out["max_joint_speed"] = lim.float("max_joint_speed", minimum=1e-3, maximum=10.0)
    lo = lim.vec("workspace_min", 3, minimum=-10.0, maximum=10.0)
    hi = lim.vec("workspace_max", 3, minimum=-10.0, maximum=10.0)
    if any(a >= b for a, b in zip(lo, hi)):
        raise lim.error("workspace_max", f"must exceed workspace_min {list(lo)} on every "
                        f"axis, got {list(hi)}")
    out["workspace_min"], out["workspace_max"] = lo, hi
    lim.done()
    return out


def _read_ros_optional(f: Fields) -> dict:
    """Read the optional tables: ``[clock]`` (a simulated arm's clock), ``[trainer]``
    (the topics and timeout of a trainer) and ``[wrench]`` (a force-torque topic)."""
    out: dict = {}
    c = f.table("clock", {})  # optional: a simulated arm's clock (rosgraph_msgs/Clock)
    out["use_sim_time"] = c.bool("use_sim_time", False)
    out["clock_topic"] = _ros_name(c, "topic") if c.has("topic") else "/clock"
    out["clock_silent_after_s"] = c.float("silent_after_s", 3.0, minimum=0.1, maximum=60.0)
    c.done()
    tr = f.table("trainer", {})
    if "request_topic" in tr.data:
        out["trainer_request_topic"] = _ros_name(tr, "request_topic")
    if "done_topic" in tr.data:
        out["trainer_done_topic"] = _ros_name(tr, "done_topic")
    out["trainer_timeout_s"] = tr.float("timeout_s", RobotProfile.trainer_timeout_s,
                                        minimum=1.0, maximum=3600.0)
    tr.done()
    wr = f.table("wrench", {})
    if wr.data:
        out["wrench_topic"], out["wrench_frame"] = _ros_name(wr, "topic"), _ros_name(wr, "frame")
    wr.done()
    return out
