"""A scene built from data: the ``[[body]]`` tables of ``scene.toml`` and their values.

Each ``[[body]]`` names a registered body kind (:data:`BODY_KINDS`) and gives its fields;
a number may be written as an arithmetic expression over the scene's ``[values]`` and
other bodies' fields, so that a variant or a location changes one value and everything
built from it follows::

    [values]
    table_top = -0.20

    [[body]]
    name = "tube1"
    kind = "tube"
    length = 0.30                               # a variant sets "tube1.length"
    floor_z = "table_top + 0.10 + tube1.wall"
    ...

    [[body]]
    name = "cube1"
    kind = "box"
    position = ["tube1.mouth_x + tube1.length - back_gap", "tube1.axis_y + lateral", ...]

Expressions take ``+ - * / **``, parentheses, numbers, ``pi``, names of ``[values]``,
``body.field`` (``body.field[i]`` for a vector), ``tool.<quantity>`` of the episode's
tool (:mod:`creative_py.backends.pybullet.tools`) and the functions ``min max abs sqrt sin cos
radians``. Variants (``case.toml``) and locations (``tasks.toml``) override values
with dotted keys (``"tube1.length" = 0.45``, ``back_gap = 0.04``).

Body kinds
----------
``box``
    A box (static when ``mass`` is 0), frame at its centre or its ``bottom``.
``tube``
    A closed tube of five box walls along +x, frame at the mouth on the axis on the
    inner floor; the top wall collides but is clear (cameras see in). Facts:
    ``tube_mouth/4``, ``tube_length_m/2``, ``tube_inner_m/3``.
``shelf``
    A low plate on four corner legs, the space under it a passage along +x like a
    tube's (for a tool pushed under it). Facts: ``shelf_front/4``,
    ``shelf_depth_m/2``, ``shelf_clearance_m/3``.
``door``
    A panel on a vertical revolute hinge with a holder (a position motor that keeps it
    at ``open_angle`` and swings it for the arm) and a closer (``closing_torque``,
    applied once the door is released). Facts: ``hinge/3``, ``door_width_m/2``,
    ``door_closed_heading/2``, ``door_angle/2``, ``door_gap_m/2``.
``lane``
    An open passage along +x with no walls (nothing collides): where a tool works on an
    open table, or the passage between walls built of boxes, and a flat goal mark at
    ``goal_x``. Facts: ``lane_start/4``, ``lane_length_m/2``, ``lane_room_m/3``,
    ``lane_goal/3``.
``sphere``
    A ball (static when ``mass`` is 0) of ``radius``, frame at its centre. Rolling
    friction and damping are pybullet's defaults unless given (a ball on a table rolls
    on until something stops it).
``zone``
    A goal marked on the table: a disc of ``radius`` about (``x``, ``y``) at height ``z``,
    seen by nothing that collides (a visual only, as the benchmark's goal markers).
    Facts: ``reach_zone/4`` (its centre's x, y and its radius).
``scatter``
    ``count`` cubes of side ``size`` drawn at random in a rectangle of the table
    (``x_range``, ``y_range``), each centre farther than ``min_gap`` (Euclidean, in the
    plane) from every other, by rejection sampling from ``seed`` (a location's value
    that the world sampler may jitter: a new seed, a new drawing). The cubes are boxes
    of their own, named ``<name>1`` ... ``<name><count>`` (an oracle lists them by
    name); the scatter builds nothing itself and reports the rectangle its cubes lie
    in now as ``pose/5`` and ``size/4`` of its own name (the field a tool sweeps).
``standing_shelf``
    A tall shelf standing on the floor: a top plate on four round posts and two base
    runners; the room above its top is a passage along +x from its front edge (for a
    tool carried over what lies on it). Facts: ``shelf_top/4``, ``shelf_top_depth_m/2``.
``open_box``
    A fixed box open at the top: a floor panel and four walls. Facts: ``open_box_rim/4``,
    ``open_box_inner_m/5``.
``bookends``
    Two L-shaped bookends (a base plate under the books, an upright beside them) facing
    each other across a row of books; the room above the books between the uprights is
    a passage along +x from the books' front (for a tool carried over a book). Facts:
    ``bookends_front/4``, ``bookends_room_m/4``.

Every number of a body has bounds (each kind's ``BOUNDS``), checked in every variant
and location when the world loads: coordinates within +-10 m and dimensions 0-10 m of
the robot's base, angles within +-2 pi rad, ``mass`` 0-1000 kg, ``friction`` 0-10,
``colour`` 0-1; a door's ``swing_speed`` 0.001-100 rad/s, ``hold_force`` 0-1e6 N m,
``closing_torque`` 0-1e4 N m, ``damping`` 0-1e4 N m s/rad.
"""

