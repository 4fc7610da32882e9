"""The simulator boundary: what the layers above need of a physics, and which one.

The learning loop (:mod:`creative_py.learning`) never imports a simulator. It asks the
case's manifest for its backend and talks to it through the protocols of
:mod:`creative_py.simulator.protocol`; what every backend's trials and randomised
worlds share is written once, here, above the backends::

    from creative_py.simulator import backend_for
    from creative_py.simulator.trial import run_trial
    sim = backend_for(manifest)                 # the manifest's backend = "pybullet"
    world = sim.load_world(manifest)            # World
    with sim.open_episode(world, variant, location, tool, pose_target=poses) as ep:
        ep.run_skill("pick_up")                 # SkillOutcome: how the motion ended
        ep.observe().facts                      # primitive facts
        ep.verdict()                            # what the oracle measures (Verdict)
    run_trial(world, tool, variant, location, pose, seed,
              pose_target=poses)                # TrialResult: the outcome labelled here

Modules:

``types``       the value types every backend returns (SkillOutcome, Verdict,
                Observation, TrialResult, Fact), the PoseTarget it is given and
                ``pose_numbers`` (the check of a pose skill's numbers)
``protocol``    Backend, World, Episode (and CatalogueEntry, ClipCamera, ClipRecorder):
                typing.Protocol classes, exactly what the layers above use
``catalogue``   CatalogueWorld: a backend world's ``catalogue``, ``item``,
                ``with_spec`` and ``with_catalogue``, written once for every backend
``trial``       the trial loop, once for every backend: ``run_trial`` (open the
                episode, run the manifest's skills in order, observe before the tool
                action, ask the oracle, label the outcome: ``trial_outcome``, build the
                TrialResult, call the verdict back for clips), ``play_trial`` (its body
                in an open episode), ``task_facts``
``randomise``   randomised worlds (``--world-seed``), once for every backend:
                ``draw_world`` (the seeded draws of catalogue numbers and location
                values, the redraws) and ``apply_drawn``
``load``        the tool load's rule (``robust_force``) and its record (``ToolLoad``),
                once for every backend
``paths``       the gripper's straight path (``straight_line``, ``Unreachable``), for
                every backend that moves an arm by IK
``loader``      ``backend(name)``, ``backend_for(manifest)``: the manifest's
                ``backend`` name to its module, imported on first use (the names:
                :data:`creative_py.backend_registry.BACKENDS`)

Backends: ``pybullet`` (:mod:`creative_py.backends.pybullet`, the default and the reference) and
``maniskill`` (:mod:`creative_py.backends.maniskill`, ManiSkill3 on SAPIEN, installed with
``pip install -e '.[maniskill]'``).

How to write a backend
----------------------
A backend offers only what a world must: build a scene, run a skill, observe, measure
the case's quantities, the true poses, the simulated time, steps and the load on the
tool. It does not run trials, label outcomes or draw worlds: :mod:`.trial` and
:mod:`.randomise` do, through the members below, for every backend alike.

1. Make a package ``creative_py/backends/<name>/`` that is the only home of its
   simulator's libraries (add them to the library table of ``docs/architecture.md``
   section 3, and the package's row: it may import ``simulator`` and what lies below
   it, never ``learning`` or ``bridge``: the physics asks no one).
2. At its top level, define the functions of :class:`Backend`, with the signatures and
   the meaning their docstrings give: ``load_world``, ``open_episode`` (a context
   manager that builds the scene and yields an episode), ``tool_rests``,
   ``display_reachable``, ``recorder``.
3. Its worlds have the members of :class:`World`: subclass
   :class:`~creative_py.simulator.catalogue.CatalogueWorld` (a frozen dataclass with
   ``items``) for the catalogue; ``location_values``, ``scene_value`` and
   ``with_locations`` are what the world sampler reads and sets (a backend whose
   locations are no scene values raises ValueError naming ``case.toml`` there, and
   draws no randomised worlds).
4. Its episodes have the members of :class:`Episode`, in the units they document:
   ``run_skill`` (returns a :class:`SkillOutcome`: ``ok``, or ``blocked`` with the
   guard's :class:`Verdict` as ``stop``, ``out_of_time`` with the budget's,
   ``unreachable``, ``invalid``; how the motion
   ended, never the trial's outcome), ``observe``, ``verdict`` (the case's oracle
   measured in the simulated state: a :class:`Verdict`), ``truth``,
   ``sim_time``, ``steps``, ``render_time_s``, ``measured_load``. Its recorders have
   those of :class:`ClipRecorder` (a recorder that sets the simulator's state back
   to render does so itself, after the verdict). Return the value types of
   :mod:`creative_py.simulator.types` (``from creative_py.simulator import
   SkillOutcome, Verdict, ...``).
5. Keep the physics the oracle: a verdict comes from the simulated state after the
   skills ran, never from a tool's properties; every skill a manifest binds is the
   primitive it names, with its options; an episode's facts are what its cameras and
   the robot's proprioception give, in the facts' vocabulary (``pose``, sizes,
   ``held``, each object's catalogue facts exactly as its kind's ``catalogue_facts()``
   gives them), so the engine reads them as it reads the pybullet backend's.
6. Register it: one line ``"<name>": BackendEntry("creative_py.backends.<name>",
   extra=..., setup=...)`` in :data:`creative_py.backend_registry.BACKENDS` (``extra``: the
   ``pyproject.toml`` optional dependencies it needs; ``setup``: the make target that
   installs them, named in the error when they are missing). A case chooses it with ``backend = "<name>"`` in its ``case.toml``.
7. Test it as ``tests/python/backends/pybullet/`` tests the pybullet one: a case's
   demonstration reaches the goal, a trial's outcome
   (:func:`creative_py.simulator.trial.run_trial`) follows the physics, errors name
   the file and the field. ``tests/python/test_simulator_registry.py`` checks its
   functions, world and episode against the protocols;
   ``tests/python/architecture/test_layers.py`` that no code of ``learning/`` imports
   it and that no backend defines a trial's outcome rules.
"""

from creative_py.simulator.protocol import (Backend, CatalogueEntry, ClipCamera, ClipRecorder,
                                            Episode, World)
from creative_py.simulator.loader import (BackendError, BackendUnavailable, UnknownBackend,
                                            backend, backend_for, backend_packages)
from creative_py.simulator.types import (SKILL_STATUSES, TRIAL_OUTCOMES, BackendLost, Fact,
                                         Observation, PoseTarget, SkillOutcome, TrialResult,
                                         Verdict)

__all__ = ["Backend", "BackendError", "BackendLost", "BackendUnavailable", "CatalogueEntry", "ClipCamera",
           "ClipRecorder", "Episode", "Fact", "Observation", "PoseTarget", "SKILL_STATUSES",
           "SkillOutcome", "TRIAL_OUTCOMES", "TrialResult", "UnknownBackend", "Verdict",
           "World", "backend", "backend_for", "backend_packages"]
