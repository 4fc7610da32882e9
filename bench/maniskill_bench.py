"""Evaluate a tool and pose of a ManiSkill case on fresh ManiSkill seeds.

    python bench/maniskill_bench.py CASE [--run RUN_FOLDER] [--seeds 1000:1020]

Each seed is ManiSkill's seeded initial state (``env.reset(seed=...)``), none of them a
learning location. Without ``--run`` the demonstration's tool and pose are evaluated;
with it, the learned model's choice (the tool and pose of the run's evaluation trials).
The pose's world target comes from the engine's pose solution, the verdict from
ManiSkill's ``evaluate()["success"]``. Writes ``bench/results/maniskill.json``: per
seed the outcome, ManiSkill's measures and the control steps; the success rate; the
trials and simulated environment steps the run took to learn (with ``--run``).
"""

from __future__ import annotations

import argparse
import json
import time
from dataclasses import replace
from pathlib import Path

HERE = Path(__file__).resolve().parent


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case")
    ap.add_argument("--run", type=Path, default=None)
    ap.add_argument("--seeds", default="1000:1020")
    ap.add_argument("--out", type=Path, default=HERE / "results" / "maniskill.json")
    a = ap.parse_args()

    from creative_py.bridge import Engine
    from creative_py.case import get_case
    from creative_py.learning.poses import pose_resolver
    from creative_py.simulator import backend_for

    manifest = get_case(a.case)
    sim = backend_for(manifest)
    world = sim.load_world(manifest)
    lo, hi = (int(v) for v in a.seeds.split(":"))
    seeds = list(range(lo, hi))
    learning = None
    tool, pose = manifest.demonstration.tool, tuple(manifest.demonstration.pose)
    source = "demonstration"
    if a.run is not None:
        recs = [json.loads(line) for line in (a.run / "trials.jsonl").read_text().splitlines()]
        ev = [r for r in recs if r["phase"] == "eval"]
        if not ev:
            raise SystemExit(f"error: {a.run}: no evaluation trial in trials.jsonl")
        tool = ev[0]["tool"]
        pose = tuple(ev[0]["pose"][n] for n in manifest.pose_names)
        source = f"learned model of {a.run.name}"
        use = [r for r in recs if r["phase"] == "use"]
        learning = {"trials": len(use), "demonstrations": 1,
                    "env_steps": sum(int(r["verdict"]["measures"]["control_steps"]) for r in use)}
    engine = Engine.instance()
    poses = pose_resolver(engine, manifest)
    fresh = replace(world, seeds=tuple(seeds))
    rows = []
    t0 = time.perf_counter()
    for i, seed in enumerate(seeds, 1):
        r = sim.run_trial(fresh, tool, manifest.demonstration.variant, i, pose,
                          pose_target=poses)
        rows.append({"seed": seed, "outcome": r.outcome, "steps": r.steps,
                     "cube_distance_to_base_m": r.verdict["value"],
                     "evaluate_success": r.verdict["measures"]["evaluate_success"]})
        print(seed, r.outcome, r.steps, flush=True)
    ok = sum(r["evaluate_success"] for r in rows)
    out = {"case": manifest.id, "backend": manifest.backend, "source": source,
           "tool": tool, "pose": dict(zip(manifest.pose_names, pose)),
           "variant": manifest.demonstration.variant, "seeds": seeds,
           "successes": ok, "success_rate": ok / len(rows),
           "env_steps": sum(r["steps"] for r in rows), "learning": learning,
           "wall_s": round(time.perf_counter() - t0, 1), "trials": rows}
    a.out.parent.mkdir(parents=True, exist_ok=True)
    a.out.write_text(json.dumps(out, indent=1) + "\n")
    print(f"{ok}/{len(rows)} seeds succeed ({source}); {a.out}")


if __name__ == "__main__":
    main()
