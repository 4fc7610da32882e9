"""A case's world for the ManiSkill backend, read from its folder.

The world folder of a ManiSkill case holds ``case.toml`` (``backend = "maniskill"``),
``objects.toml`` (the catalogue: one table per tool, the fields of its kind's spec,
``set``, ``friction``, ``mass`` in kg) and ``tasks.toml``:

.. code-block:: toml

    [env]                    # ManiSkill's task and the actors of its scene, by name
    task = "PullCubeTool-v1" # a registered ManiSkill task (its evaluate() is the verdict)
    tool = "l_shape_tool"    # the tool actor: built from the catalogued tool's boxes
    target = "cube"          # the actor the task moves (the case's target role)
    target_half = 0.02       # its half size, m (the size/4 fact)
    goal = ""                # optional: a goal actor that moves with the target (cube_dx)
    measures = ["cube_distance", "cube_progress"]   # evaluate() entries kept per trial

    [episode]
    max_steps = 100          # control steps of one trial (ManiSkill's task: 100)

    [[location]]
    seed = 3                 # a location is ManiSkill's seeded initial state reset(seed=3)

    [zone]                   # what the robot knows of the goal region (a fixed fact):
    centre = "robot"         # the robot base (default) or the name of an actor
    radius = 0.6             # ManiSkill's evaluate() threshold, cube to base in xy, m

    [video]                  # optional: the trial clips' camera (maniskill/recorder.py)
    eye = [0.25, -1.15, 0.95]
    target = [-0.3, 0.0, 0.05]
    fov_deg = 55.0
    width = 320
    height = 240
    fps = 5.0                # frames per second of simulated time

A variant's ``set`` may give ``cube_dx``: how much farther along +x than ManiSkill
draws it the target (with the goal actor, if any) starts (metres). Errors name the file
and the field.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence

from creative_py.case import CaseManifest
from creative_py.backends.maniskill.recorder import VideoCamera, read_video
from creative_py.simulator.catalogue import CatalogueItem, CatalogueWorld, read_catalogue
from creative_py.world_files import Fields, WorldFileError, load_toml, world_file

VARIANT_VALUES = {"cube_dx": (0.0, 0.5)}
"""The values a variant may set, with their bounds (metres)."""

PRIMITIVES = {
    "grasp": {"approach": 0.08, "lift_to": 0.25, "step_m": 0.03},
    "place_at_pose": {"carry_z": 0.25, "settle_steps": 4, "side_clear": 0.08,
                      "slide_step_m": 0.02, "step_m": 0.03},
    "pull_to_radius": {"radius": 0.55, "step_m": 0.02, "settle_steps": 3, "lift_by": 0.06},
    "push_to_zone": {"beyond": 0.0, "step_m": 0.02, "settle_steps": 3},
}
"""The skill primitives of this backend and their options with defaults
(:mod:`creative_py.backends.maniskill.episode`). ``step_m`` is the largest move of the
TCP in one control step, metres (of a grasp's approach and lift, of a placing's carry
and lowering, of a pull or a push): fewer, longer steps fit a skill into the episode's
step budget. An option ending in ``step_m`` must be above 0."""


@dataclass(frozen=True)
class TaskEnv:
    """ManiSkill's task of a world and the names of its scene's actors (``[env]``).

    Attributes
    ----------
    task : str
        ManiSkill's task id (registered by ManiSkill).
    tool, target : str
        The names of the tool actor (built from the catalogued tool) and of the actor
        the task moves.
    target_half : float
        The target's half size, m.
    goal : str
        The name of a goal actor that moves with the target, or "".
    measures : tuple of str
        The entries of ``evaluate()`` a trial's verdict keeps.
    """

    task: str
    tool: str
    target: str
    target_half: float
    goal: str = ""
    measures: tuple[str, ...] = ()


@dataclass(frozen=True)
class World(CatalogueWorld):
    """A ManiSkill case's world (see the module docstring for its files).

    Attributes
    ----------
    manifest : CaseManifest
    directory : Path
    items : dict
        ``name -> CatalogueItem``.
    seeds : tuple of int
        ManiSkill's reset seed of each location, in order.
    max_steps : int
        The control steps one trial may take.
    zone_radius : float
        The goal region's radius about the robot base, m (a fact the robot is given).
    skills : dict
        ``skill name -> (primitive, options)``.
    env : TaskEnv
        ManiSkill's task and its actors' names.
    zone_centre : str
        The goal region's centre: ``robot`` (the robot base) or an actor's name.
    """

    manifest: CaseManifest
    directory: Path
    items: dict[str, CatalogueItem]
    seeds: tuple[int, ...]
    max_steps: int
    zone_radius: float
    skills: dict[str, tuple[str, dict[str, Any]]]
    env: TaskEnv = TaskEnv("", "", "", 0.02)
    zone_centre: str = "robot"
    variation: str = ""
    video: Optional[VideoCamera] = None
    """The clips' camera and frame rate (the ``[video]`` table of ``tasks.toml``), or
    None: no clip is recorded."""
    env_cache: dict = field(default_factory=dict, compare=False, repr=False)

    @property
    def locations(self) -> tuple[int, ...]:
        """Return the 1-based indices of the locations (ManiSkill seeds)."""
        return tuple(range(1, len(self.seeds) + 1))

    def seed(self, location: int) -> int:
        """Return ManiSkill's reset seed of ``location`` (1-based)."""
        if not (isinstance(location, int) and 1 <= location <= len(self.seeds)):
            raise KeyError(f"unknown location {location!r}; locations: 1..{len(self.seeds)}")
        return self.seeds[location - 1]

    def cube_dx(self, variant: str) -> float:
        """Return how much farther the cube starts in ``variant``, m."""
        return float(self.manifest.variant(variant).set.get("cube_dx", 0.0))

    def _no_drawn_worlds(self) -> ValueError:
        return ValueError(f"{self.manifest.folder / 'case.toml'}: the maniskill backend "
                          "draws no randomised worlds (--world-seed); its locations are "
                          "ManiSkill's seeded initial states")

    def location_values(self, location: int) -> dict[str, Any]:
        """Refuse: the locations are ManiSkill's seeds, not scene values, so this
        backend draws no randomised worlds (ValueError naming ``case.toml``)."""
        raise self._no_drawn_worlds()

    def scene_value(self, key: str, variant: str, location: int, tool: str) -> float:
        """Refuse as :meth:`location_values` (ValueError)."""
        raise self._no_drawn_worlds()

    def with_locations(self, tables: Sequence[Mapping[str, Any]], variation: str) -> "World":
        """Refuse as :meth:`location_values` (ValueError)."""
        raise self._no_drawn_worlds()

    def location_listing(self) -> list[dict[str, Any]]:
        """Return each location's episode seed with its 1-based ``index``."""
        return [{"index": i, "seed": s} for i, s in enumerate(self.seeds, 1)]


