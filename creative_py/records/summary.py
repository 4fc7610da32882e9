"""A run's summary as it records it: :class:`RunSummary`, the file ``summary.json``.

The summary is the single owner of that file's format. The learner fills it
(:mod:`creative_py.learning.run` and :mod:`creative_py.learning.phases`),
:meth:`RunSummary.write` writes it, :meth:`RunSummary.read` reads and checks it; the
reports (:mod:`creative_py.report`) and the sweep (:mod:`creative_py.sweep`) read its
fields, never the file's keys. A new figure is one typed line in its part here and the
line that fills it.

Every part is a frozen dataclass of typed fields (:class:`Part`): ``from_dict`` checks
every field's type (:mod:`creative_py.records.checking`, the one checker of
the trial record too) and names the field (``create.created_tools[0].print.filament_g``)
in its error, :meth:`RunSummary.read` the file too. The JSON keeps the keys of every
``summary.json`` written so far:

- a part read from a file is written back with the keys it had, in their order, and
  the keys this module does not know (written by a later version) kept in ``extra``;
- a part the learner builds is written with every field in its order, except a field
  marked ``omit`` while it is None (``create`` of a run of phase ``use``).

Every field has a default, so a summary of an older run (without ``pose_units`` or
``use.stop``) reads as what it has. With a ``warn`` callback, :meth:`Part.from_dict`
drops a field or list item of the wrong type and says so instead of raising (the
reports show what they can of a damaged file).
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import Any, ClassVar, Optional, Sequence, Union

from creative_py.records.checking import Checked, Warn
from creative_py.records.checking import Dropped as _Dropped
from creative_py.records.checking import hints as _hints
from creative_py.records.checking import typed as _typed
from creative_py.records.checking import wrong as _wrong
from creative_py.records.folder import write_atomic
from creative_py.records.trial import PHASES, TrialRecord, as_record, jsonable

SUMMARY_NAME = "summary.json"
"""The summary's file name in the run folder."""


def _omit() -> Any:
    """A field left out of the JSON while it is None."""
    return field(default=None, metadata={"omit": True})


@dataclass(frozen=True, kw_only=True)
class Part(Checked):
    """A typed part of ``summary.json``: the base of every part (see the module)."""

    extra: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)
    """Keys of the JSON object this version does not know, kept as they were."""
    keys: Optional[tuple[str, ...]] = field(default=None, compare=False, repr=False)
    """The keys of the JSON object it was read from, in their order (None: built)."""

    _BASE: ClassVar[frozenset[str]] = frozenset({"extra", "keys"})

    # ------------------------------------------------------------------ reading
    @classmethod
    def from_dict(cls, data: Any, where: str = "", warn: Warn = None) -> Any:
        """Return the part of a JSON object, every field checked.

        ``where`` is the part's dotted place in the file (for the errors). Raises
        ValueError naming the field (``field 'use.trials': 'x' is not of type int``)
        unless ``warn`` is given: then the field is left at its default and ``warn``
        receives the same sentence.
        """
        if not isinstance(data, dict):
            raise _wrong(where, data, cls)
        hints = _hints(cls)
        values: dict[str, Any] = {}
        for f in fields(cls):
            if f.name in Part._BASE:
                continue
            name = f"{where}.{f.name}" if where else f.name
            required = f.metadata.get("required", False)
            try:
                if f.name not in data:
                    if required:
                        raise ValueError(f"field {name!r} is missing")
                    continue
                values[f.name] = _typed(data[f.name], hints[f.name], name, warn)
            except _Dropped:
                if required:
                    raise
            except ValueError as exc:
                if warn is None:
                    raise
                warn(f"{exc}; not shown")
                if required:  # the part is nothing without it
                    raise _Dropped() from None
        known = {f.name for f in fields(cls)} - Part._BASE
        extra = {k: v for k, v in data.items() if k not in known}
        return cls(**values, extra=extra, keys=tuple(str(k) for k in data))

    # ------------------------------------------------------------------ writing
    def to_dict(self) -> dict[str, Any]:
        """Return the part as its JSON object (see the module for which keys)."""
        out: dict[str, Any] = {}
        own = {f.name: f for f in fields(self) if f.name not in Part._BASE}
        if self.keys is not None:
            for key in self.keys:
                if key in own:
                    out[key] = _plain(getattr(self, key))
                elif key in self.extra:
                    out[key] = self.extra[key]
            for name, f in own.items():  # set after it was read
                if name not in out and getattr(self, name) != _default(f):
                    out[name] = _plain(getattr(self, name))
        else:
            for name, f in own.items():
                value = getattr(self, name)
                if value is None and f.metadata.get("omit"):
                    continue
                out[name] = _plain(value)
        out.update({k: v for k, v in self.extra.items() if k not in out})
        return out


