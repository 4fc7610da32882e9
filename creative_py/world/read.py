"""A case's world as its files describe it, for every backend that builds the scene.

:func:`load_world` reads a world folder (``worlds/<folder>/`` or a copy) for a
:class:`~creative_py.case.CaseManifest`; :meth:`World.with_tool` adds a created tool;
:meth:`World.location_values`, :meth:`World.scene_value` and
:meth:`World.with_locations` are what the world sampler above the boundary
(:mod:`creative_py.simulator.randomise`, ``--world-seed N``) reads and sets of it.
The folder holds, besides ``case.toml``:

``physics.toml``
    ``time_step`` (s), ``solver_iterations``, ``gravity`` (m/s^2): the physics while
    objects rest on surfaces; an optional ``[arm]`` table (``time_step``,
    ``solver_iterations``) for the arm's motions.
``scene.toml``
    ``settle_time`` (s of physics after building); ``[robot]`` (``visuals``, ``speed``
    m/s, ``turn_speed`` rad/s, ``steps_per_waypoint``, ``keep_clear``: the bodies the
    robot's own links must not strike) and ``[robot.start]`` (the
    gripper's start ``position``, ``gripper`` attitude ``forward`` or ``down`` at
    ``angle`` rad, ``keep`` IK candidates, optional ``via`` pose whose posture seeds
    the search); ``[values]`` and ``[[body]]`` (:mod:`creative_py.world.bodies`);
    ``[tool_start]`` (where the tool lies: the fields of its kind,
    :mod:`creative_py.world.handlings`); ``[perception]`` (noise and the
    ``[[perception.object]]`` the cameras track); ``[[camera]]``; an optional
    ``[video]`` (the fixed camera of the trial clips and their ``fps``,
    :class:`creative_py.world.cameras.VideoSpec`).
``objects.toml``
    The catalogue: one table per object in the array named by the manifest's
    ``roles.tools`` (``[[tool]]``, ``[[object]]``), with the spec fields of
    :mod:`creative_py.mesh.spec`, its ``set`` and ``friction``.
``tasks.toml``
    ``[[location]]`` (``set = {...}``: scene values of the target's predefined
    locations) and ``[oracle]`` (:mod:`creative_py.world.oracles`).

Every number of the scene, the start, the skills' options and the oracle may be a
scene expression; the loader resolves them all for every variant and location, so a
bad value is reported by file and field before any physics runs.

Every number has finite bounds, so that no value makes the physics run without end
(docs/new-case.md lists them): the physics' (:func:`creative_py.world_files.read_physics`);
``settle_time`` 0-10 s (:data:`SETTLE_TIME_S`); ``[robot]`` ``speed`` 0.001-2 m/s,
``turn_speed`` 0.001-10 rad/s, ``steps_per_waypoint`` 1-1000, ``keep`` 1-100; the
start poses' and ``[tool_start]``'s numbers within +-10 m (rad); ``depth_sigma_m``
0-0.1 m; an object's ``friction`` 0-10; the bodies' (:mod:`creative_py.world.bodies`);
the skills' options (:data:`creative_py.world.skills.OPTION_BOUNDS`) and the
oracle's (:data:`creative_py.world.oracles.OPTION_BOUNDS`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence

from creative_py.case import CaseManifest
from creative_py.simulator.catalogue import CatalogueItem, CatalogueWorld, read_catalogue
from creative_py.world import oracles, skills
from creative_py.world.bodies import read_bodies, resolve_bodies
from creative_py.world.cameras import VideoSpec, cameras_from_tables
from creative_py.world.expressions import Namespace
from creative_py.world.handlings import HANDLINGS, handling, quantities
from creative_py.world.oracles import ORACLES, OracleSpec
from creative_py.world.skills import REQUIRED, SKILLS
from creative_py.world_files import (Fields, OptionError, PhysicsSettings, WorldFileError,
                                     did_you_mean, load_toml, read_physics, world_file)


_ROLES = ("tool", "target", "context")


@dataclass(frozen=True)
class RobotSpec:
    """The arm's settings, start pose and placement in this scene (raw numbers or
    expressions; see module doc), for the world's robot."""

    visuals: bool
    speed: float
    turn_speed: float
    steps_per_waypoint: int
    start: dict[str, Any]
    via: dict[str, Any] | None
    keep: int
    profile: Any = None
    """The robot profile (:class:`creative_py.robots.RobotProfile`)."""
    base: tuple | None = None
    """``(position, rpy)`` of the arm's base in this scene; None: the profile's."""
    keep_clear: tuple[str, ...] = ()
    """The scene bodies (``[[body]]`` names) the robot's own links must keep clear of:
    a link that strikes one decides the trial (:attr:`SkillOutcome.struck`,
    :func:`~creative_py.simulator.trial.trial_outcome`). Bodies the arm may touch in
    its work (a table it sweeps a tool along) are left out."""


