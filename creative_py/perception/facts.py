"""Perception estimates as the primitive facts of the shared vocabulary.

``pose(Obj, X, Y, Z, Yaw)`` and ``size(Obj, Dx, Dy, Dz)``: world frame, metres and
radians; (X, Y, Z) is the centre of the object's box in its yaw frame and (Dx, Dy, Dz)
that box's extents (see :mod:`creative_py.perception.estimate`).
"""

from __future__ import annotations

from typing import Mapping, Union

from creative_py.perception.estimate import ObjectEstimate

Fact = tuple[Union[str, float], ...]


def facts_from_estimates(estimates: Mapping[str, ObjectEstimate] | list[ObjectEstimate]) -> list[Fact]:
    """Return the facts ``("pose", name, x, y, z, yaw)`` and ``("size", name, dx, dy, dz)``.

    Objects come in name order, each pose followed by its size; numbers are plain floats.

    >>> from creative_py.perception.estimate import ObjectEstimate
    >>> e = ObjectEstimate("cube1", 0.9, 0.0, -0.085, 0.1, (0.03, 0.03, 0.03), 80, ("top",))
    >>> facts_from_estimates([e])
    [('pose', 'cube1', 0.9, 0.0, -0.085, 0.1), ('size', 'cube1', 0.03, 0.03, 0.03)]
    """
    items = list(estimates.values()) if isinstance(estimates, Mapping) else list(estimates)
    facts: list[Fact] = []
    for e in sorted(items, key=lambda e: e.name):
        facts.append(("pose", e.name, float(e.x), float(e.y), float(e.z), float(e.yaw)))
        facts.append(("size", e.name, *(float(v) for v in e.size)))
    return facts
