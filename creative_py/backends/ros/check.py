"""A read-only check of an arm's ROS 2 interface against a robot profile: it subscribes
and looks for the action servers, and sends nothing (no goal, no gripper command).

    python -m creative_py.backends.ros.check --profile NAME|PATH.toml
        [--objects NAME,NAME] [--seconds S] [--timeout S]

It waits at most ``--timeout`` s for the joint states and both action servers (a
missing one is named in one line, exit 1), then listens ``--seconds`` s and prints, as
JSON: the joint states' rate and latency (arrival minus the header's stamp: both clocks
must agree, e.g. on one machine or with NTP), the profile's joints missing from them,
and each object's pose topic: messages, rate, frame. Exit 0 if everything the profile
names answered, 1 otherwise; 2 on bad input.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from typing import Optional, Sequence

from creative_py.world_files import WorldFileError

PROG = "creative_py.backends.ros.check"


def check(profile, objects: Sequence[str], seconds: float, timeout: float) -> dict:
    """Return what the arm answered (see the module's docstring)."""
    from creative_py.backends.ros.client import ArmClient, ArmUnavailable

    report: dict = {"profile": profile.source}
    t0 = time.monotonic()
    with ArmClient(profile, objects, name="creative_interface_check") as client:
        try:
            client.wait_for_arm(timeout)
        except ArmUnavailable as exc:
            report["missing"] = str(exc)
            return report
        report["arm_up_s"] = round(time.monotonic() - t0, 3)
        n0, c0 = client.joint_state.count, client.clock.count
        counts0 = {n: client.poses[n].count for n in objects}
        latencies = []
        end = time.monotonic() + seconds
        seen = -1
        while time.monotonic() < end:
            latest = client.joint_state
            if latest.count != seen and latest.msg is not None:
                seen = latest.count
                if not profile.use_sim_time:  # simulated stamps: no wall-clock latency
                    latencies.append(latest.wall - latest.stamp)
            time.sleep(0.001)
        names = list(client.joint_state.msg.name)
        report["joint_states"] = {
            "topic": profile.joint_states_topic,
            "rate_hz": round((client.joint_state.count - n0) / seconds, 1),
            "latency_ms": {"median": round(1e3 * sorted(latencies)[len(latencies) // 2], 2),
                           "max": round(1e3 * max(latencies), 2)} if latencies else None,
            "names": names,
            "profile_joints_missing": [j for j in profile.joints if j not in names]}
        if profile.use_sim_time:
            report["clock"] = {"topic": profile.clock_topic,
                               "rate_hz": round((client.clock.count - c0) / seconds, 1)}
        report["objects"] = {}
        for n in objects:
            pose = client.pose(n)
            report["objects"][n] = {
                "topic": profile.object_topic_of(n),
                "rate_hz": round((client.poses[n].count - counts0[n]) / seconds, 1),
                "frame": None if pose is None else pose[2]}
    return report


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the check; return the exit code."""
    ap = argparse.ArgumentParser(prog=f"python -m {PROG}", description=__doc__.split("\n\n")[0])
    ap.add_argument("--profile", required=True, help="robot profile: a name under robots/ "
                                                     "or a .toml path")
    ap.add_argument("--objects", default="", help="comma-separated object names")
    ap.add_argument("--seconds", type=float, default=2.0, help="how long to listen")
    ap.add_argument("--timeout", type=float, default=10.0, help="how long to wait for the arm")
    args = ap.parse_args(argv)
    for name, value in (("--seconds", args.seconds), ("--timeout", args.timeout)):
        if not 0 < value <= 600:
            print(f"{PROG}: option {name}: must be in (0, 600], got {value}", file=sys.stderr)
            return 2
    from creative_py.backends.ros.profile import load_profile

    try:
        profile = load_profile(args.profile)
    except WorldFileError as exc:
        print(f"{PROG}: {exc}", file=sys.stderr)
        return 2
    try:
        import rclpy  # noqa: F401
        from control_msgs.action import FollowJointTrajectory  # noqa: F401
    except ImportError as exc:
        print(f"{PROG}: {exc.name or 'rclpy'} is not installed: run make setup-ros "
              "(docs/real-robot.md)", file=sys.stderr)
        return 2
    objects = [o for o in args.objects.split(",") if o]
    report = check(profile, objects, args.seconds, args.timeout)
    print(json.dumps(report, indent=1))
    if "missing" in report:
        print(f"{PROG}: {report['missing']}", file=sys.stderr)
        return 1
    silent = [n for n, o in report["objects"].items() if not o["rate_hz"]]
    return 1 if silent or report["joint_states"]["profile_joints_missing"] else 0


if __name__ == "__main__":
    sys.exit(main())
