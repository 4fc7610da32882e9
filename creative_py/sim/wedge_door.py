"""Case 2: hold a self-closing door open with an object that Baxter places on the floor.

The world (``worlds/wedge_door/``) is read into frozen dataclasses; an episode builds
the scene in a fresh :class:`~creative_py.sim.core.Sim` and offers the skills
``pick_up`` (grip an object on the tray), ``position_tool`` (carry it and put it on
the floor at a :class:`WedgePose` relative to the door) and ``act`` (release the door:
its closer pushes it shut).

Arrangement (world frame = Baxter's base frame, metres, radians)
----------------------------------------------------------------
Baxter cannot bring an object down to the real floor (z = -0.926), so the door stands
on a raised stage whose top is at z = -0.10: the door room's floor ``floor1`` (the real
floor is there too, for objects pushed off the stage). The hinge is front-left of the
robot at (0.52, 0.42); closed, the door runs from the hinge towards the robot's right
(heading ``closed_heading`` = -105 deg). The door opens counter-clockwise seen from
above (door angle A >= 0, heading = closed_heading + A) and closes clockwise, towards
the robot. A door frame stops it at A = 0 (a joint limit).

The door stands at ``open_angle`` (40 deg), where the trial starts: ``act`` releases
it from rest there, and every observation outside ``position_tool`` sees it there. A
door holder swings it to ``place_angle`` (69 deg) while the arm places the object,
because the hand (about 10 cm across) would hit a door 3 cm from the object, and back
to ``open_angle`` after the arm's retreat. The zone between the door at 40 deg and the closed door's
line is within reach of the right arm with the gripper pointing down; the tray and the
arm's retreat point lie outside the door's sweep, and before the release every robot
link is checked against the sweep (a link in it makes ``act`` return ``blocked``).

Pose of the object relative to the door, :class:`WedgePose` ``(r, gap, yaw)``
-----------------------------------------------------------------------------
* ``r`` (m): distance from the hinge axis to the object's centre.
* ``gap`` (m): arc length, along the door's closing sweep at radius ``r``, from the
  face of the door at ``open_angle`` to the object's tip: with Phi the heading of
  (object - hinge) relative to the closed door,
  ``gap = r (A - Phi) - length / 2 - thickness / 2``.
* ``yaw`` (rad): the object's heading (its block frame's +x, the tip of a prism) minus
  the heading from the object towards the closing door (the counter-clockwise tangent,
  closed_heading + Phi + pi / 2), wrapped to (-pi, pi]: 0 = tip pointing at the door.
  This matches ``prolog/abstract_state.pl`` (pose_numbers/4).

The physics decides
-------------------
After the release a closing torque (``closing_torque`` of the variant) acts on the door
every step for ``held.duration`` (4 s). The door is *held* (goal ``door_held(door1)``)
when it touched the object, closed less than ``max_close_deg`` (2 deg) after the first
contact and still stands open at least ``min_open_deg`` (20 deg: a door that closed
most of the way before meeting the object is not held open). Nothing here looks at the
object's shape: a wedge holds because the door's push on its slope presses it onto the
floor; a box or a cylinder slides, a reversed prism is pushed by its vertical back.

Settings and why (measured): 1/960 s and 100 solver iterations while an object rests
on the floor (at 1/240 s a light wedge sinks into the floor and flips), 1/240 s while
the arm carries it. Door 0.8 x 0.04 x 2.0 m, 1 cm bottom gap, joint damping 0.5,
default motor freed; stage friction 0.3, objects 1.0 (pybullet multiplies the two).
The door edge's friction is 0.0 (a low-friction glide strip): with 0.1 the door's
friction on the slope adds about 6 degrees to the wedge's effective angle and a
10 cm x 3 cm wedge slips at 1 N m (2.6 degrees), so that only the 15 cm wedge would
hold any door. The medium prisms (slope 16.7 deg) sit at the floor's friction angle
(atan 0.3 = 16.7 deg), where the wedge's weight decides: they hold the 1 N m door and
slip under 8 N m (a2: 3 deg) to 20 N m (a2: 35 deg, b2: 12 deg), so the big door is a
30 kg door with a 20 N m closer; the long prisms hold it with 0.5 deg. Degrees the
door closed after first contact, object placed by the trainer at the demonstration's
pose (r 0.6 m, gap 0.03 m, tip towards the door); H = held (see also
``bench/results/sim_wedge.json`` for the same table with the arm placing):

============================== ============ ============
object (length x width x h)     standard      big_door
============================== ============ ============
wedge_a1 prism 5 x 5 x 3 cm     36.1 shut    36.1 shut
wedge_a2 prism 10 x 5 x 3 cm    0.4 H        34.9 shut
wedge_a3 prism 15 x 5 x 3 cm    0.3 H        0.5 H
box_a1 8 x 5 x 3 cm             37.5 shut    37.4 shut
cylinder_a1 5 x 3 cm            37.3 shut    37.2 shut
wedge_b1 prism 4 x 8 x 5 cm     36.9 shut    36.9 shut
wedge_b2 prism 10 x 8 x 3 cm    0.2 H        11.7
wedge_b3 prism 18 x 8 x 4 cm    0.2 H        0.5 H
box_b1 10 x 8 x 4 cm            37.7 shut    37.6 shut
cylinder_b1 8 x 4 cm            37.3 shut    37.3 shut
============================== ============ ============

("shut": the door pushed the object along and closed completely.) With the demonstrated
wedge_a2 on the standard door: tip away from the door -> shut (37.6); r 0.75 m with
gap 0.33 m (far) -> the door meets it at 11.5 deg and stops at 10.6 deg (< 20 deg,
not held); r 0.28 m (near the hinge, 2.1 times the force) -> slips 3.4 deg (arm placing).

Perception: the placed object's pose and size come from the cameras ([[camera]] in
``scene.toml``) through :mod:`creative_py.perception`; the door's angle comes from its
joint (the door's own sensor), the hinge and door size from the scene's description.
"""

