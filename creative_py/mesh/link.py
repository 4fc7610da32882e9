"""The single rigid link a tool becomes in URDF and SDF: shapes, mass and inertia.

Both writers (:mod:`creative_py.mesh.urdf`, :mod:`creative_py.mesh.sdf`) serialise the
same :class:`ToolLink`, so the two files cannot disagree. The link frame is the spec's
tool frame; lengths are metres, angles radians (roll, pitch, yaw about fixed x, y, z).
Boxes and cylinders become primitives; a convex hull part (the wedge's prism) becomes a
mesh reference to an OBJ file in metres written beside the description.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

import numpy as np
import trimesh

from creative_py.mesh.solid import MassProperties
from creative_py.mesh.spec import Box, Cylinder, Hull, KindSpec
from creative_py.mesh.tolerances import NUMERICAL_NOISE_RTOL

Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class Shape:
    """One collision-and-visual shape of the link.

    Attributes
    ----------
    kind : {"box", "cylinder", "mesh"}
        Geometry type.
    xyz : tuple of float
        Shape origin in the link frame, metres (a box's or cylinder's centre).
    rpy : tuple of float
        Shape orientation, radians.
    size : tuple of float or None
        Box edge lengths, metres.
    radius, length : float or None
        Cylinder radius and height (along the shape's z), metres.
    mesh_file : str or None
        File name of the mesh (OBJ, metres), relative to the description file.
    """

    kind: Literal["box", "cylinder", "mesh"]
    xyz: Vec3
    rpy: Vec3 = (0.0, 0.0, 0.0)
    size: Vec3 | None = None
    radius: float | None = None
    length: float | None = None
    mesh_file: str | None = None


@dataclass(frozen=True)
class ToolLink:
    """A tool as one rigid link: its shapes, mass properties and display colour."""

    name: str
    shapes: tuple[Shape, ...]
    mass: MassProperties
    rgba: tuple[float, float, float, float]


def hull_file_name(spec: KindSpec, index: int) -> str:
    """Return the OBJ file name of the spec's ``index``-th part (a convex hull)."""
    return f"{spec.name}_hull{index}.obj"


def hull_meshes(spec: KindSpec) -> dict[str, trimesh.Trimesh]:
    """Return the convex-hull parts of a spec as meshes in metres, by OBJ file name."""
    return {hull_file_name(spec, i): trimesh.convex.convex_hull(np.asarray(p.vertices))
            for i, p in enumerate(spec.parts()) if isinstance(p, Hull)}


def tool_link(spec: KindSpec, mass: MassProperties) -> ToolLink:
    """Return the link description of a spec with the given mass properties."""
    shapes = []
    for i, part in enumerate(spec.parts()):
        if isinstance(part, Box):
            shapes.append(Shape("box", part.center, (0.0, 0.0, part.yaw), size=part.size))
        elif isinstance(part, Cylinder):
            shapes.append(Shape("cylinder", part.center, radius=part.radius,
                                length=part.height))
        elif isinstance(part, Hull):
            shapes.append(Shape("mesh", (0.0, 0.0, 0.0), mesh_file=hull_file_name(spec, i)))
        else:
            raise TypeError(f"{spec.name}: unknown part type {type(part).__name__}")
    return ToolLink(spec.name, tuple(shapes), mass, tuple(spec.RGBA))


def format_number(value: float) -> str:
    """Return a float as short exact-enough text (12 significant digits, no '-0')."""
    text = f"{float(value):.12g}"
    return "0" if text in ("-0", "0") else text


def format_vector(values) -> str:
    """Return numbers as space-separated text."""
    return " ".join(format_number(v) for v in values)


def inertia_entries(mass: MassProperties) -> dict[str, str]:
    """Return the six inertia tensor entries (kg m^2) as text, numerical noise zeroed."""
    tensor = np.asarray(mass.inertia, dtype=float)
    noise = NUMERICAL_NOISE_RTOL * float(np.abs(tensor).max())
    tensor = np.where(np.abs(tensor) < noise, 0.0, tensor)
    names = {"ixx": (0, 0), "ixy": (0, 1), "ixz": (0, 2), "iyy": (1, 1), "iyz": (1, 2),
             "izz": (2, 2)}
    return {k: format_number(tensor[ij]) for k, ij in names.items()}
