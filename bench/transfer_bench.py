"""Transfer (``--prior``): tool-use trials with and without a prior, per randomised world.

For each world seed N (``--world-seed N``, seed 0, ``--phase use --video none``): the hook,
the rake and the paddle each learned alone; then the rake and the paddle with the hook's
model of world N as ``--prior``, and the hook with the rake's. One process at a time (the
CLI, so every run is a real run folder); then the table: pair, worlds, tool-use trials
without and with the prior (median, range), evaluation successes, and how the learned
h_g compares.

    python bench/transfer_bench.py run --out /tmp/transfer --pairs PRIOR:CASE,... 1 2 3
    python bench/transfer_bench.py table --out /tmp/transfer --pairs PRIOR:CASE,... \
        [--json bench/results/transfer.json]

(the measured pairs: the hook before the rake and before the paddle, the rake before the
hook; docs/results.md, "Transfer").

Not a test: it takes ~1-2 minutes a world on a 2-core machine.
"""

from __future__ import annotations

import json
import re
import statistics
import subprocess
import sys
from pathlib import Path

PAIRS: tuple[tuple[str, str, str], ...] = ()
"""(name, case, prior case) of each pair, from ``--pairs``."""


def _run(out: Path, name: str, case: str, world: int, prior: Path | None = None) -> None:
    args = [sys.executable, "-m", "creative_py.cli", "run", case, "--phase", "use",
            "--video", "none", "--world-seed", str(world), "--out", str(out / name)]
    if prior is not None:
        args += ["--prior", str(prior)]
    subprocess.run(args, check=True, capture_output=True)


def _folder(out: Path, name: str) -> Path | None:
    found = sorted((out / name).glob("*/summary.json"))
    return found[0].parent if found else None


def run(out: Path, worlds: list[int]) -> None:
    cases = sorted({c for _, a, b in PAIRS for c in (a, b)})
    for n in worlds:
        for case in cases:
            _run(out, f"{case}_w{n}", case, n)
        for _name, case, prior in PAIRS:
            _run(out, f"{case}_p{prior}_w{n}", case, n, _folder(out, f"{prior}_w{n}"))


def _summary(folder: Path | None) -> dict | None:
    if folder is None:
        return None
    s = json.loads((folder / "summary.json").read_text())
    hg = s["hypotheses"]["hg"]
    lits = set(re.findall(r"[a-z_]+\([^()]*\)", hg.split(":-")[1])) if ":-" in hg else set()
    prior = s["use"].get("prior") or {}
    return {"trials": s["use"]["trials"], "stop": s["use"]["stop"],
            "eval": [s["eval"]["successes"], s["eval"]["trials"]], "hg": sorted(lits),
            "taken": prior.get("taken", []), "dropped": prior.get("dropped", [])}


def table(out: Path) -> dict:
    result = {}
    for name, case, prior in PAIRS:
        rows = []
        for folder in sorted((out).glob(f"{case}_w*")):
            n = int(folder.name.rsplit("_w", 1)[1])
            a = _summary(_folder(out, f"{case}_w{n}"))
            b = _summary(_folder(out, f"{case}_p{prior}_w{n}"))
            if a and b:
                rows.append({"world": n, "alone": a, "prior": b})
        result[name] = rows
        if not rows:
            continue
        ta = [r["alone"]["trials"] for r in rows]
        tb = [r["prior"]["trials"] for r in rows]
        ea = [sum(r["alone"]["eval"][i] for r in rows) for i in (0, 1)]
        eb = [sum(r["prior"]["eval"][i] for r in rows) for i in (0, 1)]
        same = sum(r["alone"]["hg"] == r["prior"]["hg"] for r in rows)
        print(f"| {name} | {len(rows)} | {statistics.median(ta):g} [{min(ta)}-{max(ta)}] | "
              f"{statistics.median(tb):g} [{min(tb)}-{max(tb)}] | {ea[0]}/{ea[1]} | "
              f"{eb[0]}/{eb[1]} | {same} of {len(rows)} |")
    return result


if __name__ == "__main__":
    cmd, rest = sys.argv[1], sys.argv[2:]
    out = Path(rest[rest.index("--out") + 1])
    PAIRS = tuple((f"{p} -> {c}", c, p) for p, c in
                  (pair.split(":") for pair in rest[rest.index("--pairs") + 1].split(",")))
    if cmd == "run":
        run(out, [int(x) for x in rest if x.isdigit()])
    else:
        res = table(out)
        if "--json" in rest:
            Path(rest[rest.index("--json") + 1]).write_text(json.dumps(res, indent=1) + "\n")
