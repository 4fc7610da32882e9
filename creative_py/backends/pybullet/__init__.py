"""The pybullet backend: a case's world built in pybullet, driven by the manifest's skills.

This package is the ``pybullet`` backend of the simulator boundary
(:mod:`creative_py.simulator`): its module-level functions are the
:class:`~creative_py.simulator.Backend` protocol (``load_world``, ``open_episode``,
``tool_rests``, ``display_reachable``, ``recorder``), and the layers above reach them
through ``backend_for(manifest)``, never by importing this package. A trial (the
skills in order, the oracle, the outcome) and a randomised world are made above the
boundary, as every backend's (:mod:`creative_py.simulator.trial`,
:mod:`creative_py.simulator.randomise`). Public API::

    from creative_py.backends.pybullet import load_world, open_episode
    world = load_world(manifest)                # World (creative_py.case.CaseManifest)
    with open_episode(world, variant, location, tool) as ep:
        ep.run_skill("pick_up")                 # SkillOutcome
        ep.verdict()                            # what the oracle measures (Verdict)

A pose skill needs ``pose_target`` (:data:`PoseTarget`), given by the caller: the
learning layer's :func:`creative_py.learning.poses.pose_resolver` asks the engine.

The world it builds is read above the backends (:mod:`creative_py.world`: the world
files, the body kinds, the primitives' options, the oracle kinds); ``load_world`` and
``World`` here are that reader's. Modules, from the data to the physics:

``types``       the boundary's value types, re-exported (:mod:`creative_py.simulator.types`)
``scene``       the body kinds of :mod:`creative_py.world.bodies` built (``BODY_BUILDERS``)
``tools``       how a tool kind is held (by a handle, from the top): start, grasp,
                motion, proprioception, catalogue facts
``primitives``  the skill primitives a manifest binds by name, run
``episode``     one scene driven skill by skill (open_episode, Episode, tool_rests)
``arm``, ``bodies``, ``camera``, ``core``   the robot profile's arm, rigid bodies, cameras, the client
"""


def _import_pybullet_quietly() -> None:
    """Import pybullet once, without the build-time banner its C module writes to the
    standard error at import (every command printed it); errors still show."""
    import os
    import sys

    if "pybullet" in sys.modules:
        return
    sys.stderr.flush()
    saved, devnull = os.dup(2), os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, 2)
        import pybullet  # noqa: F401
    finally:
        os.dup2(saved, 2)
        os.close(saved)
        os.close(devnull)


_import_pybullet_quietly()

from creative_py.backends.pybullet.arm import check_profile
from creative_py.backends.pybullet.core import display_reachable
from creative_py.backends.pybullet.episode import Episode, open_episode, tool_rests
from creative_py.backends.pybullet.recorder import Recorder
from creative_py.world.read import World, load_world
from creative_py.simulator.types import (SKILL_STATUSES, Fact, Observation, PoseTarget,
                                         SkillOutcome)
from creative_py.world.cameras import VideoSpec


def recorder(camera: VideoSpec) -> Recorder:
    """Return a new recorder of one trial's clip for ``camera`` (a world's ``video``):
    :meth:`creative_py.simulator.Backend.recorder`."""
    return Recorder(camera)


__all__ = ["Episode", "Fact", "Observation", "PoseTarget", "SKILL_STATUSES", "SkillOutcome",
           "World", "check_profile", "display_reachable", "load_world", "open_episode", "recorder",
           "tool_rests"]