from __future__ import annotations

import logging
import math
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Optional, Any, NamedTuple

import numpy as np
import pybullet as pb

from creative_py.mesh.spec import BlockSpec, Box, spec_from_dict
from creative_py.sim.baxter import Baxter, BaxterConfig, MoveResult
from creative_py.sim.bodies import (Surface, frame_pose, set_frame_pose, spawn_parts,
                                    load_tool_urdf, spawn_spec, yaw_of)
from creative_py.sim.core import Pose, Sim
from creative_py.sim.trial import Fact, Observation, SkillOutcome, TrialResult
from creative_py.world import (WORLDS_ROOT, Fields, PhysicsSettings, WorldFileError,
                               load_toml, read_physics, world_file)

log = logging.getLogger(__name__)

SET_COLOURS = {"a": (0.95, 0.75, 0.1, 1.0), "b": (0.2, 0.6, 0.95, 1.0)}
"""Colours of the two object sets (RGBA); other set names are grey."""


class WedgePose(NamedTuple):
    """The object's pose relative to the door: ``r``, ``gap`` (m) and ``yaw`` (rad)."""

    r: float
    gap: float
    yaw: float


# ---------------------------------------------------------------------------- world
@dataclass(frozen=True)
class StageSpec:
    """The floor the door stands on (a static box): top face centre (x, y), size, z (m)."""

    name: str
    centre: tuple[float, float]
    size: tuple[float, float]
    top_z: float
    thickness: float
    friction: float


@dataclass(frozen=True)
class DoorSpec:
    """The door: hinge (x, y) and closed heading (rad), panel size (m), mass (kg).

    ``damping`` is the joint damping (N m s/rad), ``friction`` the panel's pybullet
    friction, ``open_angle`` the angle (rad) at which the trial starts (the door is
    released from rest there), ``place_angle`` the wider angle (rad) at which the door
    is held while the arm works, ``swing_speed`` (rad/s) how fast the holder swings it
    from there to ``open_angle``, ``hold_force`` the holder's torque (N m).
    """

    name: str
    hinge: tuple[float, float]
    closed_heading: float
    width: float
    thickness: float
    height: float
    bottom_gap: float
    mass: float
    damping: float
    friction: float
    open_angle: float
    place_angle: float
    swing_speed: float
    hold_force: float


@dataclass(frozen=True)
class TraySpec:
    """Where the episode's object lies at the start: block-frame (x, y) in m, yaw in rad."""

    position: tuple[float, float]
    yaw: float


@dataclass(frozen=True)
class Handling:
    """How the arm carries an object (metres, m/s, seconds, radians); see scene.toml."""

    carry_height: float
    grasp_clearance: float
    release_height: float
    place_gripper_yaw: float
    retreat: tuple[float, float, float]
    speed: float
    steps_per_waypoint: int
    settle_time: float


@dataclass(frozen=True)
class Variant:
    """A task variant: the closer's torque (N m) and the door's mass (kg)."""

    name: str
    description: str
    closing_torque: float
    door_mass: float


@dataclass(frozen=True)
class HeldCriterion:
    """When the door counts as held (seconds, degrees, metres); see tasks.toml."""

    duration: float
    max_close_deg: float
    min_open_deg: float
    contact_distance: float


@dataclass(frozen=True)
class WorldObject:
    """An available object: its spec, set name and pybullet friction.

    ``urdf`` names the URDF file of a tool the robot created (written by
    :mod:`creative_py.mesh`); such an object is loaded from that file, the others are
    built from their spec.
    """

    spec: BlockSpec
    set: str
    friction: float
    urdf: Optional[Path] = None


@dataclass(frozen=True)
class Demonstration:
    """The trainer's demonstration: object, variant and pose."""

    object: str
    variant: str
    pose: WedgePose


@dataclass(frozen=True)
class WedgeWorld:
    """Everything read from ``worlds/wedge_door/`` (see its TOML files for units)."""

    directory: Path
    physics: PhysicsSettings
    arm_physics: PhysicsSettings
    ground_z: float
    stage: StageSpec
    door: DoorSpec
    tray: TraySpec
    handling: Handling
    cameras: tuple
    noise: Any
    objects: dict[str, WorldObject]
    variants: dict[str, Variant]
    default_variant: str
    held: HeldCriterion
    demonstration: Demonstration

    def object(self, name: str) -> WorldObject:
        """Return the object ``name``; raise listing the available objects."""
        if name not in self.objects:
            raise KeyError(f"unknown object {name!r}; available objects: "
                           f"{', '.join(self.objects)}")
        return self.objects[name]

    def variant(self, name: str) -> Variant:
        """Return the variant ``name``; raise listing the variants."""
        if name not in self.variants:
            raise KeyError(f"unknown variant {name!r}; variants: {', '.join(self.variants)}")
        return self.variants[name]


