"""Where ``make test``'s time goes: wall and CPU seconds of its two parts, and per test.

Runs the two commands of ``make test`` as the Makefile does (the plunit tests, then
pytest ``-m "not slow" -n auto``) and records for each the wall seconds and the CPU
seconds (user + system of the command and every process it waited for: the machine is
shared, so the CPU figure is the one that does not depend on the other processes), the
load average before and after, and, through the pytest plugin ``bench/_test_cpu.py``,
the CPU and wall seconds of every test, summed by file and the ``--top`` dearest.
Writes ``bench/results/test_time.json`` (``--label`` names the measurement; earlier
measurements are kept under ``history``).

    .venv/bin/python bench/test_time.py [--label "after the shared short run"] [--top 40]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import resource
import subprocess
import sys
import tempfile
import time
from collections import defaultdict
from datetime import datetime, timezone
from pathlib import Path

from recording import add_output_options, output_path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TRACKED = "test_time.json"


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed(cmd: list[str], env: dict) -> tuple[dict, str]:
    """Run ``cmd`` in the project's root, its output shown as it comes; return its exit
    code, wall and CPU seconds, and its output."""
    cpu, wall = _children_cpu(), time.perf_counter()
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    out = []
    for line in proc.stdout:
        sys.stdout.write(line)
        out.append(line)
    rc = proc.wait()
    return ({"exit_code": rc, "wall_s": round(time.perf_counter() - wall, 1),
             "cpu_s": round(_children_cpu() - cpu, 1)}, "".join(out))


def counts(prolog_out: str, python_out: str) -> dict:
    """The tests each part ran: plunit's "N plunit tests, K failed" and pytest's summary
    line ("N passed, M skipped, K deselected in S s")."""
    m = re.search(r"(\d+) plunit tests, (\d+) failed", prolog_out)
    summary = [line for line in python_out.splitlines()
               if re.search(r"\d+ (passed|failed).* in [\d.]+s", line)]
    pytest = {k.rstrip("s") if k.startswith("error") else k: int(v) for v, k in re.findall(
        r"(\d+) (passed|failed|skipped|deselected|errors?|xfailed|xpassed)",
        summary[-1] if summary else "")}
    return {"plunit_tests": int(m.group(1)) if m else None,
            "plunit_failed": int(m.group(2)) if m else None, "pytest": pytest}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--label", default=None,
                    help="a name for this measurement in the file's history (e.g. the change "
                         "it measures)")
    ap.add_argument("--top", type=int, default=40,
                    help="the dearest tests kept, by CPU seconds (default 40)")
    add_output_options(ap, TRACKED, "the times (JSON; the file's earlier measurement moves "
                                    "to its history)")
    args = ap.parse_args(argv)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), str(HERE),
                                                    env.get("PYTHONPATH")) if p)
    load_before = os.getloadavg()
    prolog, prolog_out = timed(["swipl", "--on-warning=status", "-q", "-g", "run_all", "-t", "halt",
                    "tests/prolog/run_tests.pl"], env)
    with tempfile.NamedTemporaryFile(suffix=".jsonl", delete=False) as tmp:
        lines_path = Path(tmp.name)
    env["CREATIVE_TEST_CPU"] = str(lines_path)
    python, python_out = timed([sys.executable, "-m", "pytest", "-q", "-m", "not slow", "-n", "auto",
                    "-p", "_test_cpu"], env)
    load_after = os.getloadavg()
    tests = [json.loads(line) for line in lines_path.read_text().splitlines()]
    lines_path.unlink()
    by_file: dict[str, list[float]] = defaultdict(lambda: [0.0, 0])
    for t in tests:
        by_file[t["test"].split("::")[0]][0] += t["cpu_s"]
        by_file[t["test"].split("::")[0]][1] += 1
    python["tests"] = len(tests)
    python["cpu_in_tests_s"] = round(sum(t["cpu_s"] for t in tests), 1)
    entry = {
        "at": datetime.now(timezone.utc).strftime("%Y-%m-%dT%H:%MZ"),
        "label": args.label,
        "cpus": os.cpu_count(),
        "counts": counts(prolog_out, python_out),
        "load_average_before": [round(x, 2) for x in load_before],
        "load_average_after": [round(x, 2) for x in load_after],
        "prolog": prolog,
        "python": python,
        "total_wall_s": round(prolog["wall_s"] + python["wall_s"], 1),
        "total_cpu_s": round(prolog["cpu_s"] + python["cpu_s"], 1),
        "cpu_by_file_s": {f: {"cpu_s": round(c, 1), "tests": n} for f, (c, n) in
                          sorted(by_file.items(), key=lambda kv: -kv[1][0])},
        "dearest_tests": sorted(tests, key=lambda t: -t["cpu_s"])[:args.top],
    }
    print(f"make test: {entry['total_wall_s']} s wall, {entry['total_cpu_s']} s CPU "
          f"(load average {entry['load_average_before'][0]} before, "
          f"{entry['load_average_after'][0]} after)")
    results = output_path(args, TRACKED)
    if results is None:
        print(f"figures not written (give --out FILE, or --record to update the tracked "
              f"bench/results/{TRACKED})")
        return 0 if prolog["exit_code"] == 0 and python["exit_code"] == 0 else 1
    previous = json.loads(results.read_text()) if results.exists() else {}
    history = previous.get("history", [])
    if previous.get("latest"):
        history.append({k: previous["latest"].get(k) for k in
                        ("at", "label", "counts", "load_average_before", "load_average_after",
                         "prolog", "python", "total_wall_s", "total_cpu_s")})
    results.write_text(json.dumps({
        "what": "make test (plunit, then pytest -m 'not slow' -n auto): wall and CPU "
                "seconds (user + system, the commands and their children); per test "
                "through bench/_test_cpu.py",
        "latest": entry, "history": history}, indent=2) + "\n")
    print(f"figures written to {results}")
    return 0 if prolog["exit_code"] == 0 and python["exit_code"] == 0 else 1


if __name__ == "__main__":
    raise SystemExit(main())
