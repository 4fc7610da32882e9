"""Benchmark the hook-and-tube world: the outcome table and the simulator's speed.

Runs every tool of ``worlds/hook_tube`` at every cube location in both tube variants at
the demonstration's pose, plus the demonstrated hook at wrong poses (prong flat, prong
in front of the cube, handle beside the cube). Records per trial the outcome, its
reason, the physics steps, simulated time, wall time, CPU time, simulated / wall time
and the camera render time; and the world start-up time (building the scene: first
and later). Writes ``bench/results/sim.json`` and prints the outcome table as markdown.

    .venv/bin/python bench/sim_bench.py [--quick] [--out bench/results/sim.json]

``--quick`` runs only the demonstration location (1). The machine is shared: CPU time
(``process_time``) is recorded next to wall time so load from other processes shows.
"""

from __future__ import annotations

import argparse
import json
import logging
import math
import platform
import statistics
import time
from pathlib import Path

from creative_py.sim.hook_tube import open_hook_episode
from creative_py.sim.trial import load_case_world, run_trial

RESULTS = Path(__file__).resolve().parent / "results" / "sim.json"

WRONG_POSES = {
    "flat": (0.03, 0.0, math.pi / 2),
    "in_front": (-0.04, 0.0, 0.0),
    "beside": (0.03, 0.03, 0.0),
}


def startup_times(world, n: int = 4) -> list[float]:
    """Return the wall times (s) of building the scene ``n`` times (Baxter, tube, cube, tool).

    Later builds reuse the start posture found by the first (as the case object does).
    """
    times = []
    cache: dict = {}
    for _ in range(n):
        t0 = time.perf_counter()
        ep = open_hook_episode(world, "standard", 1, world.demonstration.tool,
                               posture_cache=cache)
        times.append(time.perf_counter() - t0)
        ep.close()
    return times


def one_trial(world, tool: str, variant: str, location: int, pose=None) -> dict:
    """Run one trial; return its record with CPU time added."""
    c0 = time.process_time()
    r = run_trial("hook", world, tool, variant, location, pose=pose)
    cpu = time.process_time() - c0
    rec = r.to_dict()
    rec["cpu_time_s"] = cpu
    rec["sim_over_wall"] = r.sim_time_s / r.wall_time_s if r.wall_time_s > 0 else None
    return rec


def markdown_table(world, trials: list[dict], variants, locations) -> str:
    """Return the tool x (variant, location) outcome table as markdown."""
    head = "| tool | " + " | ".join(f"{v} L{loc}" for v in variants for loc in locations) + " |"
    rule = "|---" * (1 + len(variants) * len(locations)) + "|"
    short = {"success": "S", "failure": "F", "blocked": "B", "unreachable": "U", "invalid": "I"}
    rows = [head, rule]
    for tool, spec in world.tools.items():
        cells = []
        for v in variants:
            for loc in locations:
                hit = [t for t in trials if t["object"] == tool and t["variant"] == v
                       and t["location"] == loc and t.get("label") == "demo_pose"]
                cells.append(short[hit[0]["outcome"]] if hit else "-")
        label = f"{tool} ({spec.handle_length:.2f} m{'' if spec.is_stick else ', ' + spec.hook_side})"
        rows.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def main() -> None:
    """Run the benchmark and write its results."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="only location 1")
    ap.add_argument("--out", type=Path, default=RESULTS)
    args = ap.parse_args()
    logging.basicConfig(level=logging.WARNING)

    world = load_case_world("hook")
    starts = startup_times(world)
    variants = list(world.variants)
    locations = [1] if args.quick else list(range(1, len(world.locations) + 1))
    trials: list[dict] = []
    for v in variants:
        for loc in locations:
            for tool in world.tools:
                rec = one_trial(world, tool, v, loc)
                rec["label"] = "demo_pose"
                trials.append(rec)
                print(f"{v:9s} L{loc} {tool:9s} {rec['outcome']:11s} "
                      f"{rec['wall_time_s']:.2f} s wall {rec['cpu_time_s']:.2f} s cpu "
                      f"{rec['reason'][:70]}", flush=True)
    demo = world.demonstration
    for label, pose in WRONG_POSES.items():
        rec = one_trial(world, demo.tool, demo.variant, demo.location, pose)
        rec["label"] = label
        trials.append(rec)
        print(f"wrong pose {label:9s} {rec['outcome']:11s} {rec['reason'][:70]}", flush=True)

    walls = [t["wall_time_s"] for t in trials]
    cpus = [t["cpu_time_s"] for t in trials]
    ratios = [t["sim_over_wall"] for t in trials if t["sim_over_wall"]]
    summary = {
        "machine": {"platform": platform.platform(), "python": platform.python_version(),
                    "processor": platform.processor() or platform.machine()},
        "startup_s": {"first": starts[0], "later_median": statistics.median(starts[1:]),
                      "all": starts},
        "trial_wall_s": {"median": statistics.median(walls), "max": max(walls),
                         "min": min(walls)},
        "trial_cpu_s": {"median": statistics.median(cpus), "max": max(cpus)},
        "sim_over_wall": {"median": statistics.median(ratios), "min": min(ratios)},
        "render_s_per_trial": {"median": statistics.median(t["render_time_s"] for t in trials)},
        "steps": {"median": statistics.median(t["steps"] for t in trials)},
        "outcomes": {o: sum(1 for t in trials if t["outcome"] == o)
                     for o in ("success", "failure", "blocked", "unreachable", "invalid")},
        "table_markdown": markdown_table(world, trials, variants, locations),
        "trials": trials,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(summary, indent=1, sort_keys=True) + "\n")
    print(summary["table_markdown"])
    print(json.dumps({k: v for k, v in summary.items()
                      if k not in ("trials", "table_markdown")}, indent=1))


if __name__ == "__main__":
    main()