def _read_fields(f: Fields, spec: dict[str, Any]) -> dict[str, Any]:
    """Read the fields named in ``spec`` (name -> "str" | "float" | "int" | n for a vector)."""
    out: dict[str, Any] = {}
    for name, kind in spec.items():
        if kind == "str":
            out[name] = f.str(name)
        elif kind == "int":
            out[name] = f.int(name, minimum=1)
        elif kind == "float":
            out[name] = f.float(name)
        elif kind == "+float":
            out[name] = f.float(name, minimum=0.0)
        else:
            out[name] = f.vec(name, kind)
    f.done()
    return out


def load_wedge_world(world_dir: Path | None = None) -> WedgeWorld:
    """Read the wedge world from ``world_dir`` (default ``worlds/wedge_door``).

    Raises :class:`~creative_py.world.WorldFileError` naming the file and the field
    for a missing file or field, a wrong type, an unknown field (a typo) or a value
    that makes no sense (a negative size, an open angle beyond pi).
    """
    from creative_py.perception.noise import NoiseModel
    from creative_py.sim.camera import cameras_from_tables

    d = Path(world_dir) if world_dir is not None else WORLDS_ROOT / "wedge_door"
    # physics.toml
    p = world_file(d, "physics.toml")
    pf = Fields(load_toml(p), p)
    arm = pf.table("arm")
    physics = read_physics(pf)
    pf.done()
    arm_physics = PhysicsSettings(time_step=arm.float("time_step", minimum=1e-5, maximum=0.1),
                                  solver_iterations=arm.int("solver_iterations", minimum=1),
                                  gravity=physics.gravity)
    arm.done()
    # scene.toml
    s = world_file(d, "scene.toml")
    sf = Fields(load_toml(s), s)
    stage = StageSpec(**_read_fields(sf.table("stage"), {
        "name": "str", "centre": 2, "size": 2, "top_z": "float", "thickness": "+float",
        "friction": "+float"}))
    gf = sf.table("ground")
    ground_z = gf.float("top_z")
    gf.done()
    door = DoorSpec(**_read_fields(sf.table("door"), {
        "name": "str", "hinge": 2, "closed_heading": "float", "width": "+float",
        "thickness": "+float", "height": "+float", "bottom_gap": "+float", "mass": "+float",
        "damping": "+float", "friction": "+float", "open_angle": "float",
        "place_angle": "float", "swing_speed": "+float", "hold_force": "+float"}))
    tray = TraySpec(**_read_fields(sf.table("tray"), {"position": 2, "yaw": "float"}))
    handling = Handling(**_read_fields(sf.table("handling"), {
        "carry_height": "+float", "grasp_clearance": "+float", "release_height": "+float",
        "place_gripper_yaw": "float", "retreat": 3, "speed": "+float",
        "steps_per_waypoint": "int", "settle_time": "+float"}))
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
    for field_name, value in (("door.width", door.width), ("door.thickness", door.thickness),
                              ("door.height", door.height), ("door.mass", door.mass),
                              ("stage.thickness", stage.thickness),
                              ("handling.speed", handling.speed)):
        if value <= 0:
            raise WorldFileError(f"{s}: field {field_name!r}: must be positive, got {value}")
    if not 0.0 < door.open_angle < math.pi:
        raise WorldFileError(f"{s}: field 'door.open_angle': must lie in (0, pi) rad, "
                             f"got {door.open_angle}")
    if not door.open_angle <= door.place_angle < math.radians(170):
        raise WorldFileError(f"{s}: field 'door.place_angle': must lie in [open_angle, "
                             f"170 deg) rad, got {door.place_angle}")
    # objects.toml
    o = world_file(d, "objects.toml")
    of = Fields(load_toml(o), o)
    objects: dict[str, WorldObject] = {}
    for tf in of.tables("object"):
        data = dict(tf.data)
        obj_set = tf.str("set")
        friction = tf.float("friction", minimum=0.0)
        for extra in ("set", "friction"):
            data.pop(extra)
        try:
            spec = spec_from_dict(data, source=f"{o}: {tf.prefix}")
        except ValueError as exc:
            raise WorldFileError(str(exc)) from None
        if not isinstance(spec, BlockSpec):
            raise tf.error("kind", "the wedge world takes block objects only")
        if spec.name in objects:
            raise tf.error("name", f"object name {spec.name!r} is used twice")
        objects[spec.name] = WorldObject(spec, obj_set, friction)
    of.done()
    if not objects:
        raise WorldFileError(f"{o}: field 'object': at least one [[object]] is needed")
    # tasks.toml
    t = world_file(d, "tasks.toml")
    tf_ = Fields(load_toml(t), t)
    from creative_py.case import manifest_of_folder

    manifest = manifest_of_folder(d)
    c = d / "case.toml"
    variants: dict[str, Variant] = {}
    for mv in manifest.variants:
        values = {}
        for key, minimum in (("door.closing_torque", 0.0), ("door.mass", 1e-3)):
            x = mv.set.get(key)
            if isinstance(x, bool) or not isinstance(x, (int, float)) or x < minimum:
                raise WorldFileError(f"{c}: field 'variant.{mv.name}.set.{key}': must be a "
                                     f"number >= {minimum}, got {x!r}")
            values[key] = float(x)
        variants[mv.name] = Variant(mv.name, mv.description, values["door.closing_torque"],
                                    values["door.mass"])
    default_variant = manifest.demonstration.variant
    hf = tf_.table("held")
    held = HeldCriterion(duration=hf.float("duration", minimum=0.01),
                         max_close_deg=hf.float("max_close_deg", minimum=0.0),
                         min_open_deg=hf.float("min_open_deg", minimum=0.0),
                         contact_distance=hf.float("contact_distance", minimum=0.0))
    hf.done()
    tf_.done()
    dm = manifest.demonstration
    if dm.tool not in objects:
        raise WorldFileError(f"{c}: field 'demonstration.tool': must be one of "
                             f"{', '.join(objects)}, got {dm.tool!r}")
    demo = Demonstration(object=dm.tool, variant=dm.variant, pose=WedgePose(*dm.pose))
    return WedgeWorld(directory=d, physics=physics, arm_physics=arm_physics, ground_z=ground_z,
                      stage=stage, door=door, tray=tray,
                      handling=handling, cameras=cameras, noise=noise, objects=objects,
                      variants=variants, default_variant=default_variant, held=held,
                      demonstration=demo)


