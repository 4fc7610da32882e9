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
    <run>/run.json            case, options and world of the run (what --resume reads)
    <run>/stopped.json        only after the backend was lost mid-run (an arm gone silent):
                              why, the trials kept, the trial it was lost in (not as
                              planned), the --resume command (removed when a resume runs
                              to the end; creative_py.learning.run)
    <run>/.lock               advisory lock (fcntl.flock) held by the process running it

A run folder is locked for the life of the run that writes it (:meth:`RunFolder.create`,
:meth:`RunFolder.open`): a second run or resume of the same folder is refused with
:class:`FolderInUse`, and :func:`running_pid` tells a run still going (locked) from one
that was interrupted (unlocked, no ``summary.json``). A resumed run reads its trials through :func:`read_resume`, which
refuses any invalid line (a torn last line aside), and keeps the folder *sealed* while
it replays them: nothing is written (no rewrite of ``trials.jsonl``, no snapshot) until
the replay has been checked and the first new trial runs (:meth:`RunFolder.unseal`).
"""

from __future__ import annotations

import errno
import fcntl
import json
import os
import shlex
import signal
import tempfile
import threading
from contextlib import contextmanager
from dataclasses import dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable, Iterator, Optional, Union

from creative_py.records.trial import REQUIRED_KEYS, TrialRecord, jsonable

RESUME_ENV = "CREATIVE_RESUME_COMMAND"
"""The environment variable of the command that resumes a run, with ``{run}`` where its
folder goes: a launcher that started the learner beside a stand-in robot sets it (the
ROS 2 backend's, :mod:`creative_py.backends.ros.launch`; ``make run BACKEND=ros``),
since ``creative run CASE --resume DIR`` alone would find no arm. Read by
:func:`resume_command`, which the run's Ctrl-C and lost-arm hints and ``stopped.json``
use (:mod:`creative_py.learning.run`)."""


def resume_command(case: str, folder: Path | str) -> str:
    """Return the command that goes on with the run in ``folder``, as the person who
    started it can type it: the launcher's (:data:`RESUME_ENV`) when one started the
    learner, else ``creative run CASE --resume FOLDER`` (the folder shell-quoted)."""
    where = shlex.quote(str(folder))
    template = os.environ.get(RESUME_ENV, "").strip()
    if template:
        return (template.replace("{run}", where) if "{run}" in template
                else f"{template} {where}")
    return f"creative run {case} --resume {where}"


class FolderInUse(ValueError):
    """The run folder is locked by another process (a run or a resume still going)."""

    def __init__(self, path: Path, pid: str) -> None:
        super().__init__(f"{path}: another run is using this folder (pid {pid or '?'})")
        self.path, self.pid = path, pid


LOCK_NAME = ".lock"
"""The lock file of a run folder (:meth:`RunFolder.lock`)."""

_HELD: set[int] = set()
"""The descriptors of the run-folder locks this process holds."""


def _close_inherited() -> None:
    """In a forked child (a clip being rendered): close the inherited lock descriptors,
    so that the lock dies with the run's own process, not with its last child (the
    parent's descriptor keeps the lock)."""
    for fd in list(_HELD):
        try:
            os.close(fd)
        except OSError:
            pass
    _HELD.clear()


os.register_at_fork(after_in_child=_close_inherited)


@contextmanager
def _sigint_held() -> Iterator[None]:
    """Hold a SIGINT back while the block runs (in the main thread, where Python runs
    signal handlers) and give it, after the block, to the handler that was there: its
    KeyboardInterrupt is raised after the block, not in the middle of it. (A handler
    that notes, not a blocked signal mask: a signal sent to the process reaches any
    thread that does not block it, and Python then runs the handler at once.)"""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    noted: list[int] = []
    before = signal.signal(signal.SIGINT, lambda signum, frame: noted.append(signum))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, before)
    if noted:
        signal.raise_signal(signal.SIGINT)