def _default(f: Any) -> Any:
    from dataclasses import MISSING

    if f.default is not MISSING:
        return f.default
    if f.default_factory is not MISSING:
        return f.default_factory()
    return None


def _plain(value: Any) -> Any:
    if isinstance(value, Part):
        return value.to_dict()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


# ------------------------------------------------------------------------ the parts
@dataclass(frozen=True, kw_only=True)
class WallTimes(Part):
    """``wall_time_s``: wall time of each phase and of the run, in seconds."""

    use: Optional[float] = _omit()
    eval: Optional[float] = _omit()
    create: Optional[float] = _omit()
    video: Optional[float] = _omit()
    total: Optional[float] = _omit()

    def phases(self) -> list[tuple[str, Any]]:
        """Return ``(name, seconds)`` of every recorded time but the total, in order."""
        return [(k, v) for k, v in self.to_dict().items() if k != "total"]


@dataclass(frozen=True, kw_only=True)
class Demonstration(Part):
    """``demonstration``: the trainer's demonstration."""

    tool: Optional[str] = None


@dataclass(frozen=True, kw_only=True)
class PriorDrop(Part):
    """One literal of the prior and the trial that decided it (``use.prior.dropped``,
    ``settled``, ``confirmed``)."""

    literal: Optional[str] = None
    trial: Optional[int] = None
    """The tool-use trial: for ``dropped`` the one that succeeded though it violated
    the literal (0: the demonstration), for ``settled`` the success that satisfied it,
    for ``confirmed`` the one after which the physics made it necessary."""


@dataclass(frozen=True, kw_only=True)
class UsePrior(Part):
    """``use.prior``: the prior case's learned model the version space started from
    (``--prior``, :mod:`creative_py.learning.prior`)."""

    source: Optional[str] = None
    """The model file read."""
    case: Optional[str] = None
    taken: list[str] = field(default_factory=list)
    """The literals taken from the prior: open predictions at the start, trusted only
    as far as the trials confirm them."""
    dropped: list[PriorDrop] = field(default_factory=list)
    """Contradicted by the physics: not in h_g, learned afresh."""
    settled: list[PriorDrop] = field(default_factory=list)
    """Spatial literals a success satisfied: in h_g, untested (the stop is certified
    relative to them)."""
    confirmed: list[PriorDrop] = field(default_factory=list)
    """Literals the physics made necessary, as without a prior."""


@dataclass(frozen=True, kw_only=True)
class UsePhase(Part):
    """``use``: tool-use learning (Algorithm 1)."""

    trials: Optional[int] = None
    converged: Optional[bool] = None
    trials_to_converge: Optional[int] = None
    strategy: Optional[str] = None
    stop: Optional[str] = None
    """``confirmed``, ``certified``, ``exhausted`` or ``budget``."""
    prior: Optional[UsePrior] = _omit()
    """The prior of a transfer run (None: learned without one)."""


@dataclass(frozen=True, kw_only=True)
class Hypotheses(Part):
    """``hypotheses``: the version space's bounds after tool-use learning."""

    hs: Optional[str] = None
    hg: Optional[str] = None


@dataclass(frozen=True, kw_only=True)
class PddlCheck(Part):
    """One task of ``pddl``: the run's PDDL files solved by the PDDL planner and
    compared with Prolog's plan (:func:`creative_py.learning.pddl_check.check_files`)."""

    domain: Optional[str] = None
    problem: Optional[str] = None
    status: Optional[str] = None
    plan: Optional[list[str]] = None
    equals_prolog: Optional[bool] = None
    planner: Optional[str] = None
    prolog_plan: Optional[list[str]] = _omit()
    prolog_plan_valid: Optional[bool] = _omit()
    variant: Optional[str] = None
    prolog: Optional[str] = _omit()
    error: Optional[str] = _omit()


@dataclass(frozen=True, kw_only=True)
class PddlChecks(Part):
    """``pddl``: the learned task's check (``use``) and the harder task's (``create``)."""

    use: Optional[PddlCheck] = None
    create: Optional[PddlCheck] = _omit()

    def tasks(self) -> list[tuple[str, PddlCheck]]:
        """Return ``(task, check)`` of each recorded task, in order."""
        return [(k, getattr(self, k)) for k in self.to_dict() if k in ("use", "create")
                and getattr(self, k) is not None]


