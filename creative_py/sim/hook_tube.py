"""Case 1: pull a cube out of a closed tube with a hook-like tool held by Baxter.

The world (``worlds/hook_tube/``) is read into frozen dataclasses; an episode builds
the scene in a fresh :class:`~creative_py.sim.core.Sim` and offers the skills
``pick_up``, ``position_tool`` and ``act`` (pull).

Pose of the tool relative to the cube, :class:`HookPose` ``(dx, dy, roll)``:

* ``dx`` (m): along the tube axis (+x world), the prong's centre minus the cube's
  centre; positive = deeper in the tube than the cube. For a stick: its tip.
* ``dy`` (m): the handle axis's y minus the cube's y.
* ``roll`` (rad): rotation of the tool about its handle axis; 0 = prong pointing down
  (-z), +pi/2 = prong pointing to +y (the robot's left), -pi/2 = to -y. The roll is
  measured from the prong, whatever side of the handle it is on.

How the skill positions the tool (the pose has no height: the skill chooses it). The
gripper carries the tool above the tube to in front of its mouth and turns it so the
prong is flat (horizontal): towards the side of the handle with more room, or at the
requested roll if that is flat. Before going down it tries the rest of the motion
(insertion, turning, pull) in the kinematics client; if the arm would run into a joint
limit on the way, it lifts the tool, re-shapes the arm in joint space into a posture
that can follow the whole path, and comes back. It then lowers the tool to just above
the cube, inserts it along +x until the prong is at ``dx``, raises the handle if needed
so that the lowered prong clears the tube's floor, and turns the tool to ``roll``.
``act`` pulls straight back along -x until the prong is outside the mouth. The goal
holds when the cube's centre is in front of the mouth.

Does the hook side matter? Not in this tube, and we say so rather than fake it: the
prong's direction is set by the roll, which the wrist turns either way, so a left and
a right hook are mirror images in use. A cube against a side wall (location 3) only
decides which way the skill lays the prong flat while inserting. What does matter
physically: handle length (the gripper's base does not fit in the mouth, only its
fingers do, up to 0.10 m, so a short handle is blocked at the mouth or pushes
nothing), roll (a flat prong passes over the cube), dx (a prong lowered in front of
the cube pushes nothing) and dy (a prong beside the cube misses it).

Perception: the cube's pose comes from the downward camera (``[[camera]]`` in
``scene.toml``) through :mod:`creative_py.perception`; the held tool's pose comes from
proprioception: forward kinematics of the arm and the known grasp.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field, fields, replace
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
import pybullet as pb

from creative_py.mesh.spec import Box, HookSpec, spec_from_dict
from creative_py.sim.baxter import Baxter, BaxterConfig, MoveResult
from creative_py.sim.bodies import (Surface, frame_pose, load_tool_urdf, spawn_parts,
                                    spawn_spec, yaw_of)
from creative_py.sim.core import Pose, Sim
from creative_py.sim.trial import Fact, Observation, SkillOutcome
from creative_py.world import (WORLDS_ROOT, Fields, PhysicsSettings, WorldFileError,
                               load_toml, read_physics, world_file)

log = logging.getLogger(__name__)

GRIPPER_FORWARD: tuple[float, float, float, float] = tuple(
    pb.getQuaternionFromEuler((0.0, math.pi / 2, 0.0)))
"""Orientation of ``right_gripper`` pointing along +x world (its +z axis), roll 0."""


class HookPose(NamedTuple):
    """The tool's pose relative to the cube: ``dx``, ``dy`` (m) and ``roll`` (rad)."""

    dx: float
    dy: float
    roll: float


# ---------------------------------------------------------------------------- world
@dataclass(frozen=True)
class TableSpec:
    """The table: top height, near edge, extents (m), friction."""

    top_z: float
    near_edge_x: float
    depth: float
    width: float
    center_y: float
    thickness: float
    friction: float


@dataclass(frozen=True)
class RiserSpec:
    """The block under the tube: height, width, overhang in front of the mouth (m)."""

    height: float
    width: float
    front: float
    friction: float


@dataclass(frozen=True)
class TubeSpec:
    """The tube's cross-section and placement (m); its length comes from the variant."""

    name: str
    mouth_x: float
    axis_y: float
    inner_width: float
    inner_height: float
    wall: float
    friction: float


@dataclass(frozen=True)
class StandSpec:
    """Where a tool lies before it is picked up (m)."""

    butt_x: float
    axis_y: float
    roll: float
    top_z: float
    width: float
    friction: float


@dataclass(frozen=True)
class SkillSettings:
    """Speeds (m/s, turn rad/s) and distances (m) of the hook skills."""

    free_speed: float
    insert_speed: float
    pull_speed: float
    turn_speed: float
    steps_per_waypoint: float
    lift: float
    clearance: float
    pull_beyond_mouth: float
    approach: float


@dataclass(frozen=True)
class CubeSpec:
    """The target cube: name, edge (m), mass (kg), friction."""

    name: str
    size: float
    mass: float
    friction: float


