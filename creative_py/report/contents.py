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
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from creative_py.records.folder import read_records
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
    info : dict
        What ``summary.json`` says of it (``phase``, ``trial``, ``tool``, ``tested``,
        ``outcome``, ``why``); empty for a clip found only in ``videos/``.
    """

    file: str
    exists: bool
    info: dict[str, Any] = field(default_factory=dict)


@dataclass
class ToolEntry:
    """One created tool: what the summary says of it and its own folder.

    Attributes
    ----------
    name : str
        The tool's name.
    folder : str
        Its folder relative to the run folder (``tools/<name>``).
    created : dict
        Its entry of ``summary.json``'s ``create.created_tools`` (empty when only the
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
    created: dict[str, Any]
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
    summary : dict
        ``summary.json`` (empty when missing, as in a run still going, or unreadable).
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
    """

    path: Path
    trials: list[TrialRecord]
    summary: dict[str, Any]
    model_text: str | None
    plot: str | None
    clips: list[Clip]
    tools: list[ToolEntry]
    pddl_files: list[str]
    warnings: list[str]

    @property
    def columns(self) -> list[tuple[str, Callable[[TrialRecord], str]]]:
        """Return the trial columns of this run's records: :data:`TRIAL_COLUMNS`, from the
        fields of their record type (:func:`~creative_py.records.trial.trial_columns`)."""
        if self.trials and type(self.trials[0]) is not TrialRecord:
            return trial_columns(type(self.trials[0]))
        return TRIAL_COLUMNS


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
    summary = _read_json(root / "summary.json", warnings)
    if not isinstance(summary, dict):
        warnings.append(f"{root / 'summary.json'}: not a JSON object; no summary shown")
        summary = {}
    model = root / "model.pl"
    model_text = model.read_text(encoding="utf-8", errors="replace") if model.is_file() else None
    return RunContents(
        path=root, trials=trials, summary=summary, model_text=model_text,
        plot="trials.png" if (root / "trials.png").is_file() else None,
        clips=_clips(root, summary, warnings), tools=_tools(root, summary, warnings),
        pddl_files=[n for n in ("domain.pddl", "problem.pddl") if (root / n).is_file()],
        warnings=warnings)


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


def _clips(root: Path, summary: dict[str, Any], warnings: list[str]) -> list[Clip]:
    listed = summary.get("videos")
    if not isinstance(listed, list):
        return [Clip(p.relative_to(root).as_posix(), True)
                for p in sorted((root / "videos").glob("*.mp4"))]
    clips = []
    for entry in listed:
        name = entry.get("file") if isinstance(entry, dict) else None
        if not isinstance(name, str):
            warnings.append(f"{root / 'summary.json'}: a videos entry has no file: {entry!r}")
            continue
        rel = relative_inside(root, name)
        if rel is None:
            warnings.append(f"{root / 'summary.json'}: video {name} is outside the run "
                            f"folder; not shown")
            continue
        info = {k: v for k, v in entry.items() if k != "file"}
        clips.append(Clip(rel, (root / rel).is_file(), info))
    return clips


def _tools(root: Path, summary: dict[str, Any], warnings: list[str]) -> list[ToolEntry]:
    create = summary.get("create")
    created = create.get("created_tools", []) if isinstance(create, dict) else []
    by_name = {c["name"]: c for c in created if isinstance(c, dict) and "name" in c}
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
        out.append(ToolEntry(name, folder, by_name.get(name, {}), manifest,
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
