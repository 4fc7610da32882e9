"""The benchmark scripts as a person meets them: every argument explained, and the
tracked figures in bench/results/ written only when asked (issue 32: running
bench/maniskill_bench.py without --out overwrote the tracked maniskill.json, and its
--help described none of its arguments)."""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from argparse import ArgumentParser
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BENCH = ROOT / "bench"
SCRIPTS = sorted(p for p in BENCH.glob("*.py") if p.name != "_test_cpu.py")

sys.path.insert(0, str(BENCH))
import recording  # noqa: E402


def _calls(tree: ast.AST, name: str) -> list[ast.Call]:
    return [n for n in ast.walk(tree) if isinstance(n, ast.Call)
            and isinstance(n.func, ast.Attribute) and n.func.attr == name]


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.name)
def test_every_argument_of_a_benchmark_has_help(script):
    tree = ast.parse(script.read_text(encoding="utf-8"))
    bare = [ast.unparse(c.args[0]) if c.args else "?"
            for c in _calls(tree, "add_argument")
            if not any(k.arg == "help" for k in c.keywords)]
    assert bare == [], f"{script.name}: arguments without help: {bare}"
    # Arguments are parsed by argparse (its --help), never picked out of sys.argv.
    picked = [n.lineno for n in ast.walk(tree) if isinstance(n, ast.Subscript)
              and ast.unparse(n.value) == "sys.argv" and not isinstance(n.slice, ast.Slice)]
    assert picked == [], f"{script.name}: sys.argv indexed at lines {picked}"


@pytest.mark.parametrize("script", SCRIPTS, ids=lambda p: p.name)
def test_a_benchmark_that_writes_bench_results_asks_for_record(script):
    """A script that names the tracked folder writes there only under --record (it
    takes the option, from bench/recording.py or its own)."""
    text = script.read_text(encoding="utf-8")
    if script.name in ("recording.py", "readme_figures.py", "run_all.py",
                       "transfer_bench.py"):
        # the helper; the generator of docs/results.md; the runner passing --record; a
        # script that writes only the file its --json names
        return
    if '"results"' in text or "bench/results" in text.replace("bench/results/<", ""):
        assert "add_output_options" in text or '"--record"' in text, script.name


def test_run_all_and_the_makefile_ask_for_the_tracked_files():
    run_all = (BENCH / "run_all.py").read_text(encoding="utf-8")
    listed = [line for line in run_all.splitlines() if 'str(HERE / "' in line]
    assert listed and all('"--record"' in line for line in listed), listed
    makefile = (ROOT / "Makefile").read_text(encoding="utf-8").replace("\\\n", " ")
    for line in makefile.splitlines():
        if line.startswith("\t") and "bench/" in line and ".py" in line:  # a recipe
            if any(s in line for s in ("readme_figures.py", "run_all.py")):
                continue
            assert "--record" in line or "--out bench/results/" in line, line


