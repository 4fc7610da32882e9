"""The simulator backends: each subpackage is one physics behind the simulator boundary
(:mod:`creative_py.simulator`), the only home of its simulator's libraries.

``pybullet``   the reference: a robot profile's arm and a case's scene in pybullet
``maniskill``  ManiSkill3 on SAPIEN (optional: ``make setup-maniskill``)
``ros``        an arm over ROS 2, the pybullet stand-in or a lab's (optional:
               ``make setup-ros``; ``creative run CASE --backend ros``)

Their registry is :mod:`creative_py.backend_registry` (re-exported here); this package
imports none of them: the loader (:mod:`creative_py.simulator.loader`) imports the one
a case's manifest names.
"""

from creative_py.backend_registry import BACKENDS, DEFAULT_BACKEND, BackendEntry

__all__ = ["BACKENDS", "BackendEntry", "DEFAULT_BACKEND"]