@dataclass(frozen=True)
class Location:
    """A predefined cube location relative to the tube's far end (m)."""

    back_gap: float
    lateral: float


@dataclass(frozen=True)
class Demonstration:
    """The trainer's demonstration: tool, variant, location, pose and step names."""

    tool: str
    variant: str
    location: int
    pose: HookPose
    steps: tuple[str, ...]


@dataclass(frozen=True)
class HookWorld:
    """Everything read from ``worlds/hook_tube/`` (see its TOML files for units).

    ``tool_urdfs`` maps created tools to their URDF files (spawned from the file
    instead of the spec); add tools with :func:`with_tool`.
    """

    directory: Path
    physics: PhysicsSettings
    table: TableSpec
    riser: RiserSpec
    tube: TubeSpec
    stand: StandSpec
    skills: SkillSettings
    cameras: tuple
    noise: Any
    cube: CubeSpec
    tools: dict[str, HookSpec]
    tool_sets: dict[str, str]
    locations: tuple[Location, ...]
    variants: dict[str, float]
    demonstration: Demonstration
    robot_visuals: bool = False
    tool_urdfs: dict[str, Path] = field(default_factory=dict)

    def tool(self, name: str) -> HookSpec:
        """Return the spec of tool ``name``; raise listing the available tools."""
        if name not in self.tools:
            raise KeyError(f"unknown tool {name!r}; available tools: "
                           f"{', '.join(self.tools)}")
        return self.tools[name]


def _dataclass_from(cls, f: Fields, **overrides):
    values = {}
    for fld in fields(cls):
        if fld.name in overrides:
            continue
        if fld.type in ("str",):
            values[fld.name] = f.str(fld.name)
        else:
            values[fld.name] = f.float(fld.name)
    f.done()
    return cls(**values, **overrides)


def load_hook_world(world_dir: Path | None = None) -> HookWorld:
    """Read the hook world from ``world_dir`` (default ``worlds/hook_tube``).

    Raises :class:`~creative_py.world.WorldFileError` naming the file and the field
    for a missing file or field, a wrong type, or an unknown field (a typo).
    """
    from creative_py.perception.noise import NoiseModel
    from creative_py.sim.camera import cameras_from_tables

    d = Path(world_dir) if world_dir is not None else WORLDS_ROOT / "hook_tube"
    # physics.toml
    p = world_file(d, "physics.toml")
    pf = Fields(load_toml(p), p)
    physics = read_physics(pf)
    pf.done()
    # scene.toml
    s = world_file(d, "scene.toml")
    sf = Fields(load_toml(s), s)
    table = _dataclass_from(TableSpec, sf.table("table"))
    riser = _dataclass_from(RiserSpec, sf.table("riser"))
    tube = _dataclass_from(TubeSpec, sf.table("tube"))
    stand = _dataclass_from(StandSpec, sf.table("tool_stand"))
    skills = _dataclass_from(SkillSettings, sf.table("skills"))
    robot_f = sf.table("robot")
    robot_visuals = robot_f.bool("visuals")
    robot_f.done()
    perc = sf.table("perception")
    try:
        noise = NoiseModel(depth_sigma_m=perc.float("depth_sigma_m", minimum=0.0),
                           dropout=perc.float("dropout", minimum=0.0, maximum=0.99))
    except ValueError as exc:
        raise WorldFileError(f"{s}: [perception]: {exc}") from None
    perc.done()
    try:
        cameras = cameras_from_tables(sf.raw("camera"), str(s))
    except (ValueError, TypeError) as exc:
        raise WorldFileError(str(exc)) from None
    sf.done()
    for name, v in (("tube.inner_width", tube.inner_width), ("tube.inner_height", tube.inner_height),
                    ("tube.wall", tube.wall), ("riser.height", riser.height)):
        if v <= 0:
            raise WorldFileError(f"{s}: field {name!r}: must be positive, got {v}")
    # objects.toml
    o = world_file(d, "objects.toml")
    of = Fields(load_toml(o), o)
    cube = _dataclass_from(CubeSpec, of.table("cube"))
    tools: dict[str, HookSpec] = {}
    sets: dict[str, str] = {}
    for tf in of.tables("tool"):
        table_data = dict(tf.data)
        tool_set = tf.str("set")
        del table_data["set"]
        try:
            spec = spec_from_dict(table_data, source=f"{o}: {tf.prefix}")
        except ValueError as exc:
            raise WorldFileError(str(exc)) from None
        if not isinstance(spec, HookSpec):
            raise tf.error("kind", "the hook world takes hook or stick objects only")
        if spec.name in tools:
            raise tf.error("name", f"tool name {spec.name!r} is used twice")
        tools[spec.name] = spec
        sets[spec.name] = tool_set
    of.done()
    if not tools:
        raise WorldFileError(f"{o}: field 'tool': at least one [[tool]] is needed")
    # tasks.toml
    t = world_file(d, "tasks.toml")
    tf_ = Fields(load_toml(t), t)
    locations = tuple(_dataclass_from(Location, lf) for lf in tf_.tables("location"))
    if not locations:
        raise tf_.error("location", "at least one [[location]] is needed")
    tf_.done()
    for i, loc in enumerate(locations, 1):
        if abs(loc.lateral) > tube.inner_width / 2 - cube.size / 2 + 1e-9:
            raise WorldFileError(f"{t}: field 'location[{i - 1}].lateral': the cube would "
                                 f"stick into the tube's side wall ({loc.lateral} m)")
    # case.toml: the variants' tube lengths and the demonstration
    from creative_py.case import manifest_of_folder

    manifest = manifest_of_folder(d)
    c = d / "case.toml"
    variants = {}
    for v in manifest.variants:
        length = v.set.get("tube.length")
        if isinstance(length, bool) or not isinstance(length, (int, float)) or length < 0.1:
            raise WorldFileError(f"{c}: field 'variant.{v.name}.set.tube.length': must be "
                                 f"a number >= 0.1 (m), got {length!r}")
        variants[v.name] = float(length)
    dm = manifest.demonstration
    if dm.tool not in tools:
        raise WorldFileError(f"{c}: field 'demonstration.tool': must be one of "
                             f"{', '.join(tools)}, got {dm.tool!r}")
    demo = Demonstration(tool=dm.tool, variant=dm.variant, location=dm.location,
                         pose=HookPose(*dm.pose), steps=dm.steps)
    if demo.location > len(locations):
        raise WorldFileError(f"{c}: field 'demonstration.location': must be at most "
                             f"{len(locations)} (tasks.toml has {len(locations)} "
                             f"locations), got {demo.location}")
    return HookWorld(directory=d, physics=physics, table=table, riser=riser, tube=tube,
                     stand=stand, skills=skills, cameras=cameras, noise=noise, cube=cube,
                     tools=tools, tool_sets=sets, locations=locations, variants=variants,
                     demonstration=demo, robot_visuals=robot_visuals)


