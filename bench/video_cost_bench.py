"""What keeping video clips costs a run: the same whole run with ``--video none`` and ``key``.

Runs ``creative run hook --seed 0`` (``--strategy informative``, catalogued objects
first) once with ``--video none`` and once with ``--video key``, one after the other,
``--rounds`` times, alternating which goes first, each in a fresh process. Records per
run its wall time, the CPU time of the process and its children (the clip encoders are
forked children), the load average before it, and whether the two ``trials.jsonl``
agree trial for trial (tool, tested literal, outcome, reason, pose): recording must not
change the physics. Prints one JSON line a pair; ``--out FILE`` (or ``--record``: the
tracked ``bench/results/video_cost.json``) writes them.

    .venv/bin/python bench/video_cost_bench.py [--case hook] [--rounds 1] [--out FILE | --record]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from recording import add_output_options, write_figures

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
CREATIVE = Path(sys.executable).parent / "creative"
KEYS = ("phase", "trial", "tool", "tested", "outcome", "reason", "pose")


def one(case: str, video: str, out: Path) -> dict:
    """Run one whole case with ``--video video``; return its costs and trial lines."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    proc = subprocess.run([str(CREATIVE), "run", case, "--seed", "0", "--out", str(out),
                           "--video", video], cwd=ROOT, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise SystemExit(f"error: {case} --video {video}: exit {proc.returncode}: "
                         f"{proc.stderr.strip().splitlines()[-1:]}")
    folder = next(p for p in out.iterdir() if (p / "trials.jsonl").exists())
    lines = [json.loads(x) for x in (folder / "trials.jsonl").read_text().splitlines() if x]
    summary = json.loads((folder / "summary.json").read_text())
    clips = summary.get("videos", [])
    return {"video": video, "wall_s": round(wall, 1),
            "cpu_s": round((after.ru_utime + after.ru_stime)
                           - (before.ru_utime + before.ru_stime), 1),
            "load_before": round(load, 2), "clips": len(clips),
            "clip_bytes": sum(c.get("bytes", 0) for c in clips),
            "trials": [{k: t.get(k) for k in KEYS} for t in lines]}


def main() -> int:
    """Run the pairs and write the record."""
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--case", default="hook", help="the case run (default hook)")
    ap.add_argument("--rounds", type=int, default=1,
                    help="pairs of runs, alternating which goes first (default 1)")
    add_output_options(ap, "video_cost.json", "the pairs' times (JSON)")
    args = ap.parse_args()
    base = Path(tempfile.mkdtemp(prefix="video-cost-"))
    pairs = []
    try:
        for r in range(args.rounds):
            order = ("none", "key") if r % 2 == 0 else ("key", "none")
            got = {v: one(args.case, v, base / f"{r}-{v}") for v in order}
            same = got["none"]["trials"] == got["key"]["trials"]
            for v in got.values():
                del v["trials"]
            pairs.append({"order": list(order), "none": got["none"], "key": got["key"],
                          "same_trials": same,
                          "wall_ratio": round(got["key"]["wall_s"] / got["none"]["wall_s"], 3),
                          "cpu_ratio": round(got["key"]["cpu_s"] / got["none"]["cpu_s"], 3)})
            print(json.dumps(pairs[-1]), flush=True)
    finally:
        shutil.rmtree(base, ignore_errors=True)
    write_figures(args, "video_cost.json", {
        "bench": "video_cost", "case": args.case, "seed": 0,
        "command": f"creative run {args.case} --seed 0 --video none|key",
        "cores": os.cpu_count(), "recorded": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "pairs": pairs})
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
