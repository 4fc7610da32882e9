"""A tool's spec as the mesh writers see it: parts, material, volume and mass.

The specs themselves are the tool kinds' (:mod:`creative_py.kinds`: one plug-in module
per kind, ``creative_py/kinds/<kind>.py``); every writer of :mod:`creative_py.mesh`
takes any :class:`KindSpec` and asks it for its parts, dimensions, OpenSCAD model and
picture, never testing its type. Units: metres, kilograms; a tool frame is its kind's.
"""

from __future__ import annotations

from creative_py.kinds import spec_from_dict
from creative_py.kinds.parts import (MIN_SAFETY_FACTOR, PLA_DENSITY, PLA_STRENGTH, Box,
                                     Cylinder, Hull, KindSpec, Part)


__all__ = ["MIN_SAFETY_FACTOR", "PLA_DENSITY", "PLA_STRENGTH", "Box", "Cylinder", "Hull",
           "Part", "KindSpec", "spec_from_dict", "spec_mass", "spec_volume"]


def spec_volume(spec: KindSpec) -> float:
    """Return the solid volume of a spec in m^3 (overlapping parts counted once)."""
    return spec.volume()


def spec_mass(spec: KindSpec) -> float:
    """Return the mass in kg: the spec's own, or PLA density times volume."""
    return spec.mass if spec.mass is not None else PLA_DENSITY * spec_volume(spec)