@dataclass
class RunFolder:
    """A run's output folder; create it with :meth:`create`, or :meth:`open` it to
    resume; :meth:`release` its lock when the run ends."""

    path: Path
    trials: list[Union[TrialRecord, dict[str, Any]]] = field(default_factory=list)
    sealed: bool = False
    """Nothing may be written while True (a resume replaying its recorded trials)."""
    _lock_fd: Optional[int] = field(default=None, repr=False)
    _pending: Optional[list] = field(default=None, repr=False)

    @classmethod
    def create(cls, parent: Path, case: str, seed: int, name: str | None = None) -> "RunFolder":
        """Create a new, empty run folder ``<parent>/<case>-<UTC time>-s<seed>``; when
        it cannot be made, the folders above it that this call made are removed."""
        if name is None:
            stamp = datetime.now(timezone.utc).strftime("%Y%m%d-%H%M%S")
            name = f"{case}-{stamp}-s{seed}"
        parent = Path(parent)
        made = []  # the folders above the run this call makes, deepest first
        for p in (parent, *parent.parents):
            if p.exists():
                break
            made.append(p)
        try:
            parent.mkdir(parents=True, exist_ok=True)
            path, n = parent / name, 1
            while True:  # mkdir is the atomic test: two runs never share a folder
                try:
                    path.mkdir()
                    break
                except FileExistsError:
                    n += 1
                    path = parent / f"{name}-{n}"
        except OSError:  # a path too long, a full disk: leave no empty folders behind
            for p in made:
                try:
                    p.rmdir()
                except OSError:
                    break
            raise
        run = cls(path)
        run.lock(record_pid=True)
        (path / "snapshots").mkdir()
        return run

    @classmethod
    def open(cls, path: Path) -> "RunFolder":
        """Return an existing run folder, locked (raise :class:`FolderInUse` when
        another process holds it), for a resume. Its ``.lock`` is not written (a
        refused resume leaves the folder as it was): the holder's pid is found from
        the kernel's lock table."""
        run = cls(Path(path))
        run.lock()
        return run

    def lock(self, record_pid: bool = False) -> None:
        """Take the folder's advisory lock (``<run>/.lock``, ``fcntl.flock``) for the
        life of this process or until :meth:`release`; raise :class:`FolderInUse`
        naming the holder's pid when another process holds it (from ``/proc/locks``,
        else the pid the file records). ``record_pid`` (a new folder) writes this
        process's pid into the file; otherwise an existing file is left unchanged."""
        if self._lock_fd is not None:
            return
        fd = os.open(self.path / LOCK_NAME, os.O_RDWR | os.O_CREAT, 0o666)
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError as exc:
            pid = _lock_holder(fd) or os.read(fd, 32).decode("ascii", "replace").strip()
            os.close(fd)
            if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                raise FolderInUse(self.path, pid) from None
            raise
        if record_pid:
            os.ftruncate(fd, 0)
            os.write(fd, f"{os.getpid()}\n".encode())
        self._lock_fd = fd
        _HELD.add(fd)

    def release(self) -> None:
        """Release the folder's lock (the lock file stays; its pid is stale)."""
        if self._lock_fd is not None:
            fd, self._lock_fd = self._lock_fd, None
            _HELD.discard(fd)
            fcntl.flock(fd, fcntl.LOCK_UN)
            os.close(fd)

    def seal(self, records: list[TrialRecord]) -> None:
        """Write nothing until :meth:`unseal`, which then makes ``trials.jsonl`` hold
        exactly ``records`` (the checked trials a resume replays)."""
        self.sealed, self._pending, self.trials = True, list(records), list(records)

    def unseal(self) -> None:
        """End a resume's replay (checked): rewrite ``trials.jsonl`` as :meth:`seal`
        was given it (dropping a torn last line) and allow writing again."""
        if self.sealed:
            self.sealed = False
            pending, self._pending = self._pending, None
            if pending is not None and _needs_rewrite(self.trials_path, pending):
                self.rewrite_trials(pending)

    @property
    def trials_path(self) -> Path:
        """Return the path of ``trials.jsonl``."""
        return self.path / "trials.jsonl"

    def snapshot_dir(self, phase: str, trial: int) -> Optional[Path]:
        """Return (and create) the folder for one trial's camera frames; None while
        the folder is sealed (a resume replaying: the frames are there already)."""
        if self.sealed:
            return None
        d = self.path / "snapshots" / f"{phase}-{trial:03d}"
        d.mkdir(parents=True, exist_ok=True)
        return d

    def tools_dir(self) -> Path:
        """Return (and create) the folder for created tools."""
        d = self.path / "tools"
        d.mkdir(exist_ok=True)
        return d

    def append_trial(self, record: Union[TrialRecord, dict[str, Any]]) -> None:
        """Append one finished trial to ``trials.jsonl`` and flush it to disk (a
        sealed folder is unsealed first).

        The line and :attr:`trials` take the trial together: a Ctrl-C (SIGINT) is held
        back from the write to the list's append (in the main thread), so an interrupted
        run never keeps a line it does not count (it said 8 trials kept where 9 were:
        the signal came during the ``fsync``)."""
        self.unseal()
        line = _line(record)
        with _sigint_held():
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
        return write_atomic(self.path / name, json.dumps(jsonable(data), indent=2) + "\n")


