"""A scene built from data: the body kinds :mod:`creative_py.world.bodies` defines,
built in one episode's pybullet simulator.

A kind there is the schema of a ``[[body]]`` table (its fields, bounds and derived
geometry, read with the scene's expressions, :mod:`creative_py.world.expressions`);
its builder here (:data:`BODY_BUILDERS`, keyed as :data:`~creative_py.world.bodies.BODY_KINDS`)
subclasses it and adds what needs pybullet: creating the body (``build``), the
primitive facts it gives (``facts``) and where its centre is (``centre``).
"""

from __future__ import annotations

from typing import Callable

import pybullet as pb

from creative_py.kinds.parts import Cylinder as CylinderPart
from creative_py.mesh.spec import Box as BoxPart
from creative_py.backends.pybullet.bodies import Surface, frame_pose, spawn_parts, yaw_of
from creative_py.backends.pybullet.core import Sim
from creative_py.world.bodies import (BodyKind, BodyTable, BookendsKind, BoxKind, DoorKind,
                                      LaneKind, OpenBoxKind, ScatterKind, ShelfKind,
                                      SphereKind, StandingShelfKind, TubeKind, ZoneKind,
                                      resolve_bodies)
from creative_py.world.expressions import Namespace


class SceneBody(BodyKind):
    """A body of the scene, built in one episode's simulator (the defaults of a
    kind's builder: a kind's fields, bounds and geometry are its :class:`BodyKind`'s)."""

    def build(self, sim: Sim) -> int:
        """Create the body in ``sim``; return its pybullet id."""
        raise NotImplementedError

    def facts(self, sim: Sim) -> list[tuple]:
        """Return the primitive facts this body gives (its fixed geometry, sensors)."""
        return []

    def centre(self, sim: Sim) -> tuple[float, float, float, float]:
        """Return the true ``(x, y, z, yaw)`` of the body's centre (error reports only)."""
        pos, quat = frame_pose(sim, self.id)
        return (*pos, yaw_of(quat))


class BoxBody(BoxKind, SceneBody):
    """A :class:`~creative_py.world.bodies.BoxKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        centre = (0, 0, self.size[2] / 2) if self.frame == "bottom" else (0, 0, 0)
        quat = (0, 0, 0, 1) if self.yaw == 0 else tuple(pb.getQuaternionFromEuler((0, 0, self.yaw)))
        self.id = spawn_parts(sim, [BoxPart(centre, tuple(self.size))],
                              ((self.position[0], self.position[1], self.frame_z), quat),
                              self.mass, Surface(self.friction, tuple(self.colour)))
        return self.id

    def centre(self, sim: Sim) -> tuple[float, float, float, float]:
        pos, quat = frame_pose(sim, self.id)
        dz = self.size[2] / 2 if self.frame == "bottom" else 0.0
        return (pos[0], pos[1], pos[2] + dz, yaw_of(quat))


class TubeBody(TubeKind, SceneBody):
    """A :class:`~creative_py.world.bodies.TubeKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        L, W, H, k = self.length, self.inner_width, self.inner_height, self.wall
        walls = [BoxPart((L / 2, 0, -k / 2), (L, W + 2 * k, k)),                 # floor
                 BoxPart((L / 2, W / 2 + k / 2, H / 2), (L, k, H)),              # left
                 BoxPart((L / 2, -W / 2 - k / 2, H / 2), (L, k, H)),             # right
                 BoxPart((L + k / 2, 0, H / 2), (k, W + 2 * k, H + 2 * k)),      # far end
                 BoxPart((L / 2, 0, H + k / 2), (L, W + 2 * k, k))]              # top (clear)
        self.id = spawn_parts(sim, walls, ((self.mouth_x, self.axis_y, self.floor_z),
                                           (0, 0, 0, 1)), 0.0,
                              Surface(self.friction, tuple(self.colour)), hidden=[4])
        return self.id

    def facts(self, sim: Sim) -> list[tuple]:
        return [("tube_mouth", self.name, self.mouth_x, self.axis_y,
                 self.floor_z + self.inner_height / 2),
                ("tube_length_m", self.name, self.length),
                ("tube_inner_m", self.name, self.inner_width, self.inner_height)]


class ShelfBody(ShelfKind, SceneBody):
    """A :class:`~creative_py.world.bodies.ShelfKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        D, W, H, k, g = self.depth, self.inner_width, self.inner_height, self.board, self.leg
        parts = [BoxPart((D / 2, 0, H + k / 2), (D, W + 2 * g, k))]             # plate
        for x in (g / 2, D - g / 2):
            for y in (W / 2 + g / 2, -W / 2 - g / 2):
                parts.append(BoxPart((x, y, H / 2), (g, g, H)))                 # legs
        self.id = spawn_parts(sim, parts, ((self.mouth_x, self.axis_y, self.floor_z),
                                           (0, 0, 0, 1)), 0.0,
                              Surface(self.friction, tuple(self.colour)),
                              hidden=[0] if self.clear_board else [])
        return self.id

    def facts(self, sim: Sim) -> list[tuple]:
        return [("shelf_front", self.name, self.mouth_x, self.axis_y,
                 self.floor_z + self.inner_height / 2),
                ("shelf_depth_m", self.name, self.depth),
                ("shelf_clearance_m", self.name, self.inner_width, self.inner_height)]


