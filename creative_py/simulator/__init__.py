"""The simulator boundary: what the learning loop needs of a physics, and which one.

The learning loop (:mod:`creative_py.learning`) never imports a simulator. It asks the
case's manifest for its backend and talks to it through the protocols of
:mod:`creative_py.simulator.protocol`::

    from creative_py.simulator import backend_for
    sim = backend_for(manifest)                 # the manifest's backend = "pybullet"
    world = sim.load_world(manifest)            # World
    with sim.open_episode(world, variant, location, tool, pose_target=poses) as ep:
        ep.run_skill("pick_up")                 # SkillOutcome
        ep.observe().facts                      # primitive facts
        ep.goal_reached()                       # the physics oracle
    sim.run_trial(world, tool, variant, location, pose, seed,
                  pose_target=poses)            # TrialResult

Modules:

``types``       the value types every backend returns (SkillOutcome, Verdict,
                Observation, TrialResult, Fact), the PoseTarget it is given and
                ``pose_numbers`` (the check of a pose skill's numbers)
``protocol``    Backend, World, Episode (and CatalogueEntry, ClipCamera, ClipRecorder):
                typing.Protocol classes, exactly what the learning loop uses
``catalogue``   CatalogueWorld: a backend world's ``catalogue``, ``item`` and
                ``with_spec``, written once for every backend
``registry``    ``backend(name)``, ``backend_for(manifest)``: the manifest's
                ``backend`` name to its module, imported on first use (the names:
                :data:`creative_py.case.BACKENDS`)

Backends: ``pybullet`` (:mod:`creative_py.backends.pybullet`, the default and the reference) and
``maniskill`` (:mod:`creative_py.backends.maniskill`, ManiSkill3 on SAPIEN, installed with
``pip install -e '.[maniskill]'``).

How to write a backend
----------------------
1. Make a package ``creative_py/<name>/`` that is the only home of its simulator's
   libraries (add them to the library table of ``docs/architecture.md`` section 3, and
   the package's row: it may import ``simulator`` and what lies below it, never
   ``learning`` or ``bridge``: the physics asks no one).
2. At its top level, define the functions of :class:`Backend`, with the signatures and
   the meaning their docstrings give (``load_world``, ``open_episode``, ``run_trial``,
   ``tool_rests``, ``draw_world``, ``apply_drawn``, ``display_reachable``,
   ``recorder``). Its worlds have the attributes of
   :class:`World`, its episodes those of :class:`Episode`, its recorders those of
   :class:`ClipRecorder`. Return the value types of :mod:`creative_py.simulator.types`
   (``from creative_py.simulator import SkillOutcome, TrialResult, ...``), in the
   units they document.
3. Keep the physics the oracle: an outcome comes from the simulated state after the
   skills ran, never from a tool's properties; every skill a manifest binds is the
   primitive it names, with its options; an episode's facts are what its cameras and
   the robot's proprioception give, in the facts' vocabulary (``pose``, sizes,
   ``held``, each object's catalogue facts exactly as its kind's ``catalogue_facts()``
   gives them), so the engine reads them as it reads the pybullet backend's.
4. Register it: one line ``"<name>": BackendEntry("creative_py.<name>", extra=...)`` in
   :data:`creative_py.case.BACKENDS` (``extra``: the ``pyproject.toml`` optional
   dependencies it needs, named in the error when they are missing). A case chooses
   it with ``backend = "<name>"`` in its ``case.toml``.
5. Test it as ``tests/python/backends/pybullet/`` tests the pybullet one: a case's demonstration
   reaches the goal, a trial's outcome follows the physics, errors name the file and
   the field. ``tests/python/architecture/test_layers.py`` checks that no code of
   ``learning/`` imports it.
"""

from creative_py.simulator.protocol import (Backend, CatalogueEntry, ClipCamera, ClipRecorder,
                                            Episode, World)
from creative_py.simulator.registry import (BackendError, BackendUnavailable, UnknownBackend,
                                            backend, backend_for, backend_packages)
from creative_py.simulator.types import (SKILL_STATUSES, TRIAL_OUTCOMES, Fact, Observation,
                                         PoseTarget, SkillOutcome, TrialResult, Verdict)

__all__ = ["Backend", "BackendError", "BackendUnavailable", "CatalogueEntry", "ClipCamera",
           "ClipRecorder", "Episode", "Fact", "Observation", "PoseTarget", "SKILL_STATUSES",
           "SkillOutcome", "TRIAL_OUTCOMES", "TrialResult", "UnknownBackend", "Verdict",
           "World", "backend", "backend_for", "backend_packages"]
