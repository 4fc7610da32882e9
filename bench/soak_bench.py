"""Soak the simulator and the engine: many trials in one process, across every case.

Runs ``--trials`` trials (default 500) in one process, cycling over the cases (every
``worlds/*/case.toml``), their catalogued tools, variants and locations at the
demonstration's pose; each trial goes through the engine (the pose's world target) as
in a run. Records the resident memory (RSS, from ``/proc/self/status``) and the
trial's wall time at trials 10, 100, 250 and 500 (and the end), and the growth of RSS
after trial 10. Writes ``bench/results/soak.json``. Aim: RSS flat within 10 % after
trial 10.

    .venv/bin/python bench/soak_bench.py [--trials 500]
"""

from __future__ import annotations

import argparse
import itertools
import json
import statistics
import time
from pathlib import Path

from recording import add_output_options, write_figures

from creative_py.bridge import Engine
from creative_py.case import load_cases
from creative_py.learning.poses import pose_resolver
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

CHECKPOINTS = (10, 100, 250, 500)


def rss_mb() -> float:
    """Return this process's resident memory in MiB (Linux)."""
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    raise RuntimeError("no VmRSS in /proc/self/status")


def trial_plan():
    """Yield (world, tool, variant, location) over every case, round robin."""
    worlds = [load_world(m) for m in load_cases().values()]
    per_case = []
    for w in worlds:
        combos = [(w, t, v.name, loc) for t in w.catalogue for v in w.manifest.variants
                  for loc in w.locations]
        per_case.append(itertools.cycle(combos))
    for it in itertools.cycle(per_case):
        yield next(it)


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--trials", type=int, default=500,
                    help="trials to run, round robin over the cases (default 500)")
    add_output_options(ap, "soak.json", "the memory and time checkpoints (JSON)")
    args = ap.parse_args(argv)
    marks = sorted({c for c in CHECKPOINTS if c <= args.trials} | {args.trials})
    records, walls, outcomes = [], [], {}
    t_start = time.perf_counter()
    for n, (world, tool, variant, loc) in enumerate(trial_plan(), 1):
        t0 = time.perf_counter()
        res = run_trial(world, tool, variant, loc, seed=n,
                        pose_target=pose_resolver(Engine.instance(), world.manifest))
        walls.append(time.perf_counter() - t0)
        outcomes[res.outcome] = outcomes.get(res.outcome, 0) + 1
        if n in marks:
            recent = walls[-10:]
            records.append({"trial": n, "rss_mb": round(rss_mb(), 1),
                            "trial_wall_s_median_last10": round(statistics.median(recent), 3),
                            "case": world.manifest.id})
            print(json.dumps(records[-1]), flush=True)
        if n >= args.trials:
            break
    base = records[0]["rss_mb"]
    growth = max(r["rss_mb"] for r in records) / base - 1
    result = {"trials": args.trials, "cases": sorted(load_cases()), "checkpoints": records,
              "rss_growth_after_first_checkpoint": round(growth, 4),
              "trial_wall_s": {"median": round(statistics.median(walls), 3),
                               "max": round(max(walls), 3)},
              "outcomes": outcomes,
              "total_wall_s": round(time.perf_counter() - t_start, 1)}
    print(json.dumps({k: v for k, v in result.items() if k != "checkpoints"}))
    write_figures(args, "soak.json", result, indent=2)


if __name__ == "__main__":
    main()
