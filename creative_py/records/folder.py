"""The run folder: everything one run leaves behind, written as it goes.

Layout (docs/architecture.md, section 5)::

    <run>/trials.jsonl        one JSON object per finished trial, flushed at once, so an
                              interrupted run leaves a readable file of the finished trials
    <run>/model.pl            learned action models and hypotheses, loadable in a REPL
    <run>/domain.pddl         PDDL domain of the learned models
    <run>/problem.pddl        PDDL problem of the last task
    <run>/trials.png          outcomes per trial in the style of the paper's Figures 5 and 6
    <run>/snapshots/          camera frames of each trial
    <run>/videos/             MP4 clips of the kept trials (creative_py.learning.clips)
    <run>/tools/<name>.*      created tools (urdf, sdf, scad, stl, png)
    <run>/summary.json        trials per phase, successes, created tools, wall time per phase
    <run>/report.html         the run on one page (creative_py.report.page), written last
"""

from __future__ import annotations

import json
import math
import os
import tempfile
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable, Union

from creative_py.records.trial import REQUIRED_KEYS, TrialRecord


@dataclass
class RunFolder:
    """A run's output folder; create it with :meth:`create`."""

    path: Path
    trials: list[Union[TrialRecord, dict[str, Any]]] = field(default_factory=list)

    @classmethod
    def create(cls, parent: Path, case: str, seed: int, name: str | None = None) -> "RunFolder":
        """Create a new, empty run folder ``<parent>/<case>-<UTC time>-s<seed>``."""
        if name is None:
            stamp = datetime.now(timezone.utc).strftime("%Y%m%d-%H%M%S")
            name = f"{case}-{stamp}-s{seed}"
        parent = Path(parent)
        parent.mkdir(parents=True, exist_ok=True)
        path, n = parent / name, 1
        while True:  # mkdir is the atomic test: two runs never share a folder
            try:
                path.mkdir()
                break
            except FileExistsError:
                n += 1
                path = parent / f"{name}-{n}"
        (path / "snapshots").mkdir()
        return cls(path)

    @property
    def trials_path(self) -> Path:
        """Return the path of ``trials.jsonl``."""
        return self.path / "trials.jsonl"

    def snapshot_dir(self, phase: str, trial: int) -> Path:
        """Return (and create) the folder for one trial's camera frames."""
        d = self.path / "snapshots" / f"{phase}-{trial:03d}"
        d.mkdir(parents=True, exist_ok=True)
        return d

    def tools_dir(self) -> Path:
        """Return (and create) the folder for created tools."""
        d = self.path / "tools"
        d.mkdir(exist_ok=True)
        return d

    def append_trial(self, record: Union[TrialRecord, dict[str, Any]]) -> None:
        """Append one finished trial to ``trials.jsonl`` and flush it to disk."""
        line = _line(record)
        with open(self.trials_path, "a", encoding="utf-8") as fh:
            fh.write(line + "\n")
            fh.flush()
            os.fsync(fh.fileno())
        self.trials.append(record)

    def rewrite_trials(self, records: list[Union[TrialRecord, dict[str, Any]]]) -> None:
        """Replace ``trials.jsonl`` by ``records`` (atomically): a resumed run keeps its
        readable trials and drops a torn or corrupt line."""
        text = "".join(_line(r) + "\n" for r in records)
        write_atomic(self.trials_path, text)
        self.trials = list(records)

    def write_text(self, name: str, text: str) -> Path:
        """Write a text file of the run atomically (temp file, then rename)."""
        return write_atomic(self.path / name, text)

    def write_json(self, name: str, data: Any) -> Path:
        """Write a JSON file of the run atomically."""
        return write_atomic(self.path / name, json.dumps(_jsonable(data), indent=2) + "\n")


TRIAL_KEYS = REQUIRED_KEYS
"""The keys every line of ``trials.jsonl`` has (the report and the plot need them)."""


def read_records(run_dir: Path, warn: Callable[[str], None] | None = None
                 ) -> list[TrialRecord]:
    """Return every readable trial of a run folder as a checked :class:`TrialRecord`.

    A line that is not JSON (a torn last line of a killed run, a corrupt one) or not a
    valid record (:meth:`TrialRecord.from_json`: a missing key, a value of the wrong
    type, an unknown outcome) is skipped, and ``warn`` is called with one sentence
    naming the file, the line and the field.
    """
    out = []
    for n, line, path in _lines(run_dir):
        try:
            data = json.loads(line)
        except json.JSONDecodeError as exc:
            if warn:
                warn(f"{path}: line {n} is not a JSON object ({exc.msg}); skipped")
            continue
        try:
            out.append(TrialRecord.from_dict(data))
        except ValueError as exc:
            if warn:
                warn(f"{path}: line {n} {exc}; skipped")
    return out


def read_trials(run_dir: Path, warn: Callable[[str], None] | None = None) -> list[dict[str, Any]]:
    """Return every readable trial of a run folder as the JSON object of its line
    (:func:`read_records`, then :meth:`TrialRecord.to_dict`)."""
    return [r.to_dict() for r in read_records(run_dir, warn)]


def _lines(run_dir: Path) -> list[tuple[int, str, Path]]:
    """Return ``(number, text, file)`` of each non-blank line of ``trials.jsonl``."""
    path = Path(run_dir) / "trials.jsonl"
    if not path.exists():
        raise FileNotFoundError(f"{path}: no trials.jsonl in this run folder")
    lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    return [(n, line, path) for n, line in enumerate(lines, 1) if line.strip()]


def _line(record: Union[TrialRecord, dict[str, Any]]) -> str:
    """Return one line of ``trials.jsonl`` (no newline)."""
    if not isinstance(record, TrialRecord):
        record = TrialRecord.from_dict(record)  # checked like a line read back
    return record.to_json()


def write_atomic(path: Path, text: str) -> Path:
    """Write ``text`` to ``path`` through a temporary file in the same folder."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as fh:
            fh.write(text)
        os.chmod(tmp, 0o666 & ~_umask())  # as open() would: mkstemp makes it 0600
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise
    return path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def _jsonable(value: Any) -> Any:
    """Return ``value`` with Prolog terms as text and non-finite floats as strings."""
    if isinstance(value, dict):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    if isinstance(value, float) and not math.isfinite(value):
        return str(value)
    if isinstance(value, (str, int, float, bool)) or value is None:
        return value
    if isinstance(value, Path):
        return str(value)
    return str(value)