def running_pid(run_dir: Path) -> str:
    """Return the pid of the process running (or resuming) the run folder, or ``""``
    when no process holds its lock: the run finished, was interrupted, or is a folder
    without a ``.lock``.

    The lock is only looked at, never taken (a run starting or resuming the folder at
    that moment is not refused): the holder comes from Linux's ``/proc/locks``; where
    that cannot be read, a shared ``flock`` is tried and at once released.
    """
    try:
        fd = os.open(Path(run_dir) / LOCK_NAME, os.O_RDONLY)
    except OSError:
        return ""
    try:
        pid = _lock_holder(fd)
        if pid or os.path.exists("/proc/locks"):
            return pid
        try:
            fcntl.flock(fd, fcntl.LOCK_SH | fcntl.LOCK_NB)
        except OSError as exc:
            if exc.errno in (errno.EWOULDBLOCK, errno.EAGAIN, errno.EACCES):
                return os.read(fd, 32).decode("ascii", "replace").strip() or "?"
            return ""
        fcntl.flock(fd, fcntl.LOCK_UN)
        return ""
    finally:
        os.close(fd)


def _lock_holder(fd: int) -> str:
    """Return the pid of the process holding a ``flock`` on the file of ``fd``, from
    Linux's ``/proc/locks`` (``""`` when it cannot be read or names none)."""
    st = os.fstat(fd)
    key = f"{os.major(st.st_dev):02x}:{os.minor(st.st_dev):02x}:{st.st_ino}"
    try:
        with open("/proc/locks", encoding="ascii", errors="replace") as fh:
            for line in fh:
                parts = line.split()
                if "FLOCK" in parts and key in parts:
                    return parts[parts.index(key) - 1]
    except OSError:
        pass
    return ""


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
            data = _json(line)
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


def read_resume(run_dir: Path, warn: Callable[[str], None] | None = None
                ) -> tuple[list[TrialRecord], list[int]]:
    """Return the trials a resume replays, strictly checked, and their line numbers.

    No ``trials.jsonl`` (a run killed before its first trial) is no trial. A last line
    that is not JSON is the torn line of a killed run: dropped, with ``warn``. Any other
    line that is not a valid record (:meth:`TrialRecord.from_dict`: a missing key, a
    value of the wrong type, an outcome or phase outside the allowed set), a ``facts``
    entry that is not a list of ``[name, argument, ...]``, or trial numbers that do not
    run 1, 2, 3, ... raise ValueError naming the file, the line and the field.
    """
    if not (Path(run_dir) / "trials.jsonl").exists():
        return [], []
    lines = _lines(run_dir, strict=True)
    records, numbers = [], []
    for i, (n, line, path) in enumerate(lines):
        try:
            data = _json(line)
        except json.JSONDecodeError as exc:
            if i == len(lines) - 1:
                if warn:
                    warn(f"{path}: line {n} is not a JSON object ({exc.msg}): the torn "
                         f"last line of a killed run; dropped")
                break
            raise ValueError(f"{path}: line {n} is not a JSON object ({exc.msg}); the "
                             f"run cannot be resumed") from None
        try:
            rec = TrialRecord.from_dict(data)
            _check_facts(rec.facts)
            if rec.trial != len(records) + 1:
                raise ValueError(f"field 'trial' is {rec.trial}, expected "
                                 f"{len(records) + 1} (trials are numbered in order)")
        except ValueError as exc:
            raise ValueError(f"{path}: line {n}: {exc}; the run cannot be resumed") from None
        records.append(rec)
        numbers.append(n)
    return records, numbers


