"""Run every benchmark and record its figures under bench/results/ (``make bench``).

Each benchmark is a separate process (one embedded Prolog and one physics client per
process); a failing one is reported and the others still run. The learning benchmark
(several whole runs per case) and the whole runs of every case as a user makes them
(``release_runs.py``, ``video_cost_bench.py``) are the long ones: ``--quick`` leaves them
out. ``bench/readme_figures.py`` (``make readme-figures``) then writes the README's
figures and docs/results.md from what they recorded.
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent

# Each Python benchmark writes its tracked file only when asked: --record
# (bench/recording.py).
BENCHES = [
    ["swipl", str(HERE / "engine_bench.pl"), "--record"],
    [sys.executable, str(HERE / "bridge_bench.py"), "--record"],
    [sys.executable, str(HERE / "mesh_bench.py"), "--record"],
    [sys.executable, str(HERE / "perception_error.py"), "--record"],
    [sys.executable, str(HERE / "sim_bench.py"), "--record"],
    [sys.executable, str(HERE / "sim_wedge_bench.py"), "--record"],
    [sys.executable, str(HERE / "robot_cost_bench.py"), "--record"],
    [sys.executable, str(HERE / "decision_bench.py"), "--record"],
    [sys.executable, str(HERE / "soak_bench.py"), "--record"],
    [sys.executable, str(HERE / "bad_input_bench.py"), "--record"],
]
LEARNING = [sys.executable, str(HERE / "learning_bench.py"), "--record"]
RUNS = [[sys.executable, str(HERE / "release_runs.py"), "--record"],
        [sys.executable, str(HERE / "video_cost_bench.py"), "--record"]]


def main() -> int:
    """Run the benchmarks; return 1 if any failed."""
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true",
                    help="leave out the learning benchmark and the whole runs")
    args = ap.parse_args()
    (HERE / "results").mkdir(exist_ok=True)
    failed = []
    for cmd in BENCHES + ([] if args.quick else [LEARNING, *RUNS]):
        if not Path(cmd[1]).exists():
            print(f"skip {cmd[1]}: not present")
            continue
        t0 = time.perf_counter()
        print(f"== {Path(cmd[1]).name}", flush=True)
        rc = subprocess.call(cmd, cwd=ROOT)
        print(f"== {Path(cmd[1]).name}: exit code {rc}, wall time "
              f"{time.perf_counter() - t0:.1f} s",
              flush=True)
        if rc != 0:
            failed.append(Path(cmd[1]).name)
    if failed:
        print("failed: " + ", ".join(failed))
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