from __future__ import annotations

import ast
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import pybullet as pb

from creative_py.kinds.parts import Cylinder as CylinderPart
from creative_py.mesh.spec import Box as BoxPart
from creative_py.backends.pybullet.bodies import Surface, frame_pose, spawn_parts, yaw_of
from creative_py.backends.pybullet.core import Sim
from creative_py.world_files import Fields, WorldFileError

_FUNCTIONS: dict[str, Callable[..., float]] = {
    "min": min, "max": max, "abs": abs, "sqrt": math.sqrt, "sin": math.sin,
    "cos": math.cos, "radians": math.radians}
_BINOPS = {ast.Add: lambda a, b: a + b, ast.Sub: lambda a, b: a - b,
           ast.Mult: lambda a, b: a * b, ast.Div: lambda a, b: a / b,
           ast.Pow: lambda a, b: a ** b}


class Namespace:
    """Resolve scene values: ``[values]`` names, ``body.field`` and ``tool.quantity``.

    Parameters
    ----------
    values : mapping
        ``name -> raw value`` of the ``[values]`` table (numbers or expressions).
    bodies : mapping
        ``body name -> {field: raw value}``.
    tool : mapping
        ``quantity -> number`` of the episode's tool (empty when there is none).
    source : str
        Where the values come from (named in errors).
    """

    def __init__(self, values: Mapping[str, Any], bodies: Mapping[str, Mapping[str, Any]],
                 tool: Mapping[str, float] | None = None, source: str = "scene.toml") -> None:
        self.values = dict(values)
        self.bodies = {k: dict(v) for k, v in bodies.items()}
        self.tool = dict(tool or {})
        self.source = source
        self._cache: dict[str, Any] = {}
        self._busy: set[str] = set()

    def override(self, settings: Mapping[str, Any], source: str) -> None:
        """Replace values by dotted keys (``"tube1.length"``, ``"back_gap"``)."""
        for key, value in settings.items():
            if "." in key:
                body, _, name = key.partition(".")
                if body not in self.bodies or name not in self.bodies[body]:
                    raise WorldFileError(f"{source}: key {key!r}: no such scene value (body "
                                         f"fields are set as 'body.field'; bodies: "
                                         f"{', '.join(self.bodies)})")
                self.bodies[body][name] = value
            else:
                if key not in self.values:
                    raise WorldFileError(f"{source}: key {key!r}: no such scene value "
                                         f"([values]: {', '.join(self.values) or 'none'})")
                self.values[key] = value
        self._cache.clear()

    def get(self, key: str) -> Any:
        """Return the resolved value of ``key`` (a number or a tuple of numbers)."""
        if key in self._cache:
            return self._cache[key]
        if key in self._busy:
            raise WorldFileError(f"{self.source}: value {key!r} is defined through itself")
        self._busy.add(key)
        try:
            if key.startswith("tool."):
                name = key[5:]
                if name not in self.tool:
                    raise WorldFileError(f"{self.source}: {key!r}: the tool has no such "
                                         f"quantity (it has {', '.join(self.tool) or 'none'})")
                raw = self.tool[name]
            elif "." in key:
                body, _, name = key.partition(".")
                if body not in self.bodies or name not in self.bodies[body]:
                    raise WorldFileError(f"{self.source}: {key!r}: no such body field")
                raw = self.bodies[body][name]
            elif key in self.values:
                raw = self.values[key]
            else:
                raise WorldFileError(f"{self.source}: {key!r}: no such value in [values]")
            value = self.evaluate(raw, key)
        finally:
            self._busy.discard(key)
        self._cache[key] = value
        return value

    def evaluate(self, raw: Any, where: str) -> Any:
        """Return ``raw`` with every expression string evaluated (lists element-wise)."""
        if isinstance(raw, bool):
            return raw
        if isinstance(raw, (int, float)):
            return float(raw)
        if isinstance(raw, (list, tuple)):
            return tuple(self.evaluate(v, f"{where}[{i}]") for i, v in enumerate(raw))
        if isinstance(raw, str):
            try:
                tree = ast.parse(raw, mode="eval")
            except SyntaxError:
                raise WorldFileError(f"{self.source}: {where}: not an expression: "
                                     f"{raw!r}") from None
            try:
                value = self._node(tree.body, raw, where)
            except WorldFileError as exc:
                raise WorldFileError(f"{exc} (in {where} = {raw!r})") from None
            except (TypeError, ValueError, ZeroDivisionError, OverflowError) as exc:
                raise WorldFileError(f"{self.source}: {where}: {raw!r}: {exc}") from None
            if not isinstance(value, (int, float)) or not math.isfinite(value):
                raise WorldFileError(f"{self.source}: {where}: {raw!r} is not finite")
            return float(value)
        return raw

    def _node(self, node: ast.AST, text: str, where: str) -> Any:
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
                and not isinstance(node.value, bool):
            return node.value
        if isinstance(node, ast.BinOp) and type(node.op) in _BINOPS:
            return _BINOPS[type(node.op)](self._node(node.left, text, where),
                                          self._node(node.right, text, where))
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            v = self._node(node.operand, text, where)
            return -v if isinstance(node.op, ast.USub) else v
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
                and node.func.id in _FUNCTIONS and not node.keywords:
            return _FUNCTIONS[node.func.id](*(self._node(a, text, where) for a in node.args))
        if isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant):
            seq = self._node(node.value, text, where)
            try:
                return seq[node.slice.value]
            except (TypeError, IndexError):
                raise WorldFileError(f"{self.source}: {where}: bad index in {text!r}") from None
        if isinstance(node, ast.Name):
            if node.id == "pi":
                return math.pi
            return self.get(node.id)
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            return self.get(f"{node.value.id}.{node.attr}")
        raise WorldFileError(f"{self.source}: {where}: {text!r} uses something an "
                             "expression cannot (numbers, + - * / **, values, body.field, "
                             "tool.quantity, min max abs sqrt sin cos radians)")


