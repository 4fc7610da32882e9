"""Cases over drawn worlds on each robot: tool-use learning per world, side by side.

For each case and robot, ``creative sweep CASE --world-seeds A-B --phase use --serial --robot
ROBOT`` (one run per world seed, seed 0, one after the other in one process), and the
rows of its ``sweep.csv``: per world, the tool-use trials, whether learning converged
and the learned model's evaluation. Writes ``bench/results/robots_worlds.json``;
``bench/readme_figures.py`` puts the summary into ``docs/results.md``.

    .venv/bin/python bench/robots_worlds.py [--cases hook wedge] [--robots NAME ...]
                                            [--world-seeds 0-19] [--out FILE]
                                            [--record CSV ...]

``--record`` records finished sweeps' ``sweep.csv`` files again, running nothing
(each file's rows carry their robot in the run folder's ``run.json``).
"""

from __future__ import annotations

import argparse
import csv
import json
import platform
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from recording import add_output_options, write_figures

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TRACKED = "robots_worlds.json"
CREATIVE = Path(sys.executable).parent / "creative"


def rows_of(csv_path: Path) -> list[dict]:
    """Return the rows of one ``sweep.csv``, each with its robot (from ``run.json``)."""
    out = []
    with open(csv_path, newline="") as f:
        for r in csv.DictReader(f):
            meta = json.loads((Path(r["run_dir"]) / "run.json").read_text())
            out.append({"robot": meta["options"].get("robot"), "case": r["case"],
                        "world_seed": int(r["world_seed"]), "status": r["status"],
                        "use_trials": int(r["trials_to_learn"]) if r["trials_to_learn"] else None,
                        "converged": r["use_converged"] == "True",
                        "eval_successes": int(r["eval_successes"] or 0),
                        "eval_trials": int(r["eval_trials"] or 0),
                        "wall_time_s": float(r["wall_time_s"] or 0.0)})
    return out


def summary(rows: list[dict]) -> dict:
    """Return the summary of the rows per case and robot (``"hook panda"``)."""
    out = {}
    for key in sorted({f"{r['case']} {r['robot']}" for r in rows}):
        rows_of_key = [r for r in rows if f"{r['case']} {r['robot']}" == key]
        mine = [r for r in rows_of_key if r["status"] == "ok"]
        trials = [r["use_trials"] for r in mine]
        out[key] = {"worlds": len(mine), "crashed": len(rows_of_key) - len(mine),
                      "use_trials_median": statistics.median(trials) if trials else None,
                      "use_trials_min": min(trials, default=None),
                      "use_trials_max": max(trials, default=None),
                      "converged": sum(r["converged"] for r in mine),
                      "eval_successes": sum(r["eval_successes"] for r in mine),
                      "eval_trials": sum(r["eval_trials"] for r in mine)}
    return out


def main() -> int:
    """Run (or record) the sweeps and write the record."""
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", nargs="+", default=["hook", "wedge"],
                    help="case ids to sweep (default: hook wedge)")
    ap.add_argument("--robots", nargs="+", default=["baxter", "panda"],
                    help="robot profiles to sweep each case on (default: baxter panda)")
    ap.add_argument("--world-seeds", default="0-19",
                    help="the drawn worlds, as creative sweep --world-seeds takes them "
                         "(default: 0-19)")
    ap.add_argument("--from-csv", nargs="+", type=Path, metavar="CSV",
                    help="read these sweep.csv files instead of running the sweeps")
    add_output_options(ap, TRACKED, "the rows and their summary (JSON)")
    args = ap.parse_args()
    csvs = list(args.from_csv or [])
    command = (f"creative sweep CASE --world-seeds {args.world_seeds} --phase use --serial "
               "--robot ROBOT")
    if not csvs:
        base = Path(tempfile.mkdtemp(prefix="robots-worlds-"))
        for case in args.cases:
            for robot in args.robots:
                out = base / f"{case}-{robot}"
                subprocess.run([str(CREATIVE), "sweep", case, "--world-seeds",
                                args.world_seeds, "--phase", "use", "--serial", "--robot",
                                robot, "--out", str(out)], cwd=ROOT, check=False)
                csvs += sorted(out.glob("*/sweep.csv"))
    rows = [r for c in csvs for r in rows_of(c)]
    rows.sort(key=lambda r: (r["case"], r["robot"], r["world_seed"]))
    figures = {
        "bench": "robots_worlds", "command": command,
        "machine": f"{platform.node()} ({platform.machine()}), shared 2-core",
        "recorded": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "summary": summary(rows), "rows": rows}
    for key, line in figures["summary"].items():
        print(f"{key}: tool-use trials median {line['use_trials_median']}, converged in "
              f"{line['converged']} worlds, evaluation {line['eval_successes']} of "
              f"{line['eval_trials']}")
    write_figures(args, TRACKED, figures)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