def with_tool(world: HookWorld, spec: HookSpec, urdf: Path | None = None,
              tool_set: str = "created") -> HookWorld:
    """Return ``world`` with one more available tool (a created one).

    The tool's catalogue facts, grasp and skills come from ``spec``; its body comes
    from ``urdf`` (a file written by :mod:`creative_py.mesh`, link frame = tool frame)
    when given, otherwise from the spec's parts.
    """
    if not isinstance(spec, HookSpec):
        raise TypeError(f"the hook world takes HookSpec tools, got {type(spec).__name__}")
    if urdf is not None and not Path(urdf).is_file():
        raise FileNotFoundError(f"{urdf}: tool URDF not found")
    urdfs = dict(world.tool_urdfs)
    if urdf is not None:
        urdfs[spec.name] = Path(urdf)
    return replace(world, tools={**world.tools, spec.name: spec},
                   tool_sets={**world.tool_sets, spec.name: tool_set}, tool_urdfs=urdfs)


def catalogue_facts(spec: HookSpec) -> list[Fact]:
    """Return the catalogue facts of a hook-like object (metres, degrees).

    A stick gets ``hook_length_m`` and ``hook_width_m`` 0.0 and ``hook_side_is none``
    and no ``hook_angle_deg`` (it has no prong).
    """
    n = spec.name
    facts: list[Fact] = [("object_kind", n, "stick" if spec.is_stick else "hook"),
                         ("handle_length_m", n, spec.handle_length),
                         ("handle_width_m", n, spec.handle_width)]
    if spec.is_stick:
        facts += [("hook_length_m", n, 0.0), ("hook_width_m", n, 0.0),
                  ("hook_side_is", n, "none")]
    else:
        facts += [("hook_length_m", n, spec.hook_length), ("hook_width_m", n, spec.hook_width),
                  ("hook_side_is", n, spec.hook_side),
                  ("hook_angle_deg", n, spec.hook_angle_deg)]
    return facts


def prong_centre(spec: HookSpec) -> tuple[float, float, float]:
    """Return the prong box's centre (a stick: its tip), tool frame, metres."""
    if spec.is_stick:
        return (spec.handle_length, 0.0, 0.0)
    prong = spec.parts()[1]
    assert isinstance(prong, Box)
    return prong.center


def prong_reach(spec: HookSpec) -> float:
    """Return how far the prong reaches from the handle axis, metres (0 for a stick)."""
    if spec.is_stick:
        return spec.handle_width / 2
    return spec.handle_width / 2 + spec.hook_length * math.sin(math.radians(spec.hook_angle_deg))


def tool_orientation(spec: HookSpec, roll: float) -> tuple[float, float, float, float]:
    """Return the world orientation of the tool frame, handle along +x, at ``roll`` (rad)."""
    side = -1.0 if spec.hook_side == "right" else 1.0
    return tuple(pb.getQuaternionFromEuler((roll - side * math.pi / 2, 0.0, 0.0)))


