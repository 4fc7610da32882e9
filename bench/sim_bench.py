"""Benchmark the simulated worlds: the outcome tables and the simulator's speed.

For each case (default: every ``worlds/*/case.toml``) runs every catalogued tool in
every variant at every location at the demonstration's pose, skill by skill through
the manifest, plus any ``--extra NAME=A,B,C`` pose with the demonstrated tool. Records
per trial the outcome, its reason, the wall time of each skill, the physics steps,
simulated time, CPU time and camera render time, and what a released joint did (the
degrees it moved on after touching the tool); and the scene start-up time (first and
later builds). Writes ``bench/results/sim_<case>.json`` and prints the outcome table
as markdown (S success, F failure, B blocked, U unreachable, I invalid).

``--by-hand`` lets the trainer put the tool at the pose (the pose skill's ``by_hand``
option, no robot): the physics of the tool action alone, one location per variant.

    .venv/bin/python bench/sim_bench.py [CASE ...] [--quick] [--by-hand]
        [--extra flat=0.03,0,1.5708] [--out-dir bench/results]

``--quick`` runs only the demonstration's location. The machine is shared: CPU time
(``process_time``) is recorded next to wall time so load from other processes shows.
"""

from __future__ import annotations

import argparse
import json
import logging
import platform
import statistics
import sys
import time
from pathlib import Path

from creative_py.bridge import Engine
from creative_py.case import load_cases
from creative_py.learning.poses import pose_resolver
from creative_py.backends.pybullet import load_world, open_episode
from creative_py.simulator.trial import play_trial

RESULTS = Path(__file__).resolve().parent / "results"
SHORT = {"success": "S", "failure": "F", "blocked": "B", "unreachable": "U", "invalid": "I"}


def startup_times(world, n: int = 4) -> list[float]:
    """Return the wall times (s) of building the demonstration's scene ``n`` times.

    Later builds reuse the start posture the first one searched (cached in the world).
    """
    demo = world.manifest.demonstration
    times = []
    for _ in range(n):
        t0 = time.perf_counter()
        with open_episode(world, demo.variant, demo.location, demo.tool):
            times.append(time.perf_counter() - t0)
    return times


def one_trial(world, tool: str, variant: str, location: int, pose, by_hand: bool) -> dict:
    """Run one trial skill by skill; return its outcome, timings and joint records."""
    m = world.manifest
    t0, c0 = time.perf_counter(), time.process_time()
    phases: dict[str, float] = {}
    with open_episode(world, variant, location, tool, robot=not by_hand,
                      pose_target=pose_resolver(Engine.instance(), m)) as ep:
        phases["build_s"] = time.perf_counter() - t0
        # The trial loop's own body (simulator/trial.py, run_trial's): the same outcome
        # for the same ending; no camera observation, so the figures are the physics'.
        played = play_trial(ep, m, pose, observe=False, by_hand=by_hand, timings=phases)
        outcome, reason = played.outcome, played.reason
        records = {k: {"contact_angle": r.contact_angle, "final_angle": r.final_angle,
                       "closed_after_contact_deg": r.closed_after_contact_deg}
                   for k, r in ep.records.items()}
        rec = {"case": m.id, "object": tool, "variant": variant, "location": location,
               "pose": list(pose), "outcome": outcome, "reason": reason, "phases": phases,
               "records": records, "steps": ep.steps, "sim_time_s": ep.sim_time(),
               "render_time_s": ep.render_time_s, "truth": played.truth}
    rec["wall_time_s"] = time.perf_counter() - t0
    rec["cpu_time_s"] = time.process_time() - c0
    rec["sim_over_wall"] = rec["sim_time_s"] / rec["wall_time_s"]
    return rec


def markdown_table(world, trials: list[dict], variants, locations) -> str:
    """Return the tool x (variant, location) outcome table at the demonstration's pose."""
    head = "| tool | " + " | ".join(f"{v} L{loc}" for v in variants for loc in locations) + " |"
    rows = [head, "|---" * (1 + len(variants) * len(locations)) + "|"]
    for tool in world.catalogue:
        cells = []
        for v in variants:
            for loc in locations:
                hit = [t for t in trials if t["object"] == tool and t["variant"] == v
                       and t["location"] == loc and t["label"] == "demo_pose"]
                if not hit:
                    cells.append("-")
                    continue
                t = hit[0]
                closed = [r["closed_after_contact_deg"] for r in t["records"].values()
                          if r["closed_after_contact_deg"] is not None]
                cells.append(SHORT[t["outcome"]] + (f" ({closed[0]:.1f})" if closed else ""))
        rows.append(f"| {tool} | " + " | ".join(cells) + " |")
    return "\n".join(rows)