@dataclass(frozen=True, kw_only=True)
class Outcomes(Part):
    """Trials, successes and each outcome: ``eval`` and each phase of ``trials``."""

    trials: Optional[int] = None
    successes: Optional[int] = None
    outcomes: list[str] = field(default_factory=list)

    @classmethod
    def from_dict(cls, data: Any, where: str = "", warn: Warn = None) -> "Outcomes":
        """Return the counts of a JSON object, checked as :meth:`Part.from_dict` does
        and against each other: no count below 0, no more successes than trials, no more
        outcomes listed than trials, and, where the outcomes are listed, as many
        successes as ``success`` among them (an edited file said "9 of 4 trials succeeded");
        counts that contradict each other raise ValueError naming the part."""
        part = super().from_dict(data, where, warn)
        trials, successes, outcomes = part.trials, part.successes, part.outcomes
        what = f"field {where!r}: " if where else ""
        wrong = None
        if trials is not None and trials < 0:
            wrong = f"{trials} trials"
        elif successes is not None and successes < 0:
            wrong = f"{successes} successes"
        elif trials is not None and successes is not None and successes > trials:
            wrong = f"{successes} successes of {trials} trials"
        elif trials is not None and trials < len(outcomes):
            wrong = f"{trials} trials but {len(outcomes)} outcomes"
        elif (outcomes and successes is not None
              and successes != sum(o == "success" for o in outcomes)):
            wrong = (f"{successes} successes but {sum(o == 'success' for o in outcomes)} "
                     "success outcomes")
        if wrong is not None:
            raise ValueError(f"{what}{wrong}: the counts contradict each other")
        return part

    @classmethod
    def of(cls, outcomes: Sequence[str], trials: Optional[int] = None) -> "Outcomes":
        """Return the counts of ``outcomes`` (``trials`` of them unless given)."""
        return cls(trials=len(outcomes) if trials is None else trials,
                   successes=sum(o == "success" for o in outcomes), outcomes=list(outcomes))


@dataclass(frozen=True, kw_only=True)
class TrialCounts(Part):
    """``trials``: the run's trials per phase."""

    use: Optional[Outcomes] = None
    create: Optional[Outcomes] = None
    eval: Optional[Outcomes] = None

    @classmethod
    def of(cls, trials: Sequence[Union[TrialRecord, dict[str, Any]]]) -> "TrialCounts":
        """Return the counts of trials and successes per phase of the run's records."""
        records = [as_record(t) for t in trials]
        return cls(**{p: Outcomes.of([t.outcome for t in records if t.phase == p])
                      for p in PHASES})


@dataclass(frozen=True, kw_only=True)
class Prediction(Part):
    """What the pose model said of a tool in the harder task (``create.predicted``, a
    catalogue entry's ``predicted``): ``feasible`` False (unreachable, no trial run),
    True (reachable) or None (the geometry cannot tell), and why."""

    tool: Optional[str] = None
    variant: Optional[str] = None
    location: Optional[int] = None
    feasible: Optional[bool] = None
    conflict: Optional[list[str]] = _omit()
    pose: Optional[str] = _omit()
    why: Optional[str] = None


@dataclass(frozen=True, kw_only=True)
class CatalogueEntry(Part):
    """A catalogued object tried (or skipped) before a tool is made
    (``create.catalogue``)."""

    tool: Optional[str] = None
    value: Optional[str] = None
    why: Optional[str] = None
    predicted: Optional[Prediction] = None
    trial: Optional[int] = None
    outcome: Optional[str] = None
    reason: Optional[str] = _omit()


@dataclass(frozen=True, kw_only=True)
class PrintPiece(Part):
    """One printed piece of a created tool."""

    name: Optional[str] = _omit()
    role: Optional[str] = _omit()
    stl: Optional[str] = _omit()
    gcode: Optional[str] = _omit()
    bounding_box_mm: Optional[list[float]] = _omit()
    volume_mm3: Optional[float] = _omit()
    print_time_s: Optional[float] = _omit()
    print_time: Optional[str] = _omit()
    filament_mm: Optional[float] = _omit()
    filament_g: Optional[float] = _omit()
    slice_wall_time_s: Optional[float] = _omit()


