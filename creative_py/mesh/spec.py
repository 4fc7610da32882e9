"""Parametric tool specs and the solid parts they are made of.

One definition of a hook or a wedge serves the simulator (pybullet collision shapes),
the exporters (URDF, SDF, OpenSCAD, STL) and the ontology (structural facts).
This module is pure Python: no numpy, no pybullet, no trimesh.

Frames and units
----------------
All lengths are metres, masses kilograms, angles radians unless a name says ``_deg``.

*Hook-like tool frame*: the handle lies along +x from its butt end (x = 0) to its tip
(x = ``handle_length``), centred on the x axis. The prong (the hook) sits at the tip and
extends sideways in the tool's xy plane: towards +y for ``hook_side == "left"`` and -y
for ``"right"`` (seen from above with the handle pointing away from the viewer, +y is
on the left). ``hook_angle_deg`` is the angle between the handle axis and the prong
(90: perpendicular; smaller leans the prong back towards the grip). A ``stick`` has no
prong. The robot grips the handle at ``grip_point``.

*Block frame* (wedges, boxes, cylinders): the base lies on z = 0, centred on the origin
in x and y. A triangular prism runs along x with its thin edge (the tip) at
x = +length/2 and its back face, of height ``height``, at x = -length/2; ``width`` is its
lateral extent along y. A prism may be blunted: ``tip_height`` is the height of a
vertical flat at its tip (0, the default, is a knife edge), so that in side view it is a
trapezoid with parallel sides ``height`` (back) and ``tip_height`` (tip). A box is
length x width x height. A cylinder stands upright with
diameter ``length`` and height ``height`` (``width`` must equal ``length``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Literal, Union

HookSide = Literal["left", "right", "none"]
BlockShape = Literal["triangular_prism", "box", "cylinder"]

PLA_DENSITY = 1240.0  # kg/m^3, printed PLA at 100 % infill
"""The density of every printed tool (a spec with ``mass=None``: every created tool, in
runs and in ``make-tool``) and of the slicer's filament; the one density of the project."""

PLA_STRENGTH = 50.0e6  # Pa
"""Strength of printed PLA that the strength check (:mod:`creative_py.learning.strength`)
holds a tool's stress against, pascals: the tensile (and flexural) strength of PLA
printed at 100 % infill with its layers along the load, 50-60 MPa in the filament makers'
datasheets and in tests of FDM coupons; we take the low end. A hook or stick prints lying
flat, so its handle's bending stress runs along the extruded lines. PLA's compressive
strength is higher; the block's compression check uses this value too (conservative)."""

MIN_SAFETY_FACTOR = 2.0
"""The least ratio of :data:`PLA_STRENGTH` to a created tool's estimated stress that the
strength check accepts."""


@dataclass(frozen=True)
class Box:
    """An axis-aligned box in the tool frame, rotated by ``yaw`` about its centre's z."""

    center: tuple[float, float, float]
    size: tuple[float, float, float]
    yaw: float = 0.0

    @property
    def volume(self) -> float:
        """Return the volume in m^3."""
        return self.size[0] * self.size[1] * self.size[2]


@dataclass(frozen=True)
class Hull:
    """A convex polyhedron given by its vertices (tool frame).

    ``centroid`` is its centre of volume (metres); None means the mean of the vertices
    (exact for a triangular prism, not for a trapezoidal one).
    """

    vertices: tuple[tuple[float, float, float], ...]
    volume: float
    centroid: tuple[float, float, float] | None = None


@dataclass(frozen=True)
class Cylinder:
    """An upright cylinder (axis along z) with its base centre at ``center`` - h/2."""

    center: tuple[float, float, float]
    radius: float
    height: float

    @property
    def volume(self) -> float:
        """Return the volume in m^3."""
        return math.pi * self.radius**2 * self.height


Part = Union[Box, Hull, Cylinder]