def _read_catalogue(path: Path, table: str) -> dict[str, CatalogueItem]:
    def holds(spec: Any) -> Optional[str]:
        return (None if spec.HANDLING == "handle" else
                f"the ManiSkill backend holds handled tools only, not a {spec.kind}")

    return read_catalogue(path, table, holds)


def load_world(manifest: CaseManifest, world_dir: Optional[Path] = None) -> World:
    """Return the world of ``manifest`` (errors name the file and the field)."""
    d = Path(world_dir) if world_dir is not None else Path(manifest.folder)
    items = _read_catalogue(world_file(d, "objects.toml"), manifest.tools_table)
    p = world_file(d, "tasks.toml")
    f = Fields(load_toml(p), p)
    env = _read_env(f)
    ef = f.table("episode")
    max_steps = ef.int("max_steps", 100, minimum=10, maximum=1000)
    ef.done()
    seeds = _read_locations(f)
    centre, radius = _read_zone(f, env)
    video = read_video(f)
    f.done()
    skills = _read_skills(manifest)
    _check_variants(manifest)
    _check_demonstration(manifest, items, len(seeds))
    return World(manifest, d, items, tuple(seeds), max_steps, radius, skills, env, centre,
                 video=video)


def _read_locations(f: Fields) -> list[int]:
    """Read the ``[[location]]`` tables of tasks.toml: each location's episode seed."""
    seeds = []
    for lf in f.tables("location"):
        seeds.append(lf.int("seed", minimum=0, maximum=2**31 - 1))
        lf.str("description", "")
        lf.done()
    if not seeds:
        raise f.error("location", "at least one [[location]] is needed")
    return seeds


