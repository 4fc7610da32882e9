"""One session with the stand-in robot, run INSIDE a private network namespace by
test_standin.py (never in the host's): starts the stand-in as its own process, drives it
through the learner's client (creative_py.backends.ros.client) and prints what it saw as
JSON on its last line. The scenarios run in order on one stand-in (its scene build and
the DDS discovery cost about 6 s, paid once); the faults that end a stand-in (an absent
arm, one killed mid-goal) run last, the second on a stand-in of its own.

Both sides read the shipped profile with ``[clock] use_sim_time = true`` (a copy in a
temporary folder): the stand-in stamps with its physics time and the learner judges
staleness and timeouts on /clock, so a loaded machine that slows the physics makes no
arm stale. A second client with the shipped profile as it is (wall-clock time, as for a
real arm) checks the wall-clock staleness.

    python _session.py CASE
"""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time

import tempfile
from dataclasses import replace
from pathlib import Path

CASE = sys.argv[1] if len(sys.argv) > 1 else "hook"
t_start = time.monotonic()
TMP = Path(tempfile.mkdtemp(prefix="standin-session-"))
SHIPPED = Path(__file__).resolve().parents[4] / "robots" / "baxter.toml"
SIM_PROFILE = TMP / "baxter-sim.toml"
SIM_PROFILE.write_text(SHIPPED.read_text().replace("use_sim_time = false", "use_sim_time = true"))


ERRORS: list[Path] = []


def start_standin() -> subprocess.Popen:
    ERRORS.append(TMP / f"standin{len(ERRORS)}.err")  # its log, kept for a failed stop
    return subprocess.Popen([sys.executable, "-m", "creative_py.backends.ros.standin", "--case",
                             CASE, "--seconds", "240", "--profile", str(SIM_PROFILE)],
                            stdout=subprocess.PIPE, stderr=ERRORS[-1].open("w"), text=True)


def settled(client) -> list:
    """Return the arm's joint positions once it settled: two readings 0.2 s apart within
    0.002 rad (at most 10 s). A goal succeeds once every joint is within the goal
    tolerance at its end, which an arm still moving may overshoot for a moment; the
    stand-in may also run slower than real time."""
    q, end = client.arm_q(), time.monotonic() + 10.0
    while time.monotonic() < end:
        time.sleep(0.2)
        before, q = q, client.arm_q()
        if max(abs(a - b) for a, b in zip(before, q)) < 0.002:
            break
    return q


def stderr_tail(k: int) -> str:
    lines = ERRORS[k].read_text(errors="replace").splitlines()
    return "\n".join(line for line in lines if "[WARN]" not in line)[-3000:]


standin = start_standin()
out: dict = {"namespace_links": sorted(name for _, name in socket.if_nameindex()),
             "domain_id": os.environ.get("ROS_DOMAIN_ID"),
             "discovery_range": os.environ.get("ROS_AUTOMATIC_DISCOVERY_RANGE")}
