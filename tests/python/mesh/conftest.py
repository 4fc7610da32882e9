"""Shared fixtures for the mesh tests: one spec of every kind, written once per session."""

from __future__ import annotations

import pytest

from creative_py.mesh.export import write_tool_files
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec

SPECS = {
    "hook_right": HookSpec("hook_right", 0.3, hook_side="right"),
    "hook_left": HookSpec("hook_left", 0.2, handle_width=0.012, hook_length=0.04,
                          hook_side="left", mass=None),
    "hook_angled": HookSpec("hook_angled", 0.25, hook_width=0.008, hook_side="right",
                            hook_angle_deg=60.0),
    "hook_obtuse": HookSpec("hook_obtuse", 0.2, hook_side="left", hook_angle_deg=120.0),
    "stick": HookSpec("stick", 0.3, hook_side="none", hook_length=0.0),
    "prism": BlockSpec("prism", "triangular_prism", 0.1, 0.05, 0.03, tip_height=0.002),
    "box": BlockSpec("box", "box", 0.04, 0.05, 0.03, mass=0.2),
    "cylinder": BlockSpec("cylinder", "cylinder", 0.04, 0.04, 0.05),
}
"""One spec per object kind; hook_left takes its mass from PLA density; the prism's tip
is blunted (a knife edge does not print)."""


@pytest.fixture(scope="session")
def written(tmp_path_factory):
    """Return {kind: ToolFiles} for every spec in SPECS, written with pictures."""
    out = tmp_path_factory.mktemp("tools")
    return {kind: write_tool_files(spec, out) for kind, spec in SPECS.items()}


@pytest.fixture(scope="session")
def specs():
    """Return the SPECS table."""
    return SPECS


def pytest_generate_tests(metafunc):
    """Run every test that takes a ``kind`` argument once per object kind."""
    if "kind" in metafunc.fixturenames:
        metafunc.parametrize("kind", sorted(SPECS))
