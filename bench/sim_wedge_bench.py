"""Benchmark the tool action alone: the outcome table with the tool placed by hand.

For every case whose pose skill the trainer can do by hand (its primitive has the
``by_hand`` option, e.g. ``place_on_floor``), runs ``bench/sim_bench.py --by-hand``:
every tool in every variant put at the demonstration's pose without the robot, then
the tool action, judged by the oracle. The table with the arm placing comes from
``bench/sim_bench.py``. Prints each table; ``--out-dir DIR`` (or ``--record``: the
tracked ``bench/results/``) writes ``sim_<case>_by_hand.json``.

    .venv/bin/python bench/sim_wedge_bench.py [--out-dir DIR | --record]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from sim_bench import main as sim_bench_main  # noqa: E402

from creative_py.case import load_cases  # noqa: E402
from creative_py.backends.pybullet.primitives import PRIMITIVES  # noqa: E402


def by_hand_cases() -> list[str]:
    """Return the ids of the cases whose pose skill can be done by hand."""
    out = []
    for cid, m in sorted(load_cases().items()):
        pose_skill = next(s for s in m.skills if s.pose)
        if "by_hand" in PRIMITIVES[pose_skill.primitive].options:
            out.append(cid)
    return out


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--out-dir", metavar="DIR",
                       help="write each case's table (sim_<case>_by_hand.json) into DIR "
                            "(default: write nothing, only print)")
    where.add_argument("--record", action="store_true",
                       help="write them into the tracked bench/results/")
    args = ap.parse_args()
    cases = by_hand_cases()
    if cases:
        sim_bench_main([*cases, "--by-hand",
                        *(["--out-dir", args.out_dir] if args.out_dir else []),
                        *(["--record"] if args.record else [])])
