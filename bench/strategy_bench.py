"""Experiment strategies over randomised worlds, and the sweep's speed-up on Ray.

``table``: one ``creative sweep`` (every case x ``paper,informative,random`` x world
seeds 0-19, tool-use learning and the learned model's evaluation) on a local Ray
instance, or an existing sweep folder's ``sweep.csv`` (``--from``). Records, per case
and strategy: tool-use trials (median, range), how learning stopped, the learned
model's evaluation successes in those worlds, the information bound ceil(log2 N0) and
the paper's count, to ``bench/results/strategies.json``, and prints the table of docs/results.md.

``creation``: the harder task for every world seed with the default strategy (``--from``
a ``--phase all`` sweep folder, or run one): creation trials per world and whether the
model's failure was predicted (``summary.json``'s ``create.predicted``), to
``bench/results/creation_worlds_<case>.json``.

``speedup``: the same runs one after another in one process (``--serial``) and on a
local Ray instance with every core, each timed whole, to
``bench/results/sweep_speedup.json``.

    .venv/bin/python bench/strategy_bench.py table [--from runs/sweep-...] [--world-seeds 0-19]
    .venv/bin/python bench/strategy_bench.py creation --case hook [--from ...]
    .venv/bin/python bench/strategy_bench.py speedup [--cases ...] [--world-seeds 0-3]
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import tempfile
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))

from recording import add_output_options, output_path, write_figures  # noqa: E402

from creative_py.case import get_case, load_cases  # noqa: E402
from creative_py.learning.strategies import STRATEGIES  # noqa: E402
from creative_py.sweep import (SweepOptions, parse_ints, plan_runs, read_csv,  # noqa: E402
                               run_sweep)


def _machine() -> dict:
    return {"cores": os.cpu_count(), "load_before": os.getloadavg()[0]}


def _ints(rows, key):
    return [int(float(r[key])) for r in rows if r.get(key) not in ("", None)]


def summarise(rows: list[dict]) -> list[dict]:
    """Return one record per case and strategy of a sweep's rows."""
    out = []
    for case in dict.fromkeys(r["case"] for r in rows):
        for strategy in dict.fromkeys(r["strategy"] for r in rows):
            group = [r for r in rows if r["case"] == case and r["strategy"] == strategy]
            if not group:
                continue
            ok = [r for r in group if r["status"] == "ok"]
            trials = _ints(ok, "trials_to_learn")
            ev, evn = sum(_ints(ok, "eval_successes")), sum(_ints(ok, "eval_trials"))
            stops = Counter()
            for r in ok:
                summary = json.loads((Path(r["run_dir"]) / "summary.json").read_text())
                stops[summary["use"].get("stop") or
                      ("converged" if summary["use"].get("converged") else "budget")] += 1
            bounds = _ints(ok, "info_bound_trials")
            failed_eval = [int(r["world_seed"]) for r in ok
                           if r["eval_trials"] and r["eval_successes"] != r["eval_trials"]]
            out.append({
                "case": case, "strategy": strategy, "runs": len(group), "ok": len(ok),
                "crashed": [r["error"] for r in group if r["status"] != "ok"],
                "trials_median": statistics.median(trials) if trials else None,
                "trials_min": min(trials, default=None),
                "trials_max": max(trials, default=None),
                "trials": trials,
                "stops": dict(stops),
                "eval_successes": ev, "eval_trials": evn,
                "eval_rate": round(ev / evn, 4) if evn else None,
                "worlds_with_eval_failures": failed_eval,
                "info_bound_median": statistics.median(bounds) if bounds else None,
                "paper_trials": get_case(case).paper_trials,
                "trial_budget": get_case(case).trial_budget,
            })
    return out


