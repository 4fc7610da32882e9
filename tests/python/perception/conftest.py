"""Small pybullet scenes for the perception tests: a floor, a table, blocks, cameras.

The hook world's numbers are mirrored: table top at z = -0.20 (Baxter base frame), the
floor at z = -0.926, a 3 cm cube; a downward camera 1 m above the table top.
"""

from __future__ import annotations

import pybullet as p
import pytest

from creative_py.mesh.spec import Box, Cylinder, Hull

from creative_py.kinds.block import BlockSpec
from creative_py.world.cameras import CameraSpec

TABLE_TOP = -0.20
FLOOR = -0.926

TOP_CAMERA = CameraSpec("top", eye=(0.9, -0.1, 0.8), target=(0.9, -0.1, -0.2), up=(1.0, 0.0, 0.0),
                        fov_deg=40.0, width=320, height=240, near=0.1, far=3.0)
"""A downward camera 1 m above the table top, image up along +x world."""

FLOOR_TOP_CAMERA = CameraSpec("top", eye=(0.4, 0.3, 1.6), target=(0.4, 0.3, 0.0),
                              up=(1.0, 0.0, 0.0), fov_deg=45.0, width=320, height=240,
                              near=0.1, far=4.0)
"""A downward camera 1.6 m above a floor at z = 0."""

FLOOR_SIDE_CAMERA = CameraSpec("side", eye=(1.4, -0.6, 0.5), target=(0.4, 0.3, 0.0),
                               up=(0.0, 0.0, 1.0), fov_deg=45.0, width=320, height=240,
                               near=0.1, far=4.0)
"""A side camera looking at the floor area of FLOOR_TOP_CAMERA from 0.5 m up."""

# Triangles of a six-vertex prism, wound counter-clockwise seen from outside (BlockSpec
# vertex order: for y = -W/2 then +W/2: back bottom, tip bottom, back top).
PRISM_INDICES = [0, 1, 2, 3, 5, 4, 0, 4, 1, 0, 3, 4, 0, 2, 3, 2, 5, 3, 1, 4, 5, 1, 5, 2]


class Scene:
    """A DIRECT pybullet client with a floor and helpers to add blocks."""

    def __init__(self, floor_z: float, table: bool) -> None:
        self.client = p.connect(p.DIRECT)
        cid = self.client
        plane = p.createCollisionShape(p.GEOM_PLANE, physicsClientId=cid)
        self.floor = p.createMultiBody(0, plane, -1, basePosition=[0, 0, floor_z],
                                       physicsClientId=cid)
        self.table = None
        if table:
            half = [0.4, 0.5, 0.05]
            self.table = p.createMultiBody(
                0, p.createCollisionShape(p.GEOM_BOX, halfExtents=half, physicsClientId=cid),
                p.createVisualShape(p.GEOM_BOX, halfExtents=half, rgbaColor=[0.6, 0.4, 0.2, 1],
                                    physicsClientId=cid),
                basePosition=[0.9, 0.0, TABLE_TOP - 0.05], physicsClientId=cid)

    def add_block(self, spec: BlockSpec) -> int:
        """Add a static block whose body frame is the spec's block frame (base on z = 0)."""
        cid = self.client
        part = spec.parts()[0]
        colour = [0.8, 0.1, 0.1, 1]
        if isinstance(part, Hull):
            col = p.createCollisionShape(p.GEOM_MESH, vertices=part.vertices, physicsClientId=cid)
            vis = p.createVisualShape(p.GEOM_MESH, vertices=part.vertices, indices=PRISM_INDICES,
                                      rgbaColor=colour, physicsClientId=cid)
        elif isinstance(part, Box):
            half = [s / 2 for s in part.size]
            col = p.createCollisionShape(p.GEOM_BOX, halfExtents=half,
                                         collisionFramePosition=part.center, physicsClientId=cid)
            vis = p.createVisualShape(p.GEOM_BOX, halfExtents=half, visualFramePosition=part.center,
                                      rgbaColor=colour, physicsClientId=cid)
        else:
            assert isinstance(part, Cylinder)
            col = p.createCollisionShape(p.GEOM_CYLINDER, radius=part.radius, height=part.height,
                                         collisionFramePosition=part.center, physicsClientId=cid)
            vis = p.createVisualShape(p.GEOM_CYLINDER, radius=part.radius, length=part.height,
                                      visualFramePosition=part.center, rgbaColor=colour,
                                      physicsClientId=cid)
        return p.createMultiBody(0, col, vis, physicsClientId=cid)

    def place(self, body: int, x: float, y: float, z: float, yaw: float) -> None:
        """Move a body's frame to (x, y, z) metres with heading yaw radians."""
        p.resetBasePositionAndOrientation(body, [x, y, z], p.getQuaternionFromEuler([0, 0, yaw]),
                                          physicsClientId=self.client)

    def close(self) -> None:
        """Disconnect the client."""
        p.disconnect(self.client)


@pytest.fixture(scope="module")
def table_scene():
    """A table (top at z = -0.20) and a 3 cm cube named cube1 whose frame is its base."""
    scene = Scene(FLOOR, table=True)
    scene.cube = scene.add_block(BlockSpec("cube1", "box", 0.03, 0.03, 0.03))
    scene.top = TOP_CAMERA
    yield scene
    scene.close()


@pytest.fixture(scope="module")
def floor_scene():
    """An empty floor at z = 0 to which tests add blocks."""
    scene = Scene(0.0, table=False)
    scene.top = FLOOR_TOP_CAMERA
    scene.side = FLOOR_SIDE_CAMERA
    yield scene
    scene.close()


def angle_diff(a: float, b: float, period: float) -> float:
    """Return the smallest difference a - b modulo ``period`` (radians)."""
    return (a - b + period / 2) % period - period / 2


@pytest.fixture
def angle_error():
    """The helper angle_diff as a fixture (tests cannot import conftest)."""
    return angle_diff