# ------------------------------------------------------------------------ body kinds
REQUIRED = object()
"""Marks a body field without a default."""


EXTENT_M = 10.0
"""The largest size of a body's coordinate or dimension, metres."""

POSITION = (-EXTENT_M, EXTENT_M, "m")
SIZE = (0.0, EXTENT_M, "m")
ANGLE = (-2 * math.pi, 2 * math.pi, "rad")
MASS = (0.0, 1000.0, "kg")
FRICTION = (0.0, 10.0, "(a friction coefficient)")
COLOUR = (0.0, 1.0, "(RGBA)")


class SceneBody:
    """A body of the scene, built in one episode's simulator.

    A kind lists its fields in ``FIELDS`` (``name -> default``, :data:`REQUIRED` for
    none) and their bounds in ``BOUNDS`` (``name -> (low, high, unit)``, each number
    of a vector within them); :meth:`__init__` receives them resolved (numbers,
    tuples, strings) and raises ValueError for a number outside its bounds.
    """

    FIELDS: dict[str, Any] = {}
    BOUNDS: dict[str, tuple[float, float, str]] = {}
    dynamic = False

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        self.name = name
        self.v = dict(values)
        self.id = -1
        for field, (lo, hi, unit) in self.BOUNDS.items():
            value = self.v.get(field)
            for x in value if isinstance(value, tuple) else (value,):
                if isinstance(x, (int, float)) and not isinstance(x, bool) \
                        and not lo <= x <= hi:
                    raise ValueError(f"body {name}: {field} must lie within [{lo:g}, "
                                     f"{hi:g}] {unit}, got {x:g}")

    def __getattr__(self, item: str) -> Any:
        try:
            return self.__dict__["v"][item]
        except KeyError:
            raise AttributeError(item) from None

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

    @property
    def height(self) -> float | None:
        """Return the body's height if known (perception uses it), metres."""
        return None

    @property
    def passage_floor_z(self) -> float:
        """Return the z of the floor of the body's passage along +x, metres: its
        ``floor_z`` (a tube's inner floor, the base under a shelf's plate, a lane's
        surface) unless the kind says otherwise (the top of a standing shelf)."""
        return self.floor_z