@dataclass(frozen=True)
class HookSpec:
    """A hook-like tool: a square handle with an optional prong at its tip.

    Parameters
    ----------
    name : str
        Unique object name (a Prolog atom: lower case, digits and underscores).
    handle_length : float
        Length of the handle along +x, metres.
    handle_width : float
        Side of the handle's square cross-section, metres.
    hook_length : float
        How far the prong reaches beyond the handle's side, metres (0 for a stick).
    hook_width : float
        Thickness of the prong along the handle axis, metres.
    hook_side : {"left", "right", "none"}
        Side the prong points to; "none" for a stick.
    hook_angle_deg : float
        Angle between handle and prong, degrees.
    grip_offset : float
        Distance of the grip point from the butt end along +x, metres.
    mass : float or None
        Total mass in kg; None means PLA density times volume (every created tool).
        The default, 0.1 kg, is that of a catalogued object whose ``objects.toml``
        table gives no mass (the world's objects, not printed).
    """

    name: str
    handle_length: float
    handle_width: float = 0.01
    hook_length: float = 0.03
    hook_width: float = 0.01
    hook_side: HookSide = "right"
    hook_angle_deg: float = 90.0
    grip_offset: float = 0.04
    mass: float | None = 0.1
    kind: Literal["hook"] = field(default="hook", init=False)

    def __post_init__(self) -> None:
        _check_name(self.name)
        _check_positive(self, "handle_length", "handle_width")
        _check_mass(self)
        if self.hook_side == "none":
            if self.hook_length != 0.0:
                raise ValueError(f"{self.name}: a stick (hook_side 'none') has hook_length 0")
        else:
            if self.hook_side not in ("left", "right"):
                raise ValueError(f"{self.name}: hook_side must be left, right or none")
            _check_positive(self, "hook_length", "hook_width")
            if not 30.0 <= self.hook_angle_deg <= 150.0:
                raise ValueError(f"{self.name}: hook_angle_deg must lie in [30, 150]")
        if not 0.0 <= self.grip_offset < self.handle_length:
            raise ValueError(f"{self.name}: grip_offset must lie on the handle")

    @property
    def is_stick(self) -> bool:
        """Return whether the tool has no prong."""
        return self.hook_side == "none"

    @property
    def grip_point(self) -> tuple[float, float, float]:
        """Return the grip point in the tool frame, metres."""
        return (self.grip_offset, 0.0, 0.0)

    @property
    def tip_point(self) -> tuple[float, float, float]:
        """Return the centre of the prong's free end (or the handle tip), tool frame."""
        if self.is_stick:
            return (self.handle_length, 0.0, 0.0)
        sign = 1.0 if self.hook_side == "left" else -1.0
        a = math.radians(self.hook_angle_deg)
        reach = self.handle_width / 2 + self.hook_length
        x = self.handle_length - self.hook_width / 2 - reach * math.cos(a)
        return (x, sign * reach * math.sin(a), 0.0)

    def parts(self) -> list[Part]:
        """Return the solid parts (handle box and prong box) in the tool frame."""
        w = self.handle_width
        handle = Box((self.handle_length / 2, 0.0, 0.0), (self.handle_length, w, w))
        if self.is_stick:
            return [handle]
        sign = 1.0 if self.hook_side == "left" else -1.0
        a = math.radians(self.hook_angle_deg)
        # The prong box runs from the handle's axis out to its reach, so that it
        # overlaps the handle and the union is one solid.
        span = w / 2 + self.hook_length
        cx = self.handle_length - self.hook_width / 2 - (span / 2) * math.cos(a)
        cy = sign * (span / 2) * math.sin(a)
        prong = Box((cx, cy, 0.0), (self.hook_width, span, w), yaw=sign * (math.pi / 2 - a))
        return [handle, prong]