def table_md(records: list[dict]) -> str:
    """Return the markdown table (docs/results.md) of :func:`summarise`'s records."""
    cases = list(dict.fromkeys(r["case"] for r in records))
    strategies = list(dict.fromkeys(r["strategy"] for r in records))
    by = {(r["case"], r["strategy"]): r for r in records}
    head = "| case (paper's count; ceil(log2 N0)) | " + " | ".join(
        f"`{s}`" for s in strategies) + " |"
    lines = [head, "|---|" + "---|" * len(strategies)]
    for c in cases:
        any_r = next(r for r in records if r["case"] == c)
        cells = []
        for s in strategies:
            r = by.get((c, s))
            if r is None:
                cells.append("-")
                continue
            crashed = f", {len(r['crashed'])} crashed" if r["crashed"] else ""
            cells.append(f"{r['trials_median']:g} [{r['trials_min']}-{r['trials_max']}]; "
                         f"model {r['eval_successes']}/{r['eval_trials']}{crashed}")
        paper = "-" if any_r["paper_trials"] is None else any_r["paper_trials"]
        lines.append(f"| {c} ({paper}; {any_r['info_bound_median']:g}) | "
                     + " | ".join(cells) + " |")
    return "\n".join(lines)


def cmd_table(args) -> int:
    if args.source:
        folder = Path(args.source)
        meta = json.loads((folder / "sweep.json").read_text())
    else:
        runs = plan_runs(args.cases, list(STRATEGIES), [0],
                         parse_ints(args.world_seeds, "--world-seeds"))
        res = run_sweep(runs, Path(tempfile.mkdtemp(prefix="strategy-bench-")),
                        SweepOptions(phase="use"))
        folder, meta = res.folder, {"wall_time_s": res.wall_time_s}
    rows = read_csv(folder / "sweep.csv")
    records = summarise(rows)
    result = {"sweep": str(folder), "runs": len(rows), "wall_time_s": meta["wall_time_s"],
              "options": meta.get("options"), "ray": meta.get("ray"),
              "world_seeds": sorted({int(r["world_seed"]) for r in rows
                                     if r["world_seed"] != ""}),
              "machine": {"cores": os.cpu_count()} if args.source else _machine(),
              "records": records}
    print(table_md(records))
    write_figures(args, "strategies.json", result)
    return 0


def cmd_creation(args) -> int:
    if args.source:
        folder = Path(args.source)
    else:
        runs = plan_runs([args.case], ["informative"], [0],
                         parse_ints(args.world_seeds, "--world-seeds"))
        folder = run_sweep(runs, Path(tempfile.mkdtemp(prefix="creation-bench-")),
                           SweepOptions(phase="all")).folder
    per_world = []
    for r in read_csv(folder / "sweep.csv"):
        rec = {"case": r["case"], "world_seed": r["world_seed"], "status": r["status"]}
        if r["status"] == "ok":
            s = json.loads((Path(r["run_dir"]) / "summary.json").read_text())
            c = s.get("create") or {}
            outcomes = (s.get("trials", {}).get("create") or {}).get("outcomes", [])
            rec.update(trials=c.get("trials"), outcomes=outcomes,
                       predicted=bool(c.get("predicted")),
                       predicted_why=c.get("predicted"),
                       created=[{"name": t["name"], "instance": t["instance"],
                                 "dims": t["dims"]} for t in c.get("created_tools", [])],
                       created_eval=c.get("eval"),
                       use_trials=s["use"]["trials"])
        else:
            rec["error"] = r["error"]
        per_world.append(rec)
    ok = [p for p in per_world if p["status"] == "ok"]
    result = {"sweep": str(folder), "worlds": len(per_world), "ok": len(ok),
              "predicted": sum(p["predicted"] for p in ok),
              "one_trial_where_predicted": sum(p["predicted"] and p["trials"] == 1
                                               for p in ok),
              "created_eval_successes": sum((p["created_eval"] or []).count("success")
                                            for p in ok),
              "created_eval_trials": sum(len(p["created_eval"] or []) for p in ok),
              "machine": {"cores": os.cpu_count()} if args.source else _machine(),
              "per_world": per_world}
    print({k: v for k, v in result.items() if k != "per_world"})
    write_figures(args, f"creation_worlds_{args.case}.json", result)
    return 0


