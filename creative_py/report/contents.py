"""What a run folder holds, read once for the reports, without writing anything.

:func:`read_run` gathers the readable trials (``trials.jsonl``), ``summary.json``,
``model.pl``, the plot, the video clips and the created tools of a run folder into a
:class:`RunContents`. Every file name it keeps is relative to the run folder, in POSIX
form, so a page that links to them works wherever the folder is moved or unzipped; a
name that points outside the folder is dropped with a warning. The trial columns both
reports show come from the trial record's fields (:data:`TRIAL_COLUMNS`,
:func:`creative_py.records.trial.trial_columns`), so a new field with a ``column`` shows
in both without a change here.
"""

from __future__ import annotations

import json
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from creative_py.records.folder import read_records, running_pid
from creative_py.records.summary import (CreatedToolSummary, RunSummary, VideoEntry,
                                         as_summary)
from creative_py.records.trial import TrialRecord, trial_columns


@dataclass
class Clip:
    """One video clip of a run.

    Attributes
    ----------
    file : str
        Path of the MP4 relative to the run folder (POSIX form).
    exists : bool
        Whether the file is there.
    info : VideoEntry or None
        What ``summary.json`` says of it (``phase``, ``trial``, ``tool``, ``tested``,
        ``outcome``, ``why``); None for a clip found only in ``videos/``.
    """

    file: str
    exists: bool
    info: VideoEntry | None = None


@dataclass
class ToolEntry:
    """One created tool: what the summary says of it and its own folder.

    Attributes
    ----------
    name : str
        The tool's name.
    folder : str
        Its folder relative to the run folder (``tools/<name>``).
    created : CreatedToolSummary or None
        Its entry of ``summary.json``'s ``create.created_tools`` (None when only the
        folder is there, e.g. a run interrupted after manufacturing it).
    manifest : dict or None
        The tool's JSON (``tools/<name>/<name>.json``), None when missing or unreadable.
    picture : str or None
        Relative path of its render (``tools/<name>/<name>.png``) when the file exists.
    files : list of (str, str)
        ``(kind, relative path)`` of each of its files that exists (URDF, SDF, ...).
    """

    name: str
    folder: str
    created: CreatedToolSummary | None
    manifest: dict[str, Any] | None
    picture: str | None
    files: list[tuple[str, str]]


@dataclass
class RunContents:
    """Everything the reports show of one run folder.

    Attributes
    ----------
    path : Path
        The run folder.
    trials : list of TrialRecord
        The readable records of ``trials.jsonl``, in order.
    summary : RunSummary
        ``summary.json`` (empty, ``RunSummary()``, when missing, as in a run still
        going, or unreadable; a field of the wrong type is left empty with a warning).
        A dict is read as ``summary.json``.
    model_text : str or None
        The text of ``model.pl``.
    plot : str or None
        ``trials.png`` when it exists.
    clips : list of Clip
        The video clips, as ``summary.json``'s ``videos`` lists them, else every
        ``videos/*.mp4``.
    tools : list of ToolEntry
        The created tools, in the order of creation.
    pddl_files : list of str
        ``domain.pddl`` and ``problem.pddl`` when they exist.
    warnings : list of str
        One sentence per thing that could not be read.
    pose_units : dict
        The unit of each pose number (``m``, ``rad``) by name, from ``summary.json``
        (empty for a folder written before the run recorded them).
    budget : int or None
        N of Algorithm 1 as the run used it (``summary.json``'s ``trial_budget``; for an
        older folder its ``--max-trials``, else None).
    paper_trials : int or None
        The paper's count of tool-use trials for the case, from ``summary.json``.
    running : str
        The pid of the process still writing the folder (it holds the folder's lock:
        :func:`creative_py.records.folder.running_pid`), ``""`` when none does.
    case : str or None
        The case of the run, from ``run.json`` (what ``--resume`` needs).
    """

    path: Path
    trials: list[TrialRecord]
    summary: RunSummary
    model_text: str | None
    plot: str | None
    clips: list[Clip]
    tools: list[ToolEntry]
    pddl_files: list[str]
    warnings: list[str]
    pose_units: dict[str, str] = field(default_factory=dict)
    budget: int | None = None
    paper_trials: int | None = None
    running: str = ""
    case: str | None = None

    def __post_init__(self) -> None:
        # A summary given as a dict (built by hand) is read as the reports read a file:
        # a value of the wrong type is left out.
        self.summary = as_summary(self.summary, warn=lambda _why: None)

    @property
    def columns(self) -> list[tuple[str, Callable[[TrialRecord], str]]]:
        """Return the trial columns of this run's records: :data:`TRIAL_COLUMNS`, from the
        fields of their record type (:func:`~creative_py.records.trial.trial_columns`),
        with the pose in millimetres and degrees when the units are known."""
        columns = (trial_columns(type(self.trials[0]))
                   if self.trials and type(self.trials[0]) is not TrialRecord
                   else TRIAL_COLUMNS)
        units = self.pose_units
        return [(h, (lambda t: pose_text(t.get("pose"), units)) if h == "pose" else cell)
                for h, cell in columns]


