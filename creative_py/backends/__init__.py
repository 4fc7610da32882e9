"""The simulator backends: each subpackage is one physics behind the simulator boundary
(:mod:`creative_py.simulator`), the only home of its simulator's libraries.

``pybullet``   the reference: Baxter and a case's scene in pybullet
``maniskill``  ManiSkill3 on SAPIEN (optional: ``make setup-maniskill``)

Nothing above the boundary imports a backend; the registry
(:mod:`creative_py.simulator.registry`) imports the one a case's manifest names.
"""
