"""The body kinds of a scene's ``[[body]]`` tables: their fields, bounds and geometry.

Each ``[[body]]`` of ``scene.toml`` names a kind of :data:`BODY_KINDS` and gives its
fields (numbers may be expressions, :mod:`creative_py.world.expressions`). A kind
here is the schema: its fields and their defaults, their bounds, the checks of its
values and the geometry derived from them; a backend builds it (the pybullet
backend's builders, :mod:`creative_py.backends.pybullet.scene`, subclass these).

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

import math
from dataclasses import dataclass
from typing import Any, Mapping

from creative_py.world.expressions import Namespace
from creative_py.world_files import Fields, WorldFileError

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


class BodyKind:
    """A kind of body of the scene: its fields, their bounds and its derived geometry.

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


class BoxKind(BodyKind):
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


class TubeKind(BodyKind):
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


class ShelfKind(BodyKind):
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


class DoorKind(BodyKind):
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


class SphereKind(BodyKind):
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


class ZoneKind(BodyKind):
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


class ScatterKind(BodyKind):
    """``count`` cubes drawn at random without overlap in a rectangle of the table.

    Each cube's centre is drawn uniformly in ``x_range`` x ``y_range`` (m) and kept if
    it lies farther than ``min_gap`` (m, in the plane) from every cube kept before; a
    cube gets at most ``tries`` draws (a drawing that cannot be finished is an error
    naming the body). The generator is :func:`numpy.random.default_rng` of ``seed``
    (rounded to a whole number): the same seed, the same cubes. The cubes (``size`` m,
    ``mass`` kg each, ``friction``) rest on ``floor_z`` and are boxes of their own
    (:meth:`members`), named ``<name>1`` ...; the scatter itself builds nothing.
    """

    MEMBER: type[BoxKind] = BoxKind
    """The kind of the cubes (a backend's builder of boxes, in its subclass)."""

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
        self._members = {f"{name}{i + 1}": self.MEMBER(f"{name}{i + 1}", {
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

    def members(self) -> dict[str, BodyKind]:
        """Return the cubes, ``name -> box body``, in the order they were drawn."""
        return dict(self._members)

    @property
    def height(self) -> float:
        return self.size


class LaneKind(BodyKind):
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


class StandingShelfKind(BodyKind):
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


class OpenBoxKind(BodyKind):
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


class BookendsKind(BodyKind):
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


BODY_KINDS: dict[str, type[BodyKind]] = {
    "box": BoxKind,
    "tube": TubeKind,
    "shelf": ShelfKind,
    "door": DoorKind,
    "lane": LaneKind,
    "sphere": SphereKind,
    "zone": ZoneKind,
    "scatter": ScatterKind,
    "standing_shelf": StandingShelfKind,
    "open_box": OpenBoxKind,
    "bookends": BookendsKind,
}
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


def resolve_bodies(tables: tuple[BodyTable, ...], ns: Namespace,
                   kinds: Mapping[str, type[BodyKind]] = BODY_KINDS) -> dict[str, BodyKind]:
    """Return ``name -> body`` of ``kinds`` (default: the schemas, :data:`BODY_KINDS`;
    a backend passes its builders, keyed alike) with every field resolved in ``ns``
    (nothing built)."""
    bodies: dict[str, BodyKind] = {}
    for t in tables:
        schema = kinds[t.kind].FIELDS
        values = {}
        for fname, raw in t.fields.items():
            text_field = isinstance(schema[fname], str)
            values[fname] = raw if text_field else ns.get(f"{t.name}.{fname}")
        try:
            bodies[t.name] = kinds[t.kind](t.name, values)
        except (ValueError, TypeError) as exc:
            raise WorldFileError(f"{t.where}: {exc}") from None
        members = getattr(bodies[t.name], "members", None)
        for member, body in (members() if callable(members) else {}).items():
            if member in bodies or any(o.name == member for o in tables):
                raise WorldFileError(f"{t.where}: its member {member!r} has the name of "
                                     "another body")
            bodies[member] = body
    return bodies