class DoorBody(DoorKind, SceneBody):
    """A :class:`~creative_py.world.bodies.DoorKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        c = sim.client
        half = [self.width / 2, self.thickness / 2, self.height / 2]
        col = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=half,
                                      collisionFramePosition=(self.width / 2, 0, 0),
                                      physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half,
                                   visualFramePosition=(self.width / 2, 0, 0),
                                   rgbaColor=tuple(self.colour), physicsClientId=c)
        base_z = self.floor_z + self.bottom_gap + self.height / 2
        body = pb.createMultiBody(
            baseMass=0.0, baseCollisionShapeIndex=-1, baseVisualShapeIndex=-1,
            basePosition=(self.hinge[0], self.hinge[1], base_z),
            baseOrientation=pb.getQuaternionFromEuler((0, 0, self.closed_heading)),
            linkMasses=[self.mass], linkCollisionShapeIndices=[col],
            linkVisualShapeIndices=[vis], linkPositions=[(0, 0, 0)],
            linkOrientations=[(0, 0, 0, 1)], linkInertialFramePositions=[(self.width / 2, 0, 0)],
            linkInertialFrameOrientations=[(0, 0, 0, 1)], linkParentIndices=[0],
            linkJointTypes=[pb.JOINT_REVOLUTE], linkJointAxis=[(0, 0, 1)],
            physicsClientId=c)
        pb.changeDynamics(body, 0, lateralFriction=self.friction, jointDamping=self.damping,
                          linearDamping=0.0, angularDamping=0.0, jointLowerLimit=0.0,
                          jointUpperLimit=self.max_angle, physicsClientId=c)
        pb.resetJointState(body, 0, self.open_angle, 0.0, physicsClientId=c)
        pb.setJointMotorControl2(body, 0, pb.POSITION_CONTROL, targetPosition=self.open_angle,
                                 force=self.hold_force, physicsClientId=c)
        self.id = body
        return body

    def angle(self, sim: Sim) -> float:
        """Return the door's angle (rad, 0 = closed) from its joint sensor."""
        return float(pb.getJointState(self.id, 0, physicsClientId=sim.client)[0])

    def swing(self, sim: Sim, angle: float, run: Callable[[float], None]) -> None:
        """Let the holder swing the door to ``angle`` (rad) and hold it there.

        ``run(seconds)`` advances the physics while the door swings.
        """
        if angle == self.target:
            return
        pb.setJointMotorControl2(self.id, 0, pb.POSITION_CONTROL, targetPosition=angle,
                                 force=self.hold_force, maxVelocity=self.swing_speed,
                                 physicsClientId=sim.client)
        run(abs(angle - self.target) / self.swing_speed + 0.3)
        self.target = angle

    def facts(self, sim: Sim) -> list[tuple]:
        return [("hinge", self.name, self.hinge[0], self.hinge[1]),
                ("door_width_m", self.name, self.width),
                ("door_closed_heading", self.name, self.closed_heading),
                ("door_angle", self.name, self.angle(sim)),
                ("door_gap_m", self.name, self.bottom_gap)]


