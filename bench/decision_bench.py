"""Time the learning decisions of one trial at the sizes the two cases produce.

For each case (every worlds/*/case.toml): run the demonstration once in the physics, build the version space, then
time (median and worst of 30 calls, through the bridge) the three Prolog decisions a
trial needs: next_experiment (which literal, which object, which pose), label_trial
(build the example and update the version space) and vs_bounds. Prints one line a
case; ``--out FILE`` (or ``--record``: the tracked bench/results/decisions.json) writes
them. Aim: every learning decision of a trial under 50 ms.
"""

from __future__ import annotations

import argparse
import json
import statistics
import time

from recording import add_output_options, write_figures

from creative_py.bridge import Compound, Engine, fact_term
from creative_py.case import load_cases
from creative_py.learning.poses import pose_resolver
from creative_py.learning.tool_use import run_demonstration
from creative_py.simulator.trial import task_facts
from creative_py.backends.pybullet import load_world

N = 30


def timed(fn, n: int = N) -> dict:
    """Return median and worst milliseconds of ``n`` calls of ``fn``."""
    ts = []
    for _ in range(n):
        t0 = time.perf_counter()
        fn()
        ts.append((time.perf_counter() - t0) * 1000)
    return {"median_ms": round(statistics.median(ts), 2), "worst_ms": round(max(ts), 2), "n": n}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    add_output_options(ap, "decisions.json", "the median and worst times (JSON)")
    args = ap.parse_args()
    engine = Engine.instance()
    out = {}
    for case, manifest in load_cases().items():
        world = load_world(manifest)
        demo = run_demonstration(world, pose_target=pose_resolver(engine, manifest))
        steps = [Compound("step", (s.skill, list(s.args), [fact_term(f) for f in s.facts_before],
                                   [fact_term(f) for f in s.facts_after])) for s in demo.steps]
        models = engine.call("learn_from_demonstration", case, steps)
        vs = engine.call("vs_init", models.args[2])
        facts = [fact_term(f) for f in task_facts(world, manifest.demonstration.variant,
                                                   manifest.demonstration.location)]
        exp = engine.call("next_experiment", case, vs, facts, [])
        hs, _ = engine.vs_bounds(vs)
        out[case] = {
            "h_s_literals": str(hs).count("),") + 1,
            "available_objects": sum(1 for f in facts if getattr(f, "name", "") == "object_kind"),
            "next_experiment": timed(lambda: engine.call("next_experiment", case, vs, facts, [])),
            "label_trial": timed(lambda: engine.call("label_trial", case, vs, exp, facts,
                                                     "neg", "planned")),
            "vs_bounds": timed(lambda: engine.call("vs_bounds", vs)),
        }
        print(f"{case} (milliseconds of {N} calls):", json.dumps(out[case]))
    write_figures(args, "decisions.json", out, indent=2)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
