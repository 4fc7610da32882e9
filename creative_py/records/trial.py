"""One trial as a run records it: :class:`TrialRecord`, one line of ``trials.jsonl``.

The record is the single owner of that line's format; its fields are checked by the
records' one type checker (:mod:`creative_py.records.checking`). The learning loop fills it
(:class:`creative_py.learning.trials.TrialRunner`), :meth:`TrialRecord.to_json` writes
it, :meth:`TrialRecord.from_json` reads and checks it (resume, the reports, validated
replay), and the reports take their trial columns from its fields
(:func:`trial_columns`). A new field is one typed line here (with a ``column`` in its
metadata when the reports should show it) and the line that fills it; nothing else
changes. A field the physics measures is marked :func:`measured`: the trial loop gives
it by name (``TrialResult.measures``), and it reaches the file, and comes back on a
replay, with no line of the learning loop.

The JSON keeps the keys and meaning of every ``trials.jsonl`` written so far: the
fields in their order, an optional field (default None) left out while None, and the
keys this module does not know (written by a later version) kept in
:attr:`TrialRecord.extra` and written back after the known ones.
"""

from __future__ import annotations

import json
import math
import re
import typing
from dataclasses import dataclass, field, fields
from typing import Any, Callable, Sequence, Union

from creative_py.records.checking import hints, typed

TRIAL_OUTCOMES: tuple[str, ...] = ("success", "failure", "blocked", "unreachable", "invalid")
"""Outcomes of a trial: ``success`` / ``failure`` (the goal was or was not reached),
``blocked`` (a motion before the tool action was stopped by a collision, the robot
itself struck a scene body and the goal was not reached, or the trial's step or time
budget ran out before the goal was reached), ``unreachable`` (no
arm posture reaches a waypoint), ``invalid`` (the physics blew up)."""

PHASES: tuple[str, ...] = ("use", "create", "eval")
"""Phases of a run: tool-use learning, tool creation, evaluation."""

REQUIRED_KEYS: tuple[str, ...] = ("trial", "phase", "variant", "location", "tool", "outcome")
"""The keys every line of ``trials.jsonl`` has; the others have defaults."""


def _column(header: str) -> dict[str, str]:
    return {"column": header}


def measured(**metadata: Any) -> dict[str, Any]:
    """Return the metadata of a field the physics measures (with ``column`` and the
    rest of ``metadata``): the trial loop gives its value by the field's name
    (:attr:`creative_py.simulator.types.TrialResult.measures`), the learning loop records
    it as it is, and a replayed trial gives it back from its record
    (:func:`measured_fields`). Such a field is one typed line here, ``= field(default=None,
    metadata=measured())``, plus the code that measures it; nothing between changes."""
    return {"measured": True, **metadata}


