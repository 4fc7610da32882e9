"""A case is data: the manifest ``worlds/<folder>/case.toml`` read into one value.

Every tool-use task (the paper's hook and wedge cases, and any a researcher adds) is a
world folder with a ``case.toml`` manifest, in one schema (``docs/new-case.md``):

* ``id``, ``title``, ``ontology`` (the file ``ontology/cases/<ontology>.pl`` that holds
  the case's knowledge), ``trial_budget`` (N of Algorithm 1), optional ``paper_trials``
  (the paper's count of tool-use trials, marked on a sweep's plot), both within
  :data:`TRIAL_BUDGET`;
* ``backend`` (optional, default ``"pybullet"``): the simulator backend that builds
  and runs the case's world, a name of :data:`BACKENDS`
  (:func:`creative_py.simulator.backend_for`);
* ``robot`` (optional): the case's default robot, a profile of ``robots/``
  (:mod:`creative_py.robots`; ``--robot NAME`` runs another);
* ``[roles]``: which ``objects.toml`` tables are the candidate tools, the target and
  the context object; ``goal``: the task's goal literals;
* ``[[skill]]``: the innate skills in plan order, each bound to a simulator primitive,
  with the roles of its arguments; one takes the pose, one is the tool action;
* ``[pose]``: the pose term's name and its parameters (name, unit, bounds ``min`` and
  ``max`` within +-:data:`POSE_LIMIT`);
* ``[[variant]]``: task variants with the scene values they set, one marked ``harder``;
* ``[demonstration]``: the trainer's tool, variant, location, skills and pose;
* ``[randomise]`` (optional): how ``--world-seed N`` jitters the target's locations,
  ``[randomise.location.<key>]`` with ``jitter`` (the largest change, in the key's own
  unit), ``min`` and ``max`` (the value is kept inside) for a scene value a location
  sets (``back_gap``, ``"door1.open_angle"``); ``[randomise.catalogue.<field>]`` with
  ``min`` and/or ``max`` narrows the draw of a catalogue spec field (``handle_width``)
  inside each object's own qualitative range, where the simulator needs it, and a
  table per qualitative value (``short = {max = 0.20}``) narrows the draw of the
  objects that have that value, where the physics' boundary lies inside the
  ontology's range (every ``min``, ``max`` and ``jitter`` within
  +-:data:`RANDOMISE_LIMIT`).

The skills' ``options`` are checked where they are resolved, in every variant and
location (:func:`creative_py.world.read.check_values`, the bounds of
:data:`creative_py.world.skills.OPTION_BOUNDS`).

Nothing here knows any particular case: :func:`load_cases` finds every manifest under
``worlds/``, :func:`get_case` returns one by id. Errors name the file and the field
(:class:`~creative_py.world_files.WorldFileError`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional

from creative_py.backend_registry import BACKENDS, DEFAULT_BACKEND
from creative_py.robots import profile_names
from creative_py.world_files import WORLDS_ROOT, Fields, WorldFileError, load_toml

MANIFEST = "case.toml"
"""The manifest's file name in a world folder."""

ONTOLOGY_CASES = WORLDS_ROOT.parent / "ontology" / "cases"
"""The folder of the case ontology files the engine loads (``<ontology>.pl``)."""

ROLES = ("tool", "target", "context")
"""The roles a skill argument can take."""

_ID = re.compile(r"[a-z][a-z0-9_]*\Z")

TRIAL_BUDGET = (1, 10000)
"""The bounds of ``trial_budget`` and ``paper_trials``, trials."""

POSE_LIMIT = 10.0
"""The largest size of a ``[[pose.param]]``'s ``min`` and ``max`` (its unit: m, rad)."""

RANDOMISE_LIMIT = 1000.0
"""The largest size of a ``[randomise]`` ``min``, ``max`` (a scene value's or a spec
field's own unit: m, rad, degrees) and ``jitter``."""


@dataclass(frozen=True)
class SkillBinding:
    """One innate skill and the simulator primitive that carries it out."""

    name: str
    primitive: str
    args: tuple[str, ...]
    pose: bool = False
    tool_action: bool = False
    options: dict[str, Any] = field(default_factory=dict)


