"""The stand-in serving another arm's robot profile, run INSIDE a private network
namespace by test_standin_profiles.py (never in the host's): starts the stand-in of a
case with the profile, drives it through the learner's client and prints what it saw
as JSON on its last line.

The profile is read as shipped, with a ``[clock]`` table added (in a copy in a
temporary folder) so that both sides count simulated time: a loaded machine that
slows the physics makes no arm stale.

    python _profile_session.py PROFILE CASE
"""

from __future__ import annotations

import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PROFILE, CASE = sys.argv[1], sys.argv[2]
TMP = Path(tempfile.mkdtemp(prefix="standin-profile-"))
SHIPPED = Path(__file__).resolve().parents[4] / "robots" / f"{PROFILE}.toml"
SIM_PROFILE = TMP / f"{PROFILE}-sim.toml"
text = SHIPPED.read_text()
assert "[clock]" not in text, "the shipped profile has a [clock] table: set use_sim_time"
SIM_PROFILE.write_text(text + '\n[clock]\nuse_sim_time = true\ntopic = "/clock"\n')

ERR = TMP / "standin.err"
standin = subprocess.Popen([sys.executable, "-m", "creative_py.backends.ros.standin", "--case",
                            CASE, "--seconds", "240", "--profile", str(SIM_PROFILE)],
                           stdout=subprocess.PIPE, stderr=ERR.open("w"), text=True)
out: dict = {}
client = None
try:
    line = standin.stdout.readline()
    if not line.startswith("standin ready "):
        raise SystemExit(f"the stand-in did not start: {line!r}")
    info = json.loads(line[len("standin ready "):])
    out["interface"] = info
    from dataclasses import replace

    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case

    manifest = replace(get_case(CASE), robot=str(SIM_PROFILE))  # the world placed for this arm
    world = load_world(manifest)
    spec = world.item(manifest.demonstration.tool).spec

    from creative_py.backends.ros.check import check as check_interface
    from creative_py.backends.ros.client import ArmClient
    from creative_py.backends.ros.motion import Kinematics, LearnerArm
    from creative_py.backends.ros.profile import load_profile

    profile = load_profile(SIM_PROFILE)
    objects = list(info["objects"])
    client = ArmClient(profile, objects)
    client.wait_for_arm(60.0)
    out["check"] = check_interface(profile, objects, 1.0, 10.0)
    js = client.joint_state.msg
    out["joint_states"] = {"names": list(js.name), "position": list(js.position)}
    deadline = time.monotonic() + 10.0
    while any(client.pose(n) is None for n in objects) and time.monotonic() < deadline:
        time.sleep(0.05)

    # -- a pick-up over ROS with the learner's IK of this arm: behind and above the
    # grip, behind it, in, close, lift
    from creative_py.backends.pybullet.tools import tool_kind
    from creative_py.backends.ros.standin import compose, invert

    from creative_py.backends.ros.backend import world_base

    kin = Kinematics(profile, world_base(world))  # the arm's base where the scene puts it
    arm = LearnerArm(client, kin)
    position, quat, _ = client.pose(spec.name)
    grip = compose((position, quat), invert(tool_kind(spec).initial_grasp(spec)))
    (x, y, z), attitude = grip
    moves = []
    for target in ((x - 0.10, y, z + 0.05), (x - 0.10, y, z), (x, y, z)):
        moves.append(arm.move_to((target, attitude), speed=0.15).status)
    held = client.grip(True)
    moves.append(arm.move_to(((x, y, z + 0.08), attitude), speed=0.1).status)
    time.sleep(0.3)
    out["base"] = world_base(world)
    out["pick_up"] = {"moves": moves, "stalled": held.stalled,
                      "reached_goal": held.reached_goal, "tool_before": position,
                      "tool_after": client.pose(spec.name)[0],
                      "gap": client.joints()[profile.gripper_joint],
                      "goals_sent": arm.goals_sent}
    opened = client.grip(False)
    out["opened"] = [opened.position, opened.stalled, opened.reached_goal]
    kin.close()
except BaseException as exc:  # noqa: BLE001  (reported to the test as JSON)
    out["error"] = f"{type(exc).__name__}: {exc}"
finally:
    if client is not None:
        client.close()
    standin.terminate()
    try:
        standin.wait(timeout=20)
    except subprocess.TimeoutExpired:
        standin.kill()
        standin.wait()
    if "error" in out:
        out["error"] += "\n" + ERR.read_text(errors="replace")[-2000:]
print(json.dumps(out))
