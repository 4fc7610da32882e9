"""RoboToolBench's tasks as cases, over drawn worlds, beside the benchmark's published
figures (``make bench-robotoolbench``).

Every case whose manifest names the benchmark (``[benchmark] name = "robotoolbench"``,
its task in ``task``; docs/robotoolbench.md) is run whole, once per world seed:
``creative run CASE --seed 0 --world-seed W --video none`` (demonstration, tool-use
learning, evaluation, tool creation on the harder variant, which is the benchmark's own
task). Per task it records, over the worlds:

- the reward on the benchmark's task (the case's measured verdict, the benchmark's
  formula): in each world the best of the trials run on the harder variant, and its
  mean and best over the worlds (the benchmark's figure is the mean over 5 runs of each
  run's best rollout, and the best of them);
- the successes (worlds whose best reward exceeds 0.99, the benchmark's ``done()``);
- the simulated trials used, by phase (demonstration, experiments, creation,
  evaluation) and the wall time;
- which tool solved it: learned (the model's catalogued tool), catalogue (another
  catalogued object) or created, with its dimensions;
- for a case whose run cannot start because its trainer's demonstration fails the
  benchmark's done() (MoveBall, whose best state scores 0.884), one row with the
  reward of the demonstrated tool on the benchmark's task and a note saying so;

beside the published figures of VLMgineer, the robotics expert and the bare gripper
(the project page's figure, read in pixels: +-0.01) and the rollouts each used.
Writes ``bench/results/robotoolbench.json`` (``--record``); ``bench/readme_figures.py``
puts the table into ``docs/results.md``.

    .venv/bin/python bench/robotoolbench.py [--cases ID ...] [--world-seeds 0-4]
                                            [--out FILE | --record] [--from-runs DIR ...]

``--from-runs`` records finished run folders again, running nothing. Written to a file
that holds other tasks (``--cases`` re-runs some), their rows and figures are kept, each
task's figures saying when they were ``recorded``.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from recording import add_output_options, output_path, write_figures

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
TRACKED = "robotoolbench.json"
CREATIVE = Path(sys.executable).parent / "creative"
BENCHMARK = "robotoolbench"
DONE = 0.99
"""The benchmark's done(): reward > 0.99."""

SOURCE = ("vlmgineer.github.io/release, 'Quantitative Results on RoboToolBench' "
          "(static/images/quan.png, 2025-06-19), bars read in pixels (+-0.01); the "
          "compute from the configs of MatteoCasazza/vlmgineer @7a0ea40 "
          "(scripts/run_benchmark.py, configs/, baseline/)")

PUBLISHED = {
    # task: method -> (mean over 5 runs, best run); each run's figure is its best rollout.
    "BringCube": {"vlmgineer": (1.00, 1.00), "expert": (0.98, 1.00), "gripper": (0.00, 0.00)},
    "CleanTable": {"vlmgineer": (0.90, 1.00), "expert": (0.45, 0.63), "gripper": (0.00, 0.00)},
    "DislodgeCube": {"vlmgineer": (1.00, 1.00), "expert": (0.01, 0.05), "gripper": (0.00, 0.00)},
    "ElevatePlate": {"vlmgineer": (0.96, 0.99), "expert": (0.16, 0.79), "gripper": (0.00, 0.00)},
    "GatherSpheres": {"vlmgineer": (0.99, 1.00), "expert": (0.68, 0.97), "gripper": (0.00, 0.11)},
    "HighObject": {"vlmgineer": (1.00, 1.00), "expert": (0.29, 1.00), "gripper": (0.00, 0.00)},
    "LiftBox": {"vlmgineer": (0.94, 0.97), "expert": (0.16, 0.75), "gripper": (0.00, 0.00)},
    "MoveBall": {"vlmgineer": (0.86, 0.88), "expert": (0.78, 0.84), "gripper": (0.25, 0.64)},
    "OneBook": {"vlmgineer": (0.86, 0.88), "expert": (0.43, 0.75), "gripper": (0.58, 0.74)},
    "ScoreGoal": {"vlmgineer": (1.00, 1.00), "expert": (0.17, 0.40), "gripper": (0.00, 0.00)},
    "SnatchCookie": {"vlmgineer": (1.00, 1.00), "expert": (0.40, 1.00), "gripper": (0.00, 0.24)},
    "TurkeyLegs": {"vlmgineer": (1.00, 1.00), "expert": (0.00, 0.00), "gripper": (0.00, 0.00)},
}
"""The published rewards per task (docs/robotoolbench.md; the notes' section 2a)."""