@dataclass(frozen=True)
class PoseParam:
    """One number of the pose term: name, unit and the bounds a trial may use."""

    name: str
    unit: str
    min: float
    max: float
    doc: str = ""


@dataclass(frozen=True)
class Variant:
    """A task variant: the scene values it sets (dotted keys) and whether it is harder."""

    name: str
    description: str
    harder: bool
    set: dict[str, Any]


@dataclass(frozen=True)
class DemonstrationSpec:
    """The trainer's demonstration: tool, variant, location, skills and pose numbers."""

    tool: str
    variant: str
    location: int
    steps: tuple[str, ...]
    pose: tuple[float, ...]


@dataclass(frozen=True)
class LocationJitter:
    """How a randomised world moves one scene value of every location (``[randomise]``)."""

    key: str
    jitter: float
    min: float
    max: float


@dataclass(frozen=True)
class CaseManifest:
    """Everything ``worlds/<folder>/case.toml`` says about one case."""

    id: str
    title: str
    folder: Path
    ontology: str
    trial_budget: int
    tools_table: str
    target: str
    context: str
    goal: tuple[str, ...]
    skills: tuple[SkillBinding, ...]
    pose_term: str
    pose_params: tuple[PoseParam, ...]
    variants: tuple[Variant, ...]
    demonstration: DemonstrationSpec
    location_jitter: tuple[LocationJitter, ...] = ()
    paper_trials: int | None = None
    catalogue_bounds: tuple[tuple[str, float, float], ...] = ()
    """``(spec field, min, max)`` from ``[randomise.catalogue]``: a drawn number of that
    field stays within them (and within its object's own qualitative range)."""
    catalogue_value_bounds: tuple[tuple[str, str, float, float], ...] = ()
    """``(spec field, qualitative value, min, max)`` from the value tables of
    ``[randomise.catalogue.<field>]`` (``short = {max = 0.20}``): a drawn number whose
    object has that value stays within them, where the physics' boundary lies inside
    the ontology's range (a 0.24 m "short" handle already reaches the cube)."""
    backend: str = DEFAULT_BACKEND
    """The simulator backend of the case's world (a name of :data:`BACKENDS`)."""
    robot: Optional[str] = None
    """The robot the backend builds: the case's default, a profile of ``robots/``; a
    run's manifest carries ``--robot``'s instead (a name or a ``.toml`` path: the backend
    reads it from here, the one way the choice travels); None for a backend that brings
    its own arm."""
    benchmark: Optional[str] = None
    """The published benchmark the case re-expresses (``[benchmark] name``, e.g.
    ``robotoolbench``), by which a bench gathers its cases; None for the project's own."""
    benchmark_task: Optional[str] = None
    """The benchmark's name of the task (``[benchmark] task``, e.g. ``BringCube``), by
    which a bench finds its published figures."""

    @property
    def harder_variant(self) -> str:
        """Return the variant that needs a new tool."""
        return next(v.name for v in self.variants if v.harder)

    @property
    def variant_names(self) -> tuple[str, ...]:
        """Return the variants' names in manifest order."""
        return tuple(v.name for v in self.variants)

    def variant(self, name: str) -> Variant:
        """Return variant ``name``; raise listing the known ones."""
        for v in self.variants:
            if v.name == name:
                return v
        raise KeyError(f"unknown variant {name!r} of case {self.id}; variants: "
                       f"{', '.join(self.variant_names)}")

    def skill(self, name: str) -> SkillBinding:
        """Return the skill ``name``; raise listing the case's skills."""
        for s in self.skills:
            if s.name == name:
                return s
        raise KeyError(f"unknown skill {name!r} of case {self.id}; skills: "
                       f"{', '.join(s.name for s in self.skills)}")

    def role_object(self, role: str, tool: str) -> str:
        """Return the object that plays ``role`` when ``tool`` is the tool."""
        return {"tool": tool, "target": self.target, "context": self.context}[role]

    def skill_args(self, skill: SkillBinding, tool: str) -> tuple[str, ...]:
        """Return the ground arguments of ``skill`` (its STRIPS parameters)."""
        return tuple(self.role_object(r, tool) for r in skill.args)

    @property
    def pose_names(self) -> tuple[str, ...]:
        """Return the names of the pose numbers, in the pose term's order."""
        return tuple(p.name for p in self.pose_params)

    def check_pose(self, values: tuple[float, ...], source: str = "pose") -> tuple[float, ...]:
        """Return ``values`` as floats if they fit the pose parameters; raise ValueError."""
        if len(values) != len(self.pose_params):
            raise ValueError(f"{source}: {self.id} poses have {len(self.pose_params)} numbers "
                             f"({','.join(self.pose_names)}), got {len(values)}")
        out = []
        for p, v in zip(self.pose_params, values):
            v = float(v)
            if not math.isfinite(v) or not p.min <= v <= p.max:
                raise ValueError(f"{source}: {p.name} must be within [{p.min}, {p.max}] "
                                 f"{p.unit}, got {v}")
            out.append(v)
        return tuple(out)

    def parse_pose(self, text: str) -> tuple[float, ...]:
        """Parse ``"A,B,C"`` into pose numbers within their bounds; raise ValueError."""
        try:
            values = tuple(float(p) for p in text.split(","))
        except ValueError:
            raise ValueError(f"--pose must be {','.join(n.upper() for n in self.pose_names)} "
                             f"({', '.join(p.unit for p in self.pose_params)}), "
                             f"got {text!r}") from None
        return self.check_pose(values, "--pose")

    def listing(self) -> dict[str, Any]:
        """Return the manifest as plain JSON-ready data (``creative cases --json``)."""
        return {"id": self.id, "title": self.title, "world": str(self.folder),
                "ontology": self.ontology, "backend": self.backend,
                "trial_budget": self.trial_budget,
                "variants": [{"name": v.name, "harder": v.harder,
                              "description": v.description} for v in self.variants],
                "harder_variant": self.harder_variant,
                "skills": [s.name for s in self.skills],
                "pose": {"term": self.pose_term, "params": list(self.pose_names)}}


