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
from typing import Any, Callable


@dataclass
class RunFolder:
    """A run's output folder; create it with :meth:`create`."""

    path: Path
    trials: list[dict[str, Any]] = field(default_factory=list)

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

    def append_trial(self, record: dict[str, Any]) -> None:
        """Append one finished trial to ``trials.jsonl`` and flush it to disk."""
        line = json.dumps(_jsonable(record), sort_keys=False)
        with open(self.trials_path, "a", encoding="utf-8") as fh:
            fh.write(line + "\n")
            fh.flush()
            os.fsync(fh.fileno())
        self.trials.append(record)

    def rewrite_trials(self, records: list[dict[str, Any]]) -> None:
        """Replace ``trials.jsonl`` by ``records`` (atomically): a resumed run keeps its
        readable trials and drops a torn or corrupt line."""
        text = "".join(json.dumps(_jsonable(r)) + "\n" for r in records)
        write_atomic(self.trials_path, text)
        self.trials = list(records)

    def write_text(self, name: str, text: str) -> Path:
        """Write a text file of the run atomically (temp file, then rename)."""
        return write_atomic(self.path / name, text)

    def write_json(self, name: str, data: Any) -> Path:
        """Write a JSON file of the run atomically."""
        return write_atomic(self.path / name, json.dumps(_jsonable(data), indent=2) + "\n")


TRIAL_KEYS = ("trial", "phase", "variant", "location", "tool", "outcome")
"""The keys every line of ``trials.jsonl`` has (the report and the plot need them)."""


def read_trials(run_dir: Path, warn: Callable[[str], None] | None = None) -> list[dict[str, Any]]:
    """Return every readable trial of a run folder.

    A line that is not JSON (a torn last line of a killed run, a corrupt one) or lacks
    one of :data:`TRIAL_KEYS` is skipped, and ``warn`` is called with one sentence
    naming the file and the line.
    """
    out = []
    path = Path(run_dir) / "trials.jsonl"
    if not path.exists():
        raise FileNotFoundError(f"{path}: no trials.jsonl in this run folder")
    for n, line in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
        except json.JSONDecodeError as exc:
            if warn:
                warn(f"{path}: line {n} is not a JSON object ({exc.msg}); skipped")
            continue
        missing = [k for k in TRIAL_KEYS if not isinstance(record, dict) or k not in record]
        if missing:
            if warn:
                warn(f"{path}: line {n} lacks {', '.join(missing)}; skipped")
            continue
        out.append(record)
    return out


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