class BoxBody(SceneBody):
    """A box: ``size`` (m), frame at its ``centre`` or ``bottom`` face, static if mass 0.

    ``position`` is the frame's (x, y, z); with ``top_z`` it is (x, y) and the box's
    top face is at ``top_z``.
    """

    FIELDS = {"size": REQUIRED, "position": REQUIRED, "top_z": None, "yaw": 0.0,
              "mass": 0.0, "friction": 0.5, "colour": (0.55, 0.45, 0.35, 1.0),
              "frame": "centre"}
    BOUNDS = {"size": SIZE, "position": POSITION, "top_z": POSITION, "yaw": ANGLE,
              "mass": MASS, "friction": FRICTION, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        if self.frame not in ("centre", "bottom"):
            raise ValueError(f"body {name}: frame must be centre or bottom, got {self.frame!r}")
        if len(self.size) != 3 or min(self.size) <= 0:
            raise ValueError(f"body {name}: size must be three positive numbers (m)")
        want = 2 if self.top_z is not None else 3
        if len(self.position) != want:
            raise ValueError(f"body {name}: position must have {want} numbers "
                             f"({'x, y with top_z' if want == 2 else 'x, y, z'})")
        self.dynamic = self.mass > 0

    @property
    def frame_z(self) -> float:
        """Return the z of the body's frame, metres."""
        if self.top_z is None:
            return self.position[2]
        return self.top_z - (self.size[2] / 2 if self.frame == "centre" else self.size[2])

    @property
    def top(self) -> float:
        """Return the z of the top face, metres."""
        if self.top_z is not None:
            return self.top_z
        return self.position[2] + (self.size[2] / 2 if self.frame == "centre" else self.size[2])

    @property
    def height(self) -> float:
        return self.size[2]

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


class TubeBody(SceneBody):
    """A closed tube along +x: five box walls, the top one clear; frame at the mouth."""

    FIELDS = {"mouth_x": REQUIRED, "axis_y": REQUIRED, "floor_z": REQUIRED,
              "length": REQUIRED, "inner_width": REQUIRED, "inner_height": REQUIRED,
              "wall": REQUIRED, "friction": 0.5, "colour": (0.3, 0.6, 0.9, 1.0)}
    BOUNDS = {"mouth_x": POSITION, "axis_y": POSITION, "floor_z": POSITION,
              "length": SIZE, "inner_width": SIZE, "inner_height": SIZE, "wall": SIZE,
              "friction": FRICTION, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("length", "inner_width", "inner_height", "wall"):
            if self.v[f] <= 0:
                raise ValueError(f"body {name}: {f} must be positive, got {self.v[f]}")

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


class ShelfBody(SceneBody):
    """A low shelf: a plate ``inner_height`` m above ``floor_z`` on four corner legs.

    The space under it is a passage along +x like a tube's (frame at the front edge,
    on the axis, on the floor), open at the back and at the sides between the legs:
    ``mouth_x`` is its front edge, ``inner_width`` the room between the legs (the legs,
    ``leg`` m square, stand outside it), ``inner_height`` the clearance under the plate
    (``board`` m thick). The plate collides but is clear (cameras see under it) unless
    ``clear_board`` is false. Facts: ``shelf_front/4`` (front edge's x, the axis's y,
    mid-clearance z), ``shelf_depth_m/2``, ``shelf_clearance_m/3`` (width, height).
    """

    FIELDS = {"mouth_x": REQUIRED, "axis_y": REQUIRED, "floor_z": REQUIRED,
              "depth": REQUIRED, "inner_width": REQUIRED, "inner_height": REQUIRED,
              "board": 0.006, "leg": 0.012, "friction": 0.5, "clear_board": True,
              "colour": (0.6, 0.5, 0.35, 1.0)}
    BOUNDS = {"mouth_x": POSITION, "axis_y": POSITION, "floor_z": POSITION,
              "depth": SIZE, "inner_width": SIZE, "inner_height": SIZE, "board": SIZE,
              "leg": SIZE, "friction": FRICTION, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("depth", "inner_width", "inner_height", "board", "leg"):
            if self.v[f] <= 0:
                raise ValueError(f"body {name}: {f} must be positive, got {self.v[f]}")

    @property
    def length(self) -> float:
        """Return the passage's length along +x (the shelf's depth), metres."""
        return self.depth

    @property
    def wall(self) -> float:
        """Return the plate's thickness, metres."""
        return self.board

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


class DoorBody(SceneBody):
    """A door panel on a revolute hinge about +z, with a holder and a closer.

    Angles in radians, 0 = closed (the frame's stop), opening counter-clockwise seen
    from above; ``closed_heading`` is the world yaw of hinge -> free edge when closed.
    The holder (a position motor of ``hold_force`` N m) keeps the door at
    ``open_angle`` and swings it at ``swing_speed`` rad/s; once released, the closer
    applies ``closing_torque`` N m towards closed.
    """

    FIELDS = {"hinge": REQUIRED, "closed_heading": REQUIRED, "width": REQUIRED,
              "thickness": REQUIRED, "height": REQUIRED, "bottom_gap": REQUIRED,
              "floor_z": REQUIRED, "mass": REQUIRED, "damping": 0.0, "friction": 0.5,
              "open_angle": REQUIRED, "max_angle": math.radians(170),
              "swing_speed": 1.0, "hold_force": 200.0, "closing_torque": 0.0,
              "colour": (0.75, 0.7, 0.6, 1.0)}
    BOUNDS = {"hinge": POSITION, "closed_heading": ANGLE, "width": SIZE,
              "thickness": SIZE, "height": SIZE, "bottom_gap": SIZE, "floor_z": POSITION,
              "mass": MASS, "damping": (0.0, 1e4, "N m s/rad"), "friction": FRICTION,
              "open_angle": (0.0, 2 * math.pi, "rad"), "max_angle": (0.0, 2 * math.pi, "rad"),
              "swing_speed": (1e-3, 100.0, "rad/s"), "hold_force": (0.0, 1e6, "N m"),
              "closing_torque": (0.0, 1e4, "N m"), "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("width", "thickness", "height", "mass"):
            if self.v[f] <= 0:
                raise ValueError(f"body {name}: {f} must be positive, got {self.v[f]}")
        if not 0.0 < self.open_angle < self.max_angle:
            raise ValueError(f"body {name}: open_angle must lie in (0, max_angle) rad, "
                             f"got {self.open_angle}")
        self.target = self.open_angle
        self.released = False

    @property
    def height(self) -> float:
        return self.v["height"]

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


class SphereBody(SceneBody):
    """A ball of ``radius`` (m), frame at its centre ``position``; static if mass 0.

    ``rolling_friction``, ``linear_damping`` and ``angular_damping`` are pybullet's
    (defaults: none, 0.04, 0.04), so that a world states what its ball does once pushed.
    """

    FIELDS = {"radius": REQUIRED, "position": REQUIRED, "mass": 0.0, "friction": 0.5,
              "rolling_friction": 0.0, "linear_damping": 0.04, "angular_damping": 0.04,
              "colour": (0.9, 0.1, 0.1, 1.0)}
    BOUNDS = {"radius": SIZE, "position": POSITION, "mass": MASS, "friction": FRICTION,
              "rolling_friction": FRICTION, "linear_damping": (0.0, 1.0, "(pybullet's)"),
              "angular_damping": (0.0, 1.0, "(pybullet's)"), "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        if self.radius <= 0:
            raise ValueError(f"body {name}: radius must be positive, got {self.radius}")
        if len(self.position) != 3:
            raise ValueError(f"body {name}: position must have 3 numbers (x, y, z)")
        self.dynamic = self.mass > 0

    @property
    def height(self) -> float:
        return 2 * self.radius

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


class ZoneBody(SceneBody):
    """A goal disc on the table: ``radius`` (m) about (``x``, ``y``), drawn at ``z``; it
    does not collide. Facts: ``reach_zone(Name, X, Y, R)``."""

    FIELDS = {"x": REQUIRED, "y": REQUIRED, "z": 0.0, "radius": REQUIRED,
              "colour": (0.1, 0.8, 0.2, 0.5)}
    BOUNDS = {"x": POSITION, "y": POSITION, "z": POSITION, "radius": SIZE,
              "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        if self.radius <= 0:
            raise ValueError(f"body {name}: radius must be positive, got {self.radius}")

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


class ScatterBody(SceneBody):
    """``count`` cubes drawn at random without overlap in a rectangle of the table.

    Each cube's centre is drawn uniformly in ``x_range`` x ``y_range`` (m) and kept if
    it lies farther than ``min_gap`` (m, in the plane) from every cube kept before; a
    cube gets at most ``tries`` draws (a drawing that cannot be finished is an error
    naming the body). The generator is :func:`numpy.random.default_rng` of ``seed``
    (rounded to a whole number): the same seed, the same cubes. The cubes (``size`` m,
    ``mass`` kg each, ``friction``) rest on ``floor_z`` and are boxes of their own
    (:meth:`members`), named ``<name>1`` ...; the scatter itself builds nothing.
    """

    FIELDS = {"count": REQUIRED, "size": REQUIRED, "x_range": REQUIRED, "y_range": REQUIRED,
              "floor_z": REQUIRED, "min_gap": REQUIRED, "seed": REQUIRED, "tries": 100,
              "mass": 1.0, "friction": 0.5, "colour": (0.85, 0.8, 0.7, 1.0)}
    BOUNDS = {"count": (1, 100, "(a count)"), "size": SIZE, "x_range": POSITION,
              "y_range": POSITION, "floor_z": POSITION, "min_gap": SIZE,
              "seed": (0, 1e9, "(a seed)"), "tries": (1, 10000, "draws"), "mass": MASS,
              "friction": FRICTION, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("x_range", "y_range"):
            r = self.v[f]
            if len(r) != 2 or not r[0] < r[1]:
                raise ValueError(f"body {name}: {f} must be [low, high] with low < high")
        if self.size <= 0 or int(self.count) != self.count:
            raise ValueError(f"body {name}: count must be a whole number and size positive")
        self.centres = self._draw()
        self._members = {f"{name}{i + 1}": BoxBody(f"{name}{i + 1}", {
            "size": (self.size,) * 3, "position": (x, y, self.floor_z), "top_z": None,
            "yaw": 0.0, "mass": self.mass, "friction": self.friction,
            "colour": tuple(self.colour), "frame": "bottom"})
            for i, (x, y) in enumerate(self.centres)}

    def _draw(self) -> list[tuple[float, float]]:
        """Return the cubes' centres (x, y), drawn as the class docstring says."""
        import numpy as np

        rng = np.random.default_rng(int(round(self.seed)))
        kept: list[tuple[float, float]] = []
        for i in range(int(self.count)):
            for _ in range(int(self.tries)):
                x = float(rng.uniform(*self.x_range))
                y = float(rng.uniform(*self.y_range))
                if all(math.dist((x, y), c) > self.min_gap for c in kept):
                    kept.append((x, y))
                    break
            else:
                raise ValueError(f"body {self.name}: cube {i + 1} found no place "
                                 f"{self.min_gap:g} m from the others in {int(self.tries)} "
                                 f"draws (seed {int(round(self.seed))})")
        return kept

    def members(self) -> dict[str, SceneBody]:
        """Return the cubes, ``name -> box body``, in the order they were drawn."""
        return dict(self._members)

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

    @property
    def height(self) -> float:
        return self.size

    def facts(self, sim: Sim) -> list[tuple]:
        x0, x1, y0, y1 = self.extent(sim)
        s = self.size
        return [("pose", self.name, (x0 + x1) / 2, (y0 + y1) / 2, self.floor_z + s / 2, 0.0),
                ("size", self.name, x1 - x0 + s, y1 - y0 + s, s)]


class LaneBody(SceneBody):
    """An open lane along +x on a surface: the room a tool works in, with no walls.

    Nothing collides: the lane only says where the work happens, like a tube's or a
    shelf's passage (frame at its near end ``mouth_x``, on its axis ``axis_y``, on the
    surface ``floor_z``; ``length`` along +x, ``inner_width`` across, ``inner_height``
    the room above the surface), and where the target should end, ``goal_x`` on the
    axis, drawn as a flat square mark of side ``mark`` m (visual only). Facts:
    ``lane_start/4`` (near end's x, the axis's y, mid-room z), ``lane_length_m/2``,
    ``lane_room_m/3`` (width, height), ``lane_goal/3`` (the goal's x, y).
    """

    FIELDS = {"mouth_x": REQUIRED, "axis_y": REQUIRED, "floor_z": REQUIRED,
              "length": REQUIRED, "inner_width": REQUIRED, "inner_height": REQUIRED,
              "goal_x": REQUIRED, "mark": 0.07, "colour": (0.2, 0.8, 0.2, 0.5)}
    BOUNDS = {"mouth_x": POSITION, "axis_y": POSITION, "floor_z": POSITION,
              "length": SIZE, "inner_width": SIZE, "inner_height": SIZE,
              "goal_x": POSITION, "mark": SIZE, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("length", "inner_width", "inner_height", "mark"):
            if self.v[f] <= 0:
                raise ValueError(f"body {name}: {f} must be positive, got {self.v[f]}")

    @property
    def wall(self) -> float:
        """Return the thickness above the room (none: the lane is open), metres."""
        return 0.0

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


class StandingShelfBody(SceneBody):
    """A tall shelf on the floor: a top plate on four round posts and two base runners.

    The plate (``depth`` m along x, ``width`` m along y, ``board`` m thick) has its top
    face at ``top_z`` and its front edge (the robot's side) at ``front_x``, centred on
    ``axis_y``. The posts (``post_radius``) stand ``post_inset`` m inside the plate's
    front and back edges and ``post_side_inset`` m inside its sides, from ``floor_z`` up
    to the plate; the runners (``runner_width`` along x, ``runner_height`` high) join
    the posts' feet along y. The room above the top, ``room`` m high, is a passage
    along +x like a tube's (frame at the front edge, on the axis, on the top face):
    ``mouth_x``, ``floor_z`` of the passage and ``inner_width``, ``inner_height`` are
    those of that room. Facts: ``shelf_top/4`` (front edge's x, the axis's y, the top's
    z), ``shelf_top_depth_m/2``.
    """

    FIELDS = {"front_x": REQUIRED, "axis_y": REQUIRED, "top_z": REQUIRED,
              "floor_z": REQUIRED, "depth": REQUIRED, "width": REQUIRED,
              "board": REQUIRED, "post_radius": REQUIRED, "post_inset": REQUIRED,
              "post_side_inset": REQUIRED, "runner_width": REQUIRED,
              "runner_height": REQUIRED, "room": 0.30, "friction": 0.5,
              "colour": (0.8, 0.8, 0.8, 1.0)}
    BOUNDS = {"front_x": POSITION, "axis_y": POSITION, "top_z": POSITION,
              "floor_z": POSITION, "depth": SIZE, "width": SIZE, "board": SIZE,
              "post_radius": SIZE, "post_inset": SIZE, "post_side_inset": SIZE,
              "runner_width": SIZE, "runner_height": SIZE, "room": SIZE,
              "friction": FRICTION, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("depth", "width", "board", "post_radius", "room"):
            if self.v[f] <= 0:
                raise ValueError(f"body {name}: {f} must be positive, got {self.v[f]}")
        if self.top_z - self.board <= self.floor_z:
            raise ValueError(f"body {name}: top_z must lie more than board above floor_z")

    # The passage above the top, as insert_at_pose reads a context.
    @property
    def mouth_x(self) -> float:
        """Return the front edge's x, metres."""
        return self.front_x

    @property
    def length(self) -> float:
        """Return the passage's length along +x (the plate's depth), metres."""
        return self.depth

    @property
    def inner_width(self) -> float:
        """Return the passage's width (the plate's), metres."""
        return self.width

    @property
    def inner_height(self) -> float:
        """Return the room above the top, metres."""
        return self.room

    @property
    def passage_floor_z(self) -> float:
        """Return the top face's z, metres."""
        return self.top_z

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


class OpenBoxBody(SceneBody):
    """A fixed box open at the top: a floor panel and four walls, ``wall`` m thick.

    ``position`` is the (x, y) of its middle, ``floor_z`` the underside of its floor
    panel, ``size`` its outer extent (x, y, height). Facts: ``open_box_rim/4`` (the
    centre's x, y and the rim's z), ``open_box_inner_m/5`` (inner x and y extent, the
    floor's top z, the rim's z).
    """

    FIELDS = {"position": REQUIRED, "floor_z": REQUIRED, "size": REQUIRED,
              "wall": REQUIRED, "friction": 0.5, "colour": (0.96, 0.87, 0.70, 1.0)}
    BOUNDS = {"position": POSITION, "floor_z": POSITION, "size": SIZE, "wall": SIZE,
              "friction": FRICTION, "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        if len(self.position) != 2 or len(self.size) != 3 or min(self.size) <= 0:
            raise ValueError(f"body {name}: position must be (x, y), size three positive "
                             "numbers (m)")
        if not 0 < 2 * self.wall < min(self.size[:2]) or self.wall >= self.size[2]:
            raise ValueError(f"body {name}: wall must be positive and thinner than the box")

    @property
    def height(self) -> float:
        return self.size[2]

    @property
    def top(self) -> float:
        """Return the rim's z, metres."""
        return self.floor_z + self.size[2]

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


class BookendsBody(SceneBody):
    """Two fixed L-shaped bookends facing each other across a row of books.

    Each is a base plate (``depth`` m along x, ``plate_width`` m along y, ``plate``
    m thick, on ``floor_z``) under the row's end and an upright (``thickness`` m, from
    the plate up to ``height``) outside it; ``left_y`` and ``right_y`` are the inner
    faces of the uprights (left < right), ``centre_x`` the row's middle along x. The
    room above the plates between the uprights, ``room`` m high (above the books,
    whatever the uprights' height), is a passage along +x from the row's front
    (``mouth_x``; the passage's floor is the plates' top): a tool is carried over the
    books in it. Facts: ``bookends_front/4`` (the front's x, the
    middle's y, the plates' top z), ``bookends_room_m/4`` (the room between the
    uprights, its height above the plates, the depth along x).
    """

    FIELDS = {"centre_x": REQUIRED, "left_y": REQUIRED, "right_y": REQUIRED,
              "floor_z": REQUIRED, "depth": REQUIRED, "height": REQUIRED,
              "plate": REQUIRED, "plate_width": REQUIRED, "thickness": REQUIRED,
              "room": REQUIRED, "friction": 0.5, "colour": (0.35, 0.35, 0.4, 1.0)}
    BOUNDS = {"centre_x": POSITION, "left_y": POSITION, "right_y": POSITION,
              "floor_z": POSITION, "depth": SIZE, "height": SIZE, "plate": SIZE,
              "plate_width": SIZE, "thickness": SIZE, "room": SIZE, "friction": FRICTION,
              "colour": COLOUR}

    def __init__(self, name: str, values: Mapping[str, Any]) -> None:
        super().__init__(name, values)
        for f in ("depth", "height", "plate", "plate_width", "thickness", "room"):
            if self.v[f] <= 0:
                raise ValueError(f"body {name}: {f} must be positive, got {self.v[f]}")
        if self.right_y <= self.left_y:
            raise ValueError(f"body {name}: right_y must be greater than left_y")

    @property
    def mouth_x(self) -> float:
        """Return the row's front (its smallest x), metres."""
        return self.centre_x - self.depth / 2

    @property
    def axis_y(self) -> float:
        """Return the middle between the uprights, metres."""
        return (self.left_y + self.right_y) / 2

    @property
    def inner_width(self) -> float:
        """Return the room between the uprights, metres."""
        return self.right_y - self.left_y

    @property
    def inner_height(self) -> float:
        """Return the room's height above the plates (``room``), metres."""
        return self.room

    @property
    def passage_floor_z(self) -> float:
        """Return the plates' top z, metres."""
        return self.floor_z + self.plate

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


BODY_KINDS: dict[str, type[SceneBody]] = {"box": BoxBody, "tube": TubeBody, "shelf": ShelfBody,
                                          "door": DoorBody, "lane": LaneBody,
                                          "sphere": SphereBody, "zone": ZoneBody,
                                          "scatter": ScatterBody,
                                          "standing_shelf": StandingShelfBody,
                                          "open_box": OpenBoxBody, "bookends": BookendsBody}
"""The body kinds a ``[[body]]`` table may name."""


@dataclass(frozen=True)
class BodyTable:
    """One ``[[body]]`` table as written: name, kind and raw fields."""

    name: str
    kind: str
    fields: dict[str, Any]
    where: str


def read_bodies(tables: list[Fields]) -> tuple[BodyTable, ...]:
    """Read the ``[[body]]`` tables; errors name the file and the field."""
    out: list[BodyTable] = []
    for bf in tables:
        name = bf.str("name")
        kind = bf.str("kind", choices=tuple(BODY_KINDS))
        schema = BODY_KINDS[kind].FIELDS
        raw: dict[str, Any] = {}
        for fname, default in schema.items():
            if default is REQUIRED:
                raw[fname] = bf.raw(fname)
            else:
                raw[fname] = bf.raw(fname, default)
        bf.done()
        if any(b.name == name for b in out):
            raise bf.error("name", f"body name {name!r} is used twice")
        out.append(BodyTable(name, kind, raw, f"{bf.source}: {bf.prefix}"))
    return tuple(out)


def make_bodies(tables: tuple[BodyTable, ...], ns: Namespace) -> dict[str, SceneBody]:
    """Return ``name -> SceneBody`` with every field resolved in ``ns`` (nothing built)."""
    bodies: dict[str, SceneBody] = {}
    for t in tables:
        schema = BODY_KINDS[t.kind].FIELDS
        values = {}
        for fname, raw in t.fields.items():
            text_field = isinstance(schema[fname], str)
            values[fname] = raw if text_field else ns.get(f"{t.name}.{fname}")
        try:
            bodies[t.name] = BODY_KINDS[t.kind](t.name, values)
        except (ValueError, TypeError) as exc:
            raise WorldFileError(f"{t.where}: {exc}") from None
        members = getattr(bodies[t.name], "members", None)
        for member, body in (members() if callable(members) else {}).items():
            if member in bodies or any(o.name == member for o in tables):
                raise WorldFileError(f"{t.where}: its member {member!r} has the name of "
                                     "another body")
            bodies[member] = body
    return bodies
