"""The ROS 2 stand-in's rates and a goal's round trip, idle and under load.

    python bench/ros_roundtrip.py [--loads 0,2] [--nice 0] [--goals 6] [--wall-clock]
                                  [--out bench/results/ros_roundtrip.json]

Needs the ``ros`` extra (``make setup-ros``). All ROS traffic runs in a private network
namespace with loopback only (the script re-runs itself under ``unshare -rn`` or
``unshare -n``), with ``ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST`` and a domain id of its
own. For each load (that many ``while 1: pass`` processes started by this script, and
stopped by it, by their pids) it starts the stand-in of the hook case (at ``--nice``,
e.g. 10 to see it starved by the load), waits for the learner's client, then measures:

* the stand-in's real-time factor over 5 s (its ``/clock`` against the wall clock);
* the joint states' rate at the learner (messages per wall-clock second) and per
  simulated second;
* ``--goals`` round trips of a 1.0 s two-joint goal: wall-clock seconds from sending
  to accepted, first feedback and result, and the feedback messages per goal.

The load average (``/proc/loadavg``) is recorded at the start and the end of each
condition: other processes on the machine count too. The figures are not test bounds.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from recording import add_output_options, write_figures

ROOT = Path(__file__).resolve().parents[1]
MARK = "CREATIVE_ROS_BENCH_IN_NAMESPACE"


def loadavg() -> list[float]:
    return [float(v) for v in Path("/proc/loadavg").read_text().split()[:3]]


def summary(values: list[float]) -> dict:
    values = [v for v in values if v is not None]
    if not values:
        return {}
    return {"median": round(statistics.median(values), 4), "min": round(min(values), 4),
            "max": round(max(values), 4)}


def measure(load: int, nice: int, goals: int, sim_time: bool, tmp: Path,
            standin_root: Path = ROOT) -> dict:
    """Start the stand-in and the client under ``load`` busy processes; return the figures."""
    from creative_py.backends.ros.client import ArmClient
    from creative_py.backends.ros.profile import ROBOTS_ROOT, load_profile

    text = (ROBOTS_ROOT / "baxter.toml").read_text()
    path = tmp / "baxter.toml"
    path.write_text(text.replace("use_sim_time = false", f"use_sim_time = {str(sim_time).lower()}"))
    # the bench watches /clock in both cases (the stand-in always publishes it)
    watch = tmp / "watch.toml"
    watch.write_text(text.replace("use_sim_time = false", "use_sim_time = true"))
    profile, watch_profile = load_profile(path), load_profile(watch)
    if standin_root != ROOT:  # an older stand-in reads no [clock] table
        path = tmp / "older.toml"
        path.write_text(text.split("\n[clock]")[0] + "\n")
    busy = [subprocess.Popen([sys.executable, "-c", "while 1: pass"]) for _ in range(load)]
    out: dict = {"load_processes": load, "standin_nice": nice, "use_sim_time": sim_time,
                 "loadavg_start": loadavg()}
    standin = subprocess.Popen(["nice", "-n", str(nice), sys.executable, "-m",
                                "creative_py.backends.ros.standin", "--case", "hook",
                                "--seconds", "300", "--profile", str(path)],
                               stdout=subprocess.PIPE, text=True, cwd=standin_root,
                               env=dict(os.environ, PYTHONPATH=str(standin_root)))
    client = clock = None
    try:
        time.sleep(2.0)  # the load settles
        line = standin.stdout.readline()
        if not line.startswith("standin ready "):
            raise RuntimeError(f"the stand-in did not start: {line!r}")
        client = ArmClient(profile, [])
        clock = ArmClient(watch_profile, [], name="creative_bench_clock")
        client.wait_for_arm(60.0)
        try:
            clock.wait_for_arm(5.0)
        except Exception:  # a stand-in without /clock (an older one): no factor
            clock.close()
            clock = None
        time.sleep(1.0)
        now = (lambda: clock.now()) if clock is not None else (lambda: 0.0)
        n0, c0, w0 = client.joint_state.count, now(), time.monotonic()
        time.sleep(5.0)
        wall = time.monotonic() - w0
        sim = now() - c0
        js = client.joint_state.count - n0
        out["real_time_factor"] = round(sim / wall, 3) if clock is not None else None
        out["joint_states_per_wall_s"] = round(js / wall, 1)
        out["joint_states_per_sim_s"] = round(js / sim, 1) if sim > 0 else None
        q0 = client.arm_q()
        q1 = list(q0)
        q1[0] += 0.2
        q1[3] -= 0.15
        trips = []
        for k in range(goals):
            c0 = now()
            r = client.send_trajectory(client.make_goal([(1.0, q1 if k % 2 == 0 else q0)]))
            trips.append({"status": r.status, "accepted": r.times.accepted,
                          "first_feedback": r.times.first_feedback, "result": r.times.result,
                          "feedbacks": r.times.feedbacks,
                          "sim_s": round(now() - c0, 3)})
            time.sleep(0.2)
        out["goals"] = trips
        out["round_trip_s"] = {key: summary([t[key] for t in trips])
                               for key in ("accepted", "first_feedback", "result")}
        out["feedbacks_per_goal"] = summary([t["feedbacks"] for t in trips])
        out["statuses"] = sorted({t["status"] for t in trips})
    finally:
        for c in (client, clock):
            if c is not None:
                c.close()
        standin.terminate()
        standin.wait(10)
        out["loadavg_end"] = loadavg()
        for p in busy:
            p.kill()
            p.wait()
    return out


def inner(args: argparse.Namespace) -> dict:
    result = {"bench": "ros_roundtrip", "machine_cpus": os.cpu_count(),
              "standin_root": args.standin_root or ".",
              "when_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
              "goal": "a 1.0 s trajectory of two joints (0.2 and 0.15 rad), there and back",
              "conditions": []}
    with tempfile.TemporaryDirectory() as tmp:
        for load in args.loads:
            result["conditions"].append(measure(load, args.nice, args.goals,
                                                not args.wall_clock, Path(tmp),
                                                Path(args.standin_root or ROOT)))
    return result


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--loads", default="0,2", help="busy processes per condition (default 0,2)")
    ap.add_argument("--nice", type=int, default=0, help="the stand-in's niceness (default 0)")
    ap.add_argument("--goals", type=int, default=6,
                    help="trajectory goals sent per condition (default 6)")
    ap.add_argument("--wall-clock", action="store_true",
                    help="the client judges on the wall clock (default: use_sim_time)")
    ap.add_argument("--standin-root", help="run the stand-in of this checkout (a comparison)")
    add_output_options(ap, "ros_roundtrip.json", "the rates and round trips (JSON)")
    args = ap.parse_args()
    args.loads = [int(v) for v in args.loads.split(",")]
    if os.environ.get(MARK):
        print(json.dumps(inner(args)), flush=True)
        return 0
    for prefix in (["unshare", "-n"], ["unshare", "-rn"]):
        if shutil.which("unshare") and subprocess.run(
                [*prefix, "sh", "-c", "ip link set lo up"], capture_output=True).returncode == 0:
            break
    else:
        print("ros_roundtrip: no private network namespace (unshare refused): not run",
              file=sys.stderr)
        return 2
    env = dict(os.environ, **{MARK: "1"}, ROS_AUTOMATIC_DISCOVERY_RANGE="LOCALHOST",
               ROS_DOMAIN_ID=str(200 + os.getpid() % 30),
               PYTHONPATH=os.pathsep.join(filter(None, [str(ROOT), os.environ.get("PYTHONPATH")])))
    command = " ".join(["ip link set lo up && exec", sys.executable, *map(str, sys.argv)])
    r = subprocess.run([*prefix, "sh", "-c", command], env=env, cwd=ROOT, capture_output=True,
                       text=True)
    lines = r.stdout.strip().splitlines()
    if r.returncode != 0 or not lines:
        print(r.stderr[-3000:], file=sys.stderr)
        return 1
    result = json.loads(lines[-1])
    for c in result["conditions"]:
        rt = c.get("round_trip_s", {})
        print(f"load {c['load_processes']} (loadavg {c['loadavg_start'][0]:.2f}), nice "
              f"{c['standin_nice']}: real-time factor {c.get('real_time_factor')}, joint states "
              f"{c.get('joint_states_per_wall_s')}/s, result "
              f"{rt.get('result', {}).get('median')} s, first feedback "
              f"{rt.get('first_feedback', {}).get('median')} s, feedbacks/goal "
              f"{c.get('feedbacks_per_goal', {}).get('median')}")
    write_figures(args, "ros_roundtrip.json", result)
    return 0


if __name__ == "__main__":
    sys.exit(main())
