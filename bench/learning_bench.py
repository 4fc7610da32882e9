"""Whole runs of both cases over several seeds: the paper's trial counts, and wall time.

For each case and seed, one ``run_case`` (demonstration, tool-use learning, evaluation,
tool creation) in its own process. Records, per case: tool-use trials and the trial at
which the version space had nothing left to test (median and worst over the seeds),
creation trials (failed and successful), created-tool evaluation successes, and wall
time per phase. Writes bench/results/learning.json and prints a table next to the
paper's numbers (hook: 12 TUL trials, TC 1 failed + 1 successful; wedge: 9 TUL trials,
TC 2 failed + 1 successful).

    .venv/bin/python bench/learning_bench.py [--seeds 10] [--cases hook wedge]
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from recording import add_output_options, output_path  # noqa: E402
PAPER = {"hook": {"use_trials": 12, "create_failed": 1, "create_success": 1},
         "wedge": {"use_trials": 9, "create_failed": 2, "create_success": 1}}

ONE_RUN = """
import json, sys
from pathlib import Path
from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case
folder = run_case(sys.argv[1], Path(sys.argv[2]),
                  RunOptions(seed=int(sys.argv[3]), eval_trials=int(sys.argv[4])))
print(json.dumps(json.loads((folder.path / "summary.json").read_text())))
"""


def one_run(case: str, seed: int, out: Path, eval_trials: int) -> dict:
    """Run one case in a fresh process and return its summary.json."""
    proc = subprocess.run([sys.executable, "-c", ONE_RUN, case, str(out), str(seed),
                           str(eval_trials)],
                          capture_output=True, text=True, cwd=HERE.parent)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-1:] or ["?"]}
    return json.loads(proc.stdout.strip().splitlines()[-1])


def stats(values: list, worst=max) -> dict:
    """Return the median and the worst of numbers (``worst=min`` for success counts),
    ignoring None."""
    vs = [v for v in values if v is not None]
    if not vs:
        return {"median": None, "worst": None, "n": 0}
    return {"median": statistics.median(vs), "worst": worst(vs), "n": len(vs)}


def per_seed(seed: int, r: dict) -> dict:
    """Return the figures of one run, for the record."""
    if "error" in r:
        return {"seed": seed, "error": r["error"]}
    c = r.get("create", {})
    return {"seed": seed, "use_trials": r["use"]["trials"],
            "trials_to_converge": r["use"]["trials_to_converge"],
            "use_outcomes": r["trials"]["use"]["outcomes"],
            "hg": r["hypotheses"]["hg"],
            "create_outcomes": r["trials"]["create"]["outcomes"],
            "created": [(t["name"], t["instance"], t["trial_outcome"])
                        for t in c.get("created_tools", [])],
            "created_eval": c.get("eval"), "exhausted": c.get("exhausted"),
            "learned_model_eval": r["eval"]["outcomes"],
            "wall_time_s": r["wall_time_s"]["total"]}


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--seeds", type=int, default=10,
                    help="runs per case, seeds 0 to SEEDS-1 (default 10)")
    ap.add_argument("--cases", nargs="+", default=["hook", "wedge"],
                    help="the cases to run (default hook wedge)")
    ap.add_argument("--eval-trials", type=int, default=5,
                    help="evaluation trials of the learned model per run")
    add_output_options(ap, "learning.json", "the trial counts per case (JSON; the "
                       "other cases' figures already in the file are kept)")
    args = ap.parse_args()
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for case in args.cases:
            runs = []
            for seed in range(args.seeds):
                s = one_run(case, seed, Path(tmp), args.eval_trials)
                runs.append(s)
                print(f"{case} seed {seed}: " + (str(s["error"]) if "error" in s else
                      f"tool-use trials {s['use']['trials']} (nothing left to test after "
                      f"{s['use']['trials_to_converge']}), creation trials "
                      f"{s.get('create', {}).get('trials')}, wall time "
                      f"{s['wall_time_s']['total']} s"), flush=True)
            ok = [r for r in runs if "error" not in r]
            results[case] = {
                "seeds": args.seeds,
                "errors": [r["error"] for r in runs if "error" in r],
                "use_trials": stats([r["use"]["trials"] for r in ok]),
                "trials_to_converge": stats([r["use"]["trials_to_converge"] for r in ok]),
                "create_failed": stats([r["create"]["failed_trials"] for r in ok
                                        if "create" in r]),
                "create_trials": stats([r["create"]["trials"] for r in ok if "create" in r]),
                "created_tool_eval_successes": stats(
                    [sum(o == "success" for o in r["create"]["eval"]) for r in ok
                     if "create" in r], worst=min),
                "runs": [per_seed(i, r) for i, r in enumerate(runs)],
                "learned_model_eval": {
                    "trials": sum(r["eval"]["trials"] for r in ok),
                    "successes": sum(r["eval"]["successes"] for r in ok)},
                "wall_time_s": {ph: stats([r["wall_time_s"].get(ph) for r in ok])
                                for ph in ("use", "eval", "create", "total")},
                "paper": PAPER[case],
            }
    out = output_path(args, "learning.json")
    if out is not None and out.exists():  # keep the other cases' figures
        previous = json.loads(out.read_text())
        previous.update(results)
        results = previous
    print(json.dumps(results, indent=2))
    if out is None:
        print("figures not written (give --out FILE, or --record to update the tracked "
              "bench/results/learning.json)")
        return 0
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(results, indent=2) + "\n")
    print(f"figures written to {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
