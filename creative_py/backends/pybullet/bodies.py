"""Build pybullet bodies from the parametric specs of :mod:`creative_py.mesh.spec`.

A body's *link frame* is the spec's own frame (hook: butt end at the origin, handle
along +x; block: base centred on the origin). pybullet reports a base pose at the
centre of mass, so use :func:`frame_pose` / :func:`set_frame_pose` to read and write
the spec-frame pose. Poses are ``(point, quat)``: metres, world frame, ``(x, y, z, w)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import numpy as np
import pybullet as pb

from creative_py.mesh.spec import Box, Cylinder, Hull, Part, KindSpec, spec_mass
from creative_py.backends.pybullet.core import Pose, Sim

IDENTITY: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)


@dataclass(frozen=True)
class Surface:
    """Contact properties of a body.

    Attributes
    ----------
    lateral_friction : float
        Coulomb friction coefficient (pybullet multiplies the two bodies' values).
    rgba : tuple of float
        Colour of the visual shapes (red, green, blue, alpha in [0, 1]).
    """

    lateral_friction: float = 0.5
    rgba: tuple[float, float, float, float] = (0.6, 0.6, 0.6, 1.0)


def part_centre(part: Part) -> tuple[float, float, float]:
    """Return the centroid of a part in the spec frame, metres."""
    if isinstance(part, Hull):
        if part.centroid is not None:
            return tuple(float(v) for v in part.centroid)
        return tuple(float(v) for v in np.mean(np.asarray(part.vertices), axis=0))
    return part.center


def centre_of_mass(parts: Sequence[Part]) -> tuple[float, float, float]:
    """Return the volume-weighted centroid of the parts (overlaps counted twice), metres."""
    vols = np.array([p.volume for p in parts])
    cents = np.array([part_centre(p) for p in parts])
    return tuple(float(v) for v in (vols[:, None] * cents).sum(axis=0) / vols.sum())


def _hull_indices(vertices: np.ndarray) -> list[int]:
    from scipy.spatial import ConvexHull

    hull = ConvexHull(vertices)
    tris = []
    for simplex, eq in zip(hull.simplices, hull.equations):
        a, b, c = vertices[simplex]
        # Orient every face outwards (counter-clockwise seen from outside).
        if np.dot(np.cross(b - a, c - a), eq[:3]) < 0:
            simplex = simplex[[0, 2, 1]]
        tris.extend(int(i) for i in simplex)
    return tris


def _shape(sim: Sim, part: Part, visual: bool, rgba) -> int:
    c = sim.client
    if isinstance(part, Box):
        frame = dict(collisionFramePosition=part.center,
                     collisionFrameOrientation=pb.getQuaternionFromEuler((0, 0, part.yaw)))
        half = [s / 2 for s in part.size]
        if visual:
            return pb.createVisualShape(pb.GEOM_BOX, halfExtents=half, rgbaColor=rgba,
                                        visualFramePosition=frame["collisionFramePosition"],
                                        visualFrameOrientation=frame["collisionFrameOrientation"],
                                        physicsClientId=c)
        return pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half, physicsClientId=c, **frame)
    if isinstance(part, Cylinder):
        if visual:
            return pb.createVisualShape(pb.GEOM_CYLINDER, radius=part.radius,
                                        length=part.height, rgbaColor=rgba,
                                        visualFramePosition=part.center, physicsClientId=c)
        return pb.createCollisionShape(pb.GEOM_CYLINDER, radius=part.radius, height=part.height,
                                       collisionFramePosition=part.center, physicsClientId=c)
    if isinstance(part, Hull):
        verts = np.asarray(part.vertices, dtype=float)
        if visual:
            return pb.createVisualShape(pb.GEOM_MESH, vertices=verts.tolist(),
                                        indices=_hull_indices(verts), rgbaColor=rgba,
                                        physicsClientId=c)
        return pb.createCollisionShape(pb.GEOM_MESH, vertices=verts.tolist(),
                                       physicsClientId=c)
    raise TypeError(f"unknown part type {type(part).__name__}")


def spawn_parts(sim: Sim, parts: Sequence[Part], pose: Pose, mass: float,
                surface: Surface = Surface(), *, visual: bool = True,
                hidden: Sequence[int] = ()) -> int:
    """Create one rigid body made of ``parts``; return its body id.

    Parameters
    ----------
    parts : sequence of Box, Hull or Cylinder
        The solid parts in the body's own frame, metres.
    pose : Pose
        World pose of the body's own frame (not of its centre of mass).
    mass : float
        Mass in kg; 0 makes a static body.
    surface : Surface
        Friction and colour.
    visual : bool
        Give the body visual shapes (cameras see it) or none (faster to build).
    hidden : sequence of int
        Indices of parts that collide but have no visual shape (clear acrylic).

    The first part is the base link; every further part is a link fixed to it, so any
    mix of boxes, hulls and cylinders works. The mass is shared out by volume and
    each part's mass sits at its own centroid.
    """
    if not parts:
        raise ValueError("a body needs at least one part")
    c = sim.client
    cols = [_shape(sim, p, False, None) for p in parts]
    # A part without a visual shape would be drawn from its collision shape by the
    # renderer: a hidden part gets a fully transparent visual instead.
    clear = (*surface.rgba[:3], 0.0)
    vis = [(_shape(sim, p, True, clear if i in hidden else surface.rgba) if visual else -1)
           for i, p in enumerate(parts)]
    vols = np.array([p.volume for p in parts])
    masses = (mass * vols / vols.sum()).tolist()
    n = len(parts) - 1
    # Each extra part is a link whose frame coincides with the base frame; its mass
    # sits at its own centroid.
    body = pb.createMultiBody(
        baseMass=masses[0], baseCollisionShapeIndex=cols[0], baseVisualShapeIndex=vis[0],
        basePosition=pose[0], baseOrientation=pose[1],
        baseInertialFramePosition=part_centre(parts[0]) if mass > 0 else (0, 0, 0),
        linkMasses=masses[1:], linkCollisionShapeIndices=cols[1:],
        linkVisualShapeIndices=vis[1:], linkPositions=[(0, 0, 0)] * n,
        linkOrientations=[IDENTITY] * n,
        linkInertialFramePositions=[part_centre(p) for p in parts[1:]],
        linkInertialFrameOrientations=[IDENTITY] * n, linkParentIndices=[0] * n,
        linkJointTypes=[pb.JOINT_FIXED] * n, linkJointAxis=[(0, 0, 1)] * n,
        physicsClientId=c)
    for link in range(-1, n):
        pb.changeDynamics(body, link, lateralFriction=surface.lateral_friction,
                          physicsClientId=c)
        for other in range(link + 1, n):
            pb.setCollisionFilterPair(body, body, link, other, 0, physicsClientId=c)
    set_frame_pose(sim, body, pose)
    return body


def spawn_spec(sim: Sim, spec: KindSpec, pose: Pose, surface: Surface = Surface(), *,
               visual: bool = True) -> int:
    """Create the rigid body of a hook or block spec at ``pose`` (spec frame); return its id.

    The mass is :func:`creative_py.mesh.spec.spec_mass` (kg).
    """
    return spawn_parts(sim, spec.parts(), pose, spec_mass(spec), surface, visual=visual)


def load_tool_urdf(sim: Sim, path: Path, pose: Pose, lateral_friction: float = 0.5) -> int:
    """Load a tool written as a URDF file at ``pose`` (its base link frame); return its id."""
    path = Path(path)
    if not path.is_file():
        raise FileNotFoundError(f"{path}: tool URDF not found")
    body = pb.loadURDF(str(path), basePosition=pose[0], baseOrientation=pose[1],
                       flags=pb.URDF_USE_INERTIA_FROM_FILE, physicsClientId=sim.client)
    if body < 0:
        raise ValueError(f"{path}: pybullet could not load this URDF")
    for link in range(-1, pb.getNumJoints(body, physicsClientId=sim.client)):
        pb.changeDynamics(body, link, lateralFriction=lateral_friction,
                          physicsClientId=sim.client)
    set_frame_pose(sim, body, pose)
    return body


def _inertial(sim: Sim, body: int) -> Pose:
    info = pb.getDynamicsInfo(body, -1, physicsClientId=sim.client)
    return tuple(info[3]), tuple(info[4])


def frame_pose(sim: Sim, body: int) -> Pose:
    """Return the world pose of a body's own (spec or URDF base link) frame."""
    com = sim.pose(body)
    local = _inertial(sim, body)
    inv = pb.invertTransform(*local)
    pos, quat = pb.multiplyTransforms(com[0], com[1], inv[0], inv[1])
    return tuple(pos), tuple(quat)


def set_frame_pose(sim: Sim, body: int, pose: Pose) -> None:
    """Teleport a body so its own frame has world pose ``pose`` (velocity zeroed)."""
    local = _inertial(sim, body)
    pos, quat = pb.multiplyTransforms(pose[0], pose[1], local[0], local[1])
    pb.resetBasePositionAndOrientation(body, pos, quat, physicsClientId=sim.client)
    pb.resetBaseVelocity(body, (0, 0, 0), (0, 0, 0), physicsClientId=sim.client)


def local_extents(sim: Sim, body: int) -> tuple[float, float, float]:
    """Return the extents (m) of a body's box in its own frame: its axis-aligned
    bounding box (every link) with the body turned to the identity for a moment."""
    c = sim.client
    pos, quat = pb.getBasePositionAndOrientation(body, physicsClientId=c)
    pb.resetBasePositionAndOrientation(body, (0, 0, 0), (0, 0, 0, 1), physicsClientId=c)
    lo, hi = [math.inf] * 3, [-math.inf] * 3
    for link in range(-1, pb.getNumJoints(body, physicsClientId=c)):
        a, b = pb.getAABB(body, link, physicsClientId=c)
        lo = [min(x, y) for x, y in zip(lo, a)]
        hi = [max(x, y) for x, y in zip(hi, b)]
    pb.resetBasePositionAndOrientation(body, pos, quat, physicsClientId=c)
    return tuple(float(h - l) for l, h in zip(lo, hi))


def yaw_of(quat: Sequence[float]) -> float:
    """Return the yaw (rotation about world z, radians) of a quaternion (x, y, z, w)."""
    x, y, z, w = quat
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