def gripper_orientation(roll: float) -> tuple[float, float, float, float]:
    """Return the gripper orientation (pointing +x) for tool roll ``roll`` (rad)."""
    return tuple(pb.multiplyTransforms((0, 0, 0), pb.getQuaternionFromEuler((roll, 0, 0)),
                                       (0, 0, 0), GRIPPER_FORWARD)[1])


def tool_in_gripper(spec: HookSpec) -> Pose:
    """Return the tool frame's pose in the ``right_gripper`` frame (the known grasp)."""
    g_pos, g_quat = (0.0, 0.0, 0.0), gripper_orientation(0.0)
    t_quat = tool_orientation(spec, 0.0)
    inv = pb.invertTransform(g_pos, g_quat)
    _, rel = pb.multiplyTransforms(inv[0], inv[1], (0, 0, 0), t_quat)
    # The grip point (grip_offset, 0, 0) of the tool sits at the gripper's origin.
    offset = pb.multiplyTransforms((0, 0, 0), rel, (-spec.grip_offset, 0, 0), (0, 0, 0, 1))[0]
    return tuple(offset), tuple(rel)


def roll_of(spec: HookSpec, quat) -> float:
    """Return the tool roll (rad, 0 = prong down) of a tool-frame orientation."""
    side = -1.0 if spec.hook_side == "right" else 1.0
    m = np.asarray(pb.getMatrixFromQuaternion(quat)).reshape(3, 3)
    d = side * m[:, 1]
    return math.atan2(float(d[1]), float(-d[2]))


