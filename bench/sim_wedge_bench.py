"""Benchmark the door-and-wedge world: outcome table, timings, determinism.

Runs every object of ``worlds/wedge_door`` in every variant at the demonstration's
pose twice: placed by the trainer (the door's physics alone, no robot) and by the arm
(pick up, carry, place, retreat, release the door); plus a reversed, a far and a
near-hinge placement of the demonstrated wedge by the arm. Records per trial the
outcome, how far the door closed, the wall time of each phase, simulated time / wall
time and the camera render time. Writes ``bench/results/sim_wedge.json`` and prints
markdown tables.

    .venv/bin/python bench/sim_wedge_bench.py [--quick]
"""

from __future__ import annotations

import argparse
import json
import logging
import platform
import time
from pathlib import Path

from creative_py.sim.wedge_door import WedgePose, load_wedge_world, open_wedge_episode

RESULTS = Path(__file__).resolve().parent / "results" / "sim_wedge.json"


def timed_trial(world, name: str, variant: str, pose: WedgePose, seed: int = 0) -> dict:
    """Run one trial skill by skill; return its outcome, door numbers and timings."""
    t0 = time.perf_counter()
    ep = open_wedge_episode(world, variant, 1, name, seed=seed)
    try:
        t_build = time.perf_counter()
        phases = {"build_s": t_build - t0}
        outcome, reason = "success", ""
        door_wall = 0.0
        steps_before_door = 0
        sim_before_door = 0.0
        placed = None
        for label, skill in (("pick_up_s", ep.pick_up),
                             ("position_tool_s", lambda: ep.position_tool(pose)),
                             ("act_s", ep.act)):
            ts = time.perf_counter()
            if label == "act_s":
                steps_before_door = ep.steps
                sim_before_door = ep.sim_time()
                placed = ep.placed_pose()
            res = skill()
            phases[label] = time.perf_counter() - ts
            if not res.ok:
                outcome, reason = res.status, res.reason
                break
        else:
            door_wall = phases["act_s"]
            if not ep.goal_reached():
                outcome, reason = "failure", ep.door_outcome.describe()
            else:
                reason = ep.door_outcome.describe()
        ts = time.perf_counter()
        ep.observe()
        phases["observe_s"] = time.perf_counter() - ts
        wall = time.perf_counter() - t0
        d = ep.door_outcome
        return {
            "object": name, "variant": variant, "pose": list(pose), "outcome": outcome,
            "reason": reason, "placed_pose": None if placed is None else [round(v, 5) for v in placed],
            "closed_after_contact_deg": None if d is None else d.closed_after_contact_deg,
            "final_door_deg": None if d is None else d.final_angle_deg,
            "wall_time_s": wall, "phases": phases, "door_phase_wall_s": door_wall,
            "door_phase_steps": ep.steps - steps_before_door if d else 0,
            "door_phase_sim_s": ep.sim_time() - sim_before_door if d else 0.0,
            "sim_time_s": ep.sim_time(), "render_time_s": ep.render_time_s,
            "steps": ep.steps, "truth": ep.truth(),
        }
    finally:
        ep.close()


def trainer_trial(world, name: str, variant: str, pose: WedgePose) -> dict:
    """Place the object by hand (no robot) and release the door; return the door numbers."""
    t0 = time.perf_counter()
    ep = open_wedge_episode(world, variant, 1, name, with_robot=False)
    try:
        placed = ep.trainer_place(pose)
        ts = time.perf_counter()
        res = ep.act()
        door_wall = time.perf_counter() - ts
        d = ep.door_outcome
        return {"object": name, "variant": variant, "pose": list(pose),
                "outcome": ("success" if ep.goal_reached() else "failure")
                if placed.ok and res.ok else res.status,
                "reason": d.describe() if d else res.reason,
                "closed_after_contact_deg": None if d is None else d.closed_after_contact_deg,
                "final_door_deg": None if d is None else d.final_angle_deg,
                "door_phase_wall_s": door_wall, "wall_time_s": time.perf_counter() - t0}
    finally:
        ep.close()


