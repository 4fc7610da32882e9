"""A short run interrupted after its first trial and resumed equals an uninterrupted one.

The quick counterpart of ``test_resume.py`` (which kills whole runs at a random trial,
in the slow suite): the rake case, tool-use learning only, two trials, no evaluation
(a few seconds a run). The run is interrupted as soon as ``trials.jsonl`` has a line
(its progress callback raises KeyboardInterrupt, as Ctrl-C would), then resumed through
:func:`resume_run`: the trials must be numbered 1..2 once each (the replayed one is not
appended again) and equal, timings aside, to those of the uninterrupted run, and so
must the summary's learning figures and hypotheses.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import resume_run, run_case

pytestmark = pytest.mark.sim

TIMINGS = ("wall_time_s", "decision_time_s", "sim_time_s")
OPTIONS = RunOptions(seed=0, phase="use", max_trials=2, eval_trials=0, strategy="paper",
                     video="none")


def _trials(folder: Path) -> list[dict]:
    out = []
    for line in (folder / "trials.jsonl").read_text().splitlines():
        record = json.loads(line)
        for key in TIMINGS:
            record.pop(key, None)
        out.append(record)
    return out


def _summary(folder: Path) -> dict:
    s = json.loads((folder / "summary.json").read_text())
    return {k: s[k] for k in ("use", "hypotheses", "vs_count_initial", "vs_count_final",
                              "plan", "trials")}


def test_a_short_run_interrupted_after_trial_1_resumes_to_the_same_trials(tmp_path):
    full = run_case("rake", tmp_path / "full", OPTIONS).path
    folders = []

    def interrupt(line: str) -> None:
        if line.startswith("run folder "):
            folders.append(Path(line[len("run folder "):]))
        if folders and (folders[0] / "trials.jsonl").is_file() and \
                (folders[0] / "trials.jsonl").read_text().strip():
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_case("rake", tmp_path / "killed", OPTIONS, progress=interrupt)
    killed = folders[0]
    assert [t["trial"] for t in _trials(killed)] == [1]
    assert not (killed / "summary.json").exists()

    lines = []
    resumed = resume_run(killed, progress=lines.append).path
    assert resumed == killed
    assert lines[0] == f"resuming {killed}: replaying 1 recorded trials"
    trials = _trials(killed)
    assert [t["trial"] for t in trials] == [1, 2]
    assert trials == _trials(full)
    assert _summary(killed) == _summary(full)
    assert _summary(killed)["use"]["trials"] == 2