ROLLOUTS = {
    "vlmgineer": ("up to 8,000 per run (20 agents x 10 tools x 10 action sets x 4 rounds; "
                  "HighObject's config 16,000), each run's figure its best rollout; "
                  "80 VLM calls"),
    "expert": "not stated in the sources read (one human-prompted design per run)",
    "gripper": "50 per run (5 agents x 10 action sets, baseline/no_tool.py)",
}
"""What each published figure cost in simulated rollouts, per run of 5."""


def benchmark_cases(root: Path | None = None) -> dict[str, str]:
    """Return ``case id -> the benchmark's task`` for every case the benchmark marks
    (the cases of ``root``, default ``worlds/``); raise ValueError naming the case file
    whose ``[benchmark] task`` is no task of :data:`PUBLISHED` (its figures would be
    missing from the table)."""
    import difflib

    from creative_py.case import load_cases

    tasks = {}
    for cid, m in sorted(load_cases(root).items()):
        if m.benchmark != BENCHMARK:
            continue
        if m.benchmark_task not in PUBLISHED:
            close = difflib.get_close_matches(m.benchmark_task, list(PUBLISHED), n=1)
            raise ValueError(
                f"{m.folder / 'case.toml'}: field 'benchmark.task': "
                f"{m.benchmark_task!r} is no RoboToolBench task"
                + (f" (did you mean {close[0]!r}?)" if close else "")
                + f"; tasks: {', '.join(PUBLISHED)}")
        tasks[cid] = m.benchmark_task
    return tasks


def _sizes(fields: dict) -> dict:
    """Return the lengths and widths (m) of a tool's fields."""
    return {k: round(float(v), 4) for k, v in fields.items()
            if isinstance(v, (int, float)) and not isinstance(v, bool)
            and (k.endswith("length") or k.endswith("width"))}


def _tool_dimensions(summary: dict, tool: str | None) -> dict:
    """Return the solving tool's lengths and widths (m): a created tool's from the
    summary, a catalogued one's from the run's drawn world or the case's catalogue."""
    if tool is None:
        return {}
    for t in (summary.get("create") or {}).get("created_tools") or ():
        if isinstance(t, dict) and t.get("name") == tool:
            return _sizes(t.get("dims") or {})
    from creative_py.case import load_cases
    from creative_py.simulator.loader import backend_for

    manifest = load_cases()[summary["case"]]
    world = backend_for(manifest).load_world(manifest)
    dims = _sizes(world.item(tool).spec.feature_dimensions())
    drawn = summary.get("drawn_world") or {}
    objects = drawn.get("objects") if isinstance(drawn, dict) else None
    if isinstance(objects, dict) and isinstance(objects.get(tool), dict):
        dims.update(_sizes(objects[tool]))  # a drawn world holds the fields it redrew
    return dims


def world_row(run_dir: Path) -> dict:
    """Return one world's figures from a finished run folder."""
    summary = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))
    trials = [json.loads(line) for line in
              (run_dir / "trials.jsonl").read_text(encoding="utf-8").splitlines() if line]
    create = summary.get("create") or {}
    harder = create.get("variant")
    on_task = [t for t in trials if t.get("variant") == harder
               and (t.get("verdict") or {}).get("quantity") == "reward"]
    best = max(on_task, key=lambda t: t["verdict"]["value"], default=None)
    reward = None if best is None else best["verdict"]["value"]
    by_phase = {k: (summary.get("trials") or {}).get(k, {}).get("trials", 0)
                for k in ("use", "eval", "create")}
    created = [t.get("name") for t in create.get("created_tools") or ()
               if isinstance(t, dict)]
    solved_by = create.get("solved_by")
    tool = None
    if best is not None and reward is not None and reward > DONE:
        tool = best.get("tool")
    kind = ("created" if tool in created else
            "catalogued" if tool is not None else None)
    return {"case": summary["case"], "world_seed": summary.get("world_seed"),
            "run_dir": str(run_dir), "reward": reward,
            "success": reward is not None and reward > DONE,
            "trials": {"demonstration": _demonstrations(summary),
                       "experiments": by_phase["use"],
                       "creation": by_phase["create"], "evaluation": by_phase["eval"]},
            "trials_on_task": len(on_task),
            "wall_time_s": (summary.get("wall_time_s") or {}).get("total"),
            "solved_by": solved_by, "tool": tool, "tool_kind": kind,
            "tool_dimensions": _tool_dimensions(summary, tool)}


