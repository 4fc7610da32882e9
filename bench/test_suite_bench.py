"""How many tests ``make test`` runs and how long it takes.

Runs ``make test`` (the plunit suites, then pytest without the slow tests, one worker a
core) once, timing each part, and records the counts each reports (``run_all``'s "N
plunit tests, K failed", pytest's "N passed, M skipped, K deselected"), the exit code and the load
average before and after. Writes ``bench/results/test_suite.json``; a failing suite is
recorded too (and the script exits 1). ``CREATIVE_TEST_SUITE_BENCH`` tells
``tests/python/test_readme_figures.py`` not to check the README's ``test-suite`` block,
which this run is measuring.

    .venv/bin/python bench/test_suite_bench.py
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def part(target: str) -> dict:
    """Run ``make <target>``; return its wall time, exit code and output's tail."""
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    env = {**os.environ, "CREATIVE_TEST_SUITE_BENCH": "1"}
    proc = subprocess.run(["make", "--no-print-directory", target], cwd=ROOT,
                          capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t0
    out = proc.stdout + proc.stderr
    sys.stdout.write(out[-3000:])
    return {"target": target, "exit_code": proc.returncode, "wall_s": round(wall, 1),
            "load_before": round(load, 2), "output": out}


def main() -> int:
    """Run both parts of ``make test`` and write the record."""
    prolog, python = part("test-prolog"), part("test-python")
    m = re.search(r"(\d+) plunit tests, (\d+) failed", prolog["output"])
    n_prolog = int(m.group(1)) if m else None
    summary = [line for line in python["output"].splitlines()
               if re.search(r"\d+ (passed|failed).* in [\d.]+s", line)]
    counts = {k: int(v) for v, k in re.findall(
        r"(\d+) (passed|failed|skipped|deselected|errors?|xfailed|xpassed)",
        summary[-1] if summary else "")}
    for p in (prolog, python):
        p["tail"] = p.pop("output").strip().splitlines()[-3:]
    record = {"bench": "test_suite", "command": "make test", "cores": os.cpu_count(),
              "recorded": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
              "plunit_tests": n_prolog, "pytest": counts,
              "wall_s": round(prolog["wall_s"] + python["wall_s"], 1),
              "load_after": round(os.getloadavg()[0], 2), "parts": [prolog, python]}
    (HERE / "results" / "test_suite.json").write_text(json.dumps(record, indent=1) + "\n")
    ok = prolog["exit_code"] == 0 and python["exit_code"] == 0
    print(f"make test: plunit {n_prolog}, pytest {counts}, {record['wall_s']} s, "
          f"{'ok' if ok else 'FAILED'}")
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