@dataclass(frozen=True)
class PerceivedObject:
    """An object the cameras track: a role or a name, and the support it rests on."""

    name: str
    support_z: Any = None


@dataclass(frozen=True)
class SceneSpec:
    """Everything ``scene.toml`` says (bodies raw: resolved per episode)."""

    settle_time: float
    robot: RobotSpec
    values: dict[str, Any]
    bodies: tuple
    tool_start: dict[str, Any]
    noise: Any
    perceived: tuple[PerceivedObject, ...]
    cameras: tuple
    video: Any = None
    """The clips' camera and frame rate (:class:`~creative_py.world.cameras.VideoSpec`):
    the ``[video]`` table, else the first camera at 5 frames per second, else None."""


@dataclass(frozen=True)
class SkillSpec:
    """A manifest skill bound to its primitive, options raw (resolved per episode)."""

    name: str
    primitive: str
    options: dict[str, Any]


@dataclass(frozen=True)
class World(CatalogueWorld):
    """Everything the simulator needs to build a case's scenes.

    Attributes
    ----------
    manifest : CaseManifest
        The case (roles, skills, pose parameters, variants, demonstration).
    directory : Path
        The world folder.
    physics : dict
        ``"rest"`` and ``"arm"`` :class:`~creative_py.world_files.PhysicsSettings`.
    scene : SceneSpec
        The scene description.
    items : dict
        ``name -> CatalogueItem`` of every available object, created ones included.
    location_sets : tuple of dict
        The scene values of each predefined location, in order.
    oracle : OracleSpec
        The success oracle.
    skills : dict
        ``skill name -> SkillSpec``.
    """

    manifest: CaseManifest
    directory: Path
    physics: dict[str, PhysicsSettings]
    scene: SceneSpec
    items: dict[str, CatalogueItem]
    location_sets: tuple[dict[str, Any], ...]
    oracle: Any
    skills: dict[str, SkillSpec]
    postures: dict = field(default_factory=dict, compare=False, repr=False)
    variation: str = ""
    """Empty for the world as its files say; ``world seed N`` for a drawn one (part of
    every cache key that depends on the world's numbers)."""

    @property
    def locations(self) -> tuple[int, ...]:
        """Return the 1-based indices of the target's predefined locations."""
        return tuple(range(1, len(self.location_sets) + 1))

    @property
    def video(self) -> Any:
        """Return the camera of the trial clips (``scene.video``,
        :class:`~creative_py.world.cameras.VideoSpec`), or None."""
        return self.scene.video

    def with_tool(self, spec: Any, urdf: Path | None = None) -> "World":
        """Return this world with one more available tool (a created one).

        Its catalogue facts, grasp and skills come from ``spec`` (its kind); its body
        from ``urdf`` (written by :mod:`creative_py.mesh`, link frame = tool frame)
        when given, otherwise from the spec's parts. It takes the friction of the
        catalogue's first object (the same printed material).
        """
        handling(spec)  # a handling the world files know (a backend builds each)
        return super().with_tool(spec, urdf)

    def location_listing(self) -> list[dict[str, Any]]:
        """Return each location's scene values with its 1-based ``index``."""
        return [{"index": i, **s} for i, s in enumerate(self.location_sets, 1)]

    def location_values(self, location: int) -> dict[str, Any]:
        """Return the scene values location ``location`` sets (its ``set`` table of
        ``tasks.toml``, or a drawn world's); KeyError for an unknown location."""
        if not (isinstance(location, int) and 1 <= location <= len(self.location_sets)):
            raise KeyError(f"unknown location {location!r}; locations: "
                           f"1..{len(self.location_sets)}")
        return self.location_sets[location - 1]

    def scene_value(self, key: str, variant: str, location: int, tool: str) -> float:
        """Return the scene value ``key`` as the episode of ``variant``, ``location``
        and ``tool`` resolves it (:meth:`namespace`)."""
        return float(self.namespace(variant, location, tool).get(key))

    def with_locations(self, tables: Sequence[Mapping[str, Any]], variation: str) -> "World":
        """Return this world with the locations' scene values ``tables`` (one per
        location) and ``variation``; the start postures are searched again and every
        scene value of every variant and location is checked (:func:`check_values`)."""
        new = replace(self, location_sets=tuple(dict(t) for t in tables), postures={},
                      variation=variation)
        for v in new.manifest.variants:
            for loc in new.locations:
                check_values(new, v.name, loc, new.manifest.demonstration.tool)
        return new

    def namespace(self, variant: str, location: int, tool: str):
        """Return the scene values of one episode (variant and location applied)."""
        v = self.manifest.variant(variant)
        if not (isinstance(location, int) and 1 <= location <= len(self.location_sets)):
            raise KeyError(f"unknown location {location!r}; locations: "
                           f"1..{len(self.location_sets)}")
        spec = self.item(tool).spec
        ns = Namespace(self.scene.values, {b.name: b.fields for b in self.scene.bodies},
                       quantities(spec), str(self.directory / "scene.toml"))
        ns.override(v.set, f"{self.manifest.folder / 'case.toml'}: variant {v.name!r}: set")
        ns.override(self.location_sets[location - 1],
                    f"{self.directory / 'tasks.toml'}: location[{location - 1}]: set")
        return ns