def cmd_speedup(args) -> int:
    runs = plan_runs(args.cases, [args.strategy], [0],
                     parse_ints(args.world_seeds, "--world-seeds"))
    opts = SweepOptions(phase=args.phase)
    out = Path(tempfile.mkdtemp(prefix="speedup-bench-"))
    load0 = os.getloadavg()[0]
    serial = run_sweep(runs, out, opts, serial=True, name="serial")
    ray = run_sweep(runs, out, opts, name="ray", fresh_workers=args.fresh_workers)
    same = ([r["trials_to_learn"] for r in serial.rows]
            == [r["trials_to_learn"] for r in ray.rows])
    result = {"cases": args.cases, "strategy": args.strategy, "phase": args.phase,
              "fresh_workers": args.fresh_workers,
              "world_seeds": args.world_seeds,
              "runs": len(runs), "serial_s": serial.wall_time_s, "ray_s": ray.wall_time_s,
              "speedup": round(serial.wall_time_s / ray.wall_time_s, 3),
              "same_trial_counts": same, "load_before": load0,
              "cores": os.cpu_count(),
              "serial_run_s": [r["wall_time_s"] for r in serial.rows],
              "ray_run_s": [r["wall_time_s"] for r in ray.rows]}
    print(result)
    path = output_path(args, "sweep_speedup.json")
    recorded = json.loads(path.read_text()) if path is not None and path.exists() else {}
    recorded["fresh_workers" if args.fresh_workers else "reused_workers"] = result
    write_figures(args, "sweep_speedup.json", recorded)
    return 0


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="what", required=True)
    source = "read the runs of this sweep folder (its sweep.csv) instead of running them"
    t = sub.add_parser("table", help="trials to learn per strategy and case, over drawn "
                                     "worlds")
    t.add_argument("--from", dest="source", metavar="SWEEP_FOLDER", help=source)
    t.add_argument("--cases", nargs="+", default=sorted(load_cases()),
                   help="the cases (default: every case)")
    t.add_argument("--world-seeds", default="0-19",
                   help="the drawn worlds, as --world-seed takes them (default 0-19)")
    add_output_options(t, "strategies.json", "the table's figures (JSON)")
    c = sub.add_parser("creation", help="the creation phase of one case over drawn worlds")
    c.add_argument("--from", dest="source", metavar="SWEEP_FOLDER", help=source)
    c.add_argument("--case", required=True, help="the case")
    c.add_argument("--world-seeds", default="0-19",
                   help="the drawn worlds, as --world-seed takes them (default 0-19)")
    add_output_options(c, "creation_worlds_<case>.json", "the per-world creation figures "
                                                          "(JSON)")
    s = sub.add_parser("speedup", help="the same sweep serially and on ray's workers")
    s.add_argument("--cases", nargs="+", default=sorted(load_cases()),
                   help="the cases (default: every case)")
    s.add_argument("--strategy", default="informative",
                   help="the strategy of every run (default informative)")
    s.add_argument("--phase", default="use", help="the phase the runs stop after "
                                                  "(default use)")
    s.add_argument("--world-seeds", default="0-3",
                   help="the drawn worlds, as --world-seed takes them (default 0-3)")
    s.add_argument("--fresh-workers", action="store_true",
                   help="a fresh ray worker process for every run (default: reused)")
    add_output_options(s, "sweep_speedup.json", "the two wall times (JSON; the file's "
                                                 "figures of the other worker mode are "
                                                 "kept)")
    args = ap.parse_args()
    return {"table": cmd_table, "creation": cmd_creation, "speedup": cmd_speedup}[args.what](args)


if __name__ == "__main__":
    sys.exit(main())