def test_figures_go_to_out_or_the_tracked_file_under_record_and_nowhere_else(
        tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(recording, "RESULTS", tmp_path / "results")
    parser = ArgumentParser()
    recording.add_output_options(parser, "x.json")
    figures = {"successes": 3}

    assert recording.write_figures(parser.parse_args([]), "x.json", figures) is None
    assert not (tmp_path / "results").exists()
    assert capsys.readouterr().out == (
        "figures not written (give --out FILE, or --record to update the tracked "
        "bench/results/x.json)\n")

    out = tmp_path / "mine.json"
    assert recording.write_figures(parser.parse_args(["--out", str(out)]), "x.json",
                                   figures) == out
    assert json.loads(out.read_text()) == figures and not (tmp_path / "results").exists()

    tracked = recording.write_figures(parser.parse_args(["--record"]), "x.json", figures)
    assert tracked == tmp_path / "results" / "x.json"
    assert json.loads(tracked.read_text()) == figures
    assert capsys.readouterr().out.splitlines()[-1] == f"figures written to {tracked}"
    with pytest.raises(SystemExit):
        parser.parse_args(["--out", str(out), "--record"])


def test_maniskill_bench_help_explains_every_argument():
    proc = subprocess.run([sys.executable, str(BENCH / "maniskill_bench.py"), "--help"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    for option in ("case ", "--run RUN_FOLDER", "--seeds FIRST:END", "--out FILE",
                   "--record"):
        assert option in proc.stdout
    assert "bench/results/maniskill.json" in proc.stdout


def test_the_robotoolbench_row_counts_every_demonstration_and_the_whole_tool(tmp_path):
    """A drawn world's run plays the demonstration once per checked draw and once for
    itself (redraws + 2), and a catalogued tool's dimensions are its catalogue's with
    the drawn fields over them (the drawn world keeps only what it redrew)."""
    import robotoolbench

    run = tmp_path / "run"
    run.mkdir()
    summary = {"case": "bring_cube", "world_seed": 3,
               "drawn_world": {"seed": 3, "redraws": 2,
                               "objects": {"hook_a1": {"handle_length": 0.31}}},
               "trials": {"use": {"trials": 6}}, "create": {"variant": "benchmark"}}
    (run / "summary.json").write_text(json.dumps(summary))
    trial = {"variant": "benchmark", "tool": "hook_a1",
             "verdict": {"quantity": "reward", "value": 0.995}}
    (run / "trials.jsonl").write_text(json.dumps(trial) + "\n")
    row = robotoolbench.world_row(run)
    assert row["trials"]["demonstration"] == 4 and row["tool_kind"] == "catalogued"
    dims = row["tool_dimensions"]
    assert dims["handle_length"] == 0.31 and "hook_length" in dims


def test_robotoolbench_re_running_some_tasks_keeps_the_others_figures(tmp_path, monkeypatch):
    """``--cases`` re-runs some tasks; the file's other tasks keep their rows and
    figures, each task saying when it was recorded (the whole file was rewritten with
    only the re-run task before)."""
    import robotoolbench

    run = tmp_path / "run"
    run.mkdir()
    (run / "summary.json").write_text(json.dumps({
        "case": "bring_cube", "world_seed": 0, "drawn_world": {"seed": 0, "redraws": 0},
        "trials": {"use": {"trials": 5}}, "create": {"variant": "benchmark"}}))
    (run / "trials.jsonl").write_text(json.dumps({
        "variant": "benchmark", "tool": "hook_a1",
        "verdict": {"quantity": "reward", "value": 0.995}}) + "\n")
    old_row = {"case": "one_book", "world_seed": 0, "reward": 0.5}
    out = tmp_path / "figures.json"
    out.write_text(json.dumps({
        "recorded": "2026-01-01 00:00 UTC",
        "tasks": {"OneBook": {"case": "one_book", "reward_mean": 0.5}},
        "worlds": [old_row], "failed_runs": []}))
    monkeypatch.setattr(sys, "argv", ["robotoolbench.py", "--cases", "bring_cube",
                                      "--from-runs", str(run), "--out", str(out)])
    assert robotoolbench.main() == 0
    got = json.loads(out.read_text())
    assert list(got["tasks"]) == ["BringCube", "OneBook"]
    assert got["tasks"]["OneBook"] == {"recorded": "2026-01-01 00:00 UTC", "case": "one_book",
                                       "reward_mean": 0.5}
    assert got["tasks"]["BringCube"]["recorded"] == got["recorded"] != "2026-01-01 00:00 UTC"
    assert [r["case"] for r in got["worlds"]] == ["bring_cube", "one_book"]
    assert got["worlds"][1] == old_row


def test_robotoolbench_refuses_a_task_it_has_no_published_figures_for(tmp_path, monkeypatch,
                                                                      capsys):
    """A misspelled ``[benchmark] task`` showed "n/a" in the table, silently."""
    import shutil

    import robotoolbench

    from creative_py.world_files import WORLDS_ROOT

    shutil.copytree(WORLDS_ROOT / "bring_cube", tmp_path / "bring_cube")
    case = tmp_path / "bring_cube" / "case.toml"
    case.write_text(case.read_text().replace('task = "BringCube"', 'task = "BringCub"'))
    message = (f"{case}: field 'benchmark.task': 'BringCub' is no RoboToolBench task (did "
               f"you mean 'BringCube'?); tasks: {', '.join(robotoolbench.PUBLISHED)}")
    with pytest.raises(ValueError) as info:
        robotoolbench.benchmark_cases(tmp_path)
    assert str(info.value) == message
    real = robotoolbench.benchmark_cases
    monkeypatch.setattr(robotoolbench, "benchmark_cases", lambda: real(tmp_path))
    monkeypatch.setattr(sys, "argv", ["robotoolbench.py", "--out", str(tmp_path / "o.json")])
    assert robotoolbench.main() == 2
    out, err = capsys.readouterr()
    assert (out, err) == ("", f"error: {message}\n")
    assert not (tmp_path / "o.json").exists()
    assert set(real().values()) <= set(robotoolbench.PUBLISHED)    # the shipped cases
