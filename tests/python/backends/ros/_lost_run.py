"""A whole hook run over ROS 2 whose arm is killed mid-trial, then resumed; run INSIDE a
private network namespace by test_ros_backend.py (never in the host's).

1. ``creative run hook --phase use --backend ros`` against the stand-in (its own
   process); once two trials are recorded, the stand-in is killed (SIGKILL) a few
   seconds into the third: the learner must stop with exit 75, the folder resumable,
   the third trial in ``stopped.json`` as not as planned;
2. a new stand-in, then ``creative run hook --resume <folder>``: it replays the two
   trials, runs the lost one again and the rest;
3. the same run in one process with the pybullet backend, to compare the trials (run
   beside the first two from the start).

Prints what it saw as JSON on its last line.

    python _lost_run.py
"""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[4]
TMP = Path(tempfile.mkdtemp(prefix="lost-run-"))
# Both sides on the simulated clock (as _session.py and _hook_trials.py): a stand-in
# starved of CPU runs slower instead of looking dead; a killed one stops its clock.
SIM_PROFILE = TMP / "baxter-sim.toml"
SIM_PROFILE.write_text((ROOT / "robots" / "baxter.toml").read_text()
                       .replace("use_sim_time = false", "use_sim_time = true"))
RUN = ["run", "hook", "--seed", "0", "--phase", "use", "--video", "none",
       "--robot", str(SIM_PROFILE)]  # run.json records it: the resume keeps it
KEPT = 2  # trials recorded before the kill
INTO = 4.0  # seconds into the next trial (its scene set up, its first skills running)

out: dict = {"namespace_links": sorted(name for _, name in socket.if_nameindex())}
env = dict(os.environ, CREATIVE_ROS_WAIT_S="60")


def start_standin() -> subprocess.Popen:
    p = subprocess.Popen([sys.executable, "-m", "creative_py.backends.ros.standin", "--case",
                          "hook", "--seconds", "900", "--profile", str(SIM_PROFILE)],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    line = p.stdout.readline()
    if not line.startswith("standin ready "):
        raise SystemExit(f"the stand-in did not start: {line!r}")
    return p


def creative(name: str, *args: str, backend: bool = True) -> subprocess.Popen:
    """Start ``creative <args>`` (its output in TMP/<name>.log)."""
    extra = ["--backend", "ros"] if backend else []
    log = open(TMP / f"{name}.log", "w")  # noqa: SIM115 - closed with the process
    return subprocess.Popen([sys.executable, "-m", "creative_py.cli", *args, *extra], cwd=ROOT,
                            env=env, stdout=log, stderr=subprocess.STDOUT, text=True)


def ended(p: subprocess.Popen, name: str, timeout: float) -> tuple[int, str]:
    """Wait for ``p``; return its exit code and its log's last lines."""
    rc = p.wait(timeout=timeout)
    return rc, "\n".join((TMP / f"{name}.log").read_text().splitlines()[-40:])


def trials(folder: Path) -> list[dict]:
    rows = [json.loads(line) for line in (folder / "trials.jsonl").read_text().splitlines()]
    return [{**{k: t.get(k) for k in ("trial", "phase", "tool", "variant", "location", "pose",
                                      "outcome", "reason", "facts", "hs")},
             "value": (t.get("verdict") or {}).get("value")} for t in rows]


standins: list[subprocess.Popen] = []
direct = None
try:
    # the same run in one process (pybullet), to compare: beside the ROS run, which
    # waits on the stand-in much of its time
    direct = creative("direct", *RUN, "--out", str(TMP / "direct"), backend=False)
    standins.append(start_standin())
    learner = creative("lost", *RUN, "--out", str(TMP / "ros"))
    t0, folder = time.monotonic(), None
    while time.monotonic() - t0 < 300 and learner.poll() is None:
        found = list((TMP / "ros").glob("hook-*/trials.jsonl"))
        if found and len(found[0].read_text().splitlines()) >= KEPT:
            folder = found[0].parent
            break
        time.sleep(0.1)
    if folder is None:
        raise SystemExit(f"no {KEPT} trials within 300 s (exit {learner.poll()}): "
                         f"{(TMP / 'lost.log').read_text()[-2000:]}")
    jsonl = folder / "trials.jsonl"
    time.sleep(INTO)
    out["recorded_at_kill"] = len(jsonl.read_text().splitlines())
    standins[0].send_signal(signal.SIGKILL)
    t_kill = time.monotonic()
    out["stopped_rc"], log = ended(learner, "lost", 120)
    out["stop_s"] = round(time.monotonic() - t_kill, 2)
    out["stopped_log"] = log
    out["stopped_json"] = (json.loads((folder / "stopped.json").read_text())
                           if (folder / "stopped.json").is_file() else None)
    out["summary_after_stop"] = (folder / "summary.json").exists()
    out["trials_at_stop"] = trials(folder)
    # the arm is back (a new stand-in): the resume goes on
    standins[0].wait()
    standins.append(start_standin())
    t = time.monotonic()
    resume = creative("resume", "run", "hook", "--resume", str(folder), backend=False)
    out["resume_rc"], out["resume_log"] = ended(resume, "resume", 600)
    out["resume_s"] = round(time.monotonic() - t, 1)
    out["stopped_json_after"] = (folder / "stopped.json").exists()
    out["resumed_trials"] = trials(folder)
    summary = json.loads((folder / "summary.json").read_text())
    out["resumed"] = summary.get("resumed")
    out["direct_rc"], _ = ended(direct, "direct", 300)
    out["direct_trials"] = trials(next((TMP / "direct").glob("hook-*")))
except BaseException as exc:  # noqa: BLE001 - reported to the test as JSON
    import traceback

    out["error"] = f"{type(exc).__name__}: {exc}\n{traceback.format_exc()}"
finally:
    for p in standins + ([direct] if direct is not None else []):
        if p.poll() is None:
            p.terminate()
            try:
                p.wait(timeout=20)
            except subprocess.TimeoutExpired:
                p.kill()
print(json.dumps(out), flush=True)