def read_manifest(folder: Path) -> CaseManifest:
    """Read and check ``folder/case.toml``; errors name the file and the field."""
    folder = Path(folder)
    path = folder / MANIFEST
    if not path.is_file():
        raise WorldFileError(f"{path}: file not found (a case folder needs a {MANIFEST})")
    f = Fields(load_toml(path), path)
    cid = f.str("id")
    if not _ID.match(cid):
        raise f.error("id", f"must be a lower-case Prolog atom, got {cid!r}")
    title = f.str("title")
    ontology = f.str("ontology")
    backend = f.str("backend", DEFAULT_BACKEND, choices=tuple(sorted(BACKENDS)))
    robot = f.str("robot") if f.has("robot") else None
    benchmark = benchmark_task = None
    if f.has("benchmark"):
        bf = f.table("benchmark")
        benchmark, benchmark_task = bf.str("name"), bf.str("task")
        if not _ID.match(benchmark):
            raise bf.error("name", f"must be a lower-case word, got {benchmark!r}")
        bf.done()
    if robot is not None and robot not in profile_names():
        raise f.error("robot", f"no robot profile {robot!r} in robots/; profiles: "
                      f"{', '.join(profile_names())}")
    budget = f.int("trial_budget", minimum=TRIAL_BUDGET[0], maximum=TRIAL_BUDGET[1])
    paper_trials = (f.int("paper_trials", minimum=TRIAL_BUDGET[0], maximum=TRIAL_BUDGET[1])
                    if f.has("paper_trials") else None)
    roles = f.table("roles")
    tools_table, target, context = roles.str("tools"), roles.str("target"), roles.str("context")
    roles.done()
    goal = f.raw("goal")
    if not isinstance(goal, list) or not goal or not all(isinstance(g, str) for g in goal):
        raise f.error("goal", "must be a non-empty list of literals written as text")
    skills = _read_skills(f)
    pose_term, params = _read_pose(f)
    variants = _read_variants(f)
    demo = _read_demonstration(f, skills, params, variants)
    jitters, bounds, value_bounds = _read_randomise(f)
    f.done()
    _check_ontology(f, cid, ontology)  # after the fields' own checks: a typo first
    manifest = CaseManifest(cid, title, folder, ontology, budget, tools_table, target,
                            context, tuple(goal), skills, pose_term, params,
                            variants, demo, jitters, paper_trials, bounds, value_bounds,
                            backend, robot, benchmark, benchmark_task)
    try:
        manifest.check_pose(demo.pose, "demonstration.pose")
    except ValueError as exc:
        raise WorldFileError(f"{path}: field 'demonstration.pose': {exc}") from None
    return manifest