client = None
try:
    line = standin.stdout.readline()
    if not line.startswith("standin ready "):
        raise SystemExit(f"the stand-in did not start: {line!r}")
    out["standin_ready_s"] = time.monotonic() - t_start
    info = json.loads(line[len("standin ready "):])
    out["interface"] = info
    # the world is read before any subscription (it holds the GIL for a while)
    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case

    manifest = get_case(CASE)
    spec = load_world(manifest).item(manifest.demonstration.tool).spec

    from creative_py.backends.ros.client import ArmClient
    from creative_py.backends.ros.limits import OutOfBounds, goal_checker, urdf_forward
    from creative_py.backends.ros.profile import load_profile

    profile = load_profile(SIM_PROFILE)
    wall_profile = load_profile("baxter")
    objects = list(info["objects"])
    client = ArmClient(profile, objects)
    client.wait_for_arm(30.0)
    wall_client = ArmClient(wall_profile, [], name="creative_wall_clock")
    wall_client.wait_for_arm(30.0)
    out["arm_up_s"] = time.monotonic() - t_start

    # -- the read-only interface check, and an arm that is not there (a renamed topic)
    import tempfile
    from pathlib import Path

    from creative_py.backends.ros.check import check as check_interface

    out["check"] = check_interface(profile, objects, 1.0, 10.0)
    with tempfile.TemporaryDirectory() as tmp:
        absent = Path(tmp) / "absent.toml"
        absent.write_text(Path(wall_profile.source).read_text().replace(
            'topic = "joint_states"', 'topic = "absent/joint_states"'))
        t = time.monotonic()
        out["check_absent"] = check_interface(load_profile(absent), [], 1.0, 2.0)
        out["check_absent_s"] = time.monotonic() - t
        # a misspelt action name: the error lists the servers the arm does offer
        misspelt = Path(tmp) / "misspelt.toml"
        misspelt.write_text(Path(wall_profile.source).read_text().replace(
            'action = "right_gripper_controller/gripper_cmd"',
            'action = "right_gripper_controller/gripper_command"'))
        out["check_misspelt"] = check_interface(load_profile(misspelt), [], 1.0, 2.0)

    # -- joint states: names and rate over one second
    n0 = client.joint_state.count
    time.sleep(1.0)
    js = client.joint_state.msg
    out["joint_states"] = {"names": list(js.name), "per_s": client.joint_state.count - n0,
                           "position": list(js.position)}

    # -- object poses
    deadline = time.monotonic() + 5.0
    while any(client.pose(n) is None for n in objects) and time.monotonic() < deadline:
        time.sleep(0.05)
    out["poses"] = {n: client.pose(n) for n in objects}

    # -- round trips: there and back, 1 s each, through the learner's bounds
    forward = urdf_forward(profile)
    check = goal_checker(profile, client.arm_q, forward)
    q0 = client.arm_q()
    q1 = list(q0)
    q1[0] += 0.2
    q1[3] -= 0.15
    trips = []
    for k in range(6):
        target = q1 if k % 2 == 0 else q0
        first: list = []
        r = client.send_trajectory(client.make_goal([(1.0, target)]), check=check,
                                   on_feedback=lambda fb: first.append(fb) if not first else None)
        q = settled(client)
        trips.append({"status": r.status, "code": r.error_code, "times": vars(r.times),
                      "error_after": max(abs(a - b) for a, b in zip(q, target)),
                      "feedback_names": list(first[0].joint_names) if first else [],
                      "feedback_index": first[0].index if first else None,
                      "last_feedback_actual": list(r.last_feedback.actual.positions)
                      if r.last_feedback is not None else []})
    out["round_trips"] = trips
    out["q1"] = q1

    # -- goals the arm rejects (as ros2_control's controller does)
    bad_joint = client.make_goal([(1.0, q0)], joint_names=[*profile.joints[:-1], "no_such_joint"])
    beyond = list(q0)
    beyond[3] = 5.0  # outside right_e1's limits
    out["rejected"] = {
        "unknown_joint": client.send_trajectory(bad_joint).status,
        "beyond_limits": client.send_trajectory(client.make_goal([(1.0, beyond)])).status,
        "time_not_increasing": client.send_trajectory(
            client.make_goal([(1.0, q1), (0.5, q0)])).status,
    }

    # -- the learner's bounds: a goal outside them is never sent
    sent = [0]
    original = client.trajectory.send_goal_async

    def counting(*a, **k):
        sent[0] += 1
        return original(*a, **k)

    client.trajectory.send_goal_async = counting
    too_fast = client.make_goal([(0.1, q1)])
    # the collision target below: the gripper 5 cm under the table top, pointing forward
    from creative_py.backends.pybullet.arm import Arm, gripper_forward
    from creative_py.backends.pybullet.core import Sim
    from creative_py.world_files import PhysicsSettings

    kin = Arm(Sim(PhysicsSettings(1 / 240, 50, (0.0, 0.0, -9.81))), "baxter")
    kin.reset_posture(q0)  # profile order is the Baxter's right-arm order here
    below = kin.solve_ik(((0.75, -0.45, -0.25), gripper_forward(0.0)), seed=q0)
    out["below_table_target"] = below
    refused = {}
    for name, goal in (("too_fast", too_fast),
                       ("outside_workspace", client.make_goal([(4.0, below)]))):
        try:
            client.send_trajectory(goal, check=check)
            refused[name] = "sent"
        except OutOfBounds as exc:
            refused[name] = str(exc)
    client.trajectory.send_goal_async = original
    out["refused"] = refused
    out["goals_sent_while_refusing"] = sent[0]
    out["q_after_refusals"] = client.arm_q()

    # -- into the table: no path tolerance -> GOAL_TOLERANCE_VIOLATED; default -> PATH_...
    r = client.send_trajectory(client.make_goal([(4.0, below)],
                                                path_tolerance={j: -1.0 for j in profile.joints},
                                                goal_time_tolerance=0.3))
    out["blocked_no_path_tolerance"] = {"status": r.status, "code": r.error_code,
                                        "message": r.error_string}
    back = client.send_trajectory(client.make_goal([(4.0, q0)]))
    out["back_to_start"] = {"status": back.status, "code": back.error_code}
    r = client.send_trajectory(client.make_goal([(4.0, below)]))
    out["collision"] = {"status": r.status, "code": r.error_code, "message": r.error_string,
                        "result_s": r.times.result}
    client.send_trajectory(client.make_goal([(4.0, q0)]))

    # -- the gripper: closing far from the tool holds nothing, opening again
    closed = client.grip(True)
    opened = client.grip(False)
    # the gap as the joint states publish it after the answer: two messages later (the
    # stand-in may run slower than real time; a fixed wait once read the closed gap)
    n0, end = client.joint_state.count, time.monotonic() + 10.0
    while client.joint_state.count < n0 + 2 and time.monotonic() < end:
        time.sleep(0.02)
    out["gripper"] = {"closed": [closed.position, closed.stalled, closed.reached_goal],
                      "opened": [opened.position, opened.stalled, opened.reached_goal],
                      "gap_in_joint_states": client.joints()[profile.gripper_joint]}

    # -- the learner's side: straight gripper moves through its own IK, and the episode
    from creative_py.backends.ros.motion import Kinematics, LearnerArm

    kin = Kinematics(profile)
    arm = LearnerArm(client, kin)
    here = arm.gripper_pose()
    up = ((here[0][0], here[0][1], here[0][2] + 0.05), here[1])
    r = arm.move_to(up, speed=0.1)
    after = kin.forward(settled(client))
    out["move_up"] = {"status": r.status, "reason": r.reason, "from": here[0], "to": after[0],
                      "target": up[0], "goals_sent": arm.goals_sent}
    down = ((here[0][0], here[0][1], -0.22), here[1])
    r = arm.move_to(down, speed=0.1)
    out["move_below_the_box"] = {"status": r.status, "reason": r.reason,
                                 "goals_sent": arm.goals_sent}
    r = arm.move_to(here, speed=0.1)
    out["move_back"] = {"status": r.status, "reason": r.reason}

    # -- a pick-up over ROS, as the hook-like grasp does it: behind and above the grip,
    # behind it, in, close, lift (the grasp frame is the tool kind's, on the learner's side)
    from creative_py.backends.pybullet.tools import tool_kind
    from creative_py.backends.ros.standin import compose, invert

    position, quat, _ = client.pose(spec.name)
    grip = compose((position, quat), invert(tool_kind(spec).initial_grasp(spec)))
    (x, y, z), attitude = grip
    moves = []
    for target in ((x - 0.10, y, z + 0.05), (x - 0.10, y, z), (x, y, z)):
        moves.append(arm.move_to((target, attitude), speed=0.15).status)
    held = client.grip(True)
    moves.append(arm.move_to(((x, y, z + 0.08), attitude), speed=0.1).status)
    time.sleep(0.3)
    out["pick_up"] = {"moves": moves, "stalled": held.stalled, "reached_goal": held.reached_goal,
                      "tool_before": position, "tool_after": client.pose(spec.name)[0],
                      "gap": client.joints()[profile.gripper_joint]}
    kin.close()

    # -- an aborted goal through the learner's arm: 'blocked' with the error code
    from creative_py.backends.ros.motion import Kinematics as _K

    arm = LearnerArm(client, _K(profile))
    # the box would refuse the goal under the table: here a lab's box reaching lower
    loose = replace(profile, workspace_min=(0.2, -1.1, -0.5))
    arm.check = goal_checker(loose, client.arm_q, forward)
    q_home = client.arm_q()
    r = arm.move_joints(below, min_duration=4.0)
    out["learner_blocked"] = {"status": r.status, "reason": r.reason,
                              "stop": r.stop.to_dict() if r.stop is not None else None,
                              "lost": arm.lost is not None}
    arm.move_joints(q_home, min_duration=4.0)
    arm.check = goal_checker(profile, client.arm_q, forward)

    # -- stale joint states of a live arm (SIGUSR1: the stand-in stops them, its clock
    # goes on): the learner refuses to send a goal, naming the staleness
    import signal
    import threading

    from creative_py.backends.ros.client import ArmUnavailable

    q = client.arm_q()
    sent_before = arm.goals_sent
    os.kill(standin.pid, signal.SIGUSR1)
    try:
        time.sleep(0.3)
        t = client.now()
        while client.now() < t + profile.stale_after_s + 0.2:  # simulated time
            time.sleep(0.05)
        r = arm.move_joints(q)
        out["muted"] = {"move": vars(r) | {"stop": None}, "goals_sent": arm.goals_sent - sent_before,
                        "lost": type(arm.lost).__name__, "clock_ok": client.now() > t}
    finally:
        os.kill(standin.pid, signal.SIGUSR1)
    time.sleep(0.5)
    out["after_unmute"] = {"arm_q_ok": len(client.arm_q()) == len(profile.joints)}

    # -- a frozen arm (SIGSTOP): its clock stops; the wall-clock client sees stale
    # joint states, the simulated-time one a stopped clock; a goal ends 'silent'
    os.kill(standin.pid, signal.SIGSTOP)
    try:
        time.sleep(max(profile.clock_silent_after_s, wall_profile.stale_after_s) + 0.3)
        found = {}
        for key, c in (("sim", client), ("wall", wall_client)):
            # On a loaded machine the last messages sent before the stop may reach this
            # process late: ask again until the arm counts as silent (bounded, no hang).
            deadline = time.monotonic() + 20.0
            while True:
                try:
                    c.arm_q()
                    found[key] = "no error"
                except ArmUnavailable as exc:
                    found[key] = str(exc)
                    break
                if time.monotonic() > deadline:
                    break
                time.sleep(0.2)
        arm2 = LearnerArm(client, _K(profile))
        out["stale"] = {"arm_q": found["wall"], "sim_arm_q": found["sim"],
                        "move": vars(arm2.move_joints(q)) | {"stop": None}}
    finally:
        os.kill(standin.pid, signal.SIGCONT)
    time.sleep(0.5)
    target = list(q)
    target[0] += 0.1
    box: dict = {}
    worker = threading.Thread(target=lambda: box.update(
        r=client.send_trajectory(client.make_goal([(1.0, target)]), timeout=30.0)))
    t = time.monotonic()
    worker.start()
    time.sleep(0.3)
    os.kill(standin.pid, signal.SIGSTOP)
    worker.join()
    out["frozen_mid_goal"] = {"status": box["r"].status, "after_s": time.monotonic() - t,
                              "message": box["r"].error_string,
                              "feedbacks": box["r"].times.feedbacks}
    os.kill(standin.pid, signal.SIGCONT)
    time.sleep(0.5)
    out["after_thaw"] = {"arm_q_ok": len(client.arm_q()) == len(profile.joints)}

    # -- the stand-in stopped: an arm absent at start names the topic it waited for
    standin.terminate()
    out["standin_rc"] = standin.wait(10)
    if out["standin_rc"] != 0:
        out["standin_stderr"] = stderr_tail(0)
    for key, prof in (("sim", profile), ("wall", wall_profile)):
        t = time.monotonic()
        with ArmClient(prof, [], name=f"creative_absent_{key}") as absent_client:
            try:
                absent_client.wait_for_arm(2.0)
                found = "no error"
            except ArmUnavailable as exc:
                found = str(exc)
        out.setdefault("absent", {})[key] = {"message": found, "after_s": time.monotonic() - t}

    # -- an arm killed mid-goal (SIGKILL of a second stand-in): the learner's motion
    # comes back 'invalid' naming what went silent, and the arm is kept as lost
    wall_client.close()
    n0 = client.joint_state.count
    standin = start_standin()
    line = standin.stdout.readline()
    if not line.startswith("standin ready "):
        raise SystemExit(f"the second stand-in did not start: {line!r}")
    deadline = time.monotonic() + 30.0
    while client.joint_state.count < n0 + 10 and time.monotonic() < deadline:
        time.sleep(0.05)  # the new stand-in's own joint states (its clock restarts at 0)
    client.wait_for_arm(30.0)
    arm3 = LearnerArm(client, _K(profile))
    q = client.arm_q()
    target = list(q)
    target[0] += 0.3
    box = {}
    worker = threading.Thread(target=lambda: box.update(
        r=arm3.move_joints(target, min_duration=3.0)))
    t = time.monotonic()
    worker.start()
    time.sleep(0.8)
    os.kill(standin.pid, signal.SIGKILL)
    worker.join()
    try:
        arm3.raise_if_lost()
        raised = "nothing"
    except BaseException as exc:
        from creative_py.simulator.types import BackendLost

        raised = [type(exc).__name__, isinstance(exc, BackendLost), str(exc)]
    out["killed_mid_goal"] = {"status": box["r"].status, "reason": box["r"].reason,
                              "after_s": time.monotonic() - t, "raised": raised,
                              "goal_timeout_s": 3.0 + arm3.timeout,
                              "rc": standin.wait(10)}
except BaseException as exc:  # report what went wrong as the session's result
    out["error"] = f"{type(exc).__name__}: {exc}"
finally:
    if client is not None:
        client.close()
    if standin.poll() is None:
        standin.terminate()
        try:
            out.setdefault("standin_rc", standin.wait(10))
        except subprocess.TimeoutExpired:
            standin.kill()
            out["standin_rc"] = "killed"
    out["session_s"] = time.monotonic() - t_start
    print(json.dumps(out), flush=True)