class SphereBody(SphereKind, SceneBody):
    """A :class:`~creative_py.world.bodies.SphereKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        c = sim.client
        col = pb.createCollisionShape(pb.GEOM_SPHERE, radius=self.radius, physicsClientId=c)
        vis = pb.createVisualShape(pb.GEOM_SPHERE, radius=self.radius,
                                   rgbaColor=tuple(self.colour), physicsClientId=c)
        self.id = pb.createMultiBody(baseMass=self.mass, baseCollisionShapeIndex=col,
                                     baseVisualShapeIndex=vis,
                                     basePosition=tuple(self.position), physicsClientId=c)
        pb.changeDynamics(self.id, -1, lateralFriction=self.friction,
                          rollingFriction=self.rolling_friction,
                          linearDamping=self.linear_damping,
                          angularDamping=self.angular_damping, physicsClientId=c)
        return self.id


class ZoneBody(ZoneKind, SceneBody):
    """A :class:`~creative_py.world.bodies.ZoneKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        c = sim.client
        vis = pb.createVisualShape(pb.GEOM_CYLINDER, radius=self.radius, length=0.001,
                                   rgbaColor=tuple(self.colour), physicsClientId=c)
        self.id = pb.createMultiBody(baseMass=0.0, baseCollisionShapeIndex=-1,
                                     baseVisualShapeIndex=vis,
                                     basePosition=(self.x, self.y, self.z),
                                     physicsClientId=c)
        return self.id

    def centre(self, sim: Sim) -> tuple[float, float, float, float]:
        return (self.x, self.y, self.z, 0.0)

    def facts(self, sim: Sim) -> list[tuple]:
        return [("reach_zone", self.name, self.x, self.y, self.radius)]


class ScatterBody(ScatterKind, SceneBody):
    """A :class:`~creative_py.world.bodies.ScatterKind` built in pybullet."""

    MEMBER = BoxBody

    def build(self, sim: Sim) -> int:
        return -1  # the cubes are built as bodies of their own

    def extent(self, sim: Sim) -> tuple[float, float, float, float]:
        """Return where the cubes' centres lie now: (x_min, x_max, y_min, y_max), m."""
        pts = [m.centre(sim) for m in self._members.values()]
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return min(xs), max(xs), min(ys), max(ys)

    def centre(self, sim: Sim) -> tuple[float, float, float, float]:
        x0, x1, y0, y1 = self.extent(sim)
        return ((x0 + x1) / 2, (y0 + y1) / 2, self.floor_z + self.size / 2, 0.0)

    def facts(self, sim: Sim) -> list[tuple]:
        x0, x1, y0, y1 = self.extent(sim)
        s = self.size
        return [("pose", self.name, (x0 + x1) / 2, (y0 + y1) / 2, self.floor_z + s / 2, 0.0),
                ("size", self.name, x1 - x0 + s, y1 - y0 + s, s)]


class LaneBody(LaneKind, SceneBody):
    """A :class:`~creative_py.world.bodies.LaneKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        c = sim.client
        half = (self.mark / 2, self.mark / 2, 0.0005)
        vis = pb.createVisualShape(pb.GEOM_BOX, halfExtents=half,
                                   rgbaColor=tuple(self.colour), physicsClientId=c)
        self.id = pb.createMultiBody(0.0, -1, vis, (self.goal_x, self.axis_y,
                                                    self.floor_z + 0.0005),
                                     physicsClientId=c)
        return self.id

    def centre(self, sim: Sim) -> tuple[float, float, float, float]:
        return (self.goal_x, self.axis_y, self.floor_z, 0.0)

    def facts(self, sim: Sim) -> list[tuple]:
        return [("lane_start", self.name, self.mouth_x, self.axis_y,
                 self.floor_z + self.inner_height / 2),
                ("lane_length_m", self.name, self.length),
                ("lane_room_m", self.name, self.inner_width, self.inner_height),
                ("lane_goal", self.name, self.goal_x, self.axis_y)]


