"""creative sweep: two runs on a local Ray instance, and bad options refused before Ray.

The two runs (the rake case, world seeds 0 and 1, tool-use learning limited to one
trial, no evaluation) each run in their own Ray worker process and run folder; the
sweep's sweep.csv is read back with the csv module, and sweep.png with matplotlib.
"""

import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from creative_py.sweep import (COLUMNS, SweepOptions, parse_ints, plan_runs, run_sweep)

ROOT = Path(__file__).resolve().parents[2]
CREATIVE = [sys.executable, "-m", "creative_py.cli"]


@pytest.mark.sim  # about 20 s on 2 quiet cores: Ray's start and two short runs
def test_two_runs_on_a_local_ray_instance(tmp_path):
    runs = plan_runs(["rake"], ["paper"], [0], parse_ints("0-1", "--world-seeds"))
    lines = []
    res = run_sweep(runs, tmp_path, SweepOptions(phase="use", max_trials=1, eval_trials=0),
                    num_cpus=2, progress=lines.append, name="s")
    with (tmp_path / "s" / "sweep.csv").open(newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert [tuple(r) for r in rows][:1] == [tuple(COLUMNS)]
    assert [(r["case"], r["strategy"], r["seed"], r["world_seed"]) for r in rows] == [
        ("rake", "paper", "0", "0"), ("rake", "paper", "0", "1")]
    assert [r["status"] for r in rows] == ["ok", "ok"], [r["error"] for r in rows]
    for r in rows:
        assert r["trials_to_learn"] == "1"
        folder = Path(r["run_dir"])
        assert folder.parent == tmp_path / "s" / "runs"
        summary = json.loads((folder / "summary.json").read_text())
        assert summary["world_seed"] == int(r["world_seed"])
        meta = json.loads((folder / "run.json").read_text())
        assert meta["drawn_world"] == summary["drawn_world"]
    assert rows[0]["run_dir"] != rows[1]["run_dir"]
    import matplotlib.image
    img = matplotlib.image.imread(tmp_path / "s" / "sweep.png")
    assert img.shape[0] > 100 and img.shape[1] > 100
    assert len(lines) == 2 and "[2/2, 0 left]" in lines[-1]
    assert json.loads((tmp_path / "s" / "sweep.json").read_text())["ok"] == 2
    assert res.wall_time_s > 0


@pytest.mark.parametrize("args, says", [
    (["hook", "--seeds", "5-2"], "--seeds 5-2: the range 5-2 is empty"),
    (["hook", "--strategies", "paper,bogus"], "unknown strategy 'bogus'"),
    (["hok"], "unknown case 'hok'"),
    (["hook", "--world-seeds", "1-x"], "--world-seeds 1-x"),
    (["hook", "--world-seeds", "3", "--prior", "/nonexistent/hook-w{world}"],
     "--prior /nonexistent/hook-w3: no such run folder or model file"),
])
def test_bad_options_are_one_line_and_exit_2_before_ray(tmp_path, args, says):
    env = dict(os.environ, RAY_ADDRESS="")
    p = subprocess.run(CREATIVE + ["sweep", *args, "--out", str(tmp_path)], cwd=ROOT,
                       capture_output=True, text=True, env=env, timeout=120)
    assert p.returncode == 2
    errors = [ln for ln in p.stderr.splitlines() if ln.startswith("error:")]
    assert len(errors) == 1 and says in errors[0], p.stderr
    assert "Traceback" not in p.stderr
    assert list(tmp_path.iterdir()) == []


@pytest.mark.sim
@pytest.mark.slow
def test_two_runs_one_after_another_in_one_process(tmp_path):
    """--serial: the runs share this process and its one Prolog engine."""
    runs = plan_runs(["rake"], ["paper"], [0], [0, 1])
    res = run_sweep(runs, tmp_path, SweepOptions(phase="use", max_trials=1, eval_trials=0),
                    serial=True, progress=lambda _m: None, name="s")
    assert [r["status"] for r in res.rows] == ["ok", "ok"], [r["error"] for r in res.rows]
    drawn = [json.loads((Path(r["run_dir"]) / "run.json").read_text())["drawn_world"]
             for r in res.rows]
    assert drawn[0] != drawn[1]
    assert (tmp_path / "s" / "sweep.png").is_file()


def test_a_crashed_run_is_a_row_and_the_sweep_goes_on(tmp_path, monkeypatch):
    """A run that raises is recorded (status crashed, its error's last line) and the
    next run still runs; sweep.csv, sweep.json and sweep.png are written."""
    import creative_py.learning.run as run_mod

    calls = []

    def fake_run_case(case, out, opts, run_name=None):
        calls.append(opts.world_seed)
        if opts.world_seed == 0:
            raise RuntimeError("the arm fell off\nsecond line")
        folder = Path(out) / run_name
        folder.mkdir(parents=True)
        (folder / "summary.json").write_text(json.dumps({
            "use": {"trials": 3, "converged": True}, "eval": {"trials": 2, "successes": 2},
            "info_bound_trials": 4, "vs_count_initial": 16}))
        return type("Run", (), {"path": folder})()

    monkeypatch.setattr(run_mod, "run_case", fake_run_case)
    lines = []
    res = run_sweep(plan_runs(["rake"], ["paper"], [0], [0, 1]), tmp_path,
                    SweepOptions(phase="use"), serial=True, progress=lines.append, name="s")
    assert calls == [0, 1]
    assert [r["status"] for r in res.rows] == ["crashed", "ok"]
    assert res.rows[0]["error"] == "RuntimeError: the arm fell off second line"
    assert res.rows[1]["trials_to_learn"] == 3
    rows = list(csv.DictReader((tmp_path / "s" / "sweep.csv").open(newline="")))
    assert [r["status"] for r in rows] == ["crashed", "ok"]
    meta = json.loads((tmp_path / "s" / "sweep.json").read_text())
    assert (meta["ok"], meta["crashed"]) == (1, 1)
    assert (tmp_path / "s" / "sweep.png").stat().st_size > 0
    assert "crashed" in lines[0] and "[2/2, 0 left]" in lines[1]


def test_each_run_gets_its_prior_of_its_world(tmp_path, monkeypatch):
    """--prior with {world}: each run of the sweep starts from the prior of its world."""
    import creative_py.learning.run as run_mod
    from creative_py.sweep import RunSpec, prior_for

    assert prior_for(RunSpec("rake", "informative", 2, 7), "r/hook-w{world}-s{seed}") \
        == "r/hook-w7-s2"
    assert prior_for(RunSpec("rake", "informative", 0, None), "r/{world}") == "r/files"
    assert prior_for(RunSpec("rake", "informative", 0, 1), None) is None
    seen = {}

    def fake_run_case(case, out, opts, run_name=None):
        seen[opts.world_seed] = opts.prior
        raise RuntimeError("not run")

    monkeypatch.setattr(run_mod, "run_case", fake_run_case)
    run_sweep(plan_runs(["rake"], ["informative"], [0], [1, 2]), tmp_path,
              SweepOptions(phase="use", prior="m/hook-w{world}"), serial=True,
              progress=lambda _m: None, name="s")
    assert seen == {1: "m/hook-w1", 2: "m/hook-w2"}
