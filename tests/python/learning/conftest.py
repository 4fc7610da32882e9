"""Fixtures of the learning tests: a recorded real run, resumed through the real engine.

``tests/fixtures/runs/hook_s0/`` is a whole hook run (seed 0, paper strategy, all
phases) recorded from the physics. :func:`resumed_hook` copies it into a temporary
folder and resumes it: every trial replays from its recorded outcome and observed facts
through Prolog (labels, version space, plan, creation, evaluation), checked against its
record, and the summary, model and PDDL are written again. Once per test session (per
xdist worker): about 8 s.
"""

from __future__ import annotations

import shutil
from dataclasses import dataclass
from pathlib import Path

import pytest

RECORDED = Path(__file__).resolve().parents[2] / "fixtures" / "runs"


@dataclass(frozen=True)
class ResumedRun:
    """A recorded run resumed in a temporary folder."""

    path: Path
    """The run folder after the resume."""
    recorded: Path
    """The recorded fixture it was copied from (not written)."""
    lines: list[str]
    """The progress lines of the resume, in order."""


def resume_recorded(name: str, into: Path) -> ResumedRun:
    """Copy the recorded run ``name`` into ``into`` and resume it."""
    from creative_py.learning.run import resume_run

    folder = into / name
    shutil.copytree(RECORDED / name, folder)
    lines: list[str] = []
    resume_run(folder, progress=lines.append)
    return ResumedRun(folder, RECORDED / name, lines)


@pytest.fixture(scope="session")
def resumed_hook(tmp_path_factory) -> ResumedRun:
    """The recorded hook run (seed 0, all phases), resumed once a session."""
    return resume_recorded("hook_s0", tmp_path_factory.mktemp("recorded"))