SETTLE_TIME_S = (0.0, 10.0)
"""The bounds of ``settle_time`` (scene.toml), seconds of physics after building."""

SPEED_M_S = (1e-3, 2.0)
"""The bounds of the arm's Cartesian speeds (``[robot] speed``, the skills' speeds), m/s."""

TURN_SPEED_RAD_S = (1e-3, 10.0)
"""The bounds of ``[robot] turn_speed``, rad/s."""

STEPS_PER_WAYPOINT = (1, 1000)
"""The bounds of ``[robot] steps_per_waypoint``, physics steps."""

KEEP = (1, 100)
"""The bounds of ``[robot.start] keep``, IK candidates."""

EXTENT_M = 10.0
"""The largest size of a coordinate of the scene (a start position, a tool's start
field), metres from the robot's base; angles are bounded by it too, in radians."""

SIGMA_M = (0.0, 0.1)
"""The bounds of ``[perception] depth_sigma_m``, metres."""


def _read_robot(rf: Fields, profile: Any, bodies: Sequence[str]
                ) -> tuple[RobotSpec, dict[str, Any]]:
    """Read ``[robot]`` for the robot ``profile``: ``speed`` (m/s) within
    :data:`SPEED_M_S`, ``turn_speed`` (rad/s) within :data:`TURN_SPEED_RAD_S`,
    ``steps_per_waypoint`` within :data:`STEPS_PER_WAYPOINT`, ``[robot.start] keep``
    within :data:`KEEP`; the start's and the via pose's numbers are resolved by
    :func:`check_values` (each within +-:data:`EXTENT_M`).

    A sub-table named after a robot profile (``[robot.NAME]``) places the scene for that
    arm: its fields replace ``[robot]``'s (``start`` whole), ``base`` (``position`` m,
    ``rpy`` rad) puts the arm's base there and ``values`` replaces scene values. Every
    such table is read (a typo in one is an error whichever arm runs); the one of
    ``profile`` is applied. Returns the spec and the scene values it replaces.
    """
    from creative_py.robots import profile_names

    known = set(profile_names())
    placed = [k for k, v in rf.data.items() if isinstance(v, dict) and k != "start"]
    for name in placed:
        if name not in known:
            raise rf.error(name, f"names no robot profile of robots/ "
                           f"({', '.join(sorted(known))}) and no field of [robot]")
    own = _read_robot_fields(rf, None, bodies, placement=False)  # [robot]'s own errors first
    for name in placed:
        got = _read_robot_fields(rf.table(name), rf, bodies, placement=True)
        if name == profile.name:
            own = got
    spec, values = own
    return replace(spec, profile=profile), values