def markdown_table(world, names, rows, demo) -> str:
    """Return a markdown table object x variant of outcomes and degrees closed."""
    lines = ["| object | " + " | ".join(world.variants) + " |",
             "|---|" + "---|" * len(world.variants)]
    for name in names:
        cells = []
        for variant in world.variants:
            t = next(t for t in rows if t["object"] == name and t["variant"] == variant
                     and t["pose"] == list(demo))
            c = t["closed_after_contact_deg"]
            mark = "held" if t["outcome"] == "success" else t["outcome"]
            cells.append(f"{mark} ({c:.1f} deg)" if c is not None else mark)
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def main() -> None:
    """Run the benchmark and write its JSON record."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="only the set-A prisms and the box")
    args = ap.parse_args()
    logging.basicConfig(level=logging.WARNING)
    world = load_wedge_world()
    demo = world.demonstration.pose
    names = list(world.objects)
    if args.quick:
        names = ["wedge_a1", "wedge_a2", "wedge_a3", "box_a1"]
    trainer = []
    for variant in world.variants:
        for name in names:
            r = trainer_trial(world, name, variant, demo)
            trainer.append(r)
            print(f"trainer {variant:9s} {name:12s} {r['outcome']:8s} door "
                  f"{r['door_phase_wall_s']:.3f} s  {r['reason']}", flush=True)
    trials = []
    for variant in world.variants:
        for name in names:
            r = timed_trial(world, name, variant, demo)
            trials.append(r)
            print(f"{variant:9s} {name:12s} {r['outcome']:11s} {r['wall_time_s']:5.2f} s  "
                  f"door {r['door_phase_wall_s']:.3f} s  {r['reason']}", flush=True)
    extra = [("reversed (tip away)", WedgePose(demo.r, demo.gap, 3.141592653589793)),
             ("far from the door", WedgePose(0.75, 0.35, 0.0)),
             ("near the hinge", WedgePose(0.28, 0.03, 0.0))]
    for label, pose in extra:
        r = timed_trial(world, world.demonstration.object, "standard", pose)
        r["label"] = label
        trials.append(r)
        print(f"{label:22s} {r['outcome']:11s} {r['reason']}", flush=True)
    again = timed_trial(world, world.demonstration.object, "standard", demo)
    first = next(t for t in trials if t["object"] == world.demonstration.object
                 and t["variant"] == "standard" and t["pose"] == list(demo))
    deterministic = again["truth"] == first["truth"] and again["outcome"] == first["outcome"]
    done = [t for t in trials if t["door_phase_steps"]]
    summary = {
        "trials": len(trials),
        "mean_wall_time_s": sum(t["wall_time_s"] for t in trials) / len(trials),
        "mean_door_phase_wall_s": sum(t["door_phase_wall_s"] for t in done) / len(done),
        "max_door_phase_wall_s": max(t["door_phase_wall_s"] for t in done),
        "sim_over_wall": sum(t["sim_time_s"] for t in trials) / sum(t["wall_time_s"]
                                                                     for t in trials),
        "door_phase_sim_over_wall": sum(t["door_phase_sim_s"] for t in done)
        / sum(t["door_phase_wall_s"] for t in done),
        "mean_render_time_s": sum(t["render_time_s"] for t in trials) / len(trials),
        "deterministic_same_seed": deterministic,
    }
    summary["trainer_mean_door_phase_wall_s"] = (sum(t["door_phase_wall_s"] for t in trainer)
                                                 / len(trainer))
    summary["trainer_mean_wall_time_s"] = sum(t["wall_time_s"] for t in trainer) / len(trainer)
    record = {"machine": platform.platform(), "python": platform.python_version(),
              "summary": summary, "trainer_placed": trainer, "trials": trials}
    RESULTS.parent.mkdir(parents=True, exist_ok=True)
    RESULTS.write_text(json.dumps(record, indent=1, sort_keys=True))
    print("\nPlaced by the trainer:\n" + markdown_table(world, names, trainer, demo))
    print("\nPlaced by the arm:\n" + markdown_table(world, names, trials, demo))
    print(json.dumps(summary, indent=1))


if __name__ == "__main__":
    main()