# -------------------------------------------------------------------------- episode
class HookEpisode:
    """One hook-and-tube scene in its own simulator, driven skill by skill.

    Build it with :func:`open_hook_episode` (or :func:`creative_py.sim.trial.open_episode`).
    """

    def __init__(self, world: HookWorld, variant: str, location: int, tool: str,
                 seed: int = 0, gui: bool = False, images_dir: Path | None = None,
                 posture_cache: dict | None = None) -> None:
        if variant not in world.variants:
            raise KeyError(f"unknown variant {variant!r}; variants: {', '.join(world.variants)}")
        if not (isinstance(location, int) and 1 <= location <= len(world.locations)):
            raise KeyError(f"unknown location {location!r}; locations: 1..{len(world.locations)}")
        self.world = world
        self.variant = variant
        self.location = location
        self.spec = world.tool(tool)
        self.tube_length = world.variants[variant]
        self.rng = np.random.default_rng(seed)
        self.images_dir = images_dir
        self.render_time_s = 0.0
        self._shots = 0
        self._postures = posture_cache
        self.sim = Sim(world.physics, gui=gui)
        try:
            self._build()
        except BaseException:
            self.close()
            raise

    # ------------------------------------------------------------ scene building
    @property
    def floor_z(self) -> float:
        """Return the z of the tube's inner floor, metres."""
        w = self.world
        return w.table.top_z + w.riser.height + w.tube.wall

    def _build(self) -> None:
        w, sim = self.world, self.sim
        t, r, tb = w.table, w.riser, w.tube
        L = self.tube_length
        grey = Surface(t.friction, (0.55, 0.45, 0.35, 1.0))
        spawn_parts(sim, [Box((0, 0, 0), (t.depth, t.width, t.thickness))],
                    ((t.near_edge_x + t.depth / 2, t.center_y, t.top_z - t.thickness / 2),
                     (0, 0, 0, 1)), 0.0, grey)
        riser_len = L + r.front + tb.wall
        spawn_parts(sim, [Box((0, 0, 0), (riser_len, r.width, r.height))],
                    ((tb.mouth_x - r.front + riser_len / 2, tb.axis_y, t.top_z + r.height / 2),
                     (0, 0, 0, 1)), 0.0, Surface(r.friction, (0.4, 0.4, 0.45, 1.0)))
        # Tube walls in the tube frame: origin at the mouth on the axis, on the floor.
        W, H, k = tb.inner_width, tb.inner_height, tb.wall
        walls = [Box((L / 2, 0, -k / 2), (L, W + 2 * k, k)),                     # floor
                 Box((L / 2, W / 2 + k / 2, H / 2), (L, k, H)),                  # left
                 Box((L / 2, -W / 2 - k / 2, H / 2), (L, k, H)),                 # right
                 Box((L + k / 2, 0, H / 2), (k, W + 2 * k, H + 2 * k)),          # far end
                 Box((L / 2, 0, H + k / 2), (L, W + 2 * k, k))]                  # top (clear)
        self.tube_body = spawn_parts(sim, walls, ((tb.mouth_x, tb.axis_y, self.floor_z),
                                                  (0, 0, 0, 1)), 0.0,
                                     Surface(tb.friction, (0.3, 0.6, 0.9, 1.0)), hidden=[4])
        # The cube at its location.
        c = w.cube
        loc = w.locations[self.location - 1]
        cx = tb.mouth_x + L - loc.back_gap - c.size / 2
        cy = tb.axis_y + loc.lateral
        self.cube_body = spawn_parts(sim, [Box((0, 0, c.size / 2), (c.size,) * 3)],
                                     ((cx, cy, self.floor_z), (0, 0, 0, 1)), c.mass,
                                     Surface(c.friction, (0.9, 0.2, 0.2, 1.0)))
        # The tool on its stand, prong flat.
        st, spec = w.stand, self.spec
        grip = spec.grip_offset
        x0 = st.butt_x + grip + 0.06
        x1 = st.butt_x + spec.handle_length - (0.0 if spec.is_stick else spec.hook_width) - 0.01
        if x1 - x0 < 0.03:
            x0 = x1 - 0.03
        stand_h = st.top_z - t.top_z
        spawn_parts(sim, [Box((0, 0, 0), (x1 - x0, st.width, stand_h))],
                    (((x0 + x1) / 2, st.axis_y, t.top_z + stand_h / 2), (0, 0, 0, 1)), 0.0,
                    Surface(st.friction, (0.3, 0.3, 0.3, 1.0)))
        lie_roll = st.roll
        lying = ((st.butt_x, st.axis_y, st.top_z + spec.handle_width / 2 + 0.0005),
                 tool_orientation(spec, lie_roll))
        if spec.name in w.tool_urdfs:
            self.tool_body = load_tool_urdf(sim, w.tool_urdfs[spec.name], lying)
        else:
            self.tool_body = spawn_spec(sim, spec, lying, Surface(0.5, (0.95, 0.8, 0.1, 1.0)))
        self.robot = Baxter(sim, BaxterConfig(
            visuals=w.robot_visuals, turn_speed=w.skills.turn_speed,
            steps_per_waypoint=int(w.skills.steps_per_waypoint)))
        # Start with the gripper pointing +x above the stand's near end, prong-flat roll,
        # in the family of arm postures that works at the tube's mouth (found first,
        # farthest from the joint limits), so that Cartesian moves carry it over.
        # Solved at roll 0, the margin rule centres the wrist's roll joint, so that
        # both flat rolls (+-pi/2) stay within its limits.
        work = ((tb.mouth_x - 0.25, tb.axis_y, self.floor_z + tb.inner_height / 2),
                gripper_orientation(0.0))
        home = ((st.butt_x - 0.1, st.axis_y, self._travel_z()), gripper_orientation(lie_roll))
        key = (work, home)
        if self._postures is not None and key in self._postures:
            q = self._postures[key]  # the same numbers the search below gives
        else:
            q_work = self.robot.solve_ik_global(work)
            q = self.robot.solve_ik_global(home, keep=1, seeds=[q_work] if q_work else ())
            if self._postures is not None and q is not None:
                self._postures[key] = q
        if q is None:
            raise RuntimeError(f"{w.directory / 'scene.toml'}: field 'tool_stand': the arm "
                               f"cannot reach its start pose above the stand {home[0]}")
        self.robot.reset_posture(q)
        self.grasp = tool_in_gripper(spec)
        self.sim.step(60)  # let the cube and the tool settle
        self.held = False

    # ------------------------------------------------------------- perception
    def tool_pose(self) -> Pose:
        """Return the held tool's frame pose by proprioception (FK + the known grasp)."""
        g = self.robot.gripper_pose()
        pos, quat = pb.multiplyTransforms(g[0], g[1], *self.grasp)
        return tuple(pos), tuple(quat)

    def tip_position(self) -> tuple[float, float, float]:
        """Return the world position of the prong's centre (stick: tip), proprioception."""
        pos, quat = self.tool_pose()
        return tuple(pb.multiplyTransforms(pos, quat, prong_centre(self.spec), (0, 0, 0, 1))[0])

    def tool_roll(self) -> float:
        """Return the held tool's roll (rad, 0 = prong down) by proprioception."""
        return roll_of(self.spec, self.tool_pose()[1])

    def _frames(self) -> tuple:
        from creative_py.sim.camera import capture_frames

        frames = capture_frames(self.sim.client, self.world.cameras, self.images_dir,
                                self._shots)
        self.render_time_s += sum(f.render_time_s for f in frames)
        self._shots += self.images_dir is not None
        return frames

    def perceive_cube(self, frames=None):
        """Return the camera estimate of the cube (or None if no camera sees it)."""
        from creative_py.perception import estimate_objects

        frames = self._frames() if frames is None else frames
        c = self.world.cube
        est = estimate_objects(frames, {c.name: self.cube_body}, self.world.noise, self.rng,
                               heights={c.name: c.size})
        return est.get(c.name), frames

    def observe(self) -> Observation:
        """Return the facts the robot perceives now (see the module docstring)."""
        from creative_py.perception import facts_from_estimates

        w, tb = self.world, self.world.tube
        est, frames = self.perceive_cube()
        facts: list[Fact] = []
        if est is not None:
            facts += facts_from_estimates([est])
        if self.held:
            n = self.spec.name
            facts += [("held", n), ("tip_position", n, *self.tip_position()),
                      ("tool_roll", n, self.tool_roll())]
        facts += [("tube_mouth", tb.name, tb.mouth_x, tb.axis_y,
                   self.floor_z + tb.inner_height / 2),
                  ("tube_length_m", tb.name, self.tube_length),
                  ("tube_inner_m", tb.name, tb.inner_width, tb.inner_height)]
        for spec in w.tools.values():
            facts += catalogue_facts(spec)
        return Observation(facts=tuple(facts), frames=frames, truth=self.truth())

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ground-truth ``name -> (x, y, z, yaw)`` (cube centre, tool frame)."""
        c = self.world.cube
        pos, quat = frame_pose(self.sim, self.cube_body)
        out = {c.name: (pos[0], pos[1], pos[2] + c.size / 2, yaw_of(quat))}
        tpos, tquat = frame_pose(self.sim, self.tool_body)
        out[self.spec.name] = (*tpos, yaw_of(tquat))
        return {k: tuple(float(v) for v in p) for k, p in out.items()}

    # ------------------------------------------------------------------- skills
    def _move(self, pos, roll: float, speed: float) -> MoveResult:
        """Move the gripper (pointing +x) to ``pos`` while turning the tool to ``roll``.

        A big change of roll is split into pieces under 70 degrees, so that the
        orientation turns through the intermediate rolls (about the handle axis)
        instead of taking whichever way a half-turn slerp picks.
        """
        start_pos, start_quat = self.robot.gripper_pose()
        start_roll = roll_of(self.spec, pb.multiplyTransforms(start_pos, start_quat,
                                                              *self.grasp)[1])
        n = max(1, math.ceil(abs(roll - start_roll) / math.radians(70)))
        for i in range(1, n + 1):
            t = i / n
            p = tuple(a + t * (b - a) for a, b in zip(start_pos, pos))
            r = start_roll + t * (roll - start_roll)
            res = self.robot.move_to((p, gripper_orientation(r)), speed=speed,
                                     watch=[self.cube_body])
            if not res.ok:
                return res
        return res

    def _gripper_for_tool(self, tool_origin, roll: float) -> tuple[float, float, float]:
        """Return the gripper position that puts the tool frame's origin at ``tool_origin``."""
        q = tool_orientation(self.spec, roll)
        grip_world = pb.multiplyTransforms(tool_origin, q, self.spec.grip_point, (0, 0, 0, 1))[0]
        return tuple(grip_world)

    def pick_up(self) -> SkillOutcome:
        """Grasp the tool lying on its stand and lift it to the travel height."""
        if self.held:
            return SkillOutcome("ok", "already holding the tool")
        sk, spec = self.world.skills, self.spec
        origin, quat = frame_pose(self.sim, self.tool_body)
        roll = roll_of(spec, quat)
        grip = pb.multiplyTransforms(origin, quat, spec.grip_point, (0, 0, 0, 1))[0]
        pre = (grip[0] - sk.approach, grip[1], grip[2])
        for target, speed in (((pre[0], pre[1], pre[2] + 0.05), sk.free_speed),
                              (pre, sk.insert_speed), (grip, sk.insert_speed)):
            res = self._move(target, roll, speed)
            if not res.ok:
                return SkillOutcome(res.status, f"pick_up: {res.reason}")
        self.robot.grasp(self.tool_body, self.grasp)
        self.held = True
        res = self._move((grip[0], grip[1], self._travel_z()), roll, sk.free_speed)
        if not res.ok:
            return SkillOutcome(res.status, f"pick_up: {res.reason}")
        return SkillOutcome("ok")

    def _travel_z(self) -> float:
        tb = self.world.tube
        return max(self.world.stand.top_z + self.world.skills.lift,
                   self.floor_z + tb.inner_height + tb.wall + prong_reach(self.spec) + 0.04)

    def position_tool(self, pose: HookPose | tuple) -> SkillOutcome:
        """Insert the held tool into the tube and put it at ``pose`` relative to the cube.

        The cube's position comes from the camera. Returns ``blocked`` if the tool or
        the arm hits something on the way, ``unreachable`` if the arm cannot follow.
        """
        pose = HookPose(*(float(v) for v in pose))
        if not all(math.isfinite(v) for v in pose):
            raise ValueError(f"pose numbers must be finite, got {pose}")
        if not self.held:
            return SkillOutcome("blocked", "position_tool: no tool is held (pick_up first)")
        est, _ = self.perceive_cube()
        if est is None:
            return SkillOutcome("unreachable", "position_tool: the camera does not see "
                                f"{self.world.cube.name}")
        sk, spec, tb = self.world.skills, self.spec, self.world.tube
        cube_x, cube_y = est.x, est.y
        cube_top = est.z + est.size[2] / 2
        axis_y = cube_y + pose.dy
        # Insertion roll: the requested one if it lays the prong flat, otherwise flat
        # towards the side of the handle with more room.
        if abs(pose.roll) >= math.pi / 4 or spec.is_stick:
            flat = pose.roll
        else:
            room_left = tb.axis_y + tb.inner_width / 2 - axis_y
            room_right = axis_y - (tb.axis_y - tb.inner_width / 2)
            flat = math.pi / 2 if room_left > room_right else -math.pi / 2
        half_t = spec.handle_width / 2
        z_insert = cube_top + half_t + sk.clearance
        tip_local = prong_centre(spec)
        # Tool-frame origin x so that the prong centre is at cube_x + dx.
        q_flat = tool_orientation(spec, flat)
        tip_off = pb.multiplyTransforms((0, 0, 0), q_flat, tip_local, (0, 0, 0, 1))[0]
        goal_origin_x = cube_x + pose.dx - tip_off[0]
        far_x = max(spec.handle_length, tip_local[0] + spec.hook_width)
        pre_origin_x = tb.mouth_x - 0.03 - far_x
        carried = self.tool_roll()
        steps = [
            ((pre_origin_x, axis_y, self._travel_z()), carried, sk.free_speed),
            ((pre_origin_x, axis_y, self._travel_z()), flat, sk.free_speed),
            ((pre_origin_x, axis_y, z_insert), flat, sk.free_speed),
            ((goal_origin_x, axis_y, z_insert), flat, sk.insert_speed),
        ]
        # Raise the handle, if needed, so that the lowered prong clears the floor.
        z_down = min(max(z_insert, self.floor_z + prong_reach(spec) + 0.004),
                     self.floor_z + tb.inner_height - half_t - 0.002)
        steps.append(((goal_origin_x, axis_y, z_down), flat, sk.insert_speed))
        steps.append(((goal_origin_x, axis_y, z_down), pose.roll, sk.insert_speed))
        pull_dx = min(0.0, tb.mouth_x - sk.pull_beyond_mouth - (cube_x + pose.dx))
        for i, (origin, roll, speed) in enumerate(steps):
            target = self._gripper_for_tool(origin, roll)
            res = self._move(target, roll, speed)
            if not res.ok:
                return SkillOutcome(res.status, f"position_tool: {res.reason}")
            if i == 0:
                res = self._choose_posture(steps[1:], pull_dx)
                if not res.ok:
                    return SkillOutcome(res.status, f"position_tool: {res.reason}")
        self._pull_roll = pose.roll
        log.info("position_tool %s at %s: ok", spec.name, pose)
        return SkillOutcome("ok")

    def _gripper_path(self, steps, pull_dx: float) -> list[Pose]:
        """Return the gripper poses of ``steps`` then the pull, rolls split as in :meth:`_move`."""
        pos, quat = self.robot.gripper_pose()
        roll = roll_of(self.spec, pb.multiplyTransforms(pos, quat, *self.grasp)[1])
        path: list[Pose] = []
        for origin, new_roll, _ in steps:
            goal = self._gripper_for_tool(origin, new_roll)
            n = max(1, math.ceil(abs(new_roll - roll) / math.radians(70)))
            for i in range(1, n + 1):
                t = i / n
                p = tuple(a + t * (b - a) for a, b in zip(pos, goal))
                path.append((p, gripper_orientation(roll + t * (new_roll - roll))))
            pos, roll = goal, new_roll
        path.append(((pos[0] + pull_dx, pos[1], pos[2]), gripper_orientation(roll)))
        return path

    def _start_candidates(self, here: Pose, path: list[Pose]):
        """Yield start postures at ``here`` for following ``path``.

        Direct IK solutions at ``here`` first; then, for key poses of the path (where
        the tool turns flat, the deepest point, the last turn), IK solutions there
        walked back along the path to ``here`` in the kinematics client: a posture
        that can hold the hard poses and still reach the start.
        """
        rb = self.robot
        yield from rb.ik_candidates(here, keep=4)
        turned = path[:-1]  # every pose before the pull
        deep = max(range(len(turned)), key=lambda i: turned[i][0][0])
        for key in sorted({0, deep, len(turned) - 1}):
            for cand in rb.ik_candidates(turned[key], keep=4):
                q = rb.dry_run(cand, [*reversed(turned[:key]), here])
                if q is not None:
                    yield q

    def _choose_posture(self, steps, pull_dx: float) -> MoveResult:
        """Make sure the arm can follow the insertion and the pull; re-shape it if not.

        The path is tried in the kinematics client from the current posture. If IK
        would lose it (a joint limit on the way), other postures at the current
        gripper pose are tried; the first that carries the whole path is reached by
        lifting the tool clear, moving in joint space, and coming back down.
        """
        rb = self.robot
        path = self._gripper_path(steps, pull_dx)
        if rb.dry_run(rb.arm_q(), path) is not None:
            return MoveResult("ok")
        here = rb.gripper_pose()
        for cand in self._start_candidates(here, path):
            if rb.dry_run(cand, path) is None:
                continue
            # Re-shape high above everything: the held tool may swing on the way.
            for lift in (0.30, 0.22, 0.15, 0.10, 0.05):
                high = ((here[0][0], here[0][1], here[0][2] + lift), here[1])
                q_high = rb.dry_run(cand, [high])
                if q_high is not None:
                    break
            else:
                continue
            for res in (rb.move_to(high, speed=self.world.skills.free_speed,
                                   watch=[self.cube_body]),
                        rb.move_joints(q_high, watch=[self.cube_body]),
                        rb.move_to(here, speed=self.world.skills.free_speed,
                                   watch=[self.cube_body])):
                if not res.ok:
                    return res
            return MoveResult("ok")
        return MoveResult("unreachable", "no arm posture can carry the tool along the "
                          "insertion and the pull (joint limits)")

    def act(self) -> SkillOutcome:
        """Pull: move the tool straight back along -x until the prong is out of the tube."""
        if not self.held:
            return SkillOutcome("blocked", "pull: no tool is held")
        sk, tb = self.world.skills, self.world.tube
        g_pos, _ = self.robot.gripper_pose()
        tip = self.tip_position()
        dx = (tb.mouth_x - sk.pull_beyond_mouth) - tip[0]
        roll = getattr(self, "_pull_roll", self.tool_roll())
        res = self._move((g_pos[0] + min(dx, 0.0), g_pos[1], g_pos[2]), roll, sk.pull_speed)
        if not res.ok:
            return SkillOutcome(res.status, f"pull: {res.reason}")
        self.sim.step(60)
        why = self.sim.blow_up(self.cube_body)
        if why:
            return SkillOutcome("invalid", f"pull: {why}")
        return SkillOutcome("ok")

    pull = act

    def goal_reached(self) -> bool:
        """Return whether the cube is out of the tube (simulated state).

        Out means its centre is in front of the mouth: from there it has dropped onto
        the table in front of the riser (or will).
        """
        pos, _ = frame_pose(self.sim, self.cube_body)
        return bool(pos[0] < self.world.tube.mouth_x)

    def sim_time(self) -> float:
        """Return the simulated time so far, seconds."""
        return self.sim.time

    @property
    def steps(self) -> int:
        """Return the physics steps taken so far."""
        return self.sim.steps

    def close(self) -> None:
        """Release the simulator (idempotent)."""
        robot = getattr(self, "robot", None)
        if robot is not None:
            robot.close()
        self.sim.close()