def _read_robot_fields(rf: Fields, parent: Fields | None, bodies: Sequence[str],
                       placement: bool) -> tuple[RobotSpec, dict[str, Any]]:
    """Read one ``[robot]`` table (or a ``[robot.NAME]`` placement over ``parent``);
    ``bodies``: the names of the scene's ``[[body]]`` tables (``keep_clear`` names
    some)."""
    def pick(name: str, default: Any) -> Any:
        if parent is not None and not rf.has(name):
            return parent.data.get(name, default)
        return default

    visuals = rf.bool("visuals", pick("visuals", False))
    speed = rf.float("speed", pick("speed", 0.10), minimum=SPEED_M_S[0], maximum=SPEED_M_S[1])
    turn = rf.float("turn_speed", pick("turn_speed", 1.0), minimum=TURN_SPEED_RAD_S[0],
                    maximum=TURN_SPEED_RAD_S[1])
    spw = rf.int("steps_per_waypoint", pick("steps_per_waypoint", 4),
                 minimum=STEPS_PER_WAYPOINT[0], maximum=STEPS_PER_WAYPOINT[1])
    keep_clear = rf.raw("keep_clear", pick("keep_clear", []))
    if not (isinstance(keep_clear, list) and all(isinstance(n, str) for n in keep_clear)):
        raise rf.error("keep_clear", f"must be a list of [[body]] names, got {keep_clear!r}")
    for name in keep_clear:
        if name not in bodies:
            raise rf.error("keep_clear", f"{name!r} is no [[body]] of the scene "
                           f"({', '.join(bodies)}){did_you_mean(name, bodies)}")
    base = None
    values: dict[str, Any] = {}
    if placement:
        if rf.has("base"):
            bf = rf.table("base")
            base = (bf.vec("position", 3, minimum=-EXTENT_M, maximum=EXTENT_M),
                    bf.vec("rpy", 3, (0.0, 0.0, 0.0), minimum=-EXTENT_M, maximum=EXTENT_M))
            bf.done()
        if rf.has("values"):
            vf = rf.table("values")
            values = dict(vf.data)
            for k in values:
                vf.raw(k)
            vf.done()
    else:
        for k in [k for k, v in rf.data.items() if isinstance(v, dict) and k != "start"]:
            rf.raw(k)  # the placements, read by the caller
    sf = rf.table("start") if (rf.has("start") or parent is None) else parent.table("start")
    start = {"position": sf.raw("position"),
             "gripper": sf.str("gripper", choices=("forward", "down")),
             "angle": sf.raw("angle", 0.0)}
    keep = sf.int("keep", 6, minimum=KEEP[0], maximum=KEEP[1])
    via = None
    if sf.has("via"):
        vf = sf.table("via")
        via = {"position": vf.raw("position"),
               "gripper": vf.str("gripper", choices=("forward", "down")),
               "angle": vf.raw("angle", 0.0)}
        vf.done()
    sf.done()
    rf.done()
    return RobotSpec(visuals, speed, turn, spw, start, via, keep, base=base,
                     keep_clear=tuple(keep_clear)), values


