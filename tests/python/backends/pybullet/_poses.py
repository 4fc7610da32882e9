"""The engine's pose resolver, for the tests that run a pose skill."""

from __future__ import annotations

from creative_py.bridge import Engine
from creative_py.learning.poses import pose_resolver


def poses(world):
    """Return the pose resolver of ``world``'s case (the learning layer's, asking the engine)."""
    return pose_resolver(Engine.instance(), world.manifest)
