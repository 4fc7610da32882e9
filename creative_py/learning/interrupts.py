"""Ctrl-C (SIGINT) during a run: always the end of the run.

Python turns SIGINT into :class:`KeyboardInterrupt` at the next bytecode, but code the
run does not own may swallow it (a C library calling back into Python, a broad
``except``), and the run would then go on and end with exit 0. :func:`watching` installs
a handler that also *notes* the interrupt; :func:`check` (called before every trial and
every clip) raises :class:`KeyboardInterrupt` again while the note stands, and
:func:`interrupted` tells the command line to exit 130 even if the exception was lost::

    with interrupts.watching():
        run_case(...)              # KeyboardInterrupt at the next bytecode or trial
    if interrupts.interrupted():
        ...                        # exit 130 with the resume hint

A clip is started inside :func:`deferred`: a SIGINT is noted there and raised only
after it, so the clip process forked there (a copy of the run,
:meth:`creative_py.simulator.ClipRecorder.render_then`) inherits a handler that notes
and goes on: a Ctrl-C at the terminal reaches the whole process group, and the clip of
a trial that has ended is finished and written instead of being lost half encoded.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager
from typing import Any, Iterator

_NOTED = {"sigint": False}


def _handler(signum: int, frame: Any) -> None:
    _NOTED["sigint"] = True
    raise KeyboardInterrupt


@contextmanager
def watching() -> Iterator[None]:
    """Note every SIGINT while the block runs (and raise KeyboardInterrupt as Python's
    own handler does); the previous handler is restored after it. Outside the main
    thread nothing is installed (signals reach the main thread only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _NOTED["sigint"] = False
    before = signal.signal(signal.SIGINT, _handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, before)


def interrupted() -> bool:
    """Whether a SIGINT arrived inside the last :func:`watching` block."""
    return _NOTED["sigint"]


def check() -> None:
    """Raise KeyboardInterrupt if a SIGINT arrived and was swallowed on its way."""
    if _NOTED["sigint"]:
        raise KeyboardInterrupt


def _note(signum: int, frame: Any) -> None:
    _NOTED["sigint"] = True


@contextmanager
def deferred() -> Iterator[None]:
    """Hold a SIGINT back while the block runs: it is noted, and KeyboardInterrupt is
    raised when the block ends (a process forked inside keeps the noting handler and
    is not interrupted). Outside the main thread nothing changes."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    before = signal.signal(signal.SIGINT, _note)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, before)
    check()
