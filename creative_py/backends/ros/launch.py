"""Run a ``creative`` command against the stand-in robot: two processes, one machine.

    python -m creative_py.backends.ros.launch --case hook [--realtime F] -- run hook \\
        --backend ros --seed 0

starts the stand-in (:mod:`creative_py.backends.ros.standin`) of the case in its own
process, waits for its ``standin ready`` line, runs ``creative <args>`` (the learner,
in a second process), then stops the stand-in; the exit code is the learner's. What
``make run CASE=<id> BACKEND=ros`` runs, inside a private network namespace with only
loopback (the Makefile's ``unshare``). A lab's arm needs none of this: run ``creative
run CASE --backend ros --robot-profile mylab.toml`` where the arm's topics are.
"""

from __future__ import annotations

import argparse
import os
import signal
import subprocess
import sys
import time
from typing import Optional, Sequence


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Start the stand-in, run the learner's command, stop the stand-in."""
    argv = list(sys.argv[1:] if argv is None else argv)
    if "--" not in argv:
        print("creative_py.backends.ros.launch: give the creative command after --",
              file=sys.stderr)
        return 2
    at = argv.index("--")
    ap = argparse.ArgumentParser(prog="python -m creative_py.backends.ros.launch")
    ap.add_argument("--case", required=True, help="the case the stand-in builds")
    ap.add_argument("--profile", default=None,
                    help="the stand-in's robot profile (default: the case's robot)")
    ap.add_argument("--realtime", default="1", help="the stand-in's --realtime")
    ap.add_argument("--ready-timeout", type=float, default=120.0,
                    help="s to wait for the stand-in's ready line")
    args = ap.parse_args(argv[:at])
    command = argv[at + 1:]
    if args.profile is None:
        from creative_py.case import get_case
        from creative_py.world_files import WorldFileError

        try:
            args.profile = get_case(args.case).robot or ""
        except (WorldFileError, KeyError) as exc:
            print(f"creative_py.backends.ros.launch: {exc}", file=sys.stderr)
            return 2
    standin = subprocess.Popen(
        [sys.executable, "-m", "creative_py.backends.ros.standin", "--case", args.case,
         "--profile", args.profile, "--realtime", args.realtime],
        stdout=subprocess.PIPE, text=True, start_new_session=True)
    try:
        t0 = time.monotonic()
        line = standin.stdout.readline()
        if not line.startswith("standin ready "):
            print(f"creative_py.backends.ros.launch: the stand-in did not start "
                  f"(exit {standin.poll()}): {line.strip()!r}", file=sys.stderr)
            return 2
        print(f"the stand-in is ready after {time.monotonic() - t0:.1f} s (pid "
              f"{standin.pid})", file=sys.stderr, flush=True)
        env = dict(os.environ, CREATIVE_ROBOT_PROFILE=args.profile)
        return subprocess.call([sys.executable, "-m", "creative_py.cli", *command], env=env)
    finally:
        if standin.poll() is None:
            standin.send_signal(signal.SIGTERM)
            try:
                standin.wait(timeout=10)
            except subprocess.TimeoutExpired:
                standin.kill()
                standin.wait()


if __name__ == "__main__":
    sys.exit(main())
