"""Transfer (``--prior``): tool-use trials with and without a prior, per randomised world,
as sweeps on Ray (:func:`creative_py.sweep.run_sweep`).

For the world seeds given (``--world-seed N``, seed 0, ``--phase use --video none``):

1. one sweep runs every case of the pairs alone (``alone/``);
2. one sweep per pair ``PRIOR:CASE`` runs CASE with ``--prior`` the PRIOR case's run of
   the same world (``PRIOR_to_CASE/``, the sweep's ``{world}`` placeholder);
3. one sweep per edited pair ``PRIOR!:CASE`` runs CASE with a deliberately wrong prior:
   the PRIOR case's model of the same world with h_g replaced by the h_s its first
   tool-use trial left (every literal of the demonstration that one trial did not
   rule out claimed necessary: tool properties the physics shows unnecessary among
   them) (``PRIOR_edited_to_CASE/``).

A prior the ontology cannot map is refused by the run (exit 2 on the command line); its
rows are counted as refused. Then the table: pair, worlds, tool-use trials without and
with the prior (median, range), evaluation successes, how many learned h_g equal the
run without a prior, and the prior's literals settled, confirmed and contradicted.

    nice python bench/transfer_bench.py run --out /tmp/transfer \\
        --pairs hook:rake,hook:paddle_tube,rake:hook,wedge:hook,hook!:hook \\
        --num-cpus 2 --worlds 1-20
    python bench/transfer_bench.py table --out /tmp/transfer --pairs ... --worlds 1-20 \\
        [--json bench/results/transfer.json]

Not a test: ~10 s a run; 7 sweeps of 20 worlds take ~15 min on 2 cores.
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import sys
from pathlib import Path

from creative_py.sweep import SweepOptions, parse_ints, plan_runs, run_sweep

PAIRS: tuple[tuple[str, str, str, bool], ...] = ()
"""(name, case, prior case, edited) of each pair, from ``--pairs``."""


def _sweep_name(case: str, prior: str, edited: bool) -> str:
    return f"{prior}_{'edited_' if edited else ''}to_{case}"


def _run_dir(out: Path, sweep: str, case: str, world: int) -> Path:
    return out / sweep / "runs" / f"{case}-informative-s0-w{world}"


def _edit(out: Path, prior: str, world: int) -> Path:
    """Write the edited (wrong) prior of ``world``: the prior case's model with h_g
    replaced by the h_s of its first tool-use trial."""
    src = _run_dir(out, "alone", prior, world)
    first = json.loads((src / "trials.jsonl").read_text().splitlines()[0])
    hs = first["hs"]
    dest = out / "edited" / f"{prior}-w{world}"
    dest.mkdir(parents=True, exist_ok=True)
    (dest / "model.pl").write_text(
        "% Deliberately wrong prior: h_g := the h_s after the first tool-use trial of\n"
        f"% {src} (every literal left claimed necessary).\n"
        f"learned_hypothesis({prior}, hs, ({hs})).\n"
        f"learned_hypothesis({prior}, hg, ({hs})).\n")
    return dest


def run(out: Path, worlds: list[int], num_cpus: int) -> None:
    cases = sorted({c for _, a, b, _e in PAIRS for c in (a, b)})
    say = lambda m: print(m, file=sys.stderr, flush=True)  # noqa: E731
    if not (out / "alone").exists():
        run_sweep(plan_runs(cases, ["informative"], [0], worlds), out,
                  SweepOptions(phase="use"), num_cpus=num_cpus, name="alone", progress=say)
    for _name, case, prior, edited in PAIRS:
        sweep = _sweep_name(case, prior, edited)
        if (out / sweep).exists():
            continue
        if edited:
            for n in worlds:
                _edit(out, prior, n)
            template = str(out / "edited" / f"{prior}-w{{world}}")
        else:
            template = str(out / "alone" / "runs" / f"{prior}-informative-s0-w{{world}}")
        run_sweep(plan_runs([case], ["informative"], [0], worlds), out,
                  SweepOptions(phase="use", prior=template), num_cpus=num_cpus,
                  name=sweep, progress=say)


def _summary(folder: Path) -> dict | None:
    if not (folder / "summary.json").is_file():
        return None
    s = json.loads((folder / "summary.json").read_text())
    hg = s["hypotheses"]["hg"]
    lits = set(re.findall(r"[a-z_]+\([^()]*\)", hg.split(":-")[1])) if ":-" in hg else set()
    prior = s["use"].get("prior") or {}
    return {"trials": s["use"]["trials"], "stop": s["use"]["stop"],
            "eval": [s["eval"]["successes"], s["eval"]["trials"]], "hg": sorted(lits),
            "taken": prior.get("taken", []), "dropped": prior.get("dropped", []),
            "settled": prior.get("settled", []), "confirmed": prior.get("confirmed", [])}


def _refusal(out: Path, sweep: str, case: str, world: int) -> str | None:
    path = out / sweep / "sweep.csv"
    if not path.is_file():
        return None
    from creative_py.sweep import read_csv

    for row in read_csv(path):
        if row["case"] == case and row["world_seed"] == str(world) and row["status"] != "ok":
            return row["error"]
    return None


def _span(xs: list[int]) -> str:
    return f"{statistics.median(xs):g} [{min(xs)}-{max(xs)}]" if xs else "-"


def table(out: Path, worlds: list[int]) -> dict:
    result = {}
    print("| prior -> case | worlds | trials alone | trials with prior | eval alone | "
          "eval with prior | h_g as alone | prior literals contradicted (runs) |")
    print("|---|---|---|---|---|---|---|---|")
    for name, case, prior, edited in PAIRS:
        sweep = _sweep_name(case, prior, edited)
        rows, refused = [], []
        for n in worlds:
            a = _summary(_run_dir(out, "alone", case, n))
            b = _summary(_run_dir(out, sweep, case, n))
            if a and b:
                rows.append({"world": n, "alone": a, "prior": b})
            elif a:
                why = _refusal(out, sweep, case, n)
                if why:
                    refused.append({"world": n, "alone": a, "refused": why})
        result[name] = {"rows": rows, "refused": refused}
        ta = [r["alone"]["trials"] for r in rows + refused]
        tb = [r["prior"]["trials"] for r in rows]
        ea = [sum(r["alone"]["eval"][i] for r in rows + refused) for i in (0, 1)]
        eb = [sum(r["prior"]["eval"][i] for r in rows) for i in (0, 1)]
        same = sum(r["alone"]["hg"] == r["prior"]["hg"] for r in rows)
        contra = sum(bool(r["prior"]["dropped"]) for r in rows)
        if refused and not rows:
            print(f"| {name} | {len(refused)} | {_span(ta)} | refused in {len(refused)} "
                  f"of {len(refused)} (exit 2) | {ea[0]}/{ea[1]} | - | - | - |")
            continue
        print(f"| {name} | {len(rows)} | {_span(ta)} | {_span(tb)} | {ea[0]}/{ea[1]} | "
              f"{eb[0]}/{eb[1]} | {same} of {len(rows)} | {contra} |")
    return result


def _pairs(text: str) -> tuple[tuple[str, str, str, bool], ...]:
    out = []
    for pair in text.split(","):
        prior, case = pair.split(":")
        edited = prior.endswith("!")
        prior = prior.rstrip("!")
        out.append((f"{prior}{' (edited, wrong)' if edited else ''} -> {case}", case,
                    prior, edited))
    return tuple(out)


def parse(argv: list[str] | None = None) -> argparse.Namespace:
    """Return the command line's arguments (``run`` or ``table``, see the module's
    docstring)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="\n".join(__doc__.splitlines()[2:]))
    ap.add_argument("command", choices=("run", "table"),
                    help="run: the sweeps; table: the table of sweeps already run")
    ap.add_argument("--out", type=Path, required=True, metavar="DIR",
                    help="the folder of the sweeps (run writes it, table reads it)")
    ap.add_argument("--pairs", required=True, metavar="PRIOR:CASE,...",
                    help="the pairs, PRIOR:CASE each (PRIOR!:CASE: an edited, wrong prior)")
    ap.add_argument("--num-cpus", type=int, default=2,
                    help="ray's CPUs for the sweeps (default 2)")
    ap.add_argument("--worlds", default="1-20",
                    help="the world seeds, as --world-seed takes them (default 1-20)")
    ap.add_argument("--json", type=Path, default=None, metavar="FILE",
                    help="table: also write the table's figures (JSON) to FILE (e.g. the "
                         "tracked bench/results/transfer.json; default: only print)")
    return ap.parse_args(argv)


if __name__ == "__main__":
    args = parse()
    PAIRS = _pairs(args.pairs)
    worlds = parse_ints(args.worlds, "--worlds")
    if args.command == "run":
        run(args.out.resolve(), worlds, args.num_cpus)
    else:
        res = table(args.out.resolve(), worlds)
        if args.json is not None:
            args.json.write_text(json.dumps(res, indent=1) + "\n")
