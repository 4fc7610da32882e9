"""A run killed with SIGKILL at a random trial and resumed equals an uninterrupted run.

Runs are deterministic (the same seed gives the same trials), so ``creative run
--resume`` replays the recorded trials into the version space without physics and goes
on; its ``trials.jsonl`` must equal an uninterrupted run's, timings aside, and so must
the learned hypotheses and the created tool.
"""

from __future__ import annotations

import json
import os
import random
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
from _runs import trials

pytestmark = [pytest.mark.slow, pytest.mark.sim]

def _creative(*args: str) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "creative_py.cli", *args],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)


@pytest.mark.parametrize("case", ["hook", "rake"])
def test_a_run_killed_at_a_random_trial_resumes_to_the_same_result(tmp_path, case):
    # As make hook runs it: a tool is created even after a catalogued object succeeded.
    full = _creative("run", case, "--out", str(tmp_path / "full"), "--demonstrate-creation")
    full_dir = Path(full.communicate(timeout=600)[0].strip().splitlines()[-1])
    assert full.returncode == 0
    kill_after = random.Random().randint(1, 12)
    killed = _creative("run", case, "--out", str(tmp_path / "killed"),
                       "--demonstrate-creation")
    deadline = time.monotonic() + 600
    while time.monotonic() < deadline:
        found = list((tmp_path / "killed").glob("*/trials.jsonl"))
        if found and len(found[0].read_text().splitlines()) >= kill_after:
            break
        time.sleep(0.2)
    os.kill(killed.pid, signal.SIGKILL)
    killed.wait()
    run_dir = found[0].parent
    resumed = _creative("run", case, "--resume", str(run_dir))
    out = resumed.communicate(timeout=600)[0]
    assert resumed.returncode == 0, f"killed after {kill_after} trials"
    assert Path(out.strip().splitlines()[-1]) == run_dir
    assert trials(run_dir) == trials(full_dir), f"killed after {kill_after} trials"
    a, b = (json.loads((d / "summary.json").read_text()) for d in (full_dir, run_dir))
    assert a["hypotheses"] == b["hypotheses"]
    assert a["create"]["created_tools"][0]["dims"] == b["create"]["created_tools"][0]["dims"]
    assert a["create"]["eval"] == b["create"]["eval"]


def test_resume_refuses_a_folder_that_is_not_a_run(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "run", "hook", "--resume",
                           str(tmp_path)], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2
    assert "not a resumable run folder (no run.json)" in proc.stderr
