"""The run folder: trials are flushed one per line, an interrupted run stays readable."""

import json

import pytest

from creative_py.records.folder import RunFolder, read_trials, write_atomic
from creative_py.records.summary import TrialCounts
from creative_py.report import plot_trials


def _trial(i, phase="use", outcome="success", tool="hook_a2"):
    return {"trial": i, "phase": phase, "phase_trial": i, "variant": "standard",
            "location": 1, "tool": tool, "tested": [], "outcome": outcome}


def test_trials_are_appended_and_read_back(tmp_path):
    run = RunFolder.create(tmp_path, "hook", 3)
    assert run.path.name.startswith("hook-") and run.path.name.endswith("-s3")
    for i in range(1, 4):
        run.append_trial(_trial(i, outcome="failure" if i == 2 else "success"))
    assert [t["outcome"] for t in read_trials(run.path)] == ["success", "failure", "success"]


def test_a_torn_last_line_is_skipped(tmp_path):
    run = RunFolder.create(tmp_path, "wedge", 0)
    run.append_trial(_trial(1))
    with open(run.trials_path, "a") as fh:  # killed in the middle of a write
        fh.write('{"trial": 2, "phase": "us')
    assert len(read_trials(run.path)) == 1


def test_two_runs_never_share_a_folder(tmp_path):
    a = RunFolder.create(tmp_path, "hook", 0, name="same")
    b = RunFolder.create(tmp_path, "hook", 0, name="same")
    assert a.path != b.path


def test_missing_trials_file_is_named(tmp_path):
    with pytest.raises(FileNotFoundError, match="trials.jsonl"):
        read_trials(tmp_path)


def test_atomic_write_replaces_whole_file(tmp_path):
    p = tmp_path / "summary.json"
    write_atomic(p, json.dumps({"a": 1}))
    write_atomic(p, json.dumps({"a": 2}))
    assert json.loads(p.read_text()) == {"a": 2}
    assert [f.name for f in tmp_path.iterdir()] == ["summary.json"]


def test_non_finite_numbers_are_written_as_text(tmp_path):
    run = RunFolder.create(tmp_path, "hook", 0)
    run.append_trial({**_trial(1), "wall_time_s": float("nan")})
    assert read_trials(run.path)[0]["wall_time_s"] == "nan"


def test_plot_and_summary(tmp_path):
    trials = [_trial(1, outcome="failure", tool="hook_a1"), _trial(2),
              _trial(3, phase="create", outcome="failure"),
              _trial(4, phase="create", tool="hook_new1"),
              _trial(5, phase="eval", tool="hook_new1")]
    png = plot_trials(trials, tmp_path / "t.png", title="x")
    assert png.stat().st_size > 1000
    s = TrialCounts.of(trials).to_dict()
    assert s["use"] == {"trials": 2, "successes": 1, "outcomes": ["failure", "success"]}
    assert s["create"]["trials"] == 2 and s["eval"]["successes"] == 1


def test_plot_labels_name_the_tested_literal():
    from creative_py.report import trial_labels

    trials = [dict(_trial(i, outcome="failure"), tested=[lit])
              for i, lit in enumerate(["hook_down(hook_a2)", "behind(hook_a2,cube1)",
                                       "centred_on(hook_a2,cube1)"], start=2)]
    trials.append(_trial(5, phase="eval"))
    labels = trial_labels(trials)
    assert labels == ["#2 TUL  hook_down(hook_a2)", "#3 TUL  behind(hook_a2,cube1)",
                      "#4 TUL  centred_on(hook_a2,cube1)", "#5 EV"]
