"""The hook case end to end over ROS 2 (the learner and the stand-in arm in two
processes) beside the same run in one process with the pybullet backend.

For each kind of run (``default``: ``creative run hook --seed 0``; ``make``: the same
with ``--demonstrate-creation``, as ``make hook``, so that a tool is created), both with
``--video none`` (the ros backend records no clips):

* ``direct``: ``creative run hook ...`` (the pybullet backend, one process);
* ``ros``: ``python -m creative_py.backends.ros.launch --case hook -- run hook ...
  --backend ros``: the stand-in in its own process, the learner in another, talking
  ROS 2 inside a private network namespace with only loopback (this script re-runs
  itself under ``unshare -rn`` (or ``-n``), ``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST``,
  its own domain id).

Records per run: the wall time, the trials (phase, tool, variant, location, pose,
outcome, reason, the oracle's value and how far the cube moved, steps, the trial's own
time), the learned model and what solved the harder task; for the ros run every
trajectory goal's round trip (sent -> accepted, first feedback, result; the result
minus the trajectory's planned duration) and the scene set-ups; the load (``uptime``)
before and after. Then the trial-by-trial comparison: the same experiment (phase,
tool, variant, location and the literal tested), the pose within :data:`POSE_TOLERANCE`,
the same outcome. Writes ``bench/results/ros_hook.json`` (the case's robot, the Baxter)
or, with ``--robot NAME``, ``bench/results/ros_hook_NAME.json``: both runs on that robot
profile (``--robot NAME``; over ROS the stand-in serves the profile's interface).

    PYTHONPATH=. <venv with the ros extra>/bin/python bench/ros_hook_bench.py \
        [--robot panda] [--kinds default make] [--keep DIR]
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from recording import add_output_options, write_figures

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
TRACKED = "ros_hook.json"
KINDS = {"default": [], "make": ["--demonstrate-creation"]}
POSE_TOLERANCE = 0.002
"""The largest difference of a pose parameter (m or rad) for two trials' poses to count
as the same: the learner's IK and the arm's settling differ by a fraction of this."""


def tracked(robot: str | None) -> str:
    """Return the tracked results file of the runs on ``robot`` (None: the case's)."""
    return TRACKED if robot is None else f"ros_hook_{robot}.json"


def uptime() -> str:
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def run(kind: str, backend: str, out: Path, robot: str | None = None) -> dict:
    """Run one whole hook run (on ``robot``, None: the case's); return its figures
    (folder, wall time, log tail)."""
    args = ["run", "hook", "--seed", "0", "--out", str(out), "--video", "none", *KINDS[kind],
            *(["--robot", robot] if robot else [])]
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    goal_log = out / "goals.json"
    if backend == "ros":
        env["CREATIVE_ROS_GOAL_LOG"] = str(goal_log)
        cmd = [sys.executable, "-m", "creative_py.backends.ros.launch", "--case", "hook",
               "--", *args, "--backend", "ros"]
    else:
        cmd = [sys.executable, "-m", "creative_py.cli", *args]
    before = uptime()
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=ROOT, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} ended {p.returncode}: {p.stderr[-3000:]}")
    folder = Path(p.stdout.strip().splitlines()[-1])
    rec = {"command": " ".join(["creative", *args] + (["--backend", "ros"] if backend == "ros"
                                                       else [])),
           "wall_time_s": round(wall, 2), "uptime_before": before, "uptime_after": uptime(),
           "folder": folder}
    if goal_log.is_file():
        rec["goal_log"] = json.loads(goal_log.read_text())
    return rec


def trials(folder: Path) -> list[dict]:
    out = []
    for line in (folder / "trials.jsonl").read_text().splitlines():
        t = json.loads(line)
        v = t.get("verdict") or {}
        out.append({"trial": t["trial"], "phase": t.get("phase"), "tool": t.get("tool"),
                    "variant": t.get("variant"), "location": t.get("location"),
                    "tested": t.get("tested"),
                    "pose": t.get("pose"), "outcome": t.get("outcome"),
                    "reason": t.get("reason"), "value": v.get("value"),
                    "moved_m": (v.get("measures") or {}).get("moved_m"),
                    "stop": (v.get("stop") or {}).get("brief"),
                    "steps": t.get("steps"), "sim_time_s": t.get("sim_time_s"),
                    "wall_time_s": t.get("wall_time_s")})
    return out


