"""Evaluate a tool and pose of a ManiSkill case on fresh ManiSkill seeds.

    python bench/maniskill_bench.py CASE [--run RUN_FOLDER] [--seeds 1000:1020]
                                    [--out FILE | --record]

Each seed is ManiSkill's seeded initial state (``env.reset(seed=...)``), none of them a
learning location. Without ``--run`` the demonstration's tool and pose are evaluated;
with it, the learned model's choice (the tool and pose of the run's evaluation trials).
The pose's world target comes from the engine's pose solution, the verdict from
ManiSkill's ``evaluate()["success"]``. Each seed is also tried without a tool (a bare-finger
pull: the closed gripper lowered 4.5 cm behind the cube's centre, then drawn towards the
robot base): a seed solved that way needs no tool, and the success rate is given both
over all seeds and over the seeds that need the tool. Prints one labelled line a seed;
with ``--out FILE`` (or ``--record``: the tracked ``bench/results/maniskill.json``) writes
per seed the outcome, ManiSkill's measures and the control steps; the success rate; the
trials and simulated environment steps the run took to learn (with ``--run``).
"""

from __future__ import annotations

import argparse
import json
import os
import time
from dataclasses import replace
from pathlib import Path

from recording import add_output_options, write_figures

HERE = Path(__file__).resolve().parent
TRACKED = "maniskill.json"


def bare_finger(sim, world, variant: str, location: int, tool: str) -> bool:
    """Return whether ManiSkill's evaluate() says success after a bare-finger move (same
    step budget). A goal region about the robot base: the closed gripper goes down
    4.5 cm behind the target (away from the robot) and is drawn straight towards the
    robot base until it is 0.45 m from it. A goal region about an actor: the closed
    gripper goes down 4.5 cm behind the target on the side away from the goal's centre
    and pushes it along that line until the target's centre would be 2 cm past the
    goal's, then holds still for 6 control steps."""
    import numpy as np

    from creative_py.backends.maniskill.skills import CLOSED

    with sim.open_episode(world, variant, location, tool) as ep:
        d = ep.driver
        cube = next(f for f in ep.observe().facts if f[0] == "pose")
        base = np.array([f for f in ep.observe().facts if f[0] == "reach_zone"][0][2:4])
        if world.zone_centre == "robot":
            behind = np.array([cube[2] + 0.045, cube[3], 0.02])
            out = behind[:2] - base
            end = np.array([*(base + out / np.linalg.norm(out) * 0.45), 0.02])
            settle = 3
        else:
            c = np.array(cube[2:4], dtype=float)
            u = (base - c) / np.linalg.norm(base - c)
            behind = np.array([*(c - u * 0.045), 0.02])
            end = np.array([*(base + u * (0.02 - 0.045)), 0.02])
            settle = 6
        (d.set_gripper(CLOSED, 2) and d.move(behind + [0, 0, 0.08])
         and d.move(behind, settle=2) and d.move(end, settle=settle, step_m=0.02))
        return ep.verdict().holds