def _read_scene(path: Path, kinds: set[str], profile: Any) -> SceneSpec:
    from creative_py.perception.noise import NoiseModel
    f = Fields(load_toml(path), path)
    settle = f.float("settle_time", minimum=SETTLE_TIME_S[0], maximum=SETTLE_TIME_S[1])
    bodies = read_bodies(f.tables("body"))
    robot, placed_values = _read_robot(f.table("robot"), profile, [b.name for b in bodies])
    vf = f.table("values", {})
    values = dict(vf.data)
    for k in values:
        vf.raw(k)
    vf.done()
    for k in placed_values:
        if k not in values:
            raise WorldFileError(f"{path}: field 'robot.{profile.name}.values.{k}': names no "
                                 f"value of [values]")
    values.update(placed_values)
    tf = f.table("tool_start")
    tool_start: dict[str, Any] = {}
    for kind in sorted(kinds):
        for name, default in HANDLINGS[kind].start_fields.items():
            if name not in tool_start:
                tool_start[name] = tf.raw(name) if default is None else tf.raw(name, default)
    tf.done()
    pf = f.table("perception")
    try:
        noise = NoiseModel(depth_sigma_m=pf.float("depth_sigma_m", minimum=SIGMA_M[0],
                                                  maximum=SIGMA_M[1]),
                           dropout=pf.float("dropout", minimum=0.0, maximum=0.99))
    except ValueError as exc:
        raise WorldFileError(f"{path}: [perception]: {exc}") from None
    perceived = []
    for of in pf.tables("object", []):
        perceived.append(PerceivedObject(of.str("object"), of.raw("support_z", None)))
        of.done()
    pf.done()
    try:
        cameras = cameras_from_tables(f.raw("camera", []), str(path))
        table = f.raw("video", None)
        video = (VideoSpec.from_table(table, str(path)) if table is not None
                 else VideoSpec(cameras[0]) if cameras else None)
    except (ValueError, TypeError) as exc:
        raise WorldFileError(str(exc)) from None
    f.done()
    return SceneSpec(settle, robot, values, bodies, tool_start, noise, tuple(perceived),
                     cameras, video)


def _read_catalogue(path: Path, table: str) -> dict[str, CatalogueItem]:
    def holds(spec: Any) -> Optional[str]:
        return (None if spec.HANDLING in HANDLINGS else
                f"the simulator has no handling {spec.HANDLING!r} for a {spec.kind}")

    return read_catalogue(path, table, holds)


def _read_tasks(path: Path):
    f = Fields(load_toml(path), path)
    locations = []
    for lf in f.tables("location"):
        values = lf.raw("set", {})
        if not isinstance(values, dict):
            raise lf.error("set", "must be a table of scene values")
        lf.str("description", "")
        lf.done()
        locations.append(dict(values))
    if not locations:
        raise f.error("location", "at least one [[location]] is needed")
    of = f.table("oracle")
    kind = of.str("kind", choices=tuple(ORACLES))
    options = {}
    for name, default in ORACLES[kind].options.items():
        options[name] = of.raw(name) if default is None else of.raw(name, default)
    of.done()
    f.done()
    return tuple(locations), OracleSpec(kind, options)


def _read_skills(manifest: CaseManifest) -> dict[str, SkillSpec]:
    path = manifest.folder / "case.toml"
    out = {}
    for i, s in enumerate(manifest.skills):
        where = f"{path}: field 'skill[{i}]"
        if s.primitive not in SKILLS:
            raise WorldFileError(f"{where}.primitive': unknown primitive {s.primitive!r}; "
                                 f"primitives: {', '.join(SKILLS)}")
        known = SKILLS[s.primitive].options
        for name in s.options:
            if name not in known:
                raise WorldFileError(f"{where}.options.{name}': unknown option of "
                                     f"{s.primitive}; options: {', '.join(known)}")
        options = {}
        for name, default in known.items():
            if name in s.options:
                options[name] = s.options[name]
            elif default is not REQUIRED:
                options[name] = default
        out[s.name] = SkillSpec(s.name, s.primitive, options)
    return out