def bench_case(manifest, args) -> dict:
    """Run one case's table and extra poses; return the JSON record."""
    world = load_world(manifest)
    demo = manifest.demonstration
    starts = [] if args.by_hand else startup_times(world)
    variants = list(manifest.variant_names)
    locations = [demo.location] if (args.quick or args.by_hand) else list(world.locations)
    trials: list[dict] = []
    for v in variants:
        for loc in locations:
            for tool in world.catalogue:
                rec = one_trial(world, tool, v, loc, demo.pose, args.by_hand)
                rec["label"] = "demo_pose"
                trials.append(rec)
                print(f"{manifest.id} {v:9s} L{loc} {tool:12s} {rec['outcome']:11s} "
                      f"{rec['wall_time_s']:.2f} s wall {rec['cpu_time_s']:.2f} s cpu "
                      f"{rec['reason'][:70]}", flush=True)
    for text in args.extra:
        label, _, numbers = text.partition("=")
        pose = manifest.parse_pose(numbers)
        rec = one_trial(world, demo.tool, demo.variant, demo.location, pose, args.by_hand)
        rec["label"] = label
        trials.append(rec)
        print(f"{manifest.id} extra pose {label:12s} {rec['outcome']:11s} {rec['reason'][:70]}",
              flush=True)
    again = one_trial(world, demo.tool, demo.variant, demo.location, demo.pose, args.by_hand)
    first = next(t for t in trials if t["object"] == demo.tool and t["variant"] == demo.variant
                 and t["location"] == demo.location and t["label"] == "demo_pose")
    walls = [t["wall_time_s"] for t in trials]
    return {
        "case": manifest.id, "by_hand": args.by_hand,
        "machine": {"platform": platform.platform(), "python": platform.python_version(),
                    "processor": platform.processor() or platform.machine()},
        "startup_s": ({"first": starts[0], "later_median": statistics.median(starts[1:]),
                       "all": starts} if starts else None),
        "trial_wall_s": {"median": statistics.median(walls), "max": max(walls),
                         "min": min(walls)},
        "trial_cpu_s": {"median": statistics.median(t["cpu_time_s"] for t in trials)},
        "sim_over_wall": {"median": statistics.median(t["sim_over_wall"] for t in trials)},
        "render_s_per_trial": {"median": statistics.median(t["render_time_s"] for t in trials)},
        "outcomes": {o: sum(1 for t in trials if t["outcome"] == o) for o in SHORT},
        "deterministic_same_seed": (again["truth"] == first["truth"]
                                    and again["outcome"] == first["outcome"]),
        "table_markdown": markdown_table(world, trials, variants, locations),
        "trials": trials,
    }


def by_hand_refusal(manifest) -> str | None:
    """Return why the trainer cannot place ``manifest``'s tool by hand (its pose skill's
    primitive has no ``by_hand`` option), or None when it can."""
    from creative_py.backends.pybullet.primitives import primitive

    world = load_world(manifest)
    for binding in manifest.skills:
        if binding.pose:
            name = world.skills[binding.name].primitive
            if "by_hand" not in primitive(name).options:
                return (f"--by-hand: case {manifest.id!r}: its pose skill {binding.name!r} "
                        f"binds {name}, which has no trainer placing (by_hand)")
    return None


def main(argv: list[str] | None = None) -> None:
    """Run the benchmark and write its results."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="*", help="case ids (default: every case)")
    ap.add_argument("--quick", action="store_true", help="only the demonstration's location")
    ap.add_argument("--by-hand", action="store_true",
                    help="the trainer places the tool; no robot")
    ap.add_argument("--extra", action="append", default=[], metavar="NAME=POSE",
                    help="one more pose for the demonstrated tool, e.g. flat=0.03,0,1.5708")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--out-dir", type=Path, default=None, metavar="DIR",
                       help="write each case's table (sim_<case>[_by_hand].json) into DIR (default: write nothing, only print)")
    where.add_argument("--record", action="store_true",
                       help="write them into the tracked bench/results/, which "
                            "docs/results.md is made from")
    args = ap.parse_args(argv)
    logging.basicConfig(level=logging.WARNING)
    cases = {cid: m for cid, m in load_cases().items() if m.backend == "pybullet"}
    chosen = args.cases or sorted(cases)
    for cid in chosen:
        if cid not in cases:
            print(f"sim_bench: unknown pybullet case {cid!r}; cases: "
                  f"{', '.join(sorted(cases))}", file=sys.stderr)
            sys.exit(2)
    if args.by_hand:
        refusals = {cid: by_hand_refusal(cases[cid]) for cid in chosen}
        if args.cases and any(refusals.values()):
            print(f"sim_bench: {next(r for r in refusals.values() if r)}", file=sys.stderr)
            sys.exit(2)
        chosen = [cid for cid in chosen if not refusals[cid]]
    for cid in chosen:
        record = bench_case(cases[cid], args)
        print(record["table_markdown"])
        print(json.dumps({k: v for k, v in record.items()
                          if k not in ("trials", "table_markdown")}, indent=1))
        out_dir = args.out_dir or (RESULTS if args.record else None)
        name = f"sim_{cid}{'_by_hand' if args.by_hand else ''}.json"
        if out_dir is None:
            print(f"figures not written (give --out-dir DIR, or --record to update the "
                  f"tracked bench/results/{name})")
            continue
        out = out_dir / name
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text(json.dumps(record, indent=1, sort_keys=True) + "\n")
        print(f"figures written to {out}")


if __name__ == "__main__":
    main()
