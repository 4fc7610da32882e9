"""What every tool kind is made of: solid parts, the material, and the kind's interface.

A kind module (:mod:`creative_py.kinds`) describes its tools with the parts below (boxes,
convex hulls, upright cylinders in the tool frame, metres) and a spec class derived from
:class:`KindSpec`; :mod:`creative_py.mesh` and :mod:`creative_py.backends.pybullet` interpret them
generically. This module is pure Python (numbers only): it imports nothing of the
project and no third-party engine.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any, Mapping, Union

PLA_DENSITY = 1240.0  # kg/m^3, printed PLA at 100 % infill
"""The density of every printed tool (a spec with ``mass=None``: every created tool, in
runs and in ``make-tool``) and of the slicer's filament; the one density of the project."""

PLA_STRENGTH = 50.0e6  # Pa
"""Strength of printed PLA that the strength check (:mod:`creative_py.fabrication.strength`)
holds a tool's stress against, pascals: the tensile (and flexural) strength of PLA
printed at 100 % infill with its layers along the load, 50-60 MPa in the filament makers'
datasheets and in tests of FDM coupons; we take the low end. A handled tool prints lying
flat, so its handle's bending stress runs along the extruded lines. PLA's compressive
strength is higher; the block's compression check uses this value too (conservative)."""

MIN_SAFETY_FACTOR = 2.0
"""The least ratio of :data:`PLA_STRENGTH` to a created tool's estimated stress that the
strength check accepts."""

Fact = tuple
"""A catalogue fact: ``(name, object, value, ...)`` (as :data:`creative_py.simulator.types.Fact`)."""


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


class KindSpec:
    """The interface of a tool kind's spec (a frozen dataclass deriving from this).

    Geometry and data only: the mesh writers, the simulator and the strength check ask a
    spec these questions and never test its type. Lengths in metres, angles in degrees
    where a name says ``_deg``, else radians.

    Class attributes a kind sets:

    ``HANDLING``
        How the simulator holds it (:data:`creative_py.backends.pybullet.tools.HANDLINGS`):
        ``"handle"`` (lies on a pedestal, gripped at the butt end of a handle along +x,
        turned about the handle's axis) or ``"top"`` (stands on its base, gripped from
        above).
    ``FACT_FIELDS``
        The spec field behind each numeric catalogue fact (``handle_length_m`` ->
        ``handle_length``): what a randomised world redraws.
    ``RGBA``
        Display colour of its files' pictures and models (red, green, blue, alpha).
    ``DRAWING_PLANE``
        The plane of the dimensioned drawing: ``"top"`` (x-y) or ``"side"`` (x-z).
    """

    HANDLING: str = ""
    FACT_FIELDS: dict[str, str] = {}
    RGBA: tuple[float, float, float, float] = (0.6, 0.6, 0.6, 1.0)
    DRAWING_PLANE: str = "top"

    name: str
    kind: str
    mass: float | None

    # ------------------------------------------------------------- geometry
    def parts(self) -> list[Part]:
        """Return the solid parts in the tool frame."""
        raise NotImplementedError

    def volume(self) -> float:
        """Return the solid volume, m^3 (overlapping parts counted once)."""
        return sum(p.volume for p in self.parts())

    # ---------------------------------------------------------- the catalogue
    def catalogue_facts(self) -> list[Fact]:
        """Return the catalogue facts of the tool (``object_kind`` first; m, deg)."""
        raise NotImplementedError

    def quantities(self) -> dict[str, float]:
        """Return the named sizes that scene expressions may use (``tool.<q>``), metres."""
        return {}

    def redrawn(self, values: Mapping[str, float]) -> "KindSpec":
        """Return the spec with drawn ``values`` of its :attr:`FACT_FIELDS`."""
        return replace(self, **values)  # type: ignore[type-var]

    # ---------------------------------------------------------- manufacturing
    def feature_dimensions(self) -> dict[str, float]:
        """Return the printable dimensions by field name, metres (each at least the
        printer's minimum feature; a field named ``tip_height`` the minimum tip)."""
        raise NotImplementedError

    def thin_tip_length(self, min_tip: float) -> float:
        """Return how far (m) from a tapering tip the tool is thinner than ``min_tip``."""
        return 0.0

    def scad(self, mm, segments: int) -> tuple[str, str, list[str]]:
        """Return the OpenSCAD model: (what the tool is, its frame, the source lines).

        ``mm`` turns metres into the text of a number of millimetres; ``segments`` is the
        number of facets of a circle.
        """
        raise NotImplementedError

    def title(self) -> str:
        """Return the word that names the tool in its picture's title."""
        return self.kind

    def caption_extra(self) -> str:
        """Return what the picture's caption adds after the dimensions."""
        return ""

    # ---------------------------------------------------------------- strength
    def load_model(self, force_n: float, point: tuple | None, grasp: tuple | None, *,
                   strength_pa: float = PLA_STRENGTH,
                   safety_factor: float = MIN_SAFETY_FACTOR) -> dict[str, Any]:
        """Return the stress estimate under the largest contact force of a trial.

        ``point`` and ``grasp`` are the contact and grasp points in the tool frame
        (metres; None when not recorded); the material's strength and the safety
        factor asked for size a handle that would pass. The result holds the
        :class:`~creative_py.fabrication.strength.StrengthCheck` fields ``model``,
        ``lever_arm_m``, ``section_m``, ``area_m2``, ``second_moment_m4``,
        ``section_modulus_m3``, ``moment_nm``, ``stress_pa``, ``grasp_point_m``,
        ``required_handle_width_m`` and ``note``.
        """
        raise NotImplementedError


