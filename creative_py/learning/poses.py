"""The pose resolver: the engine's pose solution, handed to the simulator.

A pose skill of the simulator (:meth:`creative_py.simulator.Episode.run_skill`)
needs the world target of a relative pose in the state the robot perceives at that
moment (``tip(X, Y, Roll)``, ``place(X, Y, Heading)``). The case's ontology knows it
(its ``pose_target/5`` hook), so the learning layer, which talks to the engine, builds
the resolver and gives it to every episode it opens; the simulator asks no one::

    poses = pose_resolver(Engine.instance(), world.manifest)
    run_trial(world, tool, variant, location, pose_target=poses)   # simulator.trial
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from creative_py.bridge import Compound, Engine, fact_term
from creative_py.case import CaseManifest

if TYPE_CHECKING:
    from creative_py.simulator import Fact, PoseTarget


def pose_resolver(engine: Engine, manifest: CaseManifest) -> "PoseTarget":
    """Return the :data:`~creative_py.simulator.PoseTarget` of a case: ``engine`` solves it.

    The returned callable ``(facts, tool, pose) -> target`` asks the engine (``api``
    operation ``pose_target``, the case's ``abstract_state:pose_world/5``) for the world
    target of the relative pose numbers ``pose`` (the manifest's ``pose_term``) of
    ``tool`` in the perceived state ``facts``; the answer is a tuple
    ``(name, numbers...)``, e.g. ``("tip", x, y, roll)`` in metres and radians, or
    ``()`` if the state lacks what the case needs.

    Parameters
    ----------
    engine : Engine
        The process's engine, with the case's ontology loadable.
    manifest : CaseManifest
        The case (its ``id`` and ``pose_term``).
    """
    case_id, pose_term = manifest.id, manifest.pose_term

    def target(facts: "list[Fact]", tool: str, pose: tuple[float, ...]) -> tuple:
        answer = engine.pose_target(case_id, tool, [fact_term(f) for f in facts],
                                    Compound(pose_term, tuple(float(v) for v in pose)))
        if answer is None:
            return ()
        if isinstance(answer, Compound):
            return (answer.name, *answer.args)
        return (answer,)

    return target
