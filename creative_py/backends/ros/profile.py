"""A robot profile: the names of an arm's ROS 2 interface, read from a TOML file.

A profile (``robots/<name>.toml``; ``robots/baxter.toml`` is the stand-in's) says which
topics and action servers the arm offers, the joints and frames, the controller's
default tolerances and the bounds the learner keeps to. A lab remaps its arm by
writing a profile, without code. Reading it needs no ROS installation.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from creative_py.world_files import Fields, WorldFileError, load_toml

ROBOTS_ROOT = Path(__file__).resolve().parents[3] / "robots"
"""The folder holding the shipped robot profiles (``robots/<name>.toml``)."""


@dataclass(frozen=True)
class RobotProfile:
    """An arm's ROS 2 interface and the learner's bounds (see ``robots/baxter.toml``)."""

    source: str
    name: str
    urdf: str
    world_frame: str
    base_frame: str
    joint_states_topic: str
    joint_states_rate_hz: float
    stale_after_s: float
    arm_action: str
    joints: tuple[str, ...]
    path_tolerance: float
    goal_tolerance: float
    goal_time_tolerance: float
    gripper_action: str
    gripper_joint: str
    gripper_open: float
    gripper_closed: float
    gripper_max_effort: float
    object_topic: str
    object_rate_hz: float
    object_names: dict[str, str]
    max_joint_speed: float
    workspace_min: tuple[float, float, float]
    workspace_max: tuple[float, float, float]
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


def _name(f: Fields, field: str) -> str:
    value = f.str(field)
    if not value or any(c.isspace() for c in value):
        raise f.error(field, f"must be a ROS name without spaces, got {value!r}")
    return value


def load_profile(spec: str | Path = "baxter") -> RobotProfile:
    """Return the profile ``spec``: a shipped profile's name (``baxter``) or a path.

    Raises
    ------
    WorldFileError
        The file is missing or a field is missing, mistyped, out of bounds or unknown
        (one line naming the file and the field).
    """
    path = Path(spec)
    if path.suffix != ".toml":
        path = ROBOTS_ROOT / f"{spec}.toml"
        if not path.is_file():
            shipped = sorted(p.stem for p in ROBOTS_ROOT.glob("*.toml"))
            raise WorldFileError(f"{path}: no robot profile {str(spec)!r}; shipped profiles: "
                                 f"{', '.join(shipped)} (or give a .toml path)")
    f = Fields(load_toml(path), path)
    name, urdf = _name(f, "name"), f.str("urdf")
    fr = f.table("frames")
    frames = (_name(fr, "world"), _name(fr, "base"))
    fr.done()
    js = f.table("joint_states")
    js_topic = _name(js, "topic")
    js_rate = js.float("rate_hz", minimum=1.0, maximum=1000.0)
    stale = js.float("stale_after_s", minimum=0.01, maximum=10.0)
    js.done()
    arm = f.table("arm")
    arm_action = _name(arm, "action")
    joints = arm.raw("joints")
    if (not isinstance(joints, list) or not joints
            or not all(isinstance(j, str) and j for j in joints) or len(set(joints)) != len(joints)):
        raise arm.error("joints", f"must be a list of distinct joint names, got {joints!r}")
    tolerances = (arm.float("path_tolerance", minimum=1e-4, maximum=3.2),
                  arm.float("goal_tolerance", minimum=1e-5, maximum=3.2),
                  arm.float("goal_time_tolerance", minimum=0.0, maximum=60.0))
    arm.done()
    g = f.table("gripper")
    gripper = (_name(g, "action"), _name(g, "joint"), g.float("open_position", minimum=0.0, maximum=1.0),
               g.float("closed_position", minimum=0.0, maximum=1.0),
               g.float("max_effort", minimum=0.0, maximum=1e4))
    if gripper[3] >= gripper[2]:
        raise g.error("closed_position", f"must be below open_position ({gripper[2]}), "
                      f"got {gripper[3]}")
    g.done()
    o = f.table("objects")
    topic = _name(o, "topic")
    if "{name}" not in topic:
        raise o.error("topic", f"must contain {{name}} (one topic per object), got {topic!r}")
    rate = o.float("rate_hz", minimum=1.0, maximum=1000.0)
    names = o.raw("names", {})
    if not isinstance(names, dict) or not all(isinstance(v, str) and v for v in names.values()):
        raise o.error("names", f"must be a table of object name = mocap name, got {names!r}")
    o.done()
    lim = f.table("limits")
    speed = lim.float("max_joint_speed", minimum=1e-3, maximum=10.0)
    lo = lim.vec("workspace_min", 3, minimum=-10.0, maximum=10.0)
    hi = lim.vec("workspace_max", 3, minimum=-10.0, maximum=10.0)
    if any(a >= b for a, b in zip(lo, hi)):
        raise lim.error("workspace_max", f"must exceed workspace_min {list(lo)} on every "
                        f"axis, got {list(hi)}")
    lim.done()
    c = f.table("clock", {})  # optional: a simulated arm's clock (rosgraph_msgs/Clock)
    clock = (c.bool("use_sim_time", False), _name(c, "topic") if c.has("topic") else "/clock",
             c.float("silent_after_s", 3.0, minimum=0.1, maximum=60.0))
    c.done()
    tr = f.table("trainer", {})
    trainer = (_name(tr, "request_topic") if "request_topic" in tr.data
               else RobotProfile.trainer_request_topic,
               _name(tr, "done_topic") if "done_topic" in tr.data
               else RobotProfile.trainer_done_topic,
               tr.float("timeout_s", RobotProfile.trainer_timeout_s, minimum=1.0,
                        maximum=3600.0))
    tr.done()
    wr = f.table("wrench", {})
    wrench = ((_name(wr, "topic"), _name(wr, "frame")) if wr.data else ("", ""))
    wr.done()
    f.done()
    return RobotProfile(str(path), name, urdf, *frames, js_topic, js_rate, stale, arm_action,
                        tuple(joints), *tolerances, *gripper, topic, rate, dict(names), speed,
                        lo, hi, *clock, *trainer, *wrench)
