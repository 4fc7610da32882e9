"""The robots x cases table: every case with a robot run whole on every robot profile named.

Each run is ``creative run CASE --robot ROBOT --seed 0 --strategy informative --video
none --demonstrate-creation`` in its own process, one after the other (a tool is made
even when a catalogued object solved the harder task, so every cell shows a created
tool). Records per run: the tool-use trials and their stop, the evaluation of the
learned model, the created tool (its trial, its evaluation, its strength verdict), the
wall time and the robot's physics step cost (the arm alone at rest, from ``creative
robots``' check). Writes ``bench/results/robots_cases.json`` (runs already recorded for
other pairs are kept); ``bench/readme_figures.py`` puts the table into
``docs/results.md``.

    .venv/bin/python bench/robots_cases.py [--robots NAME ...] [--cases CASE ...]
                                           [--out FILE] [--keep DIR] [--steps-only]
"""

from __future__ import annotations

import argparse
import json
import platform
import re
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from recording import add_output_options, output_path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TRACKED = "robots_cases.json"
CREATIVE = Path(sys.executable).parent / "creative"


def record(folder: Path, wall_s: float) -> dict:
    """Return the figures of one finished run folder."""
    summary = json.loads((folder / "summary.json").read_text())
    use = summary.get("use") or {}
    create = summary.get("create") or {}
    tools = []
    for t in create.get("created_tools", []):
        strength = t.get("strength") or {}
        tools.append({"name": t.get("name"), "dims": t.get("dims"),
                      "trial_outcome": t.get("trial_outcome"),
                      "eval_outcomes": t.get("eval_outcomes"),
                      "strength": strength.get("verdict"),
                      "safety_factor": strength.get("safety_factor")})
    trials = [json.loads(line) for line in
              (folder / "trials.jsonl").read_text().splitlines() if line.strip()]
    return {"robot": (summary.get("options") or {}).get("robot"),
            "use_trials": use.get("trials"), "use_stop": use.get("stop"),
            "eval": summary.get("eval"), "solved_by": create.get("solved_by"),
            "created_tools": tools, "trials": len(trials),
            "trial_lines": [{k: t.get(k) for k in ("phase", "tool", "variant", "outcome")}
                            for t in trials],
            "wall_time_s": round(wall_s, 1)}


def step_cost(robot: str) -> float | None:
    """Return the robot's physics step cost (us) as ``creative robots`` measures it."""
    proc = subprocess.run([str(CREATIVE), "robots", robot], cwd=ROOT, capture_output=True,
                          text=True)
    m = re.search(r"(\d+) us per step", proc.stdout)
    return float(m.group(1)) if m else None


def write(out: Path | None, steps: dict, runs: dict) -> None:
    """Write the record (nowhere without --out or --record)."""
    if out is None:
        return
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps({
        "bench": "robots_cases", "machine": f"{platform.node()} ({platform.machine()}), "
        "shared 2-core", "recorded": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "step_us": steps, "runs": runs}, indent=1) + "\n")


def main() -> int:
    """Run the pairs and write the record; return 1 if a run failed."""
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--robots", nargs="+", default=["baxter", "panda"],
                    help="robot profiles to run every case on (default: baxter panda)")
    ap.add_argument("--cases", nargs="+", default=None,
                    help="case ids (default: every case that names a robot)")
    add_output_options(ap, TRACKED, "the table's runs (JSON; runs of robots and cases "
                       "not run again are kept from the file)")
    ap.add_argument("--keep", type=Path, help="keep the run folders under DIR")
    ap.add_argument("--steps-only", action="store_true",
                    help="measure the robots' step costs again, running no case")
    args = ap.parse_args()
    if args.cases is None:
        from creative_py.case import load_cases

        args.cases = sorted(c for c, m in load_cases().items() if m.robot)
    target = output_path(args, TRACKED)
    old = json.loads(target.read_text()) if target and target.exists() else {}
    runs, steps = dict(old.get("runs", {})), dict(old.get("step_us", {}))
    base = args.keep or Path(tempfile.mkdtemp(prefix="robots-cases-"))
    failed = []
    for robot in args.robots:
        steps[robot] = step_cost(robot)
        for case in [] if args.steps_only else args.cases:
            out = base / f"{robot}-{case}"
            shutil.rmtree(out, ignore_errors=True)
            argv = [str(CREATIVE), "run", case, "--robot", robot, "--seed", "0", "--out",
                    str(out), "--strategy", "informative", "--video", "none",
                    "--demonstrate-creation"]
            t0 = time.perf_counter()
            proc = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True)
            wall = time.perf_counter() - t0
            folders = sorted(p for p in out.glob("*") if (p / "summary.json").exists())
            if proc.returncode != 0 or not folders:
                failed.append(f"{robot}-{case}")
                runs[f"{robot}-{case}"] = {"robot": robot, "error":
                                           (proc.stderr.strip().splitlines() or [""])[-1]}
                print(f"robot {robot}, case {case}: the run failed (exit "
                      f"{proc.returncode})", flush=True)
                continue
            runs[f"{robot}-{case}"] = record(folders[-1], wall)
            print(f"robot {robot}, case {case}: {wall:.0f} s of wall time, run folder "
                  f"{folders[-1]}", flush=True)
            write(target, steps, runs)
    write(target, steps, runs)
    print(f"figures written to {target}" if target else "figures not written (give --out "
          f"FILE, or --record to update the tracked bench/results/{TRACKED})")
    if args.keep is None:
        shutil.rmtree(base, ignore_errors=True)
    if failed:
        print("failed: " + ", ".join(failed))
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