PIECE_KEYS: tuple[str, ...] = tuple(f.name for f in fields(PrintPiece)
                                    if f.name not in Part._BASE)
"""The figures of a printed piece a summary keeps."""


@dataclass(frozen=True, kw_only=True)
class PrintSummary(Part):
    """A created tool's ``print``: the figures of its tool manifest's ``"print"`` entry
    a summary shows (:meth:`of_manifest`)."""

    pieces: list[PrintPiece] = field(default_factory=list)
    joint: Optional[str] = _omit()
    clearance_mm: Optional[float] = _omit()
    build_volume_mm: Optional[list[float]] = _omit()
    union_volume_error_pct: Optional[float] = _omit()
    union_mismatch_pct: Optional[float] = _omit()
    print_time_s: Optional[float] = _omit()
    filament_mm: Optional[float] = _omit()
    filament_g: Optional[float] = _omit()
    sliced: Optional[bool] = _omit()
    wall_time_s: Optional[float] = _omit()

    @classmethod
    def of_manifest(cls, entry: dict[str, Any]) -> "PrintSummary":
        """Return the summary's figures of a tool manifest's ``"print"`` entry
        (:func:`print_summary`), checked."""
        return cls.from_dict(print_summary(entry), "print")


PRINT_KEYS: tuple[str, ...] = tuple(f.name for f in fields(PrintSummary)
                                    if f.name not in Part._BASE and f.name != "pieces")
"""The totals of a tool's print a summary keeps."""


def print_summary(entry: dict[str, Any]) -> dict[str, Any]:
    """Return the figures of a tool manifest's ``"print"`` entry that a run's summary
    shows (:class:`PrintSummary`): the joint, the union's volume check, per piece its
    files, bounding box (mm), volume (mm^3), print time (s) and filament (mm, g), and
    the totals; a figure the entry lacks is left out."""
    return {
        "pieces": [{k: p[k] for k in PIECE_KEYS if k in p} for p in entry.get("pieces", [])],
        **{k: entry[k] for k in PRINT_KEYS if k in entry},
    }


@dataclass(frozen=True, kw_only=True)
class StrengthSummary(Part):
    """A created tool's ``strength``: the strength check of its successful trial
    (:meth:`creative_py.fabrication.strength.StrengthCheck.to_dict`)."""

    model: Optional[str] = None
    force_n: Optional[float] = None
    lever_arm_m: Optional[float] = None
    section_m: Optional[list[Optional[float]]] = None
    area_m2: Optional[float] = None
    second_moment_m4: Optional[float] = None
    section_modulus_m3: Optional[float] = None
    moment_nm: Optional[float] = None
    stress_mpa: Optional[float] = None
    strength_mpa: Optional[float] = None
    safety_factor: Optional[float] = None
    required_safety_factor: Optional[float] = None
    verdict: Optional[str] = None
    contact_point_m: Optional[list[float]] = None
    grasp_point_m: Optional[list[float]] = None
    bodies: Optional[list[str]] = None
    trial: Optional[int] = None
    required_handle_width_m: Optional[float] = None
    thickened_from: Optional[str] = None
    thickened_into: Optional[str] = None
    note: Optional[str] = None
    reason: Optional[str] = None
    peak_force_n: Optional[float] = None
    peak_safety_factor: Optional[float] = None
    caveat: Optional[str] = None


@dataclass(frozen=True, kw_only=True)
class CreatedToolSummary(Part):
    """A tool the robot designed, sized and manufactured (``create.created_tools``)."""

    name: Optional[str] = None
    replaced: Optional[str] = None
    general: Optional[str] = None
    instance: Optional[str] = None
    structural: list[str] = field(default_factory=list)
    dims: Optional[dict[str, Any]] = None
    files: Optional[dict[str, Any]] = None
    """Its files by kind (``urdf``, ``stl``, ...), relative to the run folder."""
    trial_outcome: Optional[str] = None
    """``no_pose`` when it was not tried (``reason`` says why)."""
    eval_outcomes: list[str] = field(default_factory=list)
    mass_kg: Optional[float] = None
    print: Optional[PrintSummary] = None
    strength: Optional[StrengthSummary] = None
    reason: Optional[str] = _omit()
    """Why it was not tried, in words (absent when it was)."""