def _check_ontology(f: Fields, cid: str, ontology: str) -> None:
    """Raise WorldFileError naming ``case.toml`` and its field ``ontology`` unless
    ``ontology/cases/<ontology>.pl`` exists and declares ``case(<id>).`` (the file
    that holds this case's knowledge, which the engine loads)."""
    if not _ID.match(ontology):
        raise f.error("ontology", f"must name a file of ontology/cases/ without its .pl "
                      f"(a lower-case Prolog atom), got {ontology!r}")
    path = ONTOLOGY_CASES / f"{ontology}.pl"
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        why = "no such file" if isinstance(exc, FileNotFoundError) else (exc.strerror or exc)
        raise f.error("ontology", f"{path}: {why}") from None
    if not re.search(rf"^case\(\s*{re.escape(cid)}\s*\)\s*\.", text, re.MULTILINE):
        raise f.error("ontology", f"{path} does not declare case({cid}). (the case's "
                      f"ontology file starts with it)")


def _read_skills(f: Fields) -> tuple[SkillBinding, ...]:
    """Return the ``[[skill]]`` bindings; exactly one takes the pose, one is the action."""
    skills = []
    for sf in f.tables("skill"):
        args = sf.raw("args")
        if not isinstance(args, list) or not all(a in ROLES for a in args):
            raise sf.error("args", f"must be a list of roles among {', '.join(ROLES)}, "
                           f"got {args!r}")
        options = sf.raw("options", {})
        if not isinstance(options, dict):
            raise sf.error("options", "must be a table")
        skills.append(SkillBinding(sf.str("name"), sf.str("primitive"), tuple(args),
                                   sf.bool("pose", False), sf.bool("tool_action", False),
                                   dict(options)))
        sf.done()
    if not skills:
        raise f.error("skill", "at least one [[skill]] is needed")
    for flag in ("pose", "tool_action"):
        marked = [s.name for s in skills if getattr(s, flag)]
        if len(marked) != 1:
            raise f.error("skill", f"exactly one skill must set {flag} = true, got "
                          f"{len(marked)} ({', '.join(marked) or 'none'})")
    return tuple(skills)


def _read_pose(f: Fields) -> tuple[str, tuple[PoseParam, ...]]:
    """Return the ``[pose]`` term's functor and its ``[[pose.param]]`` parameters."""
    pf = f.table("pose")
    pose_term = pf.str("term")
    params = []
    for p in pf.tables("param"):
        lo = p.float("min", minimum=-POSE_LIMIT, maximum=POSE_LIMIT)
        hi = p.float("max", minimum=-POSE_LIMIT, maximum=POSE_LIMIT)
        if lo > hi:
            raise p.error("max", f"must be >= min ({lo}), got {hi}")
        params.append(PoseParam(p.str("name"), p.str("unit"), lo, hi, p.str("doc", "")))
        p.done()
    if not params:
        raise pf.error("param", "at least one [[pose.param]] is needed")
    pf.done()
    return pose_term, tuple(params)


def _read_variants(f: Fields) -> tuple[Variant, ...]:
    """Return the ``[[variant]]`` tables: unique names, exactly one ``harder``."""
    variants = []
    for vf in f.tables("variant"):
        values = vf.raw("set", {})
        if not isinstance(values, dict):
            raise vf.error("set", "must be a table of dotted scene keys and values")
        variants.append(Variant(vf.str("name"), vf.str("description", ""),
                                vf.bool("harder", False), dict(values)))
        vf.done()
    names = [v.name for v in variants]
    if not variants or len(set(names)) != len(names):
        raise f.error("variant", f"needs at least one [[variant]] with unique names, got {names}")
    if sum(v.harder for v in variants) != 1:
        raise f.error("variant", "exactly one variant must be marked harder = true")
    return tuple(variants)