class SquareBarTool(KindSpec):
    """A kind held by a square bar along +x from its butt end, with its head at the far
    end (a paddle's shaft, a pusher's pole): what the simulator's ``"handle"`` handling
    and the strength check ask of it, from the bar alone.

    Tool frame: the bar runs from the butt end at the origin along +x for its length,
    centred on the x axis, its square section's side its width. A kind names the two
    fields in :attr:`BAR` and has a ``grip_offset`` field (the grip point's distance from
    the butt end along +x, metres).
    """

    HANDLING = "handle"
    BAR: tuple[str, str] = ("", "")
    """The fields of the bar's length and of its section's side (metres)."""

    grip_offset: float

    roll_side = 1.0
    """Roll is measured from the tool frame's +y (the head's side, or either: a symmetric
    head)."""

    has_head = True
    """The head stands out sideways at the bar's far end."""

    @property
    def handle_length(self) -> float:
        """Return the length of what the simulator holds as a handle: the bar, m."""
        return getattr(self, self.BAR[0])

    @property
    def handle_width(self) -> float:
        """Return the side of the held bar's section, m."""
        return getattr(self, self.BAR[1])

    @property
    def grip_point(self) -> tuple[float, float, float]:
        """Return the grip point in the tool frame, metres."""
        return (self.grip_offset, 0.0, 0.0)

    def bar(self) -> Box:
        """Return the bar as a part: its whole length, centred on the x axis."""
        length, width = self.handle_length, self.handle_width
        return Box((length / 2, 0.0, 0.0), (length, width, width))

    def bar_scad(self) -> list[str]:
        """Return the OpenSCAD lines of the bar (inside the model's ``union()``), in the
        variables named after :attr:`BAR`."""
        length, width = self.BAR
        return [f"    translate([0, -{width} / 2, -{width} / 2])",
                f"        cube([{length}, {width}, {width}]);"]

    def load_model(self, force_n: float, point: tuple | None, grasp: tuple | None, *,
                   strength_pa: float = PLA_STRENGTH,
                   safety_factor: float = MIN_SAFETY_FACTOR) -> dict[str, Any]:
        """Return the cantilever model of the square bar from the grasp to the contact
        (:func:`square_handle_load`; the head is shorter and no thinner, so the bar
        governs)."""
        return square_handle_load(force_n, point, grasp or self.grip_point,
                                  self.handle_width, strength_pa, safety_factor)


