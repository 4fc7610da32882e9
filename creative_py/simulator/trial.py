"""The trial loop above the simulator boundary: what every backend's trials share.

``task_facts``  what the robot perceives of a task before acting, observed once per
                task through the case's backend (the planner's and the size model's
                facts)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from creative_py.case import CaseManifest
    from creative_py.simulator.protocol import World


_TASK_FACTS: dict[tuple, list[tuple]] = {}


def task_facts(world: World, variant: str, location: int) -> list[tuple]:
    """Return what the robot perceives of a task before acting: the catalogue of
    available objects, the apparatus and the target's pose.

    The scene is built and observed once per (world folder, available objects, variant,
    location) by the manifest's backend; nothing moves.
    """
    from creative_py.simulator.registry import backend_for

    m: CaseManifest = world.manifest
    key = (m.id, str(m.folder), world.variation,
           tuple(sorted(world.catalogue)), variant, int(location))
    if key not in _TASK_FACTS:
        # The robot is not built: it is invisible to the cameras and holds nothing yet,
        # so the facts are the same (checked for every case, variant and location) and
        # the scene builds seven times faster.
        with backend_for(m).open_episode(world, variant, int(location),
                                         m.demonstration.tool, seed=0, robot=False) as ep:
            _TASK_FACTS[key] = list(ep.observe().facts)
    return _TASK_FACTS[key]