def open_hook_episode(world: HookWorld, variant: str, location: int, tool: str,
                      seed: int = 0, gui: bool = False, images_dir: Path | None = None,
                      posture_cache: dict | None = None) -> HookEpisode:
    """Return a new :class:`HookEpisode` (close it when done).

    ``posture_cache`` (a dict kept by the caller) remembers the start posture found by
    the IK search for a scene geometry, so later scenes start up faster; the search
    is deterministic, so a cached posture equals a recomputed one.
    """
    return HookEpisode(world, variant, location, tool, seed, gui, images_dir, posture_cache)


class HookTubeCase:
    """The hook case for :mod:`creative_py.sim.trial`."""

    name = "hook"
    object_option = "tool"

    def __init__(self) -> None:
        self._postures: dict = {}

    def load_world(self, world_dir: Path | None) -> HookWorld:
        """Return the hook world (see :func:`load_hook_world`)."""
        return load_hook_world(world_dir)

    def open_episode(self, world: HookWorld, variant: str, location: int, object_name: str,
                     seed: int, gui: bool, images_dir: Path | None) -> HookEpisode:
        """Return a new episode."""
        return open_hook_episode(world, variant, location, object_name, seed, gui, images_dir,
                                 posture_cache=self._postures)

    def default_pose(self, world: HookWorld) -> HookPose:
        """Return the demonstration's pose."""
        return world.demonstration.pose

    def parse_pose(self, text: str) -> HookPose:
        """Parse ``"DX,DY,ROLL"`` (m, m, rad)."""
        parts = [p.strip() for p in text.split(",")]
        try:
            values = [float(p) for p in parts]
        except ValueError:
            values = []
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise ValueError(f"--pose must be DX,DY,ROLL (metres, metres, radians), got {text!r}")
        return HookPose(*values)

    def listing(self, world: HookWorld) -> dict[str, Any]:
        """Return tools (spec fields and set), locations, variants and default pose."""
        from dataclasses import asdict

        tools = {}
        for n, spec in world.tools.items():
            d = asdict(spec)
            d["set"] = world.tool_sets.get(n, "created")
            if n in world.tool_urdfs:
                d["urdf"] = str(world.tool_urdfs[n])
            tools[n] = d
        return {
            "case": self.name,
            "objects": tools,
            "locations": [{"index": i, **asdict(loc)} for i, loc in
                          enumerate(world.locations, 1)],
            "variants": {k: {"tube_length": v} for k, v in world.variants.items()},
            "default_pose": dict(world.demonstration.pose._asdict()),
            "demonstration": {"tool": world.demonstration.tool,
                              "variant": world.demonstration.variant,
                              "location": world.demonstration.location,
                              "steps": list(world.demonstration.steps)},
        }