def catalogue_facts(spec: BlockSpec) -> list[Fact]:
    """Return the catalogue facts of a block (metres): kind, shape, length, width, height."""
    n = spec.name
    return [("object_kind", n, "block"), ("block_shape", n, spec.shape),
            ("block_length_m", n, spec.length), ("block_width_m", n, spec.width),
            ("block_height_m", n, spec.height)]


def wrap_angle(a: float) -> float:
    """Return ``a`` (rad) wrapped to (-pi, pi]."""
    w = a - 2 * math.pi * math.floor((a + math.pi) / (2 * math.pi))
    return w + 2 * math.pi if w <= -math.pi else w


def place_from_pose(door: DoorSpec, angle: float, length: float,
                    pose: WedgePose) -> tuple[float, float, float]:
    """Return the object's centre (x, y) and heading (rad) for ``pose`` (world frame).

    ``angle`` is the door's angle (rad) when the object is placed and ``length`` the
    object's extent along its heading (m). The inverse of :func:`pose_from_place`.
    """
    if pose.r <= 0:
        raise ValueError(f"wedge pose r must be positive metres, got {pose.r}")
    phi = angle - (pose.gap + length / 2 + door.thickness / 2) / pose.r
    heading = door.closed_heading + phi
    x = door.hinge[0] + pose.r * math.cos(heading)
    y = door.hinge[1] + pose.r * math.sin(heading)
    return x, y, wrap_angle(heading + math.pi / 2 + pose.yaw)


def pose_from_place(door: DoorSpec, angle: float, length: float, x: float, y: float,
                    yaw: float) -> WedgePose:
    """Return the :class:`WedgePose` of an object centred at (x, y) with heading ``yaw``."""
    dx, dy = x - door.hinge[0], y - door.hinge[1]
    r = math.hypot(dx, dy)
    phi = wrap_angle(math.atan2(dy, dx) - door.closed_heading)
    gap = r * (angle - phi) - length / 2 - door.thickness / 2
    return WedgePose(r, gap, wrap_angle(yaw - (door.closed_heading + phi + math.pi / 2)))


def gripper_down(yaw: float) -> tuple[float, float, float, float]:
    """Return the orientation of ``right_gripper`` pointing down (-z) with its x axis at ``yaw``."""
    return tuple(pb.getQuaternionFromEuler((math.pi, 0.0, yaw)))


@dataclass(frozen=True)
class DoorOutcome:
    """What the door did after its release (degrees; None where it never happened)."""

    touched: bool
    contact_angle_deg: float | None
    final_angle_deg: float
    closed_after_contact_deg: float | None
    held: bool

    def describe(self) -> str:
        """Return the outcome in words."""
        if not self.touched:
            return f"the door never touched the object and closed to {self.final_angle_deg:.1f} deg"
        verdict = "held" if self.held else "not held"
        return (f"door {verdict}: first contact at {self.contact_angle_deg:.1f} deg, closed "
                f"{self.closed_after_contact_deg:.1f} deg more, stands at "
                f"{self.final_angle_deg:.1f} deg")