@dataclass(frozen=True)
class BlockSpec:
    """A simple block used as a doorstop candidate: prism, box or cylinder.

    Parameters
    ----------
    name : str
        Unique object name (a Prolog atom).
    shape : {"triangular_prism", "box", "cylinder"}
        The block's shape.
    length : float
        Extent along x (the run of a prism; a cylinder's diameter), metres.
    width : float
        Lateral extent along y, metres.
    height : float
        Extent along z (the back height of a prism), metres.
    mass : float or None
        Mass in kg; None means PLA density times volume (every created tool). The
        default, 0.1 kg, is that of a catalogued object whose table gives no mass.
    tip_height : float
        A prism's height at its tip (x = +length/2), metres: 0 is a knife edge, a
        positive value a blunted tip (a flat that a printer can lay down), below
        ``height``. A box or a cylinder has no tip (0).
    """

    name: str
    shape: BlockShape
    length: float
    width: float
    height: float
    mass: float | None = 0.1
    tip_height: float = 0.0
    kind: Literal["block"] = field(default="block", init=False)

    def __post_init__(self) -> None:
        _check_name(self.name)
        if self.shape not in ("triangular_prism", "box", "cylinder"):
            raise ValueError(f"{self.name}: shape must be triangular_prism, box or cylinder")
        _check_positive(self, "length", "width", "height")
        _check_mass(self)
        if self.shape == "cylinder" and abs(self.width - self.length) > 1e-9:
            raise ValueError(f"{self.name}: a cylinder's width must equal its length (diameter)")
        t = self.tip_height
        if not (isinstance(t, (int, float)) and math.isfinite(t) and t >= 0):
            raise ValueError(f"{self.name}: tip_height must be a number of metres >= 0, "
                             f"got {t!r}")
        if self.shape == "triangular_prism" and not t < self.height:
            raise ValueError(f"{self.name}: tip_height ({t:g} m) must be below the prism's "
                             f"height ({self.height:g} m)")
        if self.shape != "triangular_prism" and t != 0:
            raise ValueError(f"{self.name}: a {self.shape} has no tip; tip_height must be 0")

    @property
    def slope_ratio(self) -> float:
        """Return length / height, the wedge's mechanical advantage (dimensionless)."""
        return self.length / self.height

    def parts(self) -> list[Part]:
        """Return the solid part in the block frame."""
        L, W, H = self.length, self.width, self.height
        if self.shape == "box":
            return [Box((0.0, 0.0, H / 2), (L, W, H))]
        if self.shape == "cylinder":
            return [Cylinder((0.0, 0.0, H / 2), L / 2, H)]
        T = self.tip_height
        verts = []
        for y in (-W / 2, W / 2):
            verts += [(-L / 2, y, 0.0), (L / 2, y, 0.0), (-L / 2, y, H)]
            if T > 0:
                verts.append((L / 2, y, T))
        if T == 0:
            return [Hull(tuple(verts), volume=0.5 * L * H * W)]
        # The trapezoid's centroid: x from the back face, z above the base.
        x = L * (H + 2 * T) / (3 * (H + T))
        z = (H * H + H * T + T * T) / (3 * (H + T))
        return [Hull(tuple(verts), volume=0.5 * L * (H + T) * W, centroid=(x - L / 2, 0.0, z))]


ToolSpec = Union[HookSpec, BlockSpec]


def spec_volume(spec: ToolSpec) -> float:
    """Return the solid volume of a spec in m^3 (overlaps of hook parts counted once)."""
    parts = spec.parts()
    vol = sum(p.volume for p in parts)
    if isinstance(spec, HookSpec) and not spec.is_stick:
        # The prong box (same z extent as the handle) overlaps the handle; at angles
        # other than 90 degrees the overlap is not a plain half-width block, so clip
        # the prong's footprint by the handle's rectangle.
        handle, prong = parts
        w = spec.handle_width
        vol -= w * _footprint_overlap_area(prong, (0.0, spec.handle_length), (-w / 2, w / 2))
    return vol


