"""Time how long the command line takes to refuse each bad input of the corpus.

Runs every row of ``tests/reliability/test_bad_input.py``'s ``CORPUS`` (the real
``creative`` command line in its own process, as the test does) ``--repeat`` times and
records the median and worst wall time per row, with the exit code, in
``bench/results/bad_input.json``. Aim: every refusal under 10 s (issue: "no bad input
in the corpus takes longer than 10 s to be refused").

    .venv/bin/python bench/bad_input_bench.py [--repeat 3]
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests" / "reliability"))

from test_bad_input import CORPUS, creative  # noqa: E402

from recording import add_output_options, write_figures  # noqa: E402

AIM_S = 10.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs of each refused command; its worst time counts (default 3)")
    add_output_options(parser, "bad_input.json", "each command's median and worst time (JSON)")
    args = parser.parse_args()
    rows = []
    for argv, _message in CORPUS:
        times, codes = [], set()
        for _ in range(args.repeat):
            with tempfile.TemporaryDirectory() as tmp:
                a_file = Path(tmp) / "a_file"
                a_file.write_text("not a folder\n")
                cmd = [a.format(tmp=tmp, a_file=a_file) for a in argv]
                t0 = time.perf_counter()
                proc = creative(*cmd)
                times.append(time.perf_counter() - t0)
                codes.add(proc.returncode)
        rows.append({"args": argv, "median_s": round(statistics.median(times), 3),
                     "worst_s": round(max(times), 3), "exit_codes": sorted(codes)})
        print(f"worst of {args.repeat}: {max(times):6.2f} s  creative {' '.join(argv)}",
              flush=True)
    worst = max(r["worst_s"] for r in rows)
    result = {"rows": rows, "repeat": args.repeat, "worst_s": worst, "aim_s": AIM_S,
              "all_under_aim": worst < AIM_S,
              "note": "wall time of one refused command, process start included"}
    print(f"worst refused command: {worst:.2f} s (aim < {AIM_S:g} s)")
    write_figures(args, "bad_input.json", result)
    return 0


if __name__ == "__main__":
    sys.exit(main())