# ------------------------------------------------------------------ beam formulas
def cantilever_stress(force_n: float, lever_arm_m: float, width_m: float,
                      height_m: float) -> float:
    """Return the largest bending stress (Pa) of a rectangular cantilever.

    ``sigma = M c / I`` with ``M = F L``, ``I = b h^3 / 12`` and ``c = h / 2``, h the
    section's extent in the direction of the load (``height_m``), b across it.
    """
    moment = force_n * lever_arm_m
    inertia = width_m * height_m ** 3 / 12.0
    return moment * (height_m / 2.0) / inertia


def required_square_width(force_n: float, lever_arm_m: float,
                          strength_pa: float = PLA_STRENGTH,
                          safety_factor: float = MIN_SAFETY_FACTOR) -> float:
    """Return the side (m) of the thinnest square section whose cantilever stress under
    ``force_n`` at ``lever_arm_m`` is ``strength_pa / safety_factor``:
    ``(6 F L s / strength)^(1/3)``."""
    return (6.0 * force_n * lever_arm_m * safety_factor / strength_pa) ** (1.0 / 3.0)


WIDTH_STEP = 1e-4
"""A required handle width is rounded up to this, metres (0.1 mm, the size model's
resolution)."""


def round_up_width(width: float) -> float:
    """Return ``width`` (m) rounded up to :data:`WIDTH_STEP`."""
    return round(math.ceil(width / WIDTH_STEP - 1e-9) * WIDTH_STEP, 6)


def square_handle_load(force_n: float, point: tuple | None, grasp: tuple, width: float,
                       strength_pa: float = PLA_STRENGTH,
                       safety_factor: float = MIN_SAFETY_FACTOR) -> dict[str, Any]:
    """Return the load model of a square handle of side ``width`` (m) held at ``grasp``:
    a cantilever from the grasp to the contact ``point`` (tool frame, m), the whole force
    across it (an upper bound: a pull along the handle bends it less)."""
    arm = abs(point[0] - grasp[0]) if point is not None else 0.0
    inertia = width ** 4 / 12.0
    return dict(
        model="cantilever", lever_arm_m=arm, section_m=(width, width), area_m2=None,
        second_moment_m4=inertia, section_modulus_m3=inertia / (width / 2),
        moment_nm=force_n * arm, stress_pa=cantilever_stress(force_n, arm, width, width),
        grasp_point_m=grasp,
        required_handle_width_m=round_up_width(required_square_width(
            force_n, arm, strength_pa, safety_factor)),
        note="the handle as a cantilever from the grasp to the contact, the whole "
             "force across it")


# ----------------------------------------------------------------- field checks
def check_name(name: str) -> None:
    """Raise ``ValueError`` unless ``name`` is a Prolog atom."""
    if not (isinstance(name, str) and name[:1].islower()
            and all(c.isalnum() or c == "_" for c in name) and name.isascii()):
        raise ValueError(f"object name {name!r} must be a Prolog atom: a lower-case letter "
                         "followed by letters, digits or underscores")


def check_positive(spec: Any, *fields: str) -> None:
    """Raise ``ValueError`` naming the first of ``fields`` that is not a positive number."""
    for f in fields:
        v = getattr(spec, f)
        if isinstance(v, bool) or not (isinstance(v, (int, float)) and math.isfinite(v)
                                       and v > 0):
            raise ValueError(f"{spec.name}: {f} must be a positive number of metres, got {v!r}")


def check_mass(spec: Any) -> None:
    """Raise ``ValueError`` unless the spec's mass is None or a positive number (kg)."""
    # A zero mass would make pybullet treat the tool as static.
    m = spec.mass
    if m is not None and (isinstance(m, bool) or not (isinstance(m, (int, float))
                                                      and math.isfinite(m) and m > 0)):
        raise ValueError(f"{spec.name}: mass must be a positive number of kg or None, got {m!r}")


def footprint_overlap_area(box: Box, xs: tuple[float, float],
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