def _check_facts(facts: Any) -> None:
    """Raise ValueError unless ``facts`` is a list of ``[name, argument, ...]`` lists
    (names text, arguments text, numbers or such lists)."""
    def atomic(v: Any) -> bool:
        return (isinstance(v, (str, int, float)) and not isinstance(v, bool)) or (
            isinstance(v, list) and all(atomic(x) for x in v))

    if facts is None:
        return
    if not isinstance(facts, list):
        raise ValueError(f"field 'facts' must be a list, got {type(facts).__name__}")
    for k, f in enumerate(facts):
        if not (isinstance(f, list) and f and isinstance(f[0], str) and f[0]
                and all(atomic(a) for a in f[1:])):
            raise ValueError(f"field 'facts': entry {k} is not [name, argument, ...] "
                             f"({json.dumps(f)[:60]})")


def _needs_rewrite(path: Path, records: list[TrialRecord]) -> bool:
    """Return whether ``trials.jsonl`` differs from the lines of ``records``."""
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except FileNotFoundError:
        return bool(records)
    lines = [line for line in text.splitlines() if line.strip()]
    if len(lines) != len(records) or not text.endswith("\n") and text:
        return True
    return any(json.loads(a) != json.loads(b.to_json()) for a, b in zip(lines, records))


def _json(line: str) -> Any:
    """Return the JSON value of one line; raise json.JSONDecodeError for one that is
    not JSON, nested too deeply for the parser among them (``[[[[...``)."""
    try:
        return json.loads(line)
    except RecursionError:
        raise json.JSONDecodeError("nested too deeply", line, 0) from None


def _lines(run_dir: Path, strict: bool = False) -> list[tuple[int, str, Path]]:
    """Return ``(number, text, file)`` of each non-blank line of ``trials.jsonl``.

    A byte that is not UTF-8 becomes U+FFFD, or, with ``strict`` (a resume, which
    rewrites the file), raises :class:`NotUtf8` naming the file, the line and the
    byte (the torn last line of a killed run aside, a last line cut short before its
    closing brace: it is returned with U+FFFD, and is not JSON)."""
    path = Path(run_dir) / "trials.jsonl"
    if not Path(run_dir).is_dir():
        why = "not a folder" if Path(run_dir).exists() else "no such folder"
        raise FileNotFoundError(f"{run_dir}: {why} (a run folder was expected)")
    if not path.exists():
        raise FileNotFoundError(f"{path}: no trials.jsonl in this run folder")
    if not path.is_file():
        raise NotARunFile(f"{path}: not a file (a run's trials.jsonl holds one JSON "
                          f"object per line)")
    raw = path.read_bytes().splitlines()
    out = []
    for n, line in enumerate(raw, 1):
        try:
            text = line.decode("utf-8")
        except UnicodeDecodeError as exc:
            torn = (not any(rest.strip() for rest in raw[n:])
                    and not line.rstrip().endswith(b"}"))  # cut short: not JSON anyway
            if strict and not torn:
                raise NotUtf8(f"{path}: line {n}: byte 0x{line[exc.start]:02x} at column "
                              f"{exc.start + 1} is not UTF-8 text; the run cannot be "
                              f"resumed") from None
            text = line.decode("utf-8", errors="replace")
        if text.strip():
            out.append((n, text, path))
    return out


class NotARunFile(ValueError):
    """A file of the run folder is a folder or another kind of non-file."""


class NotUtf8(ValueError):
    """A line of ``trials.jsonl`` holds a byte that is not UTF-8."""


def _line(record: Union[TrialRecord, dict[str, Any]]) -> str:
    """Return one line of ``trials.jsonl`` (no newline)."""
    if not isinstance(record, TrialRecord):
        record = TrialRecord.from_dict(record)  # checked like a line read back
    return record.to_json()


def write_atomic(path: Path, text: Union[str, bytes]) -> Path:
    """Write ``text`` (UTF-8; or ``bytes`` as they are) to ``path`` through a temporary
    file in the same folder: the file is replaced whole or not at all. An OSError that
    names no file (a full disk: ENOSPC) is raised again naming ``path``."""
    path = Path(path)
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
        with os.fdopen(fd, "wb") as fh:
            fh.write(text if isinstance(text, bytes) else text.encode("utf-8"))
        os.chmod(tmp, 0o666 & ~_umask())  # as open() would: mkstemp makes it 0600
        os.replace(tmp, path)
    except BaseException as exc:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(exc, OSError) and not exc.filename and exc.errno:
            raise OSError(exc.errno, os.strerror(exc.errno), str(path)) from exc
        raise
    return path


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask
