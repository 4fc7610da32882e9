"""Benchmark what a trial costs with the light robot against the heavy one, in one run.

For each case (default: hook and wedge, the case ids of ``worlds/*/case.toml``) runs
the same trials once per robot mode of :data:`creative_py.backends.pybullet.arm.ROBOT_MODES`:
``heavy`` (the robot of before: every joint simulated, a kinematics client with the
full model and a second URDF load per episode, the start posture's via solution
searched per tool), ``exact`` (the full physics model, the rest light: results bit for
bit the heavy ones) and ``light`` (the default: idle joints fixed and merged). A trial
is :func:`creative_py.simulator.trial.run_trial`, as a learning run calls it: the scene
built, every skill of the manifest, the engine's pose target, the oracle. The trials are the first
``--trials`` catalogued tools at the demonstration's variant, location and pose, each
mode in a world of its own (so every mode searches its start postures), the modes
interleaved trial by trial so that the load of other processes falls on all of them.
A warm-up trial per mode (the engine, the cached URDF files) is not counted.

Records per case the CPU seconds per trial (``process_time``: this process only, the
machine is shared) of each mode, the ratios ``light / heavy`` and ``exact / heavy``,
each trial's outcome per mode, whether ``exact`` reproduced ``heavy`` to the last bit,
and the CPU milliseconds of one physics step of the built scene with each robot model
and without a robot. Writes ``bench/results/robot_cost.json``.

    .venv/bin/python bench/robot_cost_bench.py [CASE ...] [--trials 4] [--out-dir DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import statistics
import sys
import time
from pathlib import Path

from creative_py.case import load_cases
from creative_py.backends.pybullet import baxter, load_world, open_episode
from creative_py.simulator.trial import run_trial

RESULTS = Path(__file__).resolve().parent / "results"
MODES = baxter.ROBOT_MODES
STEP_SAMPLE = 480
"""Physics steps timed per model for the cost of one step."""


def step_cost_ms(world, mode: str | None) -> float:
    """Return the CPU ms of one physics step of the demonstration's built scene.

    ``mode`` is a robot mode, or None for the scene without a robot; the arm holds its
    start posture while the physics runs.
    """
    demo = world.manifest.demonstration
    baxter.ROBOT = mode or "light"
    with open_episode(world, demo.variant, demo.location, demo.tool,
                      robot=mode is not None) as ep:
        c0 = time.process_time()
        ep.sim.step(STEP_SAMPLE)
        return 1000 * (time.process_time() - c0) / STEP_SAMPLE


def timed_trial(world, mode: str, tool: str) -> dict:
    """Run one trial with the robot of ``mode``; return its outcome and costs."""
    demo = world.manifest.demonstration
    baxter.ROBOT = mode
    t0, c0 = time.perf_counter(), time.process_time()
    res = run_trial(world, tool, demo.variant, demo.location, demo.pose, seed=0)
    return {"outcome": res.outcome, "reason": res.reason, "steps": res.steps,
            "cpu_s": time.process_time() - c0, "wall_s": time.perf_counter() - t0,
            "true_final": res.true_final}


def bench_case(manifest, n_trials: int) -> dict:
    """Run one case's trials in every mode; return the JSON record."""
    warm = load_world(manifest)
    demo = manifest.demonstration
    for mode in MODES:  # the engine, pybullet and the URDF files warmed up: not counted
        timed_trial(warm, mode, demo.tool)
    worlds = {mode: load_world(manifest) for mode in MODES}
    tools = list(worlds["light"].catalogue)[:n_trials]
    trials = []
    for tool in tools:
        row = {"tool": tool, "variant": demo.variant, "location": demo.location}
        for mode in MODES:
            row[mode] = timed_trial(worlds[mode], mode, tool)
        trials.append(row)
        print(f"{manifest.id} {tool:12s} " + "  ".join(
            f"{m} {row[m]['outcome']:11s} {row[m]['cpu_s']:.2f} s" for m in MODES), flush=True)
    cpu = {m: statistics.mean(t[m]["cpu_s"] for t in trials) for m in MODES}
    steps = {m: step_cost_ms(load_world(manifest), m) for m in MODES}
    steps["no_robot"] = step_cost_ms(load_world(manifest), None)
    exact_bitwise = all((t["exact"]["true_final"], t["exact"]["steps"])
                        == (t["heavy"]["true_final"], t["heavy"]["steps"]) for t in trials)
    for t in trials:
        for m in MODES:
            del t[m]["true_final"]
    return {
        "case": manifest.id,
        "trials_per_mode": len(trials),
        "cpu_s_per_trial": cpu,
        "ratio_light_over_heavy": cpu["light"] / cpu["heavy"],
        "ratio_exact_over_heavy": cpu["exact"] / cpu["heavy"],
        "wall_s_per_trial": {m: statistics.mean(t[m]["wall_s"] for t in trials)
                             for m in MODES},
        "step_cpu_ms": steps,
        "outcomes": {m: [t[m]["outcome"] for t in trials] for m in MODES},
        "light_outcomes_same": all(t["light"]["outcome"] == t["heavy"]["outcome"]
                                   for t in trials),
        "exact_bitwise_same_as_heavy": exact_bitwise,
        "trials": trials,
    }


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and write its results."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="*", default=["hook", "wedge"],
                    help="case ids (default: hook wedge)")
    ap.add_argument("--trials", type=int, default=4, help="tools per mode (default 4)")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--out-dir", type=Path, default=None, metavar="DIR",
                       help="write the CPU costs (robot_cost.json) into DIR (default: write nothing, only print)")
    where.add_argument("--record", action="store_true",
                       help="write them into the tracked bench/results/, which "
                            "docs/results.md is made from")
    args = ap.parse_args(argv)
    if args.trials < 1:
        sys.exit("error: option --trials must be at least 1")
    cases = load_cases()
    unknown = [c for c in args.cases if c not in cases]
    if unknown:
        sys.exit(f"error: unknown case {unknown[0]!r}; cases: {', '.join(sorted(cases))}")
    load0 = os.getloadavg()
    records = {}
    for cid in args.cases:
        rec = bench_case(cases[cid], args.trials)
        records[cid] = rec
        print(f"{cid}: CPU seconds per trial " + ", ".join(
            f"{m} {rec['cpu_s_per_trial'][m]:.2f}" for m in MODES)
              + f"; light/heavy {rec['ratio_light_over_heavy']:.2f}, exact/heavy "
              f"{rec['ratio_exact_over_heavy']:.2f}; CPU ms per physics step " + ", ".join(
                  f"{k} {v:.3f}" for k, v in rec["step_cpu_ms"].items()), flush=True)
    out = {
        "machine": {"platform": platform.platform(), "python": platform.python_version(),
                    "processor": platform.processor() or platform.machine(),
                    "cpus": os.cpu_count(), "load_average_start": load0,
                    "load_average_end": os.getloadavg()},
        "modes": list(MODES),
        "cases": records,
    }
    out_dir = args.out_dir or (RESULTS if args.record else None)
    if out_dir is None:
        print("figures not written (give --out-dir DIR, or --record to update the tracked "
              "bench/results/robot_cost.json)")
        return
    out_dir.mkdir(parents=True, exist_ok=True)
    path = out_dir / "robot_cost.json"
    path.write_text(json.dumps(out, indent=1, sort_keys=True) + "\n")
    print(f"figures written to {path}")


if __name__ == "__main__":
    main()