def spec_mass(spec: ToolSpec) -> float:
    """Return the mass in kg: the spec's own, or PLA density times volume."""
    return spec.mass if spec.mass is not None else PLA_DENSITY * spec_volume(spec)


SPEC_KINDS: dict[str, type] = {"hook": HookSpec, "stick": HookSpec, "block": BlockSpec}
"""The tool kinds a spec can have (the ``kind`` field), each with its spec class; a
kind's name is also the ontology's class literal of a tool of that kind (``hook(T)``)."""


def spec_from_dict(data: dict, *, source: str = "<dict>") -> ToolSpec:
    """Build a spec from a TOML table; errors name ``source`` and the offending field."""
    data = dict(data)
    kind = data.pop("kind", None)
    cls = SPEC_KINDS.get(kind)
    if cls is None:
        raise ValueError(f"{source}: object {data.get('name', '?')!r}: field 'kind' must be "
                         f"hook, stick or block, got {kind!r}")
    if kind == "stick":
        data.setdefault("hook_side", "none")
        data.setdefault("hook_length", 0.0)
    known = {f for f in cls.__dataclass_fields__ if f != "kind"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise ValueError(f"{source}: object {data.get('name', '?')!r}: unknown field(s) "
                         f"{', '.join(unknown)}; expected some of {', '.join(sorted(known))}")
    try:
        return cls(**data)
    except TypeError as exc:
        raise ValueError(f"{source}: object {data.get('name', '?')!r}: {exc}") from None
    except ValueError as exc:
        raise ValueError(f"{source}: {exc}") from None


def _check_mass(spec) -> None:
    # A zero mass would make pybullet treat the tool as static.
    m = spec.mass
    if m is not None and not (isinstance(m, (int, float)) and math.isfinite(m) and m > 0):
        raise ValueError(f"{spec.name}: mass must be a positive number of kg or None, got {m!r}")


def _footprint_overlap_area(box: Box, xs: tuple[float, float],
                            ys: tuple[float, float]) -> float:
    """Return the area (m^2) of a yawed box's xy footprint inside the rectangle xs x ys."""
    c, s = math.cos(box.yaw), math.sin(box.yaw)
    hx, hy = box.size[0] / 2, box.size[1] / 2
    poly = [(box.center[0] + c * u - s * v, box.center[1] + s * u + c * v)
            for u, v in ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))]
    # Sutherland-Hodgman: clip by x >= xs[0], x <= xs[1], y >= ys[0], y <= ys[1].
    for axis, bound, keep_above in ((0, xs[0], True), (0, xs[1], False),
                                    (1, ys[0], True), (1, ys[1], False)):
        def inside(p, axis=axis, bound=bound, keep_above=keep_above):
            return p[axis] >= bound if keep_above else p[axis] <= bound
        clipped = []
        for i, cur in enumerate(poly):
            prev = poly[i - 1]
            if inside(cur) != inside(prev):
                t = (bound - prev[axis]) / (cur[axis] - prev[axis])
                clipped.append((prev[0] + t * (cur[0] - prev[0]),
                                prev[1] + t * (cur[1] - prev[1])))
            if inside(cur):
                clipped.append(cur)
        poly = clipped
        if not poly:
            return 0.0
    return 0.5 * abs(sum(poly[i - 1][0] * p[1] - p[0] * poly[i - 1][1]
                         for i, p in enumerate(poly)))


def _check_name(name: str) -> None:
    if not (isinstance(name, str) and name[:1].islower()
            and all(c.isalnum() or c == "_" for c in name) and name.isascii()):
        raise ValueError(f"object name {name!r} must be a Prolog atom: a lower-case letter "
                         "followed by letters, digits or underscores")


def _check_positive(spec, *fields: str) -> None:
    for f in fields:
        v = getattr(spec, f)
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise ValueError(f"{spec.name}: {f} must be a positive number of metres, got {v!r}")
