"""A randomised world of a case, checked by a demonstration: :func:`draw_catalogue_world`
(what ``--world-seed`` runs in)."""

from __future__ import annotations

from typing import Any

from creative_py.bridge import Engine, fact_term
from creative_py.learning.checks import catalogue_ranges
from creative_py.simulator import World, backend_for
from creative_py.simulator.randomise import apply_drawn, draw_world


DEMO_CHECK_SEED = 0
"""The seed of the sensor noise in the demonstration that checks a drawn world (the
world must not depend on a run's seed; runs of seed 0 see that very demonstration)."""


def draw_catalogue_world(engine: Engine, world: World, seed: int,
                         check_demonstration: bool = True) -> dict[str, Any]:
    """Draw a randomised world of ``world`` for world seed ``seed`` (the boundary's
    :func:`creative_py.simulator.randomise.draw_world`): the engine gives each
    catalogued number's own qualitative range (``catalogue_ranges``) and checks that every drawn object keeps its structural
    literals; the physics checks that it lies still where the scene puts it (the
    backend's ``tool_rests``), else it is drawn again.
    With ``check_demonstration``, the trainer's demonstration runs in the drawn world
    (sensor noise of :data:`DEMO_CHECK_SEED`) and the demonstration's location is
    drawn again until it reaches the goal (the drawn world's ``redraws`` counts the
    times)."""
    from creative_py.learning.poses import pose_resolver
    from creative_py.learning.tool_use import DemonstrationFailed, run_demonstration

    physics = backend_for(world.manifest)
    case = world.manifest.id
    ranges = catalogue_ranges(engine, world)

    def literals(spec: Any) -> set[str]:
        state = engine.abstract_state(case, [fact_term(f) for f in spec.catalogue_facts()])
        return {str(lit) for lit in state}

    originals = {name: literals(spec) for name, spec in world.catalogue.items()}
    def keeps(name: str, spec: Any) -> bool:
        if literals(spec) != originals[name]:
            return False
        return physics.tool_rests(world.with_spec(name, spec), name)

    def demonstrates(drawn: dict[str, Any]) -> bool:
        new = apply_drawn(world, drawn)
        try:
            run_demonstration(new, seed=DEMO_CHECK_SEED,
                              pose_target=pose_resolver(engine, new.manifest))
        except DemonstrationFailed:
            return False
        return True

    return draw_world(world, seed, ranges, keeps=keeps,
                      demonstrates=demonstrates if check_demonstration else None)