def _demonstrations(summary: dict) -> int:
    """Return how many times the run played the trainer's demonstration: once, and in
    a drawn world once more for each draw of the demonstration's location checked
    against the goal (the last one the run keeps) before the run's own."""
    drawn = summary.get("drawn_world")
    if not isinstance(drawn, dict):
        return 1
    return int(drawn.get("redraws") or 0) + 2


def task_summary(task: str, rows: list[dict]) -> dict:
    """Return a task's figures over its worlds, beside the published ones."""
    rewards = [r["reward"] if r["reward"] is not None else 0.0 for r in rows]
    trials = {k: sum(r["trials"][k] for r in rows)
              for k in ("demonstration", "experiments", "creation", "evaluation")}
    walls = [r["wall_time_s"] for r in rows if r["wall_time_s"] is not None]
    tools = sorted({f"{r['tool']} ({r['tool_kind']})" for r in rows if r["tool"]})
    stopped = sorted(w for r in rows for w in r.get("stopped_worlds") or ())
    return {"case": rows[0]["case"] if rows else None,
            "worlds": len(rows) - sum(1 for r in rows if r.get("stopped_worlds"))
            + len(stopped),
            "stopped_at_demonstration": stopped,
            "reward_mean": round(statistics.mean(rewards), 4) if rewards else None,
            "reward_best": round(max(rewards), 4) if rewards else None,
            "successes": sum(r["success"] for r in rows),
            "trials": trials, "trials_total": sum(trials.values()),
            "trials_per_world": round(sum(trials.values()) / len(rows), 1) if rows else None,
            "wall_time_s": round(sum(walls), 1), "tools": tools,
            "published": PUBLISHED.get(task)}


def run_worlds(case: str, seeds: list[int], base: Path
               ) -> tuple[list[Path], list[int], list[dict]]:
    """Run the case once per world seed; return the run folders, the world seeds whose
    run stopped at the trainer's demonstration (exit 2, its error line naming the
    demonstration: it failed its verdict, nothing to learn), and the runs that failed
    otherwise (world seed, exit code, the end of the standard error)."""
    out, stopped, failed = [], [], []
    for w in seeds:
        parent = base / f"{case}-w{w}"
        proc = subprocess.run([str(CREATIVE), "run", case, "--seed", "0", "--world-seed",
                               str(w), "--video", "none", "--out", str(parent)], cwd=ROOT,
                              check=False, stderr=subprocess.PIPE, text=True)
        sys.stderr.write(proc.stderr)
        done = sorted(p.parent for p in parent.glob("*/summary.json"))
        out += done
        last = (proc.stderr.strip().splitlines() or [""])[-1]
        if done and proc.returncode == 0:
            continue
        if not done and proc.returncode == 2 and "demonstration" in last:
            stopped.append(w)
        else:
            failed.append({"case": case, "world_seed": w, "exit_code": proc.returncode,
                           "stderr_end": proc.stderr.strip().splitlines()[-5:]})
    return out, stopped, failed


def demonstration_row(case: str, world_seed: int) -> dict:
    """Return the row of a case whose run could not start: the trainer's tool and pose
    tried once on the benchmark's task (the harder variant, its first location).

    A task whose done() no state reaches (MoveBall: a ball at rest scores 0.884 at
    most) fails its demonstration's verdict, so nothing is learned; the reward the
    demonstrated tool reaches on the benchmark's task is still the figure to compare.
    """
    from creative_py.case import get_case

    m = get_case(case)
    t0 = time.monotonic()
    proc = subprocess.run([str(CREATIVE), "trial", case, "--tool", m.demonstration.tool,
                           "--variant", m.harder_variant, "--json"], cwd=ROOT,
                          capture_output=True, text=True, check=False)
    wall = round(time.monotonic() - t0, 1)
    reward = None
    if proc.returncode == 0 and proc.stdout.strip():
        verdict = json.loads(proc.stdout.strip().splitlines()[-1]).get("verdict") or {}
        if verdict.get("quantity") == "reward":
            reward = verdict.get("value")
    return {"case": case, "world_seed": world_seed, "run_dir": None, "reward": reward,
            "success": reward is not None and reward > DONE,
            "trials": {"demonstration": 1, "experiments": 0, "creation": 0,
                       "evaluation": 0},
            "trials_on_task": 1, "wall_time_s": wall, "solved_by": None, "tool": None,
            "tool_kind": None, "tool_dimensions": {},
            "note": (f"the demonstration fails done() (reward > {DONE}): nothing to learn; "
                     f"the reward is {m.demonstration.tool}'s at the demonstrated pose on "
                     "the benchmark's task")}