# -------------------------------------------------------------------------- episode
class WedgeEpisode:
    """One door-and-wedge scene in its own simulator, driven skill by skill.

    Build it with :func:`open_wedge_episode` (or :func:`creative_py.sim.trial.open_episode`).
    ``with_robot=False`` builds the scene without Baxter, for the trainer's placing
    (:meth:`trainer_place`) and the door's physics alone; the robot's skills then
    raise ``RuntimeError``.
    """

    def __init__(self, world: WedgeWorld, variant: str, location: int, object_name: str,
                 seed: int = 0, gui: bool = False, images_dir: Path | None = None,
                 with_robot: bool = True) -> None:
        self.variant = world.variant(variant)
        if location != 1:
            raise KeyError(f"unknown location {location!r}; the wedge task has one location: 1")
        self.world = world
        self.item = world.object(object_name)
        self.spec = self.item.spec
        self.rng = np.random.default_rng(seed)
        self.images_dir = images_dir
        self.render_time_s = 0.0
        self._shots = 0
        self.holding = False
        self.door_outcome: DoorOutcome | None = None
        self.robot_parked = False
        self.with_robot = with_robot
        self.robot = None
        self._time_before = 0.0
        self._steps_at_switch = 0
        self.sim = Sim(world.arm_physics, gui=gui)
        try:
            self._build()
        except BaseException:
            self.close()
            raise

    # ------------------------------------------------------------ scene building
    def _build(self) -> None:
        w, sim = self.world, self.sim
        st = w.stage
        spawn_parts(sim, [Box((0, 0, 0), (6.0, 6.0, 0.1))],
                    ((0.0, 0.0, w.ground_z - 0.05), (0, 0, 0, 1)), 0.0,
                    Surface(st.friction, (0.35, 0.35, 0.35, 1.0)))
        spawn_parts(sim, [Box((0, 0, 0), (st.size[0], st.size[1], st.thickness))],
                    ((st.centre[0], st.centre[1], st.top_z - st.thickness / 2), (0, 0, 0, 1)),
                    0.0, Surface(st.friction, (0.55, 0.45, 0.35, 1.0)))
        self.door_body = self._build_door()
        # Only the episode's object lies on the tray (every object would cost physics
        # time and none of the others takes part).
        item = self.item
        (x, y), yaw = w.tray.position, w.tray.yaw
        start = ((x, y, st.top_z + 0.0005), tuple(pb.getQuaternionFromEuler((0, 0, yaw))))
        if item.urdf is not None:
            self.body = load_tool_urdf(sim, item.urdf, start, lateral_friction=item.friction)
        else:
            self.body = spawn_spec(sim, item.spec, start,
                                   Surface(item.friction, SET_COLOURS.get(item.set,
                                                                          (0.6, 0.6, 0.6, 1.0))))
        h = w.handling
        if self.with_robot:
            self.robot = Baxter(sim, BaxterConfig(speed=h.speed,
                                                  steps_per_waypoint=h.steps_per_waypoint))
            home = (h.retreat, gripper_down(h.place_gripper_yaw))
            q = self.robot.solve_ik_global(home)
            if q is None:
                raise WorldFileError(f"{w.directory / 'scene.toml'}: field 'handling.retreat': "
                                     f"the arm cannot reach {list(h.retreat)} with the "
                                     "gripper down")
            self.robot.reset_posture(q)
        self._run(0.2)  # let the object settle

    def _use_physics(self, physics: PhysicsSettings) -> None:
        """Switch the client to ``physics`` (time step, iterations), keeping the clock."""
        if physics == self.sim.physics:
            return
        self._time_before = self.sim_time()
        self._steps_at_switch = self.sim.steps
        self.sim.physics = physics
        self.sim.configure()

    def _run(self, seconds: float) -> None:
        """Advance the physics by ``seconds`` at the current time step."""
        self.sim.step(int(round(seconds / self.sim.physics.time_step)))

    def _build_door(self) -> int:
        d, c = self.world.door, self.sim.client
        half = [d.width / 2, d.thickness / 2, d.height / 2]
        col = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half,
                                      collisionFramePosition=(d.width / 2, 0, 0),
                                      physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half,
                                   visualFramePosition=(d.width / 2, 0, 0),
                                   rgbaColor=(0.75, 0.7, 0.6, 1.0), physicsClientId=c)
        base_z = self.world.stage.top_z + d.bottom_gap + d.height / 2
        body = pb.createMultiBody(
            baseMass=0.0, baseCollisionShapeIndex=-1, baseVisualShapeIndex=-1,
            basePosition=(d.hinge[0], d.hinge[1], base_z),
            baseOrientation=pb.getQuaternionFromEuler((0, 0, d.closed_heading)),
            linkMasses=[self.variant.door_mass], linkCollisionShapeIndices=[col],
            linkVisualShapeIndices=[vis], linkPositions=[(0, 0, 0)],
            linkOrientations=[(0, 0, 0, 1)], linkInertialFramePositions=[(d.width / 2, 0, 0)],
            linkInertialFrameOrientations=[(0, 0, 0, 1)], linkParentIndices=[0],
            linkJointTypes=[pb.JOINT_REVOLUTE], linkJointAxis=[(0, 0, 1)],
            physicsClientId=c)
        # The door frame stops the door at 0 (closed); it opens up to 170 degrees.
        pb.changeDynamics(body, 0, lateralFriction=d.friction, jointDamping=d.damping,
                          linearDamping=0.0, angularDamping=0.0, jointLowerLimit=0.0,
                          jointUpperLimit=math.radians(170), physicsClientId=c)
        pb.resetJointState(body, 0, d.open_angle, 0.0, physicsClientId=c)
        pb.setJointMotorControl2(body, 0, pb.POSITION_CONTROL, targetPosition=d.open_angle,
                                 force=d.hold_force, physicsClientId=c)
        self.door_released = False
        self.door_target = d.open_angle
        return body

    def _swing_door(self, angle: float) -> None:
        """Let the door holder swing the door to ``angle`` (rad) and hold it there."""
        if angle == self.door_target:
            return
        d, c = self.world.door, self.sim.client
        pb.setJointMotorControl2(self.door_body, 0, pb.POSITION_CONTROL,
                                 targetPosition=angle, force=d.hold_force,
                                 maxVelocity=d.swing_speed, physicsClientId=c)
        self._run(abs(angle - self.door_target) / d.swing_speed + 0.3)
        self.door_target = angle

    # ------------------------------------------------------------- perception
    def door_angle(self) -> float:
        """Return the door's angle (rad, 0 = closed) from its joint sensor."""
        return float(pb.getJointState(self.door_body, 0, physicsClientId=self.sim.client)[0])

    def _frames(self) -> tuple:
        from creative_py.sim.camera import capture_frames

        frames = capture_frames(self.sim.client, self.world.cameras, self.images_dir,
                                self._shots)
        self.render_time_s += sum(f.render_time_s for f in frames)
        self._shots += self.images_dir is not None
        return frames

    def perceive_object(self, frames=None):
        """Return the camera estimate of the episode's object (None if unseen) and the frames."""
        from creative_py.perception import estimate_objects

        frames = self._frames() if frames is None else frames
        n = self.spec.name
        support = {} if self.holding else {n: self.world.stage.top_z}
        est = estimate_objects(frames, {n: self.body}, self.world.noise, self.rng,
                               support_z=support, heights={n: self.spec.height})
        return est.get(n), frames

    def observe(self) -> Observation:
        """Return the facts the robot perceives now (see the module docstring)."""
        from creative_py.perception import facts_from_estimates

        w, d = self.world, self.world.door
        est, frames = self.perceive_object()
        facts: list[Fact] = []
        if est is not None:
            facts += facts_from_estimates([est])
        if self.holding:
            facts.append(("held", self.spec.name))
        facts += [("hinge", d.name, d.hinge[0], d.hinge[1]),
                  ("door_width_m", d.name, d.width),
                  ("door_closed_heading", d.name, d.closed_heading),
                  ("door_angle", d.name, self.door_angle()),
                  ("door_gap_m", d.name, d.bottom_gap)]
        if self.goal_reached():
            facts.append(("door_held", d.name))
        for item in w.objects.values():
            facts += catalogue_facts(item.spec)
        return Observation(facts=tuple(facts), frames=frames, truth=self.truth())

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ground truth ``name -> (x, y, z, yaw)``: the centre of the object's box.

        (x, y, z) is the block frame's point (0, 0, height / 2), comparable with the
        perceived pose; yaw the heading of the block's +x axis.
        """
        pos, quat = frame_pose(self.sim, self.body)
        centre = pb.multiplyTransforms(pos, quat, (0, 0, self.spec.height / 2), (0, 0, 0, 1))[0]
        return {self.spec.name: tuple(float(v) for v in (*centre, yaw_of(quat)))}

    def placed_pose(self) -> WedgePose:
        """Return the object's true :class:`WedgePose` now (ground truth, for tests and reports)."""
        x, y, _, yaw = self.truth()[self.spec.name]
        return pose_from_place(self.world.door, self.door_angle(), self.spec.length, x, y, yaw)

    # ------------------------------------------------------------------- skills
    def _move(self, pos, yaw: float, speed: float | None = None) -> MoveResult:
        return self.robot.move_to((tuple(pos), gripper_down(yaw)), speed=speed,
                                  watch=[self.body])

    def _need_robot(self, skill: str) -> None:
        if self.robot is None or self.robot_parked:
            raise RuntimeError(f"{skill}: this episode has no robot (built with_robot=False, "
                               "or the robot was parked for the door's release)")

    def _grip_z(self, base_z: float) -> float:
        """Return the gripper height that holds the object's base at ``base_z`` (m)."""
        return base_z + self.spec.height + self.world.handling.grasp_clearance

    def pick_up(self) -> SkillOutcome:
        """Grip the object from above on the tray and lift it to the carrying height."""
        self._need_robot("pick_up")
        if self.holding:
            return SkillOutcome("ok", "already holding the object")
        w, h = self.world, self.world.handling
        base, _ = frame_pose(self.sim, self.body)
        x, y = base[0], base[1]
        yaw = h.place_gripper_yaw
        carry_z = self._grip_z(w.stage.top_z + h.carry_height)
        for target in ((x, y, carry_z), (x, y, self._grip_z(base[2]))):
            res = self._move(target, yaw)
            if not res.ok:
                return SkillOutcome(res.status, f"pick_up: {res.reason}")
        g = self.robot.gripper_pose()
        obj = frame_pose(self.sim, self.body)
        inv = pb.invertTransform(*g)
        rel = pb.multiplyTransforms(inv[0], inv[1], obj[0], obj[1])
        self.grasp = (tuple(rel[0]), tuple(rel[1]))
        self.robot.grasp(self.body, self.grasp)
        self.holding = True
        res = self._move((x, y, carry_z), yaw)
        if not res.ok:
            return SkillOutcome(res.status, f"pick_up: {res.reason}")
        return SkillOutcome("ok")

    def _gripper_for(self, x: float, y: float, base_z: float, yaw: float) -> Pose:
        """Return the gripper pose that puts the held object's frame at (x, y, base_z, yaw)."""
        obj_q = pb.getQuaternionFromEuler((0, 0, yaw))
        inv = pb.invertTransform(*self.grasp)
        pos, quat = pb.multiplyTransforms((x, y, base_z), obj_q, inv[0], inv[1])
        return tuple(pos), tuple(quat)

    def position_tool(self, pose: WedgePose | tuple) -> SkillOutcome:
        """Carry the held object and put it on the floor at ``pose`` relative to the door.

        ``pose`` is relative to the door at ``open_angle``, where the trial starts. The
        door holder swings the door wider open (``place_angle``) while the arm works:
        the arm lowers the object until its base is ``release_height`` above the
        floor, lets go, waits ``settle_time`` and retreats out of the door's sweep; then
        the holder swings the door back to ``open_angle``. Returns ``blocked`` if the object or the
        arm hits something on the way, ``unreachable`` if the arm cannot follow.
        """
        pose = WedgePose(*(float(v) for v in pose))
        if not all(math.isfinite(v) for v in pose):
            raise ValueError(f"pose numbers must be finite, got {pose}")
        if pose.r <= 0:
            raise ValueError(f"wedge pose r must be positive metres, got {pose.r}")
        self._need_robot("position_tool")
        if not self.holding:
            return SkillOutcome("blocked", "position_tool: no object is held (pick_up first)")
        w, h = self.world, self.world.handling
        x, y, yaw = place_from_pose(w.door, w.door.open_angle, self.spec.length, pose)
        self._swing_door(w.door.place_angle)
        top = w.stage.top_z
        above = self._gripper_for(x, y, top + h.carry_height, yaw)
        down = self._gripper_for(x, y, top + h.release_height, yaw)
        for target, speed in ((above, None), (down, h.speed / 2)):
            res = self.robot.move_to(target, speed=speed, watch=[self.body])
            if not res.ok:
                return SkillOutcome(res.status, f"position_tool: {res.reason}")
        self._use_physics(w.physics)
        self.robot.release()
        self.holding = False
        self._run(h.settle_time)
        why = self.sim.blow_up(self.body)
        if why:
            return SkillOutcome("invalid", f"position_tool: {why}")
        self._use_physics(w.arm_physics)
        g = self.robot.gripper_pose()[0]
        lift = (g[0], g[1], g[2] + 0.08)
        for target in (lift, h.retreat):
            res = self._move(target, h.place_gripper_yaw)
            if not res.ok:
                return SkillOutcome(res.status, f"position_tool: retreat: {res.reason}")
        self._swing_door(w.door.open_angle)
        why = self.sim.blow_up(self.body)
        if why:
            return SkillOutcome("invalid", f"position_tool: {why}")
        return SkillOutcome("ok")

    def trainer_place(self, pose: WedgePose | tuple) -> SkillOutcome:
        """Put the object on the floor at ``pose`` by hand, as the trainer does.

        The demonstration's placing is done by the trainer, not the robot: the object
        appears ``release_height`` above the floor at
        the pose and settles for ``settle_time`` seconds; the arm stays at its retreat
        point. Also the quick way to test the door's physics without the arm.
        """
        pose = WedgePose(*(float(v) for v in pose))
        if not all(math.isfinite(v) for v in pose) or pose.r <= 0:
            raise ValueError(f"pose numbers must be finite with r > 0 metres, got {pose}")
        if self.holding:
            self.robot.release()
            self.holding = False
        w = self.world
        self._swing_door(w.door.open_angle)
        x, y, yaw = place_from_pose(w.door, w.door.open_angle, self.spec.length, pose)
        set_frame_pose(self.sim, self.body,
                       ((x, y, w.stage.top_z + w.handling.release_height),
                        tuple(pb.getQuaternionFromEuler((0, 0, yaw)))))
        self._use_physics(w.physics)
        self._run(w.handling.settle_time)
        why = self.sim.blow_up(self.body)
        if why:
            return SkillOutcome("invalid", f"trainer_place: {why}")
        return SkillOutcome("ok")

    def act(self) -> SkillOutcome:
        """Release the door: its closer pushes it shut for ``held.duration`` seconds.

        Records a :class:`DoorOutcome` in ``door_outcome``. Returns ``blocked`` if a
        robot link stands in the door's sweep, ``invalid`` on a physics blow-up.
        """
        if self.door_released:
            return SkillOutcome("blocked", "release_door: the door was already released")
        w, c = self.world, self.sim.client
        crit, door, body = w.held, self.door_body, self.body
        tau = self.variant.closing_torque
        in_sweep = self._robot_in_sweep() if self.robot is not None else ""
        if in_sweep:
            return SkillOutcome("blocked", f"release_door: the robot's {in_sweep} is in the "
                                "door's sweep")
        self._swing_door(w.door.open_angle)
        self._park_robot()
        self._use_physics(w.physics)
        self.door_released = True
        pb.setJointMotorControl2(door, 0, pb.VELOCITY_CONTROL, force=0.0, physicsClientId=c)
        n = int(round(crit.duration / w.physics.time_step))
        contact = None
        for i in range(n):
            pb.setJointMotorControl2(door, 0, pb.TORQUE_CONTROL, force=-tau, physicsClientId=c)
            self.sim.step()
            if contact is None and any(
                    cp[8] <= crit.contact_distance
                    for cp in pb.getContactPoints(door, body, physicsClientId=c)):
                contact = self.door_angle()
            if i % 32 == 31:
                why = self.sim.blow_up(body)
                if why:
                    return SkillOutcome("invalid", f"release_door: {why}")
        final = self.door_angle()
        if not math.isfinite(final):
            return SkillOutcome("invalid", "release_door: the door's angle is not finite")
        closed = None if contact is None else math.degrees(contact - final)
        held = (contact is not None and closed < crit.max_close_deg
                and math.degrees(final) >= crit.min_open_deg)
        self.door_outcome = DoorOutcome(
            touched=contact is not None,
            contact_angle_deg=None if contact is None else math.degrees(contact),
            final_angle_deg=math.degrees(final), closed_after_contact_deg=closed,
            held=bool(held))
        log.info("%s/%s: %s", self.spec.name, self.variant.name, self.door_outcome.describe())
        return SkillOutcome("ok")

    release_door = act

    def _robot_in_sweep(self) -> str:
        """Return the name of a robot link that the closing door would touch, or "".

        The door is put at angles from its current one down to 0 (closed) and the
        robot's links are tested against it (1 cm margin); the state is restored.
        """
        c, door, robot = self.sim.client, self.door_body, self.robot.body
        a0 = self.door_angle()
        with self.sim.saved():
            for a in np.linspace(a0, 0.0, 9):
                pb.resetJointState(door, 0, float(a), 0.0, physicsClientId=c)
                pb.performCollisionDetection(physicsClientId=c)
                near = pb.getClosestPoints(door, robot, 0.01, physicsClientId=c)
                if near:
                    link = near[0][4]
                    return (pb.getJointInfo(robot, link, physicsClientId=c)[12].decode()
                            if link >= 0 else "base")
        return ""

    def _park_robot(self) -> None:
        """Take the idle robot out of the physics for the door's closing.

        Called only after :meth:`_robot_in_sweep` found every link clear of the door's
        sweep: the robot stands still outside it and nothing else it could touch moves,
        so the door and the object move exactly as with the robot present, while each
        physics step costs 0.03 ms instead of 0.7 ms (Baxter's 56 joints).
        """
        if self.robot is None or self.robot_parked:
            return
        pb.removeBody(self.robot.body, physicsClientId=self.sim.client)
        self.robot.close()
        self.robot_parked = True

    def goal_reached(self) -> bool:
        """Return whether the door is held open (simulated state, after :meth:`act`)."""
        return self.door_outcome is not None and self.door_outcome.held

    def sim_time(self) -> float:
        """Return the simulated time so far, seconds (across time-step changes)."""
        return (self._time_before
                + (self.sim.steps - self._steps_at_switch) * self.sim.physics.time_step)

    @property
    def steps(self) -> int:
        """Return the physics steps taken so far."""
        return self.sim.steps

    def close(self) -> None:
        """Release the simulator (idempotent)."""
        robot = getattr(self, "robot", None)
        if robot is not None and not self.robot_parked:
            robot.close()
        self.sim.close()


