"""Run a ``creative`` command against the stand-in robot: two processes, one machine.

    python -m creative_py.backends.ros.launch --case hook [--profile P] [--realtime F] \\
        -- run hook --backend ros --seed 0
    python -m creative_py.backends.ros.launch --resume runs/hook-20261206-101500-s0

starts the stand-in (:mod:`creative_py.backends.ros.standin`) of the case with the robot
profile (``--profile``, a name under ``robots/`` or a ``.toml`` path; default: the
case's robot) in its own process, waits for its ``standin ready`` line, runs ``creative
<args>`` (the learner, in a second process, with the same profile: ``--robot``, added
to a ``run`` or ``trial`` command that names none), then stops the
stand-in; the exit code is the learner's. ``--resume DIR`` goes on with an interrupted
or stopped run: the case and the profile come from the run's ``run.json`` (a
``--profile`` that differs from the recorded one is refused), and the learner runs
``creative run CASE --resume DIR``. What ``make run CASE=<id> BACKEND=ros
[PROFILE=<name>] [RESUME=DIR]`` runs, inside a private network namespace with only
loopback (the Makefile's ``unshare``). A lab's arm needs none of this: run ``creative
run CASE --backend ros --robot mylab.toml`` where the arm's topics are.

The learner's hint on Ctrl-C or a lost arm says how to go on
(:func:`creative_py.records.folder.resume_command`): this launcher tells it, in
:data:`~creative_py.records.folder.RESUME_ENV`, to print the command that resumes the
run with the stand-in started again (the Makefile's, when it gave one, else this
module's ``--resume``).
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Optional, Sequence

PROG = "python -m creative_py.backends.ros.launch"


class LaunchError(ValueError):
    """A bad command line or run folder (one line naming the option and the cause)."""


def case_robot(case: str) -> str:
    """Return the robot the case names (its ``case.toml``'s ``robot``).

    Raises
    ------
    LaunchError
        The case is unknown or its manifest is malformed (naming the file).
    """
    from creative_py.case import get_case
    from creative_py.world_files import WorldFileError

    try:
        robot = get_case(case).robot
    except (WorldFileError, KeyError) as exc:
        raise LaunchError(f"--case {case}: {exc}") from None
    if not robot:
        raise LaunchError(f"--case {case}: the case names no robot; give --profile")
    return robot


def recorded_run(folder: Path) -> tuple[str, str]:
    """Return the case and the robot profile that a run folder's ``run.json`` records
    (``options.robot``; ``options.robot_profile`` in runs recorded before ``--robot``;
    else the case's robot). Only what the stand-in needs is read here; the learner's
    ``--resume`` checks the whole file.

    Raises
    ------
    LaunchError
        No ``run.json``, not a JSON object, or its ``case`` or robot not text (naming
        the file).
    """
    meta_path = folder / "run.json"
    if not meta_path.is_file():
        raise LaunchError(f"--resume: {folder}: not a resumable run folder (no run.json)")
    try:
        meta = json.loads(meta_path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise LaunchError(f"--resume: {meta_path}: not JSON ({exc})") from None
    options = meta.get("options") if isinstance(meta, dict) else None
    case = meta.get("case") if isinstance(meta, dict) else None
    if not (isinstance(case, str) and case and isinstance(options, dict)):
        raise LaunchError(f"--resume: {meta_path}: field 'case' or 'options' is missing "
                          "or not of its type")
    profile = options.get("robot", options.get("robot_profile"))
    if profile is None:
        profile = case_robot(case)
    if not (isinstance(profile, str) and profile):
        raise LaunchError(f"--resume: {meta_path}: field 'options.robot' is not text")
    return case, profile


def plan(argv: Sequence[str]) -> tuple[argparse.Namespace, str, str, list[str]]:
    """Return the parsed options, the case, the robot profile and the ``creative``
    command the launcher runs for ``argv``.

    Raises
    ------
    LaunchError
        No command after ``--`` (and no ``--resume``), both, no ``--case``, or a
        ``--resume`` folder that is not a resumable run (naming its ``run.json``) or
        whose recorded profile differs from ``--profile``.
    """
    argv = list(argv)
    at = argv.index("--") if "--" in argv else len(argv)
    ap = argparse.ArgumentParser(prog=PROG)
    ap.add_argument("--case", help="the case the stand-in builds (default: the "
                    "command's, or the resumed run's)")
    ap.add_argument("--profile", help="the robot profile of the stand-in and the learner "
                    "(default: the resumed run's, else the case's robot)")
    ap.add_argument("--resume", metavar="DIR", help="go on with this interrupted or "
                    "stopped run folder (its case and profile from its run.json)")
    ap.add_argument("--realtime", default="1", help="the stand-in's --realtime")
    ap.add_argument("--ready-timeout", type=float, default=120.0,
                    help="s to wait for the stand-in's ready line")
    args = ap.parse_args(argv[:at])
    command = argv[at + 1:]
    if args.resume is not None:
        if command:
            raise LaunchError("--resume: give no creative command after -- (the run "
                              "goes on with the options of its run.json)")
        case, recorded = recorded_run(Path(args.resume))
        if args.profile is not None and args.profile != recorded:
            raise LaunchError(f"--profile {args.profile}: the run {args.resume} was "
                              f"recorded with the robot profile {recorded!r}; a resume "
                              "keeps it")
        if args.case is not None and args.case != case:
            raise LaunchError(f"--case {args.case}: the run {args.resume} is of case "
                              f"{case!r}")
        return args, case, recorded, ["run", case, "--resume", args.resume]
    if "--" not in argv:
        raise LaunchError("give the creative command after -- (or --resume DIR)")
    case = args.case or (command[1] if len(command) > 1 and command[0] == "run" else None)
    if case is None:
        raise LaunchError("--case: the case the stand-in builds is needed")
    given = next((command[i + 1] for i, word in enumerate(command[:-1])
                  if word in ("--robot", "--robot-profile")), None)
    if given is not None and args.profile is not None and given != args.profile:
        raise LaunchError(f"--profile {args.profile}: the command's --robot is {given!r}")
    profile = args.profile or given or case_robot(case)
    if command[:1] in (["run"], ["trial"]) and given is None:
        command = [*command, "--robot", profile]  # the learner's arm; run.json records it
    return args, case, profile, command


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Start the stand-in, run the learner's command, stop the stand-in."""
    from creative_py.records.folder import RESUME_ENV

    argv = list(sys.argv[1:] if argv is None else argv)
    try:
        args, case, profile, command = plan(argv)
    except LaunchError as exc:
        print(f"{PROG}: {exc}", file=sys.stderr)
        return 2
    standin = subprocess.Popen(
        [sys.executable, "-m", "creative_py.backends.ros.standin", "--case", case,
         "--profile", profile, "--realtime", args.realtime],
        stdout=subprocess.PIPE, text=True, start_new_session=True)
    learner = None
    try:
        t0 = time.monotonic()
        line = standin.stdout.readline()
        if not line.startswith("standin ready "):
            print(f"{PROG}: the stand-in did not start (exit {standin.poll()}): "
                  f"{line.strip()!r}", file=sys.stderr)
            return 2
        print(f"the stand-in is ready after {time.monotonic() - t0:.1f} s (pid "
              f"{standin.pid})", file=sys.stderr, flush=True)
        env = dict(os.environ)
        env.setdefault(RESUME_ENV, " ".join(
            [PROG, "--resume", "{run}"]))  # the profile comes from its run.json
        learner = subprocess.Popen([sys.executable, "-m", "creative_py.cli", *command],
                                   env=env)
        while True:
            try:
                return learner.wait()
            except KeyboardInterrupt:
                # Ctrl-C reached the learner too (the terminal's process group): it
                # ends its trial, prints how to resume and exits 130; wait for that.
                continue
    finally:
        if learner is not None and learner.poll() is None:
            learner.terminate()
            learner.wait()
        if standin.poll() is None:
            standin.send_signal(signal.SIGTERM)
            try:
                standin.wait(timeout=10)
            except subprocess.TimeoutExpired:
                standin.kill()
                standin.wait()


if __name__ == "__main__":
    sys.exit(main())
