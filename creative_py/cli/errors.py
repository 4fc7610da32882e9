"""Errors in one line: ``error: ...`` on stderr and exit code 2 (``--debug``: the
traceback first), and stdout kept for the command's own output."""

from __future__ import annotations

import os
import sys
import traceback
from contextlib import contextmanager
from typing import Iterator

import typer

DEBUG = {"on": False}
"""Whether ``--debug`` was given: then an error shows its traceback."""


@contextmanager
def one_line_errors() -> Iterator[None]:
    """Turn what user data can cause (a world or ontology file, Prolog's answer to it, the
    file system) into one line ``error: ...`` and exit code 2; ``--debug`` re-raises."""
    from creative_py.bridge import BridgeError
    from creative_py.mesh.slicer import SliceError
    from creative_py.world_files import WorldFileError

    try:
        yield
    except (BridgeError, WorldFileError, OSError, SliceError) as exc:
        if DEBUG["on"]:
            raise
        text = " ".join(str(exc).split())
        if isinstance(exc, OSError) and exc.filename:
            text = f"{exc.filename}: {exc.strerror or exc}"
        fail(text)


@contextmanager
def stdout_to_stderr() -> Iterator[None]:
    """Send what C libraries print to stdout (pybullet's banner and URDF warnings) to
    stderr, so that stdout carries only the command's output (e.g. one JSON line)."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        os.dup2(2, 1)
        yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(saved)


def fail(message: str) -> None:
    """Print ``error: message`` and exit with code 2; under ``--debug``, when an
    exception is being handled, its traceback first."""
    if DEBUG["on"] and sys.exc_info()[1] is not None:
        traceback.print_exc()
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)