def world_robot(manifest: CaseManifest) -> Any:
    """Return the robot profile of a run: the manifest's ``robot`` (the case's, or
    ``--robot``'s in a run's manifest)."""
    from creative_py.robots import load_profile

    name = manifest.robot
    if not name:
        raise WorldFileError(f"{manifest.folder / 'case.toml'}: field 'robot': missing (the "
                             "scene's robot is a robot profile's)")
    return load_profile(name)


def load_world(manifest: CaseManifest, world_dir: Path | None = None) -> World:
    """Return the world of ``manifest`` read from ``world_dir`` (default: its folder), for
    the run's robot (:func:`world_robot`).

    Errors name the world file and the field (:class:`creative_py.world_files.WorldFileError`):
    a missing file or field, a wrong type, an unknown field (with a suggestion), an
    expression that does not resolve in some variant or location.
    """
    d = Path(world_dir) if world_dir is not None else Path(manifest.folder)
    p = world_file(d, "physics.toml")
    pf = Fields(load_toml(p), p)
    rest = read_physics(pf)
    arm = rest
    if pf.has("arm"):
        af = pf.table("arm")
        arm = read_physics(af, gravity=rest.gravity)
        af.done()
    pf.done()
    items = _read_catalogue(world_file(d, "objects.toml"), manifest.tools_table)
    scene = _read_scene(world_file(d, "scene.toml"), {i.spec.HANDLING for i in items.values()},
                        world_robot(manifest))
    locations, oracle = _read_tasks(world_file(d, "tasks.toml"))
    world = World(manifest, d, {"rest": rest, "arm": arm}, scene, items, locations, oracle,
                  _read_skills(manifest))
    demo = manifest.demonstration
    case_file = manifest.folder / "case.toml"
    if demo.tool not in items:
        raise WorldFileError(f"{case_file}: field 'demonstration.tool': must be one of "
                             f"{', '.join(items)}, got {demo.tool!r}")
    if demo.location > len(locations):
        raise WorldFileError(f"{case_file}: field 'demonstration.location': must be at most "
                             f"{len(locations)} (tasks.toml has {len(locations)} locations), "
                             f"got {demo.location}")
    bodies = {b.name for b in scene.bodies}
    for name in items:
        if name in bodies:
            raise WorldFileError(f"{d / 'objects.toml'}: object {name!r}: the name is "
                                 f"already a [[body]] of scene.toml; names must be unique")
    for v in manifest.variants:
        for loc in world.locations:
            check_values(world, v.name, loc, demo.tool)
    return world


def _scene_names(world: World, bodies: dict[str, Any], tool: str) -> Any:
    """Return what an oracle's options may name in an episode with ``bodies`` and
    ``tool`` (:class:`creative_py.world.oracles.SceneNames`)."""
    manifest = world.manifest
    started = {object_name(manifest, p.name, tool) for p in world.scene.perceived}
    started |= {n for n, b in bodies.items() if getattr(b, "dynamic", False)}
    return oracles.SceneNames({r: object_name(manifest, r, tool) for r in _ROLES},
                              frozenset({*bodies, tool}), frozenset(started))


def oracle_reads(world: World, variant: str, location: int, tool: str
                 ) -> tuple[list[str], bool]:
    """Return the objects the world's oracle reads in an episode of ``variant``,
    ``location`` and ``tool`` (in order), and whether it reads a velocity."""
    ns = world.namespace(variant, location, tool)
    opts = resolve_options(world.oracle.options, ns, "oracle", words=oracle_words(world))
    names = _scene_names(world, resolve_bodies(world.scene.bodies, ns), tool)
    kind = world.oracle.oracle
    return oracles.objects_read(world.oracle.kind, opts, names), kind.velocity(opts)


