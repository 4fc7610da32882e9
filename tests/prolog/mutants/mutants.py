"""Hand-written mutants of the Prolog core, run against the plunit suite.

Each mutant replaces one snippet (a line, or a few lines that make it unique) of one
file in prolog/ by a changed one: a single change of behaviour. For each, the
repository is copied to a temporary folder (prolog/ and tests/ copied, everything else
linked), the mutant applied there, and the plunit suite run on the copy, the tests of
the mutated module first, stopping at the first failure (tests/prolog/mutants/
first_failure.pl; run_tests.pl's per-test time limit kills a looping mutant). A mutant
is *killed* when a test fails, *survived* when the whole suite passes. A snippet that
is not found exactly once is reported as ``not_applied`` (the file has changed: update
the mutant) and not counted.

    .venv/bin/python tests/prolog/mutants/mutants.py [--only ID ...] [--out FILE]

Two candidates turned out to be equivalent mutants and were replaced: pairing a negated
literal with a positive one in clause_lgg/3 (their LGG is a bare variable, never
head-connected, so it is dropped anyway), and keeping range tests on unbound variables
in nbr_reduce/3 (the prefix search never chooses a range test without the literal that
binds its variable).

Writes bench/results/prolog_mutants.json (score = killed / applied) and exits 1 when a
mutant survived or the unmutated suite fails.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
RUNNER = "tests/prolog/mutants/first_failure.pl"
TIMEOUT_S = 1800

# id, file, units run first, what the mutant breaks, original snippet, replacement
MUTANTS = [
    ("lgg_range_hull", "prolog/lgg.pl", ["lgg", "lgg_equivalence"],
     "the constrained LGG's interval takes the smaller upper end, not the hull",
     "    Hi is max(H1, H2).\n\nvalue_interval_",
     "    Hi is min(H1, H2).\n\nvalue_interval_"),
    ("lgg_head_connection_not_transitive", "prolog/lgg.pl", ["lgg", "lgg_equivalence"],
     "head connection stops after the literals that share a head variable",
     "        Q = [V|Q0]\n", "        Q = Q0\n"),
    ("lgg_ground_literals_dropped", "prolog/lgg.pl", ["lgg", "lgg_equivalence"],
     "ground literals shared by both examples are dropped",
     "    (   Ids == []\n    ->  true\n", "    (   Ids == []\n    ->  fail\n"),
    ("lgg_pair_table_key", "prolog/lgg.pl", ["lgg", "lgg_equivalence"],
     "the same pair of subterms no longer maps to the same variable",
     "        (   get_assoc(T1-T2, Tab0, V)", "        (   get_assoc(T2-T1, Tab0, V)"),
    ("lgg_first_partner_only", "prolog/lgg.pl", ["lgg", "lgg_equivalence"],
     "a body literal pairs only with the first literal of its predicate in the other clause",
     "    ->  foldl(lgg_lit_(Ctx, L1), Partners, GLits, S0, S)",
     "    ->  Partners = [P|_], lgg_lit_(Ctx, L1, P, G1, S0, S), GLits = [G1]"),
    ("subsumption_open_interval", "prolog/subsumption.pl", ["subsumption"],
     "a range test excludes its lower end",
     "    ->  Lo =< V,\n        V =< Hi\n", "    ->  Lo < V,\n        V =< Hi\n"),
    ("subsumption_reduce_self_image", "prolog/subsumption.pl",
     ["subsumption", "lgg", "lgg_equivalence"],
     "a literal may map onto itself, removed or not, in a redundancy test",
     "    \\+ L \\= C,\n    \\+ get_assoc(J, Excl, _).\n", "    \\+ L \\= C.\n"),
    ("subsumption_head_ignored", "prolog/subsumption.pl", ["subsumption"],
     "theta_subsumes/2 does not unify the heads",
     "    GH = SH,\n    split_body_(GB, GLits, GTests0),",
     "    true,\n    split_body_(GB, GLits, GTests0),"),
    ("subsumption_violation_not_counted", "prolog/subsumption.pl", ["subsumption"],
     "clause_violations/3 does not count a violated literal against a substitution",
     "    ;   NV1 is NV + 1,\n        bb_(Ss, [I|Viol], NV1, Ranges, MaxNodes, State)\n    ).\n"
     "bb_step_(test",
     "    ;   NV1 is NV,\n        bb_(Ss, [I|Viol], NV1, Ranges, MaxNodes, State)\n    ).\n"
     "bb_step_(test"),
    ("nbr_no_error_on_covered_negative", "prolog/nbr.pl", ["nbr"],
     "nbr_reduce/3 accepts a clause that covers a negative",
     "    ->  domain_error(clause_covering_no_negative, Clause)", "    ->  true"),
    ("nbr_one_literal_only", "prolog/nbr.pl", ["nbr"],
     "after choosing a literal, nbr_reduce/3 never chooses another one",
     "        nbr_(Head, [Last|Fixed], Before, Negatives, Chosen)",
     "        nbr_(Head, [Last|Fixed], [], Negatives, Chosen)"),
    ("vs_count_drops_other_constraints", "prolog/version_space.pl", ["version_space"],
     "leaving a literal out forgets the constraints it does not hit (disjoint failures)",
     "        append(Left, Rest, CsOut),\n        count_(Free1, Rest, In),",
     "        CsOut = Left,\n        count_(Free1, Rest, In),"),
    ("vs_count_bound", "prolog/version_space.pl", ["version_space"],
     "the bound beyond 20 literals subtracts the wrong power of two",
     "                     B is 2^N - 2^(N - K) ),", "                     B is 2^N - 2^K ),"),
    ("experiment_spatial_as_structure", "prolog/experiment.pl", ["experiment"],
     "task_objects/3 counts spatial literals as an object's structure",
     "                           \\+ spatial_any_(L),\n                           \\+ robot_literal_(L) ),",
     "                           \\+ robot_literal_(L) ),"),
    ("experiment_no_gripper_empty", "prolog/experiment.pl", ["experiment"],
     "observed_state/3 leaves out gripper_empty when nothing is held",
     "    ->  Grip = [gripper_empty]", "    ->  Grip = []"),
]


def copy_repo(dest: Path) -> None:
    """Copy prolog/ and tests/ to dest, link every other entry of the repository."""
    for entry in ROOT.iterdir():
        if entry.name in (".git", ".venv"):
            continue
        target = dest / entry.name
        if entry.name in ("prolog", "tests"):
            shutil.copytree(entry, target, ignore=shutil.ignore_patterns("__pycache__"))
        else:
            target.symlink_to(entry)


def run_suite(root: Path, units: list[str]) -> tuple[str, float, str]:
    """Run the suite on root, units first; return (outcome, seconds, last stderr line)."""
    goal = "first_failure([" + ", ".join(units) + "])"
    t0 = time.monotonic()
    try:
        proc = subprocess.run(["swipl", "-q", "-g", goal, "-t", "halt(2)", str(root / RUNNER)],
                              capture_output=True, text=True, timeout=TIMEOUT_S, cwd=root)
    except subprocess.TimeoutExpired:
        return "killed", time.monotonic() - t0, f"suite ran over {TIMEOUT_S} s"
    secs = time.monotonic() - t0
    last = (proc.stderr.strip().splitlines() or [""])[-1]
    if proc.returncode == 0:
        return "survived", secs, last
    return "killed", secs, last


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", nargs="+", help="run only these mutant ids")
    ap.add_argument("--out", type=Path, default=ROOT / "bench" / "results" / "prolog_mutants.json")
    args = ap.parse_args()
    chosen = [m for m in MUTANTS if not args.only or m[0] in args.only]
    if args.only and len(chosen) != len(args.only):
        known = {m[0] for m in MUTANTS}
        print(f"error: --only: unknown mutant {sorted(set(args.only) - known)}", file=sys.stderr)
        return 2
    rows = []
    with tempfile.TemporaryDirectory(prefix="prolog_mutants_") as tmp:
        base = Path(tmp) / "base"
        base.mkdir()
        copy_repo(base)
        outcome, secs, last = run_suite(base, [])
        print(f"unmutated suite: {'passes' if outcome == 'survived' else 'FAILS'} ({secs:.0f} s)",
              flush=True)
        if outcome != "survived":
            print(f"error: the unmutated plunit suite fails: {last}", file=sys.stderr)
            return 1
        for ident, rel, units, what, old, new in chosen:
            root = Path(tmp) / ident
            root.mkdir()
            copy_repo(root)
            path = root / rel
            text = path.read_text()
            if text.count(old) != 1:
                rows.append({"id": ident, "file": rel, "breaks": what, "outcome": "not_applied",
                             "detail": f"snippet found {text.count(old)} times"})
                print(f"{ident}: not applied", flush=True)
                continue
            path.write_text(text.replace(old, new))
            outcome, secs, last = run_suite(root, units)
            rows.append({"id": ident, "file": rel, "breaks": what, "outcome": outcome,
                         "seconds": round(secs, 1), "detail": last})
            print(f"{ident}: {outcome} ({secs:.0f} s) {last}", flush=True)
            shutil.rmtree(root)
    applied = [r for r in rows if r["outcome"] != "not_applied"]
    killed = sum(r["outcome"] == "killed" for r in applied)
    result = {"benchmark": "prolog_mutants", "mutants": len(rows), "applied": len(applied),
              "killed": killed, "survived": len(applied) - killed,
              "score": round(killed / len(applied), 3) if applied else None,
              "runner": "tests/prolog/mutants/mutants.py", "results": rows}
    if not args.only:
        args.out.parent.mkdir(exist_ok=True)
        args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(f"killed {killed} of {len(applied)} applied mutants"
          + (f"; wrote {args.out}" if not args.only else ""))
    return 0 if killed == len(applied) else 1


if __name__ == "__main__":
    raise SystemExit(main())