def run_figures(run: Path, recs: list[dict]) -> dict:
    """What docs/results.md says of the learning run ``run`` (its ``summary.json`` and
    ``trials.jsonl``): tool-use trials and their control steps, the stop, h_g, the tool
    the model chose with its evaluation, and the creation phase (catalogued objects
    tried, the tools made with their sizes, outcomes and strength)."""
    summary = json.loads((run / "summary.json").read_text())
    use = [r for r in recs if r["phase"] == "use"]
    create = summary.get("create") or {}
    made = [{"name": t["name"], "replaced": t["replaced"], "instance": t["instance"],
             "dims": t["dims"], "trial_outcome": t.get("trial_outcome"),
             "eval_outcomes": t.get("eval_outcomes"),
             "strength": {k: (t.get("strength") or {}).get(k)
                          for k in ("force_n", "safety_factor", "verdict")}}
            for t in create.get("created_tools", [])]
    return {"run": run.name, "trials": len(use), "demonstrations": 1,
            "budget": summary.get("trial_budget"), "strategy": summary["use"]["strategy"],
            "stop": summary["use"]["stop"],
            "env_steps": sum(int(r["verdict"]["measures"]["control_steps"]) for r in use),
            "hg": summary["hypotheses"]["hg"], "hs": summary["hypotheses"]["hs"],
            "eval": summary["eval"]["outcomes"],
            "use_sequence": [{"tool": r["tool"], "tested": r["tested"], "pose": r["pose"],
                              "outcome": r["outcome"]} for r in use],
            "wall_time_s": summary.get("wall_time_s"),
            "create": {"variant": create.get("variant"), "trials": create.get("trials"),
                       "sequence": [{"tool": r["tool"], "outcome": r["outcome"]}
                                    for r in recs if r["phase"] == "create"],
                       "solved_by": create.get("solved_by"), "made": made}}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", help="a case whose backend is ManiSkill (creative cases "
                                 "lists them)")
    ap.add_argument("--run", type=Path, default=None, metavar="RUN_FOLDER",
                    help="evaluate the tool and pose of this learning run's evaluation "
                         "trials (default: the demonstration's tool and pose)")
    ap.add_argument("--seeds", default="1000:1020", metavar="FIRST:END",
                    help="ManiSkill's reset seeds FIRST to END-1 (default 1000:1020)")
    add_output_options(ap, TRACKED, "the per-seed outcomes and success rates (JSON)")
    a = ap.parse_args()

    from creative_py.bridge import Engine
    from creative_py.case import get_case
    from creative_py.learning.poses import pose_resolver
    from creative_py.simulator import backend_for
    from creative_py.simulator.trial import run_trial

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
        learning = run_figures(a.run, recs)
    engine = Engine.instance()
    poses = pose_resolver(engine, manifest)
    fresh = replace(world, seeds=tuple(seeds))
    rows = []
    load_before = [round(v, 2) for v in os.getloadavg()]
    t0 = time.perf_counter()
    for i, seed in enumerate(seeds, 1):
        r = run_trial(fresh, tool, manifest.demonstration.variant, i, pose,
                      pose_target=poses)
        finger = bare_finger(sim, fresh, manifest.demonstration.variant, i, tool)
        rows.append({"seed": seed, "outcome": r.outcome, "steps": r.steps,
                     "cube_distance_to_base_m": r.verdict["value"],
                     "evaluate_success": r.verdict["measures"]["evaluate_success"],
                     "bare_finger_success": finger})
        print(f"seed {seed}: {r.outcome} in {r.steps} control steps; bare finger "
              f"(no tool) {'solves it too' if finger else 'does not solve it'}", flush=True)
    ok = sum(r["evaluate_success"] for r in rows)
    need = [r for r in rows if not r["bare_finger_success"]]
    ok_need = sum(r["evaluate_success"] for r in need)
    out = {"case": manifest.id, "backend": manifest.backend, "source": source,
           "tool": tool, "pose": dict(zip(manifest.pose_names, pose)),
           "variant": manifest.demonstration.variant, "seeds": seeds,
           "successes": ok, "success_rate": ok / len(rows),
           "seeds_needing_tool": len(need), "successes_needing_tool": ok_need,
           "success_rate_needing_tool": ok_need / len(need) if need else None,
           "env_steps": sum(r["steps"] for r in rows), "learning": learning,
           "wall_s": round(time.perf_counter() - t0, 1),
           "load_avg_before": load_before,
           "load_avg_after": [round(v, 2) for v in os.getloadavg()], "trials": rows}
    print(f"{ok} of {len(rows)} seeds succeed ({source}); {ok_need} of the {len(need)} "
          "seeds a bare finger does not solve")
    write_figures(a, TRACKED, out)


if __name__ == "__main__":
    main()