def check_values(world: World, variant: str, location: int, tool: str) -> None:
    """Resolve every scene value of one episode; raise :class:`WorldFileError` if one
    fails or lies outside its bounds.

    Bounded, each error naming the file and the field: the bodies' numbers
    (:mod:`creative_py.world.bodies`), every number of ``[tool_start]`` and of the robot's
    start and via poses (within +-:data:`EXTENT_M` m or rad), the skills' options
    (:func:`creative_py.world.skills.option_bound`: the primitive's own
    bound, else :data:`~creative_py.world.skills.OPTION_BOUNDS`) and the oracle's
    (:data:`creative_py.world.oracles.OPTION_BOUNDS`). Beyond bounds, what
    would fail or mean nothing mid-run: the skills' options by their primitive
    (:func:`creative_py.world.skills.check_options`: a list's length, a
    zero direction), the oracle's by its kind against the scene's objects and roles
    (:func:`creative_py.world.oracles.check_options`: names that resolve,
    vector lengths, axes, box order, non-zero scales).
    """
    ns = world.namespace(variant, location, tool)
    episode = f" (variant {variant}, location {location})"
    bodies = resolve_bodies(world.scene.bodies, ns)
    _check_start_poses(world, ns, episode)
    _check_skill_options(world, ns, episode)
    _check_oracle_options(world, ns, bodies, tool, episode)
    _check_perceived_and_roles(world, ns, bodies, tool)


def _check_start_poses(world: World, ns: Namespace, episode: str) -> None:
    """Raise :class:`WorldFileError` unless every number of ``[tool_start]`` and of the
    robot's start and via poses lies within +-:data:`EXTENT_M` (m or rad)."""
    scene_file = world.directory / "scene.toml"
    for k, v in resolve_start(world, ns).items():
        if not isinstance(v, (dict, str)):
            check_bound(v, (-EXTENT_M, EXTENT_M, "(m, rad)"),
                        f"{scene_file}: field 'tool_start.{k}'", episode)
    robot = world.scene.robot
    for name, pose in (("start", robot.start), ("start.via", robot.via)):
        for k in ("position", "angle") if pose is not None else ():
            where = f"{scene_file}: field 'robot.{name}.{k}'"
            value = ns.evaluate(pose[k], f"robot.{name}.{k}")
            if k == "position" and (not isinstance(value, tuple) or len(value) != 3):
                raise WorldFileError(f"{where}: must be a list of 3 numbers (m), got "
                                     f"{pose[k]!r}")
            check_bound(value, (-EXTENT_M, EXTENT_M, "m" if k == "position" else "rad"),
                        where, episode)


def _check_skill_options(world: World, ns: Namespace, episode: str) -> None:
    """Raise :class:`WorldFileError` unless every skill's options are well typed, within
    their bounds and valid for their primitive."""
    case_file = world.manifest.folder / "case.toml"
    flags = skills.option_flags()
    for i, s in enumerate(world.skills.values()):
        for k, raw in s.options.items():  # a flag is never a scene expression
            if k in flags and not isinstance(raw, bool):
                raise WorldFileError(f"{case_file}: field 'skill[{i}].options.{k}': must "
                                     f"be true or false, got {raw!r}")
        opts = resolve_options(s.options, ns, f"skill {s.name} options")
        for k, v in opts.items():
            where = f"{case_file}: field 'skill[{i}].options.{k}'"
            if k in flags:
                if not isinstance(v, bool):
                    raise WorldFileError(f"{where}: must be true or false, got {v!r}")
            elif (bound := skills.option_bound(s.primitive, k)) is not None:
                check_bound(v, bound, where,
                            episode if isinstance(s.options[k], str) else "")
        try:
            skills.check_options(s.primitive, opts)
        except OptionError as exc:
            raise WorldFileError(f"{case_file}: field 'skill[{i}].options.{exc.option}': "
                                 f"{exc.cause}{_context(s.options.get(exc.option), episode)}"
                                 ) from None


