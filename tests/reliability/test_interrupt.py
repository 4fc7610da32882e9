"""Issue 25: Ctrl-C (SIGINT to the process group, as a terminal sends it) at any moment
of a run ends it with exit 130 and the line that says how to resume it, and the clip of
a trial that ended is not lost (its process finishes it)."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from _runs import SHORT

pytestmark = pytest.mark.sim


def _interrupted(out: Path, after: str, delay: float) -> tuple[int, str, Path]:
    """Run the short rake run, send SIGINT to its group ``delay`` s after the first
    stderr line starting with ``after``; return the exit code, stderr and the folder."""
    proc = subprocess.Popen([sys.executable, "-m", "creative_py.cli", "run", "rake",
                             "--out", str(out), *SHORT, "--video", "all"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)
    err = []
    for line in proc.stderr:
        err.append(line)
        if line.startswith(after):
            time.sleep(delay)
            os.killpg(proc.pid, signal.SIGINT)
            break
    rest = proc.communicate(timeout=300)[1]
    text = "".join(err) + rest
    folder = next(out.iterdir())
    return proc.returncode, text, folder


@pytest.mark.parametrize("after, delay", [("#1 ", 0.0), ("#1 ", 0.4),
                                          ("#2 ", 0.1)])
def test_sigint_after_a_trial_ends_the_run_with_130_and_the_resume_hint(tmp_path, after,
                                                                        delay):
    rc, err, folder = _interrupted(tmp_path, after, delay)
    assert rc == 130, err[-2000:]
    last = err.rstrip().splitlines()[-1]
    assert last.startswith("interrupted after "), err[-2000:]
    assert last.endswith(f" trial(s); to go on: creative run rake --resume {folder}"), last
    assert "video clip not written" not in err, err[-2000:]
    assert not (folder / "summary.json").exists()
    # Every clip started (listed in clips.jsonl) was finished, not lost.
    listed = [json.loads(line)["file"]
              for line in (folder / "videos" / "clips.jsonl").read_text().splitlines()]
    assert listed and all((folder / f).is_file() for f in listed), listed
