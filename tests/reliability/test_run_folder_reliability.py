"""The run folder under stress: simultaneous creations, torn and corrupt lines, modes."""

from __future__ import annotations

import json
import os
import stat
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

from creative_py.records.folder import RunFolder, read_trials


def test_simultaneous_creations_get_distinct_folders(tmp_path):
    with ThreadPoolExecutor(max_workers=16) as pool:
        runs = list(pool.map(lambda _: RunFolder.create(tmp_path / "runs", "hook", 0, "same"),
                             range(45)))
    assert len({r.path for r in runs}) == 45
    assert all(r.path.is_dir() and (r.path / "snapshots").is_dir() for r in runs)


def test_every_file_of_a_run_has_the_same_mode(tmp_path):
    run = RunFolder.create(tmp_path, "hook", 0)
    run.append_trial({"trial": 1, "phase": "use", "variant": "standard", "location": 1,
                      "tool": "t", "outcome": "success"})
    run.write_json("summary.json", {"case": "hook"})
    run.write_text("model.pl", "% nothing learned\n")
    modes = {p.name: stat.S_IMODE(p.stat().st_mode) for p in run.path.iterdir() if p.is_file()}
    assert len(set(modes.values())) == 1, modes
    umask = os.umask(0)
    os.umask(umask)
    assert modes["summary.json"] == 0o666 & ~umask


def _trial(n, **extra):
    return {"trial": n, "phase": "use", "variant": "standard", "location": 1, "tool": "t",
            "outcome": "success", **extra}


def test_report_shows_every_readable_trial_warns_and_writes_nothing(tmp_path):
    lines = [json.dumps(_trial(1)), '{"trial": 2, "phase": "use", garbage',
             json.dumps({"trial": 3, "phase": "use"}), json.dumps(_trial(4)),
             json.dumps(_trial(5)), '{"trial": 6, "pha']
    (tmp_path / "trials.jsonl").write_text("\n".join(lines) + "\n")
    warnings: list[str] = []
    trials = read_trials(tmp_path, warn=warnings.append)
    assert [t["trial"] for t in trials] == [1, 4, 5]
    assert len(warnings) == 3 and "line 2" in warnings[0] and "line 3 lacks" in warnings[1]
    before = sorted(p.name for p in tmp_path.iterdir())
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "report", str(tmp_path)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr.count("warning: ") == 3
    assert all(f"│ {n} " in proc.stdout for n in (1, 4, 5))
    assert sorted(p.name for p in tmp_path.iterdir()) == before   # no trials.png written
