"""The options the commands share, checked: bounds of counts and seeds, paths and names
the file system takes, text the engine takes, the backend and robot, the case's
manifest. Each check fails in one line naming the option (:func:`~creative_py.cli.errors.fail`)."""

from __future__ import annotations

import errno
import os
from pathlib import Path
from typing import Optional

import typer

from creative_py.cli.errors import fail

SEED_MAX = 2 ** 63 - 1
"""The largest seed (``--seed``, ``--world-seed``): a 64-bit signed integer."""

TRIALS_MAX = 10000
"""The largest ``--max-trials`` and ``--consecutive``."""

EVAL_TRIALS_MAX = 1000
"""The largest ``--eval-trials``."""

CPUS_MAX = 1024
"""The largest ``--num-cpus``."""

NAME_MAX = 255
"""The longest file name (one path component), bytes: Linux's NAME_MAX."""

PATH_MAX = 4095
"""The longest path, bytes: Linux's PATH_MAX (4096) less its terminating NUL."""

ROOM_BELOW_OUT = 256
"""The bytes of path a run writes below ``--out`` (its folder ``<case>-<time>-s<seed>``
and, deepest, ``tools/<tool>/ros/<tool>_description/meshes/<file>``), with room to
spare; a sweep's run folders sit one level deeper."""

BACKEND_HELP = ("Run on this simulator backend instead of the case manifest's (ros: the "
                "arm over ROS 2, docs/real-robot.md).")
PROFILE_HELP = ("The robot: a profile under robots/ (creative robots lists them) or a "
                ".toml path; default: the case's robot. --robot-profile is a synonym.")


def check_counts(*checks: tuple[str, Optional[int], int, int]) -> None:
    """Fail in one line unless each ``(option, value, least, most)`` has its value
    (when given) within ``least..most``."""
    for option, value, least, most in checks:
        if value is None:
            continue
        if value < least:
            fail(f"{option} must be at least {least}, got {value}")
        if value > most:
            fail(f"{option} must be at most {most}, got {value}")


def path_option(option: str, text: Optional[str], room: int = 0) -> Optional[Path]:
    """Return the path an option names (None if not given); fail in one line on an
    empty one (``--out ''`` would otherwise mean the current folder), or as
    :func:`usable` does."""
    if text is None:
        return None
    if not text.strip():
        fail(f"{option} must name a folder, got an empty string")
    return usable(option, Path(text), room)


def usable(option: str, path: Path, room: int = 0) -> Path:
    """Return ``path`` if the file system can look it up, and, for a folder the command
    writes below, if ``room`` more bytes of path fit under Linux's PATH_MAX (a run's
    folder and files: :data:`ROOM_BELOW_OUT`); fail in one line naming the option
    otherwise (a component longer than the file system allows, ENAMETOOLONG, which
    ``Path.exists`` raises; a run that would fail at its first deep file)."""
    text = str(path)
    shown = text if len(text) <= 80 else f"{text[:60]}...{text[-12:]}"
    longest = max((len(os.fsencode(p)) for p in path.parts), default=0)
    if longest > NAME_MAX:  # even below a folder not made yet
        fail(f"{option} {shown}: {os.strerror(errno.ENAMETOOLONG)} (a name of {longest} "
             f"bytes, at most {NAME_MAX})")
    length = len(os.fsencode(os.path.abspath(path)))
    if room and length + room > PATH_MAX:
        fail(f"{option} {shown}: {os.strerror(errno.ENAMETOOLONG)} (a path of {length} "
             f"bytes leaves no room for the {room} bytes of what is written below it; "
             f"at most {PATH_MAX - room})")
    try:
        path.exists()
    except OSError as exc:
        fail(f"{option} {shown}: {exc.strerror or exc}")
    return path


def name_option(option: str, text: Optional[str]) -> Optional[str]:
    """Return a name an option gives (None if not given); fail in one line on an empty
    one (``--variant ''`` would otherwise mean the default), or as :func:`text_option`."""
    if text is not None and not text.strip():
        fail(f"{option} must not be empty")
    return text_option(option, text)


def text_option(option: str, text: Optional[str]) -> Optional[str]:
    """Return text an option gives for the engine (a name, a spec, Prolog text); fail
    in one line when the command line held bytes that are not UTF-8 (Python keeps them
    as lone surrogates, which no encoder takes)."""
    if text is not None:
        try:
            text.encode("utf-8")
        except UnicodeEncodeError as exc:
            byte = os.fsencode(text[exc.start:exc.start + 1])
            fail(f"{option}: not UTF-8 text (byte 0x{byte[0]:02x} at character "
                 f"{exc.start + 1})")
    return text


def given_options(ctx: typer.Context, exclude: tuple[str, ...] = ()) -> list[str]:
    """Return the options of the command that the command line (or the environment)
    gave, as their first spelling (``--seed``), in the command's order."""
    given = []
    for param in ctx.command.params:
        if param.name in exclude or param.param_type_name != "option":
            continue
        source = ctx.get_parameter_source(param.name)  # typer's own click's enum: by name
        if getattr(source, "name", None) in ("COMMANDLINE", "ENVIRONMENT"):
            given.append(max(param.opts, key=len))
    return given


def need_display(manifest=None) -> None:
    """Fail in one line unless the simulator's window can open (the display is set and
    can be opened: pybullet aborts the process on one it cannot open): the window of
    ``manifest``'s backend, or the default backend's before a manifest is read."""
    from creative_py.learning.checks import require_display

    try:
        require_display(manifest)
    except ValueError as exc:
        fail(str(exc))


def backend_override(backend: Optional[str], robot: Optional[str]) -> None:
    """Check ``--backend`` (a registered backend whose packages are installed) and
    ``--robot`` (a robot profile that loads), or fail in one line."""
    from creative_py.robots import load_profile
    from creative_py.simulator.loader import BackendError, backend as load_backend
    from creative_py.world_files import WorldFileError

    if backend is not None:
        try:
            load_backend(backend)
        except BackendError as exc:
            fail(f"--backend {backend}: {exc}")
    if robot is not None:
        if not robot.strip():
            fail("--robot must not be empty")
        try:
            load_profile(robot)
        except WorldFileError as exc:
            fail(f"--robot {robot}: {exc}")


def case_manifest(case: str, world: Optional[Path]):
    """Return the manifest of ``case`` (from ``world`` if given), or fail in one line."""
    from creative_py.case import get_case, read_manifest
    from creative_py.world_files import WorldFileError

    try:
        m = get_case(case) if world is None else read_manifest(world)
    except KeyError as exc:
        fail(exc.args[0])
    except WorldFileError as exc:
        fail(str(exc))
    if m.id != case:
        fail(f"{world / 'case.toml'}: declares case {m.id!r}, not {case!r}")
    return m