def seeds_of(text: str) -> list[int]:
    """Return the seeds of ``A-B`` or ``A,B,C``."""
    if "-" in text:
        a, b = text.split("-", 1)
        return list(range(int(a), int(b) + 1))
    return [int(s) for s in text.split(",")]


def main() -> int:
    """Run (or record) the worlds and write the record."""
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", nargs="+", default=None,
                    help="case ids (default: every case whose manifest names the benchmark)")
    ap.add_argument("--world-seeds", default="0-4",
                    help="the drawn worlds, A-B or A,B,C (default: 0-4)")
    ap.add_argument("--from-runs", nargs="+", type=Path, metavar="DIR",
                    help="record these finished run folders instead of running")
    add_output_options(ap, TRACKED, "the per-task figures (JSON)")
    args = ap.parse_args()
    try:
        tasks = benchmark_cases()
    except ValueError as exc:  # a world file's error (WorldFileError is one)
        print(f"error: {exc}", file=sys.stderr)
        return 2
    cases = args.cases or list(tasks)
    unknown = [c for c in cases if c not in tasks]
    if unknown:
        print(f"--cases: not RoboToolBench cases: {', '.join(unknown)} (cases: "
              f"{', '.join(tasks) or 'none'})", file=sys.stderr)
        return 2
    start = time.monotonic()
    extra: list[dict] = []
    failed: list[dict] = []
    if args.from_runs:
        dirs = list(args.from_runs)
    else:
        base = Path(tempfile.mkdtemp(prefix="robotoolbench-"))
        dirs = []
        for c in cases:
            done, stopped, bad = run_worlds(c, seeds_of(args.world_seeds), base)
            dirs += done
            failed += bad
            if stopped:  # `creative trial` takes no world seed: one row for them all
                row = demonstration_row(c, stopped[0])
                row["stopped_worlds"] = stopped
                extra.append(row)
    now = time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime())
    rows = [*(world_row(d) for d in dirs), *extra]
    by_task = {}
    for case in cases:
        mine = [r for r in rows if r["case"] == case]
        if mine:
            by_task[tasks[case]] = {**task_summary(tasks[case], mine), "recorded": now}
    # The tasks not run now keep their recorded rows and figures (--cases re-runs some).
    path = output_path(args, TRACKED)
    old = json.loads(path.read_text()) if path is not None and path.exists() else {}
    for task, figures in (old.get("tasks") or {}).items():
        if figures.get("case") not in cases and figures.get("case") in tasks:
            by_task[task] = {"recorded": old.get("recorded"), **figures}
            rows += [r for r in old.get("worlds") or () if r["case"] == figures["case"]]
            failed += [f for f in old.get("failed_runs") or () if f["case"] == figures["case"]]
    rows.sort(key=lambda r: (r["case"], r["world_seed"] or 0))
    by_task = {t: by_task[t] for t in tasks.values() if t in by_task}
    figures = {
        "bench": "robotoolbench",
        "command": (f"creative run CASE --seed 0 --world-seed W --video none, W in "
                    f"{args.world_seeds}"),
        "machine": f"{platform.node()} ({platform.machine()}), shared 2-core",
        "recorded": now,
        "bench_wall_time_s": round(time.monotonic() - start, 1),
        "done_threshold": DONE, "published_source": SOURCE, "rollouts": ROLLOUTS,
        "tasks": by_task, "worlds": rows, "failed_runs": failed}
    for task, t in by_task.items():
        if t["case"] not in cases:
            continue  # kept from the file, not run now
        pub = t["published"] or {}
        print(f"{task} ({t['case']}): reward mean {t['reward_mean']} best {t['reward_best']}, "
              f"{t['successes']} of {t['worlds']} worlds, {t['trials_total']} trials, "
              f"{t['wall_time_s']} s; VLMgineer {pub.get('vlmgineer')}, expert "
              f"{pub.get('expert')}, gripper {pub.get('gripper')}")
    for f in failed:
        print(f"{f['case']} world {f['world_seed']}: the run failed (exit {f['exit_code']}): "
              f"{(f['stderr_end'] or [''])[-1]}", file=sys.stderr)
    write_figures(args, TRACKED, figures)
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