def _read_demonstration(f: Fields, skills: tuple[SkillBinding, ...],
                        params: tuple[PoseParam, ...],
                        variants: tuple[Variant, ...]) -> DemonstrationSpec:
    """Return the ``[demonstration]``: its steps are the case's skills, its variant one
    of the case's, its pose one number per pose parameter."""
    df = f.table("demonstration")
    steps = df.raw("steps")
    known = [s.name for s in skills]
    if not isinstance(steps, list) or not all(s in known for s in steps):
        raise df.error("steps", f"must be a list of the case's skills ({', '.join(known)}), "
                       f"got {steps!r}")
    demo_variant = df.str("variant", choices=tuple(v.name for v in variants))
    pose_f = df.table("pose")
    pose = tuple(pose_f.float(p.name) for p in params)
    pose_f.done()
    demo = DemonstrationSpec(df.str("tool"), demo_variant, df.int("location", minimum=1),
                             tuple(steps), pose)
    df.done()
    return demo


def _read_randomise(f: Fields) -> tuple[tuple[LocationJitter, ...],
                                        tuple[tuple[str, float, float], ...],
                                        tuple[tuple[str, str, float, float], ...]]:
    """Return the optional ``[randomise]`` table: the location jitters, the catalogue
    fields' draw bounds and their per-value bounds (all empty without the table)."""
    if not f.has("randomise"):
        return (), (), ()
    rf = f.table("randomise")
    bounds, value_bounds = _read_catalogue_bounds(rf.table("catalogue", {}))
    jitters = []
    lf = rf.table("location", {})
    for key in list(lf.data):
        jf = lf.table(key)
        lo = jf.float("min", minimum=-RANDOMISE_LIMIT, maximum=RANDOMISE_LIMIT)
        hi = jf.float("max", minimum=-RANDOMISE_LIMIT, maximum=RANDOMISE_LIMIT)
        if lo > hi:
            raise jf.error("max", f"must be >= min ({lo}), got {hi}")
        jitters.append(LocationJitter(key, jf.float("jitter", minimum=0.0,
                                                    maximum=RANDOMISE_LIMIT), lo, hi))
        jf.done()
    lf.done()
    rf.done()
    return tuple(jitters), bounds, value_bounds


def _read_catalogue_bounds(cf: Fields) -> tuple[tuple[tuple[str, float, float], ...],
                                                tuple[tuple[str, str, float, float], ...]]:
    """Return ``[randomise.catalogue.<field>]``'s bounds per field and per value."""
    bounds: list[tuple[str, float, float]] = []
    value_bounds: list[tuple[str, str, float, float]] = []
    for key in list(cf.data):
        bf = cf.table(key)
        lo, hi = _min_max(bf)
        bounds.append((key, lo, hi))
        for value in [k for k in bf.data if k not in ("min", "max")]:
            vf = bf.table(value)
            vlo, vhi = _min_max(vf)
            value_bounds.append((key, value, vlo, vhi))
            vf.done()
        bf.done()
    cf.done()
    return tuple(bounds), tuple(value_bounds)


def _min_max(t: Fields) -> tuple[float, float]:
    """Return a table's optional ``min`` and ``max`` (unbounded when absent), min <= max."""
    lim = RANDOMISE_LIMIT
    lo = t.float("min", minimum=-lim, maximum=lim) if t.has("min") else -math.inf
    hi = t.float("max", minimum=-lim, maximum=lim) if t.has("max") else math.inf
    if lo > hi:
        raise t.error("max", f"must be >= min ({lo}), got {hi}")
    return lo, hi