@dataclass(kw_only=True)
class TrialRecord:
    """One executed trial, as written to ``trials.jsonl``.

    Attributes
    ----------
    trial : int
        Number of the trial in the run (1-based).
    phase : str
        One of :data:`PHASES`.
    phase_trial : int
        Number of the trial within its phase.
    variant, location, tool : str, int, str
        The task variant, the target location (1-based) and the tool tried.
    kind : str
        What the planner asked for: ``experiment`` (a tested literal) or ``exploit``.
    tested, violated : list of str
        The literal the trial tests, and the literals of h_g the tool or pose violates.
    pose : dict
        The pose numbers by name (``{"pose": text}`` for a pose term of another shape).
    outcome : str
        One of :data:`TRIAL_OUTCOMES`, given by the physics alone.
    reason : str
        Why, in words.
    hs, hg : str
        The version space's bounds after the trial.
    wall_time_s, sim_time_s, decision_time_s : float
        Wall time of the physics, simulated time, and the learner's decision time.
    vs_count, vs_count_exact : int or None, bool or None
        The hypotheses left between h_g and h_s after a labelled trial (None when the
        trial taught nothing: evaluation, created tools).
    facts : list of list
        What the robot observed before the tool action (or where a blocked motion
        stopped); a resumed run labels the trial with these again.
    max_tool_force_n : float or None
        The largest contact force on the tool while it acted (None when it did not act).
    tool_load : dict or None
        Where and how that force acted (``ToolLoad.to_dict``; the strength check reads it).
    verdict : dict or None
        What the physics measured against its thresholds
        (:func:`creative_py.backends.pybullet.episode.verdict_data`): ``quantity``, ``value``,
        ``threshold``, ``unit``, ``relation`` (passing needs ``value relation
        threshold``), ``holds``, ``threshold_name``, ``measures`` (the other measures by
        name), ``text`` (all of it in words) and ``asked`` (whether the outcome rests on
        it); for a motion a guard stopped, ``stop`` (the guard's verdict of the same
        shape, ``measures["touching"]`` naming what the arm and the tool touched). The
        reports show its text in the reason cell. None for a trial recorded without it.
    extra : dict
        Keys of the line this version does not know, kept as they were.
    """

    trial: int = field(metadata=_column("#"))
    phase: str = field(metadata=_column("phase"))
    phase_trial: int = 0
    """The trial's count within its phase (not shown: the reports number trials by
    ``trial`` alone, one number everywhere)."""
    variant: str = field(metadata=_column("variant"))
    location: int = field(metadata=_column("loc"))
    tool: str = field(metadata=_column("tool"))
    kind: str = ""
    tested: list[str] = field(default_factory=list, metadata=_column("tested"))
    violated: list[str] = field(default_factory=list, metadata=_column("violated"))
    pose: dict[str, Union[float, str]] = field(default_factory=dict,
                                               metadata=_column("pose"))
    outcome: str = field(metadata=_column("outcome"))
    reason: str = field(default="", metadata={"column": "reason",
                                              "cell": lambda r: reason_text(r)})
    hs: str = ""
    hg: str = ""
    wall_time_s: float = 0.0
    sim_time_s: float = 0.0
    decision_time_s: float = 0.0
    vs_count: Union[int, None] = None
    vs_count_exact: Union[bool, None] = None
    facts: list[list[Any]] = field(default_factory=list)
    max_tool_force_n: Union[float, None] = None
    tool_load: Union[dict[str, Any], None] = None
    verdict: Union[dict[str, Any], None] = None
    extra: dict[str, Any] = field(default_factory=dict, compare=False)

    # The column order of the reports: # phase tool variant loc pose tested violated
    # outcome reason (a field's own order otherwise).
    COLUMN_ORDER: typing.ClassVar[tuple[str, ...]] = (
        "trial", "phase", "tool", "variant", "location", "pose", "tested",
        "violated", "outcome", "reason")

    def __post_init__(self) -> None:
        _validate(self)

    # ----------------------------------------------------------------- JSON
    def to_dict(self) -> dict[str, Any]:
        """Return the record as the JSON object of its ``trials.jsonl`` line."""
        out: dict[str, Any] = {}
        for f in fields(self):
            if f.name == "extra":
                continue
            value = getattr(self, f.name)
            if value is None and f.default is None:
                continue  # an optional field is written only when it has a value
            out[f.name] = value
        out.update({k: v for k, v in self.extra.items() if k not in out})
        return jsonable(out)

    def to_json(self) -> str:
        """Return the record as one line of ``trials.jsonl`` (no newline)."""
        return json.dumps(self.to_dict())

    @classmethod
    def from_dict(cls, data: Any) -> "TrialRecord":
        """Return the record of a ``trials.jsonl`` object, checked.

        Raises
        ------
        ValueError
            Naming the field: a required key is missing, a value has the wrong type,
            or the outcome or phase is not one of :data:`TRIAL_OUTCOMES` /
            :data:`PHASES`.
        """
        if not isinstance(data, dict):
            raise ValueError(f"a trial record is a JSON object, not {type(data).__name__}")
        missing = [k for k in REQUIRED_KEYS if k not in data]
        if missing:
            raise ValueError(f"lacks {', '.join(missing)} (field {missing[0]!r} is required)")
        known = {f.name for f in fields(cls)} - {"extra"}
        field_types = hints(cls)
        values = {}
        for name in known & data.keys():
            values[name] = typed(data[name], field_types[name], name)
        extra = {k: v for k, v in data.items() if k not in known}
        return cls(**values, extra=extra)

    @classmethod
    def from_json(cls, line: str) -> "TrialRecord":
        """Return the record of one ``trials.jsonl`` line, checked (see
        :meth:`from_dict`); a line that is not JSON raises ValueError too."""
        try:
            data = json.loads(line)
        except json.JSONDecodeError as exc:
            raise ValueError(f"not a JSON object ({exc.msg})") from None
        return cls.from_dict(data)

    def get(self, key: str, default: Any = None) -> Any:
        """Return a field or an unknown key of the line by name (``default`` if none)."""
        if key in _field_names(type(self)):
            return getattr(self, key)
        return self.extra.get(key, default)


def measured_fields(record_type: type = TrialRecord) -> tuple[str, ...]:
    """Return the fields of ``record_type`` that the physics measures and the trial
    loop gives by name (their metadata is :func:`measured`'s)."""
    return tuple(f.name for f in fields(record_type) if f.metadata.get("measured"))


def as_record(trial: "TrialRecord | dict[str, Any]") -> TrialRecord:
    """Return ``trial`` as a record (a dict is read as a line of ``trials.jsonl``)."""
    return trial if isinstance(trial, TrialRecord) else TrialRecord.from_dict(trial)


def trial_columns(record_type: type = TrialRecord
                  ) -> list[tuple[str, Callable[[TrialRecord], str]]]:
    """Return the reports' trial columns, ``(header, cell text of a record)``: every
    field of ``record_type`` with a ``column`` in its metadata, in the order of
    ``COLUMN_ORDER`` and then of the fields."""
    shown = [f for f in fields(record_type) if "column" in f.metadata]
    order = {n: i for i, n in enumerate(record_type.COLUMN_ORDER)}
    shown.sort(key=lambda f: order.get(f.name, len(order)))
    return [(f.metadata["column"], f.metadata.get("cell") or _cell(f.name)) for f in shown]


def _cell(name: str) -> Callable[[TrialRecord], str]:
    return lambda record: cell_text(getattr(record, name))


def verdict_words(verdict: Any) -> str:
    """Return a trial's measured verdict (the ``verdict`` field) in words, for people:
    the guard's measure of a stopped motion first, then the oracle's (empty for none),
    each as :func:`measure_words` writes it."""
    if not isinstance(verdict, dict):
        return ""
    parts = []
    stop = verdict.get("stop")
    if isinstance(stop, dict) and stop.get("text"):
        parts.append(f"stopped: {measure_words(stop)}")
    struck = verdict.get("struck")
    if isinstance(struck, dict) and struck.get("text"):
        parts.append(f"struck: {measure_words(struck)}")
    if verdict.get("text"):
        parts.append(measure_words(verdict))
    return " | ".join(parts)


def measure_words(measure: dict[str, Any]) -> str:
    """Return one measured verdict (a :class:`~creative_py.simulator.types.Verdict`'s
    ``to_dict()``) in words, one unit per quantity: lengths in millimetres and angles in
    degrees (the pose column's units), the limit's source as words (``tube1.mouth_x``
    is ``tube1's mouth x``), then the other measures, their lengths in millimetres too.
    A verdict without its numbers (an older record) is its text, lengths in mm."""
    text = str(measure.get("text") or "")
    quantity, value = measure.get("quantity"), measure.get("value")
    threshold, unit = measure.get("threshold"), measure.get("unit")
    if not isinstance(quantity, str) or not isinstance(unit, str) or "(needs " not in text:
        return lengths_in_mm(text)
    head = f"{quantity} {_amount(value, unit)}"
    relation = measure.get("relation")
    if isinstance(relation, str) and relation:
        source = limit_words(measure.get("threshold_name"))
        head += (f" (needs {relation} {_amount(threshold, unit)}"
                 + (f"; the limit: {source}" if source else "") + ")")
    _, sep, detail = text.partition("); ")
    return head + (f"; {lengths_in_mm(detail)}" if sep and detail else "")


def _amount(value: Any, unit: str) -> str:
    """A measured number with its unit: metres as millimetres, radians as degrees."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return "unmeasured"
    if unit == "m":
        return f"{value * 1000:.1f} mm"
    if unit == "rad":
        return f"{math.degrees(value):.1f} deg"
    return f"{value:.4g} {unit}".rstrip()


_LIMIT_NAME = re.compile(r"\b([A-Za-z]\w*)\.([A-Za-z_]\w*)")
_UNIT_WORD = re.compile(r"_(m|mm|rad|deg|s|n)\b")


def limit_words(name: Any) -> str:
    """Return where a limit comes from in words: a scene expression ``tube1.mouth_x -
    0.05`` as ``tube1's mouth x - 0.05``, an option's key ``max_tracking_error`` as
    ``max tracking error``, its unit suffix (``grasp_slip_max_rad``) left out (the
    number beside it has its unit); ``""`` for none."""
    if not isinstance(name, str) or not name.strip():
        return ""
    text = _LIMIT_NAME.sub(r"\1's \2", name.strip())
    return _UNIT_WORD.sub("", text).replace("_", " ")


_LENGTH = re.compile(r"(?<![\w.])(-?\d+(?:\.(\d+))?) (m|cm)\b")
_POINT = re.compile(r"\((-?\d+(?:\.\d+)?(?:, -?\d+(?:\.\d+)?)+)\) m\b")


def lengths_in_mm(text: str) -> str:
    """Return ``text`` with every length written in metres or centimetres (``1.1 cm``,
    ``0.8500 m``, a point ``(0.978, -0.250, -0.052) m``) in millimetres, to the same
    precision (``11 mm``, ``850.0 mm``, ``(978, -250, -52) mm``): one unit for every
    length in a report cell."""
    def mm(number: str, unit: str) -> str:
        decimals = len(number.partition(".")[2])
        scale, shift = (1000, 3) if unit == "m" else (10, 1)
        return f"{float(number) * scale:.{max(0, decimals - shift)}f}"

    text = _POINT.sub(lambda m: "(" + ", ".join(mm(x, "m") for x in m.group(1).split(", "))
                      + ") mm", text)
    return _LENGTH.sub(lambda m: f"{mm(m.group(1), m.group(3))} mm", text)


def more_strikes(strikes: Sequence[Any]) -> str:
    """Return how many link-body strikes there were besides the strongest one
    (``strikes[0]``, the words said after it) as `` (3 more link-body contacts)``;
    ``""`` for none. The one writer of these words: a strike's verdict (the pybullet
    episode's detail) and its line (:func:`struck_line`) both say it so."""
    more = len(strikes) - 1
    return f" ({more} more link-body contact{'s' * (more > 1)})" if more > 0 else ""


def struck_line(struck: dict) -> str:
    """Return a robot's strike on the scene (a verdict's ``struck``) as one short line:
    the strongest link-body strike with its force, and how many more there were."""
    strikes = (struck.get("measures") or {}).get("struck") or []
    if not strikes:
        return f"struck: {_with_unit(struck.get('brief'), struck.get('unit'))}"
    top = strikes[0]
    return (f"struck: {top['link']} against {top['body']} with {top['force_n']:.0f} N"
            + more_strikes(strikes))


def verdict_lines(verdict: Any) -> list[str]:
    """Return a trial's measured verdict as short lines (a clip's caption, the
    terminal): the guard's measure and what was touching when it stopped a motion,
    the robot's strongest strike on the scene (:func:`struck_line`), then the oracle's
    measure and the one beside it (empty for none)."""
    if not isinstance(verdict, dict):
        return []
    lines = []
    stop = verdict.get("stop")
    if isinstance(stop, dict):
        brief = _with_unit(stop.get("brief"), stop.get("unit"))
        lines.append(f"stopped: {brief or stop.get('text', '')}")
        touching = (stop.get("measures") or {}).get("touching")
        if touching:
            lines.append(f"touching {', '.join(touching)}")
    struck = verdict.get("struck")
    if isinstance(struck, dict):
        lines.append(struck_line(struck))
    if verdict.get("brief") or verdict.get("text"):
        lines.append(_with_unit(verdict.get("brief"), verdict.get("unit"))
                     or str(verdict["text"]))
    if verdict.get("note"):
        lines.append(_with_unit(str(verdict["note"]), verdict.get("unit")))
    return lines


_BARE_LIMIT = re.compile(r"(needs (?:<|<=|>|>=) -?\d+(?:\.\d+)?)$")
"""A short line ending in a threshold without its unit (``..., needs < 0.8500``: the
simulator's ``brief`` and the oracles' notes leave it out)."""


def _with_unit(line: Any, unit: Any) -> str:
    """Return a verdict's short line with the unit after its final threshold (``needs <
    0.8500 m``), as the measure before it has it; other lines as they are."""
    if not line:
        return ""
    if not isinstance(unit, str) or not unit:
        return str(line)
    return _BARE_LIMIT.sub(rf"\1 {unit}", str(line))


def reason_text(record: TrialRecord) -> str:
    """Return the reason cell of the reports: the reason and, after it, the measured
    verdict (``reason -- measured``; ``-`` for neither)."""
    measured = verdict_words(record.verdict)
    reason = lengths_in_mm(record.reason) if record.reason else record.reason
    text = " -- ".join(t for t in (reason, measured) if t)
    return text or "-"


def cell_text(value: Any) -> str:
    """Return a field's value as the reports show it: numbers in at most six
    significant digits, mappings as ``name=value`` pairs, lists joined by commas,
    ``-`` for nothing."""
    if value is None or value in ("", [], {}):
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, dict):
        return ", ".join(f"{k}={cell_text(v)}" for k, v in value.items())
    if isinstance(value, list):
        return ", ".join(str(x) for x in value)
    return str(value)


# --------------------------------------------------------------------- checking
def _field_names(cls: type) -> set[str]:
    return {f.name for f in fields(cls)} - {"extra"}


def _validate(record: TrialRecord) -> None:
    field_types = hints(type(record))
    for f in fields(record):
        typed(getattr(record, f.name), field_types[f.name], f.name, convert=False)
    if record.outcome not in TRIAL_OUTCOMES:
        raise ValueError(f"field 'outcome': {record.outcome!r} is not one of "
                         f"{', '.join(TRIAL_OUTCOMES)}")
    if record.phase not in PHASES:
        raise ValueError(f"field 'phase': {record.phase!r} is not one of {', '.join(PHASES)}")


def jsonable(value: Any) -> Any:
    """Return ``value`` as plain JSON data (what every file of a run folder holds): tuples as lists, non-finite floats as
    strings, anything else that JSON has no type for as its text."""
    if isinstance(value, dict):
        return {str(k): jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, (str, int, float, bool)) or value is None:
        return value
    if hasattr(value, "item"):  # a numpy scalar
        return jsonable(value.item())
    return str(value)


__all__ = ["PHASES", "REQUIRED_KEYS", "TRIAL_OUTCOMES", "TrialRecord", "as_record", "cell_text",
           "lengths_in_mm", "limit_words", "measure_words", "measured", "measured_fields",
           "more_strikes", "reason_text", "trial_columns", "verdict_lines", "verdict_words"]