def open_wedge_episode(world: WedgeWorld, variant: str, location: int, object_name: str,
                       seed: int = 0, gui: bool = False, images_dir: Path | None = None,
                       with_robot: bool = True) -> WedgeEpisode:
    """Return a new :class:`WedgeEpisode` (close it when done)."""
    return WedgeEpisode(world, variant, location, object_name, seed, gui, images_dir,
                        with_robot)


def run_wedge_trial(world: WedgeWorld, object_name: str, variant: str | None = None,
                    pose: WedgePose | tuple | None = None, seed: int = 0,
                    images_dir: Path | None = None, gui: bool = False) -> TrialResult:
    """Run one door-and-wedge trial through :func:`creative_py.sim.trial.run_trial`.

    ``variant=None`` is the world's default variant, ``pose=None`` the demonstration's.
    """
    from creative_py.sim.trial import run_trial

    return run_trial("wedge", world, object_name, variant or world.default_variant, 1,
                     None if pose is None else WedgePose(*pose), seed, images_dir, gui)


class WedgeDoorCase:
    """The wedge case for :mod:`creative_py.sim.trial`."""

    name = "wedge"
    object_option = "object"

    def load_world(self, world_dir: Path | None) -> WedgeWorld:
        """Return the wedge world (see :func:`load_wedge_world`)."""
        return load_wedge_world(world_dir)

    def open_episode(self, world: WedgeWorld, variant: str, location: int, object_name: str,
                     seed: int, gui: bool, images_dir: Path | None) -> WedgeEpisode:
        """Return a new episode."""
        return open_wedge_episode(world, variant, location, object_name, seed, gui, images_dir)

    def default_pose(self, world: WedgeWorld) -> WedgePose:
        """Return the demonstration's pose."""
        return world.demonstration.pose

    def parse_pose(self, text: str) -> WedgePose:
        """Parse ``"R,GAP,YAW"`` (m, m, rad)."""
        parts = [p.strip() for p in text.split(",")]
        try:
            values = [float(p) for p in parts]
        except ValueError:
            values = []
        if len(values) != 3 or not all(math.isfinite(v) for v in values) or values[0] <= 0:
            raise ValueError(f"--pose must be R,GAP,YAW (metres > 0, metres, radians), "
                             f"got {text!r}")
        return WedgePose(*values)

    def listing(self, world: WedgeWorld) -> dict[str, Any]:
        """Return objects (spec fields, set, friction), locations, variants and default pose."""
        objects = {}
        for n, item in world.objects.items():
            d = asdict(item.spec)
            d.update(set=item.set, friction=item.friction)
            objects[n] = d
        return {
            "case": self.name,
            "objects": objects,
            "locations": [{"index": 1, "door": world.door.name,
                           "open_angle": world.door.open_angle}],
            "variants": {k: asdict(v) for k, v in world.variants.items()},
            "default_variant": world.default_variant,
            "default_pose": dict(world.demonstration.pose._asdict()),
            "demonstration": {"object": world.demonstration.object,
                              "variant": world.demonstration.variant},
        }