@dataclass(frozen=True)
class CaseIndex:
    """The case folders under one root, found without reading any manifest whole.

    Attributes
    ----------
    folders : dict
        ``id -> folder`` of every manifest whose ``id`` could be read.
    broken : dict
        ``manifest path -> error line`` of every manifest that is not valid TOML or has
        no readable ``id``, or whose ``id`` another folder declares too. A broken
        manifest affects only its own case: the others load and run.
    """

    folders: dict[str, Path]
    broken: dict[Path, str]
    duplicates: dict[str, str] = field(default_factory=dict)
    """``id -> error line`` of every id that two or more folders declare: no folder
    of it is a case (which one a run would use is not for the sort order to say)."""


_INDEX: dict[Path, CaseIndex] = {}
_MANIFESTS: dict[Path, CaseManifest] = {}


def case_index(root: Path | None = None) -> CaseIndex:
    """Return which folder of ``root`` (default ``worlds/``) declares which case id.

    Each ``<root>/*/case.toml`` is parsed only for its ``id``; a folder whose manifest
    cannot give one, or gives an id another folder declares too, is listed in
    ``broken`` with the error naming both files (every folder of a duplicate id is:
    :func:`get_case` refuses that id with the same line).
    """
    root = Path(root) if root is not None else WORLDS_ROOT
    if root not in _INDEX:
        declared: dict[str, list[Path]] = {}
        broken: dict[Path, str] = {}
        for path in sorted(root.glob(f"*/{MANIFEST}")):
            try:
                cid = Fields(load_toml(path), path).str("id")
            except WorldFileError as exc:
                broken[path] = str(exc)
                continue
            declared.setdefault(cid, []).append(path)
        folders: dict[str, Path] = {}
        duplicates: dict[str, str] = {}
        for cid, paths in declared.items():
            if len(paths) == 1:
                folders[cid] = paths[0].parent
                continue
            line = (f"case {cid!r} is declared by {len(paths)} folders: "
                    f"{' and '.join(str(p) for p in paths)} (field 'id'; give each "
                    f"folder its own id)")
            duplicates[cid] = line
            for p in paths:
                broken[p] = line
        _INDEX[root] = CaseIndex(folders, dict(sorted(broken.items())), duplicates)
    return _INDEX[root]


def load_cases(root: Path | None = None, *, strict: bool = True) -> dict[str, CaseManifest]:
    """Return ``id -> manifest`` for every ``<root>/*/case.toml`` (default ``worlds/``).

    With ``strict`` (the default) the first broken manifest raises WorldFileError naming
    its file and field; otherwise broken manifests are left out (:func:`broken_cases`
    lists them).
    """
    index = case_index(root)
    if strict and index.broken:
        raise WorldFileError(next(iter(index.broken.values())))
    cases: dict[str, CaseManifest] = {}
    for cid in index.folders:
        try:
            cases[cid] = get_case(cid, root)
        except WorldFileError:
            if strict:
                raise
    return cases


def broken_cases(root: Path | None = None) -> dict[Path, str]:
    """Return ``manifest path -> error line`` of every case folder that does not load."""
    index = case_index(root)
    out = dict(index.broken)
    for cid, folder in index.folders.items():
        try:
            get_case(cid, root)
        except WorldFileError as exc:
            out[folder / MANIFEST] = str(exc)
    return out


def get_case(case: str, root: Path | None = None) -> CaseManifest:
    """Return the manifest of case ``case``, reading only its own folder.

    Raises KeyError listing the known cases (and the folders that do not load) when no
    folder declares ``case``, and WorldFileError when its own manifest is broken.
    """
    index = case_index(root)
    if case in index.duplicates:
        raise WorldFileError(index.duplicates[case])
    folder = index.folders.get(case)
    if folder is None:
        known = ", ".join(sorted(index.folders))
        broken = "".join(f"; {p} does not load" for p in index.broken)
        raise KeyError(f"unknown case {case!r}; known cases: {known}{broken}")
    if folder not in _MANIFESTS:
        _MANIFESTS[folder] = read_manifest(folder)
    return _MANIFESTS[folder]


def manifest_of_folder(folder: Path) -> CaseManifest:
    """Return the manifest of a world folder (a user's copy of a shipped world)."""
    return read_manifest(Path(folder))
