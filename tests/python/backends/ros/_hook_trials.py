"""Hook trials over ROS 2 through the ros backend, run INSIDE a private network namespace
by test_ros_backend.py (never in the host's): first the backend with no arm (the
one-line error), then the stand-in as its own process and three trials of the hook case
through the trial loop (run_trial), each scene set up by a trainer's request. Prints
what it saw as JSON on its last line.

    python _hook_trials.py
"""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

out: dict = {"namespace_links": sorted(name for _, name in socket.if_nameindex())}
standin = None
# Both sides read the shipped profile with [clock] use_sim_time = true (as _session.py
# does): the learner judges the stand-in's staleness on its simulated clock, so a
# stand-in starved of CPU on a loaded machine runs slower instead of looking dead.
TMP = Path(tempfile.mkdtemp(prefix="hook-trials-"))
SHIPPED = Path(__file__).resolve().parents[4] / "robots" / "baxter.toml"
SIM_PROFILE = TMP / "baxter-sim.toml"
SIM_PROFILE.write_text(SHIPPED.read_text().replace("use_sim_time = false", "use_sim_time = true"))
try:
    from creative_py.case import get_case
    from creative_py.simulator.loader import backend
    from creative_py.world_files import WorldFileError

    os.environ["CREATIVE_ROS_WAIT_S"] = "2"
    ros = backend("ros")
    manifest = get_case("hook")
    from dataclasses import replace

    manifest = replace(manifest, backend="ros")
    t = time.monotonic()
    try:
        ros.load_world(manifest)
        out["absent"] = "no error"
    except WorldFileError as exc:
        out["absent"] = str(exc)
    out["absent_s"] = time.monotonic() - t
    os.environ["CREATIVE_ROS_WAIT_S"] = "60"
    # the absent arm was the case's (the shipped profile); this one is --robot's
    manifest = replace(manifest, robot=str(SIM_PROFILE))

    standin = subprocess.Popen([sys.executable, "-m", "creative_py.backends.ros.standin",
                                "--case", "hook", "--seconds", "600", "--profile", str(SIM_PROFILE)],
                               stdout=subprocess.PIPE, text=True)
    line = standin.stdout.readline()
    if not line.startswith("standin ready "):
        raise SystemExit(f"the stand-in did not start: {line!r}")
    out["interface"] = json.loads(line[len("standin ready "):])

    from creative_py.bridge import Engine
    from creative_py.learning.poses import pose_resolver
    from creative_py.simulator.trial import run_trial

    world = ros.load_world(manifest)
    poses = pose_resolver(Engine.instance(), manifest)
    trials = []
    for tool, variant, location in (("hook_a2", "standard", 1), ("hook_a1", "standard", 1),
                                    ("hook_a2", "long_tube", 2)):
        t = time.monotonic()
        r = run_trial(world, tool, variant, location, pose_target=poses)
        trials.append({"tool": tool, "variant": variant, "location": location,
                       "outcome": r.outcome, "reason": r.reason, "verdict": r.verdict,
                       "steps": r.steps, "wall_s": time.monotonic() - t,
                       "facts": [list(f) for f in r.facts_before if f[0] in ("pose", "held")],
                       "true_final": r.true_final, "tool_load": r.tool_load})
    out["trials"] = trials
    conn = ros.connection(world)
    out["scene_s"] = conn.scene_s
    # the same arm placed elsewhere by another world: the same connection (one node per
    # arm in the process), the learner's kinematics moved to the new base, then back
    moved_robot = replace(world.scene.robot, base=((0.1, -0.2, 0.0), (0.0, 0.0, 0.5)))
    moved = replace(world, scene=replace(world.scene, robot=moved_robot))
    node, goals = conn.client.node, len(conn.arm.log)
    again = ros.connection(moved)
    out["rebase"] = {"same_connection": again is conn, "same_node": again.client.node is node,
                     "base": [list(v) for v in again.base],
                     "goals_kept": len(again.arm.log) == goals > 0}
    back = ros.connection(world)
    out["rebase"]["back"] = back is conn and back.base is None
    # a scene the trainer refuses: an unknown tool of a created tool's request
    from creative_py.backends.ros.trainer import scene_request

    try:
        conn.request_scene("refused-1", scene_request("refused-1", "hook", "standard", 1,
                                                      "no_such_tool"))
        out["refused"] = "no error"
    except WorldFileError as exc:
        out["refused"] = str(exc)
except BaseException as exc:  # noqa: BLE001 - reported to the test as JSON
    import traceback

    out["error"] = f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}"
finally:
    if standin is not None:
        standin.terminate()
        try:
            out["standin_rc"] = standin.wait(timeout=20)
        except subprocess.TimeoutExpired:
            standin.kill()
            out["standin_rc"] = "killed"
print(json.dumps(out), flush=True)
os._exit(0)  # the learner's node is closed by the backend's exit hook; do not wait on it
