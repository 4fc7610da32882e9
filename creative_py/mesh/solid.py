"""The solid of a tool: manifold3d booleans over ``spec.parts()``, and its mass properties.

Frames and units: the tool frame of :mod:`creative_py.mesh.spec`, metres, kilograms.
This module (with the rest of :mod:`creative_py.mesh`) is the only home of manifold3d
and trimesh in the project.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import manifold3d
import numpy as np
import trimesh

from creative_py.mesh.spec import Box, Cylinder, Hull, Part, KindSpec, spec_mass
from creative_py.mesh.tolerances import CYLINDER_SEGMENTS, NUMERICAL_NOISE_RTOL

Vec3 = tuple[float, float, float]
Matrix3 = tuple[Vec3, Vec3, Vec3]


@dataclass(frozen=True)
class MassProperties:
    """Mass properties of a tool's solid.

    Attributes
    ----------
    mass : float
        Total mass, kg (``spec_mass``).
    volume : float
        Volume of the meshed solid, m^3.
    center_of_mass : tuple of float
        Centre of mass in the tool frame, metres.
    inertia : tuple of tuple of float
        The full 3x3 inertia tensor about the centre of mass, axes parallel to the
        tool frame, kg m^2 (uniform density = mass / volume).
    """

    mass: float
    volume: float
    center_of_mass: Vec3
    inertia: Matrix3


def part_solid(part: Part) -> manifold3d.Manifold:
    """Return one part as a manifold3d solid in the tool frame, metres.

    Parameters
    ----------
    part : Box, Cylinder or Hull
        A part from ``spec.parts()``.
    """
    if isinstance(part, Box):
        solid = manifold3d.Manifold.cube(part.size, center=True)
        if part.yaw:
            solid = solid.rotate((0.0, 0.0, math.degrees(part.yaw)))
        return solid.translate(part.center)
    if isinstance(part, Cylinder):
        return manifold3d.Manifold.cylinder(
            part.height, part.radius, circular_segments=CYLINDER_SEGMENTS, center=True
        ).translate(part.center)
    if isinstance(part, Hull):
        return manifold3d.Manifold.hull_points(np.asarray(part.vertices, dtype=float))
    raise TypeError(f"unknown part type {type(part).__name__}: expected Box, Cylinder or Hull")


def tool_solid(spec: KindSpec) -> manifold3d.Manifold:
    """Return the union of the spec's parts as one manifold3d solid, metres, tool frame.

    Raises
    ------
    ValueError
        If the union is empty or falls apart into more than one shell (the parts of a
        printable tool must touch).
    """
    solids = [part_solid(p) for p in spec.parts()]
    solid = solids[0] if len(solids) == 1 else manifold3d.Manifold.batch_boolean(
        solids, manifold3d.OpType.Add)
    if solid.status() != manifold3d.Error.NoError or solid.is_empty():
        raise ValueError(f"{spec.name}: the parts do not make a valid solid "
                         f"(manifold3d status {solid.status()})")
    shells = len(solid.decompose())
    if shells != 1:
        raise ValueError(f"{spec.name}: the parts make {shells} separate shells, expected one")
    return solid


def mesh_from_solid(solid: manifold3d.Manifold, scale: float = 1.0) -> trimesh.Trimesh:
    """Return a trimesh of a manifold3d solid, its vertices multiplied by ``scale``."""
    mesh = solid.to_mesh64()
    vertices = np.asarray(mesh.vert_properties, dtype=float)[:, :3] * scale
    faces = np.asarray(mesh.tri_verts, dtype=np.int64)
    return trimesh.Trimesh(vertices=vertices, faces=faces, process=False)


def tool_mesh(spec: KindSpec) -> trimesh.Trimesh:
    """Return the tool's watertight triangle mesh in the tool frame, metres."""
    return mesh_from_solid(tool_solid(spec))


def mass_properties(spec: KindSpec, mesh: trimesh.Trimesh | None = None) -> MassProperties:
    """Return the mass properties of a spec's solid.

    Parameters
    ----------
    spec : KindSpec
        The tool; its mass is ``spec_mass(spec)``.
    mesh : trimesh.Trimesh, optional
        The tool's mesh in metres (``tool_mesh(spec)``); built when not given.
    """
    mesh = tool_mesh(spec) if mesh is None else mesh
    mass = spec_mass(spec)
    volume = float(mesh.volume)
    if not volume > 0:
        raise ValueError(f"{spec.name}: the mesh has no positive volume ({volume!r} m^3)")
    inertia = np.asarray(mesh.moment_inertia, dtype=float) * (mass / float(mesh.mass))
    com = np.asarray(mesh.center_mass, dtype=float)
    com = np.where(np.abs(com) < NUMERICAL_NOISE_RTOL * float(mesh.extents.max()), 0.0, com)
    com = tuple(float(v) for v in com)
    return MassProperties(
        mass=mass,
        volume=volume,
        center_of_mass=com,  # type: ignore[arg-type]
        inertia=tuple(tuple(float(v) for v in row) for row in inertia),  # type: ignore[arg-type]
    )