def _check_oracle_options(world: World, ns: Namespace, bodies: dict[str, Any], tool: str,
                          episode: str) -> None:
    """Raise :class:`WorldFileError` unless the oracle's options lie within their bounds
    and are valid for its kind against the objects and roles of an episode with
    ``bodies`` and ``tool``."""
    words = oracle_words(world)
    opts = resolve_options(world.oracle.options, ns, "oracle", words=words)
    tasks_file = world.directory / "tasks.toml"
    for k, v in opts.items():
        if k not in words and k in oracles.OPTION_BOUNDS:
            check_bound(v, oracles.OPTION_BOUNDS[k], f"{tasks_file}: field 'oracle.{k}'",
                        episode if isinstance(world.oracle.options[k], str) else "")
    names = _scene_names(world, bodies, tool)
    try:
        oracles.check_options(world.oracle.kind, opts, names)
    except OptionError as exc:
        raise WorldFileError(f"{tasks_file}: field 'oracle.{exc.option}': {exc.cause}"
                             + ("" if exc.option in words else
                                _context(world.oracle.options.get(exc.option), episode))
                             ) from None


def _check_perceived_and_roles(world: World, ns: Namespace, bodies: dict[str, Any],
                               tool: str) -> None:
    """Raise :class:`WorldFileError` unless every perceived object's support height
    resolves and names an object, and every role of case.toml is a body of the scene."""
    for p in world.scene.perceived:
        if p.support_z is not None:
            ns.evaluate(p.support_z, f"perception.object {p.name} support_z")
        object_name(world.manifest, p.name, tool)
    for role in _ROLES[1:]:
        name = getattr(world.manifest, role)
        if name not in bodies:
            raise WorldFileError(f"{world.directory / 'scene.toml'}: the {role} "
                                 f"{name!r} of case.toml is not a [[body]] of the scene")


def _context(raw: Any, episode: str) -> str:
    """Return ``episode`` if the option as written, ``raw``, holds a scene expression
    (its number may differ by variant and location), else ""."""
    def expr(v: Any) -> bool:
        return isinstance(v, str) or (isinstance(v, (list, tuple)) and any(map(expr, v)))
    return episode if expr(raw) else ""


def check_bound(value: Any, bound: tuple[float, float, str], where: str,
                context: str = "") -> None:
    """Raise :class:`WorldFileError` unless ``value`` (a number, or each number of a
    tuple) lies within ``bound`` = ``(low, high, unit)``; a ``steps`` value must be whole.

    ``where`` names the file and the field, ``context`` (appended) the episode whose
    scene values gave the number.
    """
    lo, hi, unit = bound
    for v in value if isinstance(value, tuple) else (value,):
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise WorldFileError(f"{where}: must be a number ({unit}), got {v!r}{context}")
        if not lo <= v <= hi:
            raise WorldFileError(f"{where}: must lie within [{lo:g}, {hi:g}] {unit}, got "
                                 f"{v:g}{context}")
        if unit == "steps" and not float(v).is_integer():
            raise WorldFileError(f"{where}: must be a whole number of steps, got "
                                 f"{v:g}{context}")


def oracle_words(world: World) -> set[str]:
    """Return the oracle options that are words (object names, an axis), not numbers."""
    o = ORACLES[world.oracle.kind]
    return {o.subject, *o.words}


def resolve_start(world: World, ns) -> dict[str, Any]:
    """Return the tool's start fields resolved (numbers, tuples, tables as written)."""
    return {k: ns.evaluate(v, f"tool_start.{k}") for k, v in world.scene.tool_start.items()}


def resolve_options(options: Mapping[str, Any], ns, where: str,
                    words: set[str] = frozenset()) -> dict[str, Any]:
    """Return ``options`` with numbers and expressions resolved (``words`` left as text)."""
    return {k: (v if k in words else ns.evaluate(v, f"{where}: {k}"))
            for k, v in options.items()}


def object_name(manifest: CaseManifest, name: str, tool: str) -> str:
    """Return the object a role (``tool``, ``target``, ``context``) or a name denotes."""
    return manifest.role_object(name, tool) if name in _ROLES else name