class StandingShelfBody(StandingShelfKind, SceneBody):
    """A :class:`~creative_py.world.bodies.StandingShelfKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        D, W, k = self.depth, self.width, self.board
        leg_h = self.top_z - k - self.floor_z
        parts: list = [BoxPart((D / 2, 0.0, -k / 2), (D, W, k))]                 # plate
        for x in (self.post_inset, D - self.post_inset):
            for y in (W / 2 - self.post_side_inset, -W / 2 + self.post_side_inset):
                parts.append(CylinderPart((x, y, -k - leg_h / 2), self.post_radius, leg_h))
            parts.append(BoxPart((x, 0.0, -k - leg_h + self.runner_height / 2),
                                 (self.runner_width, W, self.runner_height)))    # runner
        self.id = spawn_parts(sim, parts, ((self.front_x, self.axis_y, self.top_z),
                                           (0, 0, 0, 1)), 0.0,
                              Surface(self.friction, tuple(self.colour)))
        return self.id

    def facts(self, sim: Sim) -> list[tuple]:
        return [("shelf_top", self.name, self.front_x, self.axis_y, self.top_z),
                ("shelf_top_depth_m", self.name, self.depth)]


class OpenBoxBody(OpenBoxKind, SceneBody):
    """A :class:`~creative_py.world.bodies.OpenBoxKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        X, Y, H = self.size
        k = self.wall
        parts = [BoxPart((0.0, 0.0, k / 2), (X, Y, k)),                          # floor
                 BoxPart((0.0, Y / 2 - k / 2, H / 2), (X, k, H)),                # +y wall
                 BoxPart((0.0, -Y / 2 + k / 2, H / 2), (X, k, H)),               # -y wall
                 BoxPart((X / 2 - k / 2, 0.0, H / 2), (k, Y, H)),                # +x wall
                 BoxPart((-X / 2 + k / 2, 0.0, H / 2), (k, Y, H))]               # -x wall
        self.id = spawn_parts(sim, parts, ((self.position[0], self.position[1], self.floor_z),
                                           (0, 0, 0, 1)), 0.0,
                              Surface(self.friction, tuple(self.colour)))
        return self.id

    def facts(self, sim: Sim) -> list[tuple]:
        X, Y, _ = self.size
        k = self.wall
        return [("open_box_rim", self.name, self.position[0], self.position[1], self.top),
                ("open_box_inner_m", self.name, X - 2 * k, Y - 2 * k, self.floor_z + k,
                 self.top)]


class BookendsBody(BookendsKind, SceneBody):
    """A :class:`~creative_py.world.bodies.BookendsKind` built in pybullet."""

    def build(self, sim: Sim) -> int:
        D, H, p, w, t = self.depth, self.v["height"], self.plate, self.plate_width, self.thickness
        parts = []
        for face, side in ((self.left_y, 1.0), (self.right_y, -1.0)):
            parts.append(BoxPart((0.0, face + side * (w / 2 - t), p / 2), (D, w, p)))
            parts.append(BoxPart((0.0, face - side * t / 2, H / 2), (D, t, H)))
        self.id = spawn_parts(sim, parts, ((self.centre_x, 0.0, self.floor_z), (0, 0, 0, 1)),
                              0.0, Surface(self.friction, tuple(self.colour)))
        return self.id

    def facts(self, sim: Sim) -> list[tuple]:
        return [("bookends_front", self.name, self.mouth_x, self.axis_y,
                 self.passage_floor_z),
                ("bookends_room_m", self.name, self.inner_width, self.inner_height,
                 self.depth)]


BODY_BUILDERS: dict[str, type[SceneBody]] = {
    "box": BoxBody,
    "tube": TubeBody,
    "shelf": ShelfBody,
    "door": DoorBody,
    "lane": LaneBody,
    "sphere": SphereBody,
    "zone": ZoneBody,
    "scatter": ScatterBody,
    "standing_shelf": StandingShelfBody,
    "open_box": OpenBoxBody,
    "bookends": BookendsBody,
}
"""The builder of each body kind, keyed as :data:`creative_py.world.bodies.BODY_KINDS`."""


def make_bodies(tables: tuple[BodyTable, ...], ns: Namespace) -> dict[str, SceneBody]:
    """Return ``name -> SceneBody`` with every field resolved in ``ns`` (nothing built)."""
    return resolve_bodies(tables, ns, BODY_BUILDERS)  # type: ignore[return-value]
