"""Helpers of the run-folder tests: the CLI in a child process, short runs, hashes."""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
import subprocess
import sys
import time
from pathlib import Path

SHORT = ("--phase", "use", "--max-trials", "3", "--eval-trials", "1")
"""A short run of the rake case (the demonstration, 3 trials, 1 evaluation: ~30 s)."""

TIMINGS = ("wall_time_s", "decision_time_s")


def creative(*args: str, **kw) -> subprocess.Popen:
    """Start ``creative <args>`` (stdout and stderr piped, as text)."""
    return subprocess.Popen([sys.executable, "-m", "creative_py.cli", *args],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kw)


def run_cli(*args: str, timeout: float = 600, **kw) -> subprocess.CompletedProcess:
    """Run ``creative <args>`` to its end."""
    return subprocess.run([sys.executable, "-m", "creative_py.cli", *args],
                          capture_output=True, text=True, timeout=timeout, **kw)


def short_run(out: Path, *extra: str) -> Path:
    """Run the short rake run into ``out`` and return its folder."""
    proc = run_cli("run", "rake", "--out", str(out), *SHORT, *extra)
    assert proc.returncode == 0, proc.stderr[-2000:]
    return Path(proc.stdout.strip().splitlines()[-1])


def shared_short_run(tmp_path_factory) -> Path:
    """Return the session's short rake run (:func:`short_run`, no extra option), run once
    for every test that only reads it, whichever pytest-xdist worker asks first.

    The folder is under the session's temporary root (shared by the workers of one
    session, not by two sessions); a file lock makes the other workers wait for it.
    Tests must not change it (copy it first).
    """
    root = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        root = root.parent  # the session's root, above each worker's own folder
    with open(root / "short_run.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        done = root / "short_run.path"
        if not done.exists():
            done.write_text(str(short_run(root / "short_run")))
        return Path(done.read_text())


def wait_for(test, timeout: float = 300) -> None:
    """Wait until ``test()`` is true (poll every 0.1 s)."""
    deadline = time.monotonic() + timeout
    while not test():
        assert time.monotonic() < deadline, "timed out"
        time.sleep(0.1)


def trials(run: Path) -> list[dict]:
    """Return the lines of a run's ``trials.jsonl`` without their timings."""
    out = []
    for line in (run / "trials.jsonl").read_text().splitlines():
        record = json.loads(line)
        for key in TIMINGS:
            record.pop(key, None)
        out.append(record)
    return out


def tree_digest(root: Path) -> dict[str, str]:
    """Return the SHA-256 of every file under ``root`` (relative path -> digest)."""
    root = Path(root)
    return {str(p.relative_to(root)): hashlib.sha256(p.read_bytes()).hexdigest()
            for p in sorted(root.rglob("*")) if p.is_file()}


def one_error_line(proc: subprocess.CompletedProcess) -> str:
    """Check that a command failed with exit 2 and one ``error:`` line, no traceback;
    return the line."""
    assert proc.returncode == 2, (proc.returncode, proc.stderr[-2000:])
    assert "Traceback" not in proc.stderr, proc.stderr[-2000:]
    errors = [line for line in proc.stderr.splitlines() if line.startswith("error: ")]
    assert len(errors) == 1, proc.stderr[-2000:]
    return errors[0]