def read_run(run_dir: Path | str) -> RunContents:
    """Read a run folder for the reports; write nothing.

    Parameters
    ----------
    run_dir : Path or str
        The run folder.

    Returns
    -------
    RunContents

    Raises
    ------
    FileNotFoundError
        When the folder has no ``trials.jsonl`` (not a run folder).
    """
    root = Path(run_dir)
    warnings: list[str] = []
    trials = read_records(root, warn=warnings.append)
    summary = _read_summary(root / "summary.json", warnings)
    model = root / "model.pl"
    model_text = model.read_text(encoding="utf-8", errors="replace") if model.is_file() else None
    units, budget, paper = _case_facts(summary)
    return RunContents(
        path=root, trials=trials, summary=summary, model_text=model_text,
        plot="trials.png" if (root / "trials.png").is_file() else None,
        clips=_clips(root, summary, warnings), tools=_tools(root, summary, warnings),
        pddl_files=[n for n in ("domain.pddl", "problem.pddl") if (root / n).is_file()],
        warnings=warnings, pose_units=units, budget=budget, paper_trials=paper,
        running="" if (root / "summary.json").is_file() else running_pid(root),
        case=_run_case(root))


def _run_case(root: Path) -> str | None:
    """The case ``run.json`` names (None without a readable one)."""
    try:
        case = json.loads((root / "run.json").read_text(encoding="utf-8")).get("case")
    except (OSError, ValueError, AttributeError):
        return None
    return case if isinstance(case, str) and case else None


def state_text(run: RunContents) -> str:
    """Return what a folder without ``summary.json`` is, in a sentence: a run still
    going (a process holds its lock) or one that was interrupted, with the command
    that resumes it (``""`` for a finished run)."""
    if (run.path / "summary.json").is_file():
        return ""
    n = len(run.trials)
    trials = f"{n} trial{'s' if n != 1 else ''}"
    if run.running:
        return (f"Still running (process {run.running}): {trials} recorded so far; the "
                "summary and the rest of the report come when it ends.")
    again = (f"; to go on: creative run {run.case} --resume {run.path}" if run.case
             else "")
    return (f"Interrupted after {trials} (no summary.json, and no process is running "
            f"it){again}.")


def _case_facts(summary: RunSummary) -> tuple[dict[str, str], int | None, int | None]:
    """The pose units, trial budget and paper's trial count of the run's case, as the run
    wrote them into ``summary.json`` (``pose_units``, ``trial_budget``, ``paper_trials``).

    A folder written before these fields has none of them: its poses are shown as the
    numbers they are, without units; its budget is the run's ``--max-trials`` when that
    was given, else unknown; the paper's count is not shown. The case's manifest is not
    read: the folder says everything the reports show.
    """
    budget, paper = summary.budget, summary.paper_trials
    return (dict(summary.pose_units), budget if _count(budget) else None,
            paper if _count(paper) else None)


def _count(value: Any) -> bool:
    """Whether a value read from a file is a positive whole number (not a bool)."""
    return isinstance(value, int) and not isinstance(value, bool) and value > 0


def pose_text(pose: Any, units: dict[str, str]) -> str:
    """Return a trial's pose with units: metres as millimetres, radians as degrees
    (``dx 37.5 mm, dy 0 mm, roll 0 deg``); a number of unknown unit as it is."""
    if not isinstance(pose, dict) or not pose:
        return "-" if not pose else str(pose)
    parts = []
    for name, value in pose.items():
        unit = units.get(name)
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if unit == "m":
                parts.append(f"{name} {value * 1000:.1f} mm".replace(".0 mm", " mm"))
            elif unit == "rad":
                parts.append(f"{name} {math.degrees(value):.1f} deg".replace(".0 deg", " deg"))
            else:
                parts.append(f"{name} {value:.6g}" + (f" {unit}" if unit else ""))
        else:
            parts.append(f"{name} {value}")
    return ", ".join(parts)


_PROLOG_VARIABLE = re.compile(r"(?<![\w'])_(?:G)?\d+\b")
_PAIR = re.compile(r"'-'\(([^(),]+),([^(),]+)\)")


def readable_term(text: str) -> str:
    """Return a Prolog term's text as a person reads it: the variables Prolog wrote as
    ``_G0``, ``_123`` named ``A``, ``B``, ... in order of appearance, and a pair
    ``'-'(X,tool)`` written ``X-tool``."""
    names: dict[str, str] = {}

    def name(match: re.Match) -> str:
        key = match.group(0)
        if key not in names:
            n = len(names)
            names[key] = chr(ord("A") + n % 26) + (str(n // 26) if n >= 26 else "")
        return names[key]

    return _PAIR.sub(r"\1-\2", _PROLOG_VARIABLE.sub(name, text))


_WHY = {"demonstration": "the demonstration", "creation": "a tool-creation trial",
        "first_success": "the first success", "trial": "every trial is kept"}


def why_text(why: Any) -> str:
    """Return why a clip was kept, in words (``summary.json`` keeps a key:
    ``failure:<outcome>: <reason>`` is the first trial that ended so)."""
    if not isinstance(why, str) or not why:
        return ""
    if why.startswith("failure:"):
        outcome = why.removeprefix("failure:").split(":", 1)[0]
        return f"the first {outcome} trial of its kind"
    return _WHY.get(why, why.replace("_", " "))


def relative_inside(root: Path, name: str) -> str | None:
    """Return ``name`` (relative to ``root``, or absolute) as a POSIX path relative to
    ``root``, or None when it points outside ``root``."""
    path = Path(name)
    full = (path if path.is_absolute() else root / path).resolve()
    try:
        return full.relative_to(root.resolve()).as_posix()
    except ValueError:
        return None


def _read_json(path: Path, warnings: list[str]) -> Any:
    if not path.is_file():
        return {}
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as exc:
        warnings.append(f"{path}: not JSON ({exc.msg}, line {exc.lineno}); not shown")
        return {}


def _read_summary(path: Path, warnings: list[str]) -> RunSummary:
    """The run's summary (empty when there is none or it is not a JSON object); a field
    of the wrong type is left empty, with a warning."""
    if not path.is_file():
        return RunSummary()
    try:
        return RunSummary.read(path, warn=warnings.append)
    except ValueError as exc:
        warnings.append(f"{exc}; no summary shown")
        return RunSummary()


def _clips(root: Path, summary: RunSummary, warnings: list[str]) -> list[Clip]:
    if summary.videos is None:
        return [Clip(p.relative_to(root).as_posix(), True)
                for p in sorted((root / "videos").glob("*.mp4"))]
    clips = []
    for entry in summary.videos:
        rel = relative_inside(root, entry.file)
        if rel is None:
            warnings.append(f"{root / 'summary.json'}: video {entry.file} is outside the "
                            f"run folder; not shown")
            continue
        clips.append(Clip(rel, (root / rel).is_file(), entry))
    return clips


def _tools(root: Path, summary: RunSummary, warnings: list[str]) -> list[ToolEntry]:
    created = summary.create.created_tools if summary.create else []
    by_name = {c.name: c for c in created if c.name is not None}
    names = list(by_name)
    tools_dir = root / "tools"
    if tools_dir.is_dir():  # a tool written by an interrupted run is shown too
        names += sorted(p.name for p in tools_dir.iterdir()
                        if p.is_dir() and p.name not in by_name)
    out = []
    for name in names:
        folder = f"tools/{name}"
        manifest = _read_json(root / folder / f"{name}.json", warnings)
        manifest = manifest if isinstance(manifest, dict) and manifest else None
        listed = manifest.get("files", {}) if manifest else {}
        files = []
        for kind, file_name in (listed.items() if isinstance(listed, dict) else ()):
            for one in (file_name if isinstance(file_name, list) else [file_name]):
                rel = relative_inside(root, f"{folder}/{one}") if isinstance(one, str) else None
                if rel is not None and (root / rel).is_file():
                    files.append((kind, rel))
        if manifest is not None:
            files.append(("json", f"{folder}/{name}.json"))
        picture = f"{folder}/{name}.png"
        out.append(ToolEntry(name, folder, by_name.get(name), manifest,
                             picture if (root / picture).is_file() else None, files))
    return out


def number_text(value: Any) -> str:
    """Return a number in at most six significant digits, anything else as ``str``."""
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)


def literals_text(literals: Any) -> str:
    """Return a list of literals joined by commas (``-`` when empty)."""
    if isinstance(literals, list):
        return ", ".join(str(x) for x in literals) or "-"
    return "-" if literals in (None, "") else str(literals)


TRIAL_COLUMNS: list[tuple[str, Callable[[TrialRecord], str]]] = trial_columns()
"""The trial table's columns, ``(header, cell text of a trial record)``: every field of
:class:`~creative_py.records.trial.TrialRecord` with a ``column`` (the trial's number
in the run, its phase and number within the phase, tool, task variant, location, pose,
the tested and violated literals, outcome and reason)."""


def split_top_level(text: str, sep: str = ",") -> list[str]:
    """Split ``text`` at each ``sep`` outside brackets and quotes (a Prolog term's
    arguments, a clause body's literals)."""
    parts, depth, quote, start = [], 0, "", 0
    for i, ch in enumerate(text):
        if quote:
            quote = "" if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == sep and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    parts.append(text[start:].strip())
    return [p for p in parts if p]


def plan_steps(plan: str) -> list[str] | None:
    """Return the actions of a plan term ``plan([A1, A2, ...])``, or None when the text
    is not a plan (``no_plan(...)``)."""
    text = plan.strip()
    if text.startswith("plan([") and text.endswith("])"):
        return split_top_level(text[len("plan(["):-2])
    return None


def clause_parts(clause: str) -> tuple[str, list[str]]:
    """Return the head and body literals of a clause's text ``Head :- L1, L2``."""
    head, sep, body = clause.partition(":-")
    return head.strip(), split_top_level(body) if sep else []