@dataclass(frozen=True, kw_only=True)
class CreateSummary(Part):
    """``create``: tool creation (Algorithm 2) on the harder variant."""

    variant: Optional[str] = None
    needed: Optional[bool] = None
    predicted: Optional[Prediction] = None
    predicted_failure_skipped: Optional[bool] = None
    """The learned model's best tool was not tried: the geometry predicted its failure."""
    trials: Optional[int] = None
    failed_trials: Optional[int] = None
    created_tools: list[CreatedToolSummary] = field(default_factory=list)
    slice_wall_time_s: Optional[float] = None
    print_wall_time_s: Optional[float] = None
    success: Optional[str] = None
    """The created tool that solved the harder task."""
    eval: list[str] = field(default_factory=list)
    """The outcomes of that tool's evaluation."""
    exhausted: Optional[str] = None
    """Why no literal was left to generalise, as Prolog text (``Instance-Reason``)."""
    exhausted_words: Optional[str] = _omit()
    """The same in words, lengths in millimetres (absent from older summaries)."""
    solved_by: Optional[str] = None
    """``learned`` (TC trial 1), ``catalogue``, ``created`` or None."""
    catalogue: list[CatalogueEntry] = field(default_factory=list)
    catalogue_trials: Optional[int] = None
    catalogue_success: Optional[str] = None
    model: Optional[list[str]] = _omit()
    """The harder task's action models, when a tool solved it."""

    @property
    def catalogue_recorded(self) -> bool:
        """Whether the summary records the catalogued objects tried (an older one, from
        before they were tried first, does not)."""
        return self.keys is None or "catalogue" in self.keys

    @property
    def solver(self) -> Optional[str]:
        """The tool that solved the harder task as ``solved_by`` says (the catalogued
        object or the created tool), or None."""
        return {"catalogue": self.catalogue_success,
                "created": self.success}.get(self.solved_by or "")


@dataclass(frozen=True, kw_only=True)
class VideoEntry(Part):
    """A saved video clip (``videos``; :mod:`creative_py.learning.clips`)."""

    file: str = field(default="", metadata={"required": True})
    """The MP4's path relative to the run folder."""
    phase: Optional[str] = None
    trial: Optional[int] = None
    tool: Optional[str] = None
    tested: Optional[list[str]] = None
    outcome: Optional[str] = None
    reason: Optional[str] = None
    verdict: Optional[str] = None
    why: Optional[str] = None
    """Why it was kept (``demonstration``, ``first_success``, ``failure:<outcome>: ...``)."""
    frames: Optional[int] = None
    duration_s: Optional[float] = None
    bytes: Optional[int] = None


@dataclass(frozen=True, kw_only=True)
class Resumed(Part):
    """``resumed``: the run was interrupted and went on with ``creative run --resume``
    (absent from the summary of a run that never was)."""

    replayed: Optional[int] = None
    """Trials of the interrupted run replayed (not run again) by the resume."""
    earlier_wall_time_s: Optional[float] = None
    """Wall time of the interrupted run, from its folder's start (``run.json``) to its
    last recorded trial (the time it went on after that trial is not known); None when
    unknown."""
    total_wall_time_s: Optional[float] = None
    """``earlier_wall_time_s`` plus this session's ``wall_time_s.total``."""
    lost_trial: Optional[dict[str, Any]] = None
    """The trial that did not go as planned because the backend was lost during it (from
    the interrupted run's ``stopped.json``: its number, phase, tool, variant, location,
    pose, the skill it was in, the reason); the resume ran it again. None: the run was
    not stopped by a lost backend, or not during a trial."""


