"""sweep.csv column by column, exact, from hand-built run summaries (no physics, no Ray).

``run_case`` is replaced by one that writes a given ``summary.json``; the sweep runs
serially in this process and its ``sweep.csv`` is read back. Every column of every row
is compared with a value written here by hand from the summaries (``wall_time_s`` is
only checked to be a number), so a column that counts every outcome as a success, or
swaps two figures, fails.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from creative_py.sweep import (COLUMNS, RunSpec, SweepOptions, parse_ints, plan_runs,
                               run_sweep, summary_row)

FULL = {
    "use": {"trials": 7, "converged": True},
    "eval": {"trials": 4, "successes": 3},
    "create": {"trials": 2, "predicted_failure_skipped": True,
               "eval": ["success", "failure", "blocked", "success", "unreachable"]},
    "hypotheses": {"hs": "h :- a, b", "hg": "h :- a"},
    "vs_count_initial": 1024,
    "info_bound_trials": 10,
}
"""A run of every phase: 3 of 4 model evaluations and 2 of 5 created-tool ones succeed."""

USE_ONLY = {"use": {"trials": 3, "converged": False}, "hypotheses": {"hs": "h :- a"}}
"""A run of tool-use learning only: no evaluation, no creation, no h_g, no counts."""


def test_summary_row_of_a_full_run():
    assert summary_row(FULL) == {
        "trials_to_learn": 7, "use_converged": True, "creation_trials": 2,
        "creation_skipped_trial": True, "eval_successes": 3, "eval_trials": 4,
        "created_eval_successes": 2, "created_eval_trials": 5, "hg": "h :- a",
        "vs_count_initial": 1024, "info_bound_trials": 10,
    }


def test_summary_row_of_a_use_only_run_leaves_the_rest_empty():
    assert summary_row(USE_ONLY) == {
        "trials_to_learn": 3, "use_converged": False, "creation_trials": "",
        "creation_skipped_trial": "", "eval_successes": "", "eval_trials": "",
        "created_eval_successes": "", "created_eval_trials": "", "hg": "",
        "vs_count_initial": "", "info_bound_trials": "",
    }


def test_summary_row_of_a_creation_with_no_evaluation_trial():
    row = summary_row({"create": {"trials": 1, "eval": []}})
    assert (row["created_eval_successes"], row["created_eval_trials"]) == (0, 0)
    assert row["creation_trials"] == 1 and row["creation_skipped_trial"] == ""
    assert summary_row({})["trials_to_learn"] == ""


def test_every_column_of_sweep_csv_exact(tmp_path, monkeypatch):
    import creative_py.learning.run as run_mod

    summaries = {0: FULL, 1: USE_ONLY}
    seen = []

    def fake_run_case(case, out, opts, run_name=None):
        seen.append((case, opts.strategy, opts.seed, opts.world_seed, opts.phase,
                     opts.max_trials, opts.eval_trials, run_name))
        if opts.world_seed == 2:
            raise ValueError("no reachable pose")
        folder = Path(out) / run_name
        folder.mkdir(parents=True)
        (folder / "summary.json").write_text(json.dumps(summaries[opts.world_seed]))
        return type("Run", (), {"path": folder})()

    monkeypatch.setattr(run_mod, "run_case", fake_run_case)
    runs = plan_runs(["rake"], ["informative"], [5], [0, 1, 2])
    res = run_sweep(runs, tmp_path, SweepOptions(phase="use", max_trials=9, eval_trials=1),
                    serial=True, progress=lambda _m: None, name="s")
    assert seen == [("rake", "informative", 5, w, "use", 9, 1, f"rake-informative-s5-w{w}")
                    for w in (0, 1, 2)]
    with (tmp_path / "s" / "sweep.csv").open(newline="") as fh:
        reader = csv.reader(fh)
        header = next(reader)
        rows = [dict(zip(header, r)) for r in reader]
    assert header == list(COLUMNS)
    runs_dir = tmp_path / "s" / "runs"
    for row in rows:
        float(row.pop("wall_time_s"))
    assert rows == [
        {"case": "rake", "strategy": "informative", "seed": "5", "world_seed": "0",
         "status": "ok", "error": "", "trials_to_learn": "7", "use_converged": "True",
         "creation_trials": "2", "creation_skipped_trial": "True", "eval_successes": "3",
         "eval_trials": "4", "created_eval_successes": "2", "created_eval_trials": "5",
         "hg": "h :- a", "vs_count_initial": "1024", "info_bound_trials": "10",
         "run_dir": str(runs_dir / "rake-informative-s5-w0")},
        {"case": "rake", "strategy": "informative", "seed": "5", "world_seed": "1",
         "status": "ok", "error": "", "trials_to_learn": "3", "use_converged": "False",
         "creation_trials": "", "creation_skipped_trial": "", "eval_successes": "",
         "eval_trials": "", "created_eval_successes": "", "created_eval_trials": "",
         "hg": "", "vs_count_initial": "", "info_bound_trials": "",
         "run_dir": str(runs_dir / "rake-informative-s5-w1")},
        {"case": "rake", "strategy": "informative", "seed": "5", "world_seed": "2",
         "status": "crashed", "error": "ValueError: no reachable pose",
         "trials_to_learn": "", "use_converged": "", "creation_trials": "",
         "creation_skipped_trial": "", "eval_successes": "", "eval_trials": "",
         "created_eval_successes": "", "created_eval_trials": "", "hg": "",
         "vs_count_initial": "", "info_bound_trials": "", "run_dir": ""},
    ]
    assert [r["status"] for r in res.rows] == ["ok", "ok", "crashed"]
    meta = json.loads((tmp_path / "s" / "sweep.json").read_text())
    assert (meta["ok"], meta["crashed"]) == (2, 1)


def test_plan_runs_order_and_names():
    runs = plan_runs(["rake", "hook"], ["paper", "random"], [0, 1], [None, 3])
    assert [(r.case, r.strategy, r.world_seed, r.seed) for r in runs] == [
        (c, s, w, seed) for c in ("rake", "hook") for s in ("paper", "random")
        for w in (None, 3) for seed in (0, 1)]
    assert RunSpec("hook", "paper", 2, None).name == "hook-paper-s2-files"
    assert RunSpec("hook", "paper", 2, 0).name == "hook-paper-s2-w0"


@pytest.mark.parametrize("text,expected", [
    ("3", [3]), ("0-3", [0, 1, 2, 3]), ("0,2,5-7", [0, 2, 5, 6, 7]), ("4-4", [4]),
    (" 1 , 2 ", [1, 2]),
])
def test_parse_ints_exact(text, expected):
    assert parse_ints(text, "--seeds") == expected


@pytest.mark.parametrize("text,says", [
    ("5-2", "--seeds 5-2: the range 5-2 is empty (end before start)"),
    ("1,1", "--seeds 1,1: a number is given twice"),
    ("-1", "--seeds -1: '-1' is not a whole number >= 0 or a range A-B"),
    ("1-x", "--seeds 1-x: '1-x' is not a whole number >= 0 or a range A-B"),
])
def test_parse_ints_errors_exact(text, says):
    with pytest.raises(ValueError) as caught:
        parse_ints(text, "--seeds")
    assert str(caught.value) == says