def summary(folder: Path) -> dict:
    s = json.loads((folder / "summary.json").read_text())
    create = s.get("create") or {}
    tools = create.get("created_tools") or []
    return {"hypotheses": s.get("hypotheses"), "plan": s.get("plan"),
            "use": s.get("use"), "trials": s.get("trials"),
            "solved_by": create.get("solved_by"),
            "created": [t.get("name") for t in tools],
            "create_success": create.get("success"),
            "strength": [{k: (t.get("strength") or {}).get(k)
                          for k in ("verdict", "force_n", "peak_force_n", "safety_factor",
                                    "lever_arm_m")} for t in tools]}


def goal_figures(log: dict) -> dict:
    goals = [g for conn in log.values() for g in conn["goals"]]
    scenes = [s for conn in log.values() for s in conn["scene_s"]]

    def stats(values: list[float]) -> dict:
        values = [v for v in values if v is not None]
        if not values:
            return {}
        return {"n": len(values), "median": round(statistics.median(values), 4),
                "min": round(min(values), 4), "max": round(max(values), 4)}

    done = [g for g in goals if g.get("result") is not None]
    return {"goals": len(goals),
            "status": {s: sum(g["status"] == s for g in goals)
                       for s in sorted({g["status"] for g in goals})},
            "accepted_s": stats([g.get("accepted") for g in goals]),
            "first_feedback_s": stats([g.get("first_feedback") for g in goals]),
            "result_minus_planned_s": stats([g["result"] - g["planned_s"] for g in done
                                             if g["status"] == "succeeded"]),
            "planned_s": stats([g["planned_s"] for g in goals]),
            "feedbacks_per_s": stats([g["feedbacks"] / g["result"] for g in done
                                      if g["result"] > 0.2]),
            "scene_setup_s": stats(scenes)}


def compare(direct: list[dict], ros: list[dict]) -> list[dict]:
    rows = []
    for d, r in zip(direct, ros):
        same = all(d.get(k) == r.get(k)
                   for k in ("phase", "tool", "variant", "location", "tested"))
        pose_diff = (max(abs(d["pose"][k] - r["pose"][k]) for k in d["pose"])
                     if d["pose"] and r["pose"] and set(d["pose"]) == set(r["pose"]) else None)
        rows.append({"trial": d["trial"], "same_experiment": same,
                     "same_pose": d["pose"] == r["pose"], "pose_diff": pose_diff,
                     "pose_within": (d["pose"] == r["pose"] or pose_diff is not None
                                     and pose_diff <= POSE_TOLERANCE),
                     "direct": d["outcome"], "ros": r["outcome"],
                     "same_outcome": d["outcome"] == r["outcome"],
                     "moved_m": [d["moved_m"], r["moved_m"]],
                     "value": [d["value"], r["value"]],
                     **({} if d["outcome"] == r["outcome"] else
                        {"direct_reason": d["reason"], "ros_reason": r["reason"]})})
    return rows


