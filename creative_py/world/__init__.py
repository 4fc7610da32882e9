"""The world files of a case whose scene a backend builds, read once for every backend.

A world folder (``worlds/<folder>/``) holds ``case.toml`` and the files this package
reads into a :class:`~creative_py.world.read.World`: ``scene.toml`` (the robot's
placement and start, the ``[[body]]`` tables, the tool's start, perception, cameras,
the clips' camera), ``tasks.toml`` (the target's locations and the success oracle),
``physics.toml`` and ``objects.toml`` (the catalogue,
:func:`creative_py.simulator.catalogue.read_catalogue`). Every field is checked here,
against the schemas this package holds: the body kinds (:mod:`.bodies`, their fields,
bounds and derived geometry), scene expressions (:mod:`.expressions`), the handlings'
start fields (:mod:`.handlings`), the skill primitives' options (:mod:`.skills`), the
oracle kinds (:mod:`.oracles`, which judge an episode's measured state) and the
cameras (:mod:`.cameras`).

A backend builds what these files describe (the pybullet backend's bodies, primitives
and cameras subclass or key the schemas here); none reads a world file itself, and
none imports another backend to read one.
"""
