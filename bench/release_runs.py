"""Whole runs of every shipped case as a user makes them, and what the README and
docs/results.md say of them.

Two runs per case (every case of ``worlds/`` unless ``--cases`` says), seed 0, ``--strategy informative`` (the default), each a whole
``creative run`` in its own process, one after the other:

``default``
    ``creative run CASE --seed 0 --strategy informative``: catalogued objects first
    (the default); the harder task may be solved by a catalogued object, and then
    nothing is made.
``make``
    the same with ``--demonstrate-creation``, as ``make hook``/``make wedge``/``make
    rake`` run it: a tool is made even after a catalogued object succeeded.
``paper``, ``random``
    tool-use learning alone (``--phase use``, no clips) with the other strategies, for
    the table of strategies on the shipped worlds (docs/results.md).

Records per run: the tool-use trials and their stop, the creation trials, what solved
the harder task (``solved_by``) and each catalogued object's trial, the created tools
(dimensions, mass, printed pieces with print time and filament, strength), the clips
kept (count, frames, seconds, bytes), the evaluations, the wall time, and ``model.pl``
(the learned models). Writes ``bench/results/release_runs.json``; ``bench/readme_figures.py``
puts these figures into the README's table and docs/results.md.

    .venv/bin/python bench/release_runs.py [--cases CASE ...] [--kinds default make
                                           paper random] [--keep DIR [--record-only]]

``--record-only`` records the run folders kept under ``--keep`` again without running.
"""

from __future__ import annotations

import argparse
import json
import platform
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
from recording import add_output_options, output_path, write_figures  # noqa: E402

TRACKED = "release_runs.json"
CREATIVE = Path(sys.executable).parent / "creative"
KINDS = {"default": ["--strategy", "informative", "--video", "key"],
         "make": ["--strategy", "informative", "--video", "key", "--demonstrate-creation"],
         "paper": ["--strategy", "paper", "--phase", "use", "--video", "none"],
         "random": ["--strategy", "random", "--phase", "use", "--video", "none"]}


def command(case: str, kind: str, out: Path) -> list[str]:
    """Return the ``creative run`` command line of one run."""
    return [str(CREATIVE), "run", case, "--seed", "0", "--out", str(out)] + KINDS[kind]


def created_tool(entry: dict) -> dict:
    """Return the figures of one created tool of ``summary.json`` (its file names
    left out)."""
    return {k: v for k, v in entry.items() if k != "files"}


def _measured(verdict: object) -> bool:
    """Whether a trial's verdict names a measured quantity, its value and threshold."""
    return (isinstance(verdict, dict) and bool(verdict.get("quantity"))
            and isinstance(verdict.get("value"), (int, float))
            and isinstance(verdict.get("threshold"), (int, float)))


def _door_angle(verdict: object) -> bool:
    """Whether a trial's verdict measures a door's angle."""
    return _measured(verdict) and "angle" in verdict["quantity"] and \
        verdict.get("unit") == "deg"


def record(folder: Path, argv: list[str], wall_s: float) -> dict:
    """Return the figures of one finished run folder."""
    summary = json.loads((folder / "summary.json").read_text())
    trials = [json.loads(line) for line in
              (folder / "trials.jsonl").read_text().splitlines() if line.strip()]
    create = summary.get("create") or {}
    failures = [t for t in trials if t.get("outcome") != "success"]
    return {
        "verdicts": {
            "trials": len(trials), "failures": len(failures),
            "failures_with_quantity_and_threshold": sum(1 for t in failures
                                                        if _measured(t.get("verdict"))),
            "trials_with_door_angle": sum(1 for t in trials if _door_angle(t.get("verdict")))},
        "command": " ".join(["creative"] + argv[1:]).replace(str(folder.parent), "OUT"),
        "wall_time_s": round(wall_s, 1),
        "summary_wall_time_s": summary.get("wall_time_s"),
        "use": summary["use"],
        "vs_count_initial": summary.get("vs_count_initial"),
        "vs_count_final": summary.get("vs_count_final"),
        "info_bound_trials": summary.get("info_bound_trials"),
        "trial_budget": summary.get("trial_budget"),
        "paper_trials": summary.get("paper_trials"),
        "trials": summary.get("trials"),
        "eval": summary.get("eval"),
        "create": {k: v for k, v in create.items() if k != "created_tools"},
        "created_tools": [created_tool(t) for t in create.get("created_tools", [])],
        "trial_lines": [{k: t.get(k) for k in ("phase", "trial", "tool", "variant",
                                               "kind", "tested", "outcome", "reason",
                                               "verdict")}
                        for t in trials],
        "videos": summary.get("videos", []),
        "hypotheses": summary.get("hypotheses"),
        # model.pl without its comment lines (one names the folder's absolute path).
        "model_pl": "".join(line for line in
                            (folder / "model.pl").read_text().splitlines(keepends=True)
                            if not line.startswith("%")),
    }


def main() -> int:
    """Run the cases and write the record; return 1 if a run failed."""
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cases", nargs="+", default=None,
                    help="case ids (default: every case of worlds/)")
    ap.add_argument("--kinds", nargs="+", default=list(KINDS), choices=list(KINDS),
                    help="which runs of each case (default: all of them)")
    ap.add_argument("--keep", type=Path, help="keep the run folders under DIR")
    ap.add_argument("--record-only", action="store_true",
                    help="record the folders kept under --keep again, running nothing")
    add_output_options(ap, TRACKED, "each run's figures (JSON; the runs of other cases "
                                    "already in the file are kept)")
    args = ap.parse_args()
    if args.record_only and args.keep is None:
        ap.error("--record-only needs --keep DIR")
    if args.cases is None:
        from creative_py.case import load_cases

        args.cases = sorted(load_cases())
    results = output_path(args, TRACKED)
    old = json.loads(results.read_text()) if results is not None and results.exists() else {}
    runs = dict(old.get("runs", {}))
    failed = []
    base = args.keep or Path(tempfile.mkdtemp(prefix="release-runs-"))
    for case in args.cases:
        for kind in args.kinds:
            out = base / f"{case}-{kind}"
            argv = command(case, kind, out)
            if args.record_only:
                folders = sorted(p for p in out.glob("*") if (p / "summary.json").exists())
                if folders:
                    wall = runs.get(f"{case}-{kind}", {}).get("wall_time_s") or 0.0
                    runs[f"{case}-{kind}"] = record(folders[-1], argv, wall)
                else:
                    print(f"{case} {kind}: no finished run under {out}")
                continue
            shutil.rmtree(out, ignore_errors=True)
            t0 = time.perf_counter()
            proc = subprocess.run(argv, cwd=ROOT, capture_output=True, text=True)
            wall = time.perf_counter() - t0
            folders = sorted(p for p in out.glob("*") if (p / "summary.json").exists())
            if proc.returncode != 0 or not folders:
                failed.append(f"{case}-{kind}")
                print(f"{case} {kind}: exit {proc.returncode}: "
                      f"{proc.stderr.strip().splitlines()[-1:]}", flush=True)
                continue
            runs[f"{case}-{kind}"] = record(folders[-1], argv, wall)
            print(f"{case} {kind}: wall time {wall:.0f} s, run folder {folders[-1]}",
                  flush=True)
    write_figures(args, TRACKED, {
        "bench": "release_runs",
        "machine": f"{platform.node()} ({platform.machine()}), shared 2-core",
        "recorded": time.strftime("%Y-%m-%d %H:%M UTC", time.gmtime()),
        "runs": runs})
    if args.keep is None:
        shutil.rmtree(base, ignore_errors=True)
    if failed:
        print("failed: " + ", ".join(failed))
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