def _read_zone(f: Fields, env: TaskEnv) -> tuple[str, float]:
    """Read ``[zone]`` of tasks.toml: what the zone is centred on (``robot`` or the
    goal actor named in ``[env]``) and its radius (m)."""
    zf = f.table("zone")
    centre = zf.str("centre", "robot")
    if centre != "robot" and centre not in (env.target, env.goal):
        raise zf.error("centre", f"must be 'robot' or the goal actor named in [env] "
                                 f"({env.goal or 'none'}), got {centre!r}")
    radius = zf.float("radius", minimum=0.01, maximum=2.0)
    zf.done()
    return centre, radius


def _read_skills(manifest: CaseManifest) -> dict[str, tuple[str, dict[str, Any]]]:
    """Return the manifest's skills, ``name -> (primitive, options)`` with the
    primitive's defaults filled in; raise :class:`WorldFileError` naming case.toml's
    field for an unknown primitive or option, or a step that is not a length in (0, 1] m."""
    case_file = manifest.folder / "case.toml"
    skills = {}
    for i, s in enumerate(manifest.skills):
        if s.primitive not in PRIMITIVES:
            raise WorldFileError(f"{case_file}: field 'skill[{i}].primitive': unknown primitive "
                                 f"{s.primitive!r}; primitives: {', '.join(PRIMITIVES)}")
        known = PRIMITIVES[s.primitive]
        for name in s.options:
            if name not in known:
                raise WorldFileError(f"{case_file}: field 'skill[{i}].options.{name}': unknown "
                                     f"option of {s.primitive}; options: {', '.join(known)}")
            value = s.options[name]
            if name.endswith("step_m") and not (isinstance(value, (int, float))
                                                and not isinstance(value, bool)
                                                and 0.0 < value <= 1.0):
                raise WorldFileError(f"{case_file}: field 'skill[{i}].options.{name}': must "
                                     f"be a number of metres above 0 and at most 1, got "
                                     f"{value!r}")
        skills[s.name] = (s.primitive, {**known, **s.options})
    return skills


def _check_variants(manifest: CaseManifest) -> None:
    """Raise :class:`WorldFileError` unless every value a variant sets is one of
    :data:`VARIANT_VALUES`, within its range."""
    case_file = manifest.folder / "case.toml"
    for v in manifest.variants:
        for k, val in v.set.items():
            if k not in VARIANT_VALUES:
                raise WorldFileError(f"{case_file}: variant {v.name!r}: set: unknown value "
                                     f"{k!r}; values: {', '.join(VARIANT_VALUES)}")
            lo, hi = VARIANT_VALUES[k]
            if not (isinstance(val, (int, float)) and lo <= val <= hi):
                raise WorldFileError(f"{case_file}: variant {v.name!r}: set: {k} must be a "
                                     f"number in {lo}..{hi}, got {val!r}")


def _check_demonstration(manifest: CaseManifest, items: Mapping[str, CatalogueItem],
                         n_locations: int) -> None:
    """Raise :class:`WorldFileError` unless the demonstration's tool is catalogued and its
    location is one of the ``n_locations``."""
    case_file = manifest.folder / "case.toml"
    demo = manifest.demonstration
    if demo.tool not in items:
        raise WorldFileError(f"{case_file}: field 'demonstration.tool': must be one of "
                             f"{', '.join(items)}, got {demo.tool!r}")
    if demo.location > n_locations:
        raise WorldFileError(f"{case_file}: field 'demonstration.location': must be at most "
                             f"{n_locations}, got {demo.location}")


def _read_env(f: Fields) -> TaskEnv:
    """Read ``[env]``: ManiSkill's task (checked to be registered) and its actors."""
    tf = f.table("env")
    task = tf.str("task")
    from creative_py.backends.maniskill.env import task_ids

    known = task_ids()
    if task not in known:
        raise tf.error("task", f"not a registered ManiSkill task: {task!r}")
    tool, target = tf.str("tool"), tf.str("target")
    half = tf.float("target_half", minimum=0.001, maximum=0.5)
    goal = tf.str("goal", "")
    measures = tf.raw("measures", [])
    if not (isinstance(measures, list) and all(isinstance(m, str) for m in measures)):
        raise tf.error("measures", f"must be a list of evaluate()'s entry names, got "
                                   f"{measures!r}")
    tf.done()
    return TaskEnv(task, tool, target, half, goal, tuple(measures))