@dataclass(frozen=True, kw_only=True)
class RunSummary(Part):
    """``summary.json``: what a run did, in figures.

    Every field is None (or empty) when the file lacks it: a run still going has no
    summary (:meth:`read` of a missing file is refused; the reports use ``RunSummary()``),
    an older one lacks the figures added since.
    """

    case: Optional[str] = None
    seed: Optional[int] = None
    phase: Optional[str] = None
    options: dict[str, Any] = field(default_factory=dict)
    """The run's options (``creative_py.learning.options.RunOptions``) by name."""
    robot_name: Optional[str] = _omit()
    """The robot profile's own name where the options give its ``.toml`` path (they keep
    the path: a resume loads it again); left out otherwise."""
    wall_time_s: Optional[WallTimes] = None
    world_seed: Optional[int] = None
    drawn_world: Optional[dict[str, Any]] = None
    pose_units: dict[str, str] = field(default_factory=dict)
    """The unit of each pose number (``m``, ``rad``) by name."""
    trial_budget: Optional[int] = None
    """N of Algorithm 1 as the run used it."""
    paper_trials: Optional[int] = None
    """The paper's count of tool-use trials of the case (None: not in the paper)."""
    demonstration: Optional[Demonstration] = None
    use: Optional[UsePhase] = None
    vs_count_initial: Optional[int] = None
    vs_count_initial_exact: Optional[bool] = None
    info_bound_trials: Optional[int] = None
    """ceil(log2 N0): the trials that tell the initial hypotheses apart in the worst case."""
    vs_count_final: Optional[int] = None
    hypotheses: Optional[Hypotheses] = None
    plan: Optional[str] = None
    pddl: Optional[PddlChecks] = None
    eval: Optional[Outcomes] = None
    create: Optional[CreateSummary] = _omit()
    trials: Optional[TrialCounts] = None
    videos: Optional[list[VideoEntry]] = None
    """The saved clips (None: a summary written before runs saved any)."""
    resumed: Optional[Resumed] = _omit()
    """How the run was resumed after an interruption (None: it was not)."""

    @property
    def strategy(self) -> Optional[str]:
        """The run's strategy (its options', else tool-use learning's)."""
        return self.options.get("strategy") or (self.use.strategy if self.use else None)

    @property
    def backend(self) -> Optional[str]:
        """The backend the run was driven through when its options chose one other than
        the case's (``--backend ros``), else None."""
        return self.options.get("backend")

    @property
    def robot(self) -> Optional[str]:
        """The robot profile the run's arm was built from (``--robot``, else the case's):
        its name, or as ``run.json`` recorded it where the run did not record the name
        of a profile given by path; None for a run recorded before robots were named
        or on a backend with its own arm."""
        return (self.robot_name or self.options.get("robot")
                or self.options.get("robot_profile"))

    @property
    def budget(self) -> Any:
        """N of Algorithm 1: ``trial_budget``, or for an older folder its
        ``--max-trials`` (None when neither was recorded)."""
        recorded = self.keys is None or "trial_budget" in self.keys
        return self.trial_budget if recorded else self.options.get("max_trials")

    def to_json(self) -> str:
        """Return the text of ``summary.json``."""
        return json.dumps(jsonable(self.to_dict()), indent=2) + "\n"

    def write(self, run_dir: Union[Path, str]) -> Path:
        """Write ``summary.json`` into a run folder atomically and return its path."""
        return write_atomic(Path(run_dir) / SUMMARY_NAME, self.to_json())

    @classmethod
    def read(cls, path: Union[Path, str], warn: Warn = None) -> "RunSummary":
        """Return the summary of a ``summary.json`` file (or of a run folder's), checked.

        Raises
        ------
        ValueError
            One line naming the file and the field: not JSON, not an object, a value
            of the wrong type (with ``warn``, only the first two).
        OSError
            When the file cannot be read.
        """
        path = Path(path)
        if path.is_dir():
            path = path / SUMMARY_NAME
        try:
            data = json.loads(path.read_text(encoding="utf-8"))
        except json.JSONDecodeError as exc:
            raise ValueError(f"{path}: not JSON ({exc.msg}, line {exc.lineno})") from None
        if not isinstance(data, dict):
            raise ValueError(f"{path}: not a JSON object, but {type(data).__name__}")
        try:
            return cls.from_dict(data, warn=None if warn is None
                                 else (lambda m: warn(f"{path}: {m}")))
        except ValueError as exc:
            raise ValueError(f"{path}: {exc}") from None


def as_summary(summary: "RunSummary | dict[str, Any]", warn: Warn = None) -> RunSummary:
    """Return ``summary`` as a :class:`RunSummary` (a dict is read as ``summary.json``,
    with ``warn`` as :meth:`Part.from_dict` takes it)."""
    if isinstance(summary, RunSummary):
        return summary
    return RunSummary.from_dict(summary, warn=warn)


__all__ = ["CatalogueEntry", "CreateSummary", "CreatedToolSummary", "Demonstration",
           "Hypotheses", "Outcomes", "PIECE_KEYS", "PRINT_KEYS", "Part", "PddlCheck", "PddlChecks",
           "Prediction", "PrintPiece", "PrintSummary", "Resumed", "RunSummary", "SUMMARY_NAME",
           "StrengthSummary", "TrialCounts", "UsePhase", "VideoEntry", "WallTimes",
           "as_summary", "print_summary"]