def inside(kinds: list[str], keep: str | None = None, robot: str | None = None) -> dict:
    links = sorted(name for _, name in socket.if_nameindex())
    if links != ["lo"]:
        raise SystemExit(f"not in a loopback-only namespace: {links}")
    result = {"bench": "bench/ros_hook_bench.py", "machine": f"{platform.machine()}, "
              f"{os.cpu_count()} cores (shared)", "recorded": time.strftime(
                  "%Y-%m-%d %H:%M UTC", time.gmtime()),
              "robot": robot or "the case's", "pose_tolerance": POSE_TOLERANCE,
              "namespace_links": links, "runs": {}}
    tmp = Path(keep) if keep else Path(tempfile.mkdtemp(prefix="ros_hook_"))
    tmp.mkdir(parents=True, exist_ok=True)
    try:
        for kind in kinds:
            runs = {b: run(kind, b, tmp / f"{kind}-{b}", robot) for b in ("direct", "ros")}
            t = {b: trials(r["folder"]) for b, r in runs.items()}
            s = {b: summary(r["folder"]) for b, r in runs.items()}
            entry = {}
            for b, r in runs.items():
                entry[b] = {k: v for k, v in r.items() if k not in ("folder", "goal_log")}
                entry[b]["trials"] = t[b]
                entry[b]["summary"] = s[b]
            entry["ros"]["round_trip"] = goal_figures(runs["ros"]["goal_log"])
            rows = compare(t["direct"], t["ros"])
            entry["comparison"] = {
                "trials": [len(t["direct"]), len(t["ros"])],
                "same_experiments": sum(r["same_experiment"] for r in rows),
                "same_poses": sum(r["same_pose"] for r in rows),
                "poses_within_tolerance": sum(r["pose_within"] for r in rows),
                "largest_pose_diff": max((r["pose_diff"] for r in rows
                                          if r["pose_diff"] is not None), default=None),
                "same_outcomes": sum(r["same_outcome"] for r in rows),
                "same_model": s["direct"]["hypotheses"] == s["ros"]["hypotheses"],
                "same_plan": s["direct"]["plan"] == s["ros"]["plan"],
                "rows": rows}
            result["runs"][kind] = entry
    finally:
        if not keep:
            shutil.rmtree(tmp, ignore_errors=True)
    return result


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--kinds", nargs="+", default=list(KINDS), choices=list(KINDS),
                    help="which runs: default (the run as it is) and make (with "
                         "--demonstrate-creation, as make runs it); default both")
    ap.add_argument("--keep", metavar="DIR", help="keep the run folders under DIR (new)")
    ap.add_argument("--robot", metavar="NAME", help="run both on this robot profile "
                    "(robots/NAME.toml; default: the case's robot) and record to "
                    "bench/results/ros_hook_NAME.json")
    ap.add_argument("--inside", action="store_true", help=argparse.SUPPRESS)
    add_output_options(ap, "ros_hook.json (ros_hook_NAME.json with --robot)",
                       "the comparison of the two runs (JSON)")
    args = ap.parse_args()
    if args.robot and not (ROOT / "robots" / f"{args.robot}.toml").is_file():
        print(f"{Path(__file__).name}: option --robot: no robot profile robots/"
              f"{args.robot}.toml", file=sys.stderr)
        sys.exit(2)
    if args.keep and Path(args.keep).exists():
        raise SystemExit(f"--keep {args.keep}: exists already; give a new folder")
    if args.inside:
        result = inside(args.kinds, args.keep, args.robot)
        for kind, e in result["runs"].items():
            c = e["comparison"]
            print(f"{kind}: trials {c['trials']}, same experiments {c['same_experiments']}, "
                  f"poses within {POSE_TOLERANCE * 1000:g} mm {c['poses_within_tolerance']} "
                  f"(largest difference {c['largest_pose_diff']}), "
                  f"same outcomes {c['same_outcomes']}, same model {c['same_model']}; wall "
                  f"time {e['direct']['wall_time_s']} s direct, {e['ros']['wall_time_s']} s "
                  f"over ROS; {e['ros']['round_trip']['goals']} trajectory goals sent")
        write_figures(args, tracked(args.robot), result)
        return
    for prefix in (["unshare", "-n"], ["unshare", "-rn"]):
        ok = subprocess.run([*prefix, "true"], capture_output=True).returncode == 0
        if ok:
            break
    else:
        raise SystemExit("unshare refused a private network namespace: the ROS traffic "
                         "needs one")
    env = dict(os.environ, ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
               ROS_DOMAIN_ID=str(150 + os.getpid() % 50), PYTHONPATH=str(ROOT))
    script = " ".join(["ip link set lo up && exec", sys.executable, str(Path(__file__).resolve()),
                       "--inside", "--kinds", *args.kinds,
                       *(["--robot", args.robot] if args.robot else []),
                       *(["--out", str(Path(args.out).resolve())] if args.out else []),
                       *(["--record"] if args.record else []),
                       *(["--keep", str(Path(args.keep).resolve())] if args.keep else [])])
    sys.exit(subprocess.call([*prefix, "sh", "-c", script], env=env, cwd=ROOT))


if __name__ == "__main__":
    main()
