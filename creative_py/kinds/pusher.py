"""Pushers (``ontology/kinds/pusher.pl``): a head of upright walls hung below the end of
a pole, for pushing or sweeping things along a table.

*Tool frame*: the pole (square section, side ``pole_width``) runs along +x from its butt
end at the origin for ``pole_length``. At its far end a neck (as wide as the pole) drops
``drop`` along +y to the head. The head is upright walls ``wall_height`` high (along +y,
from ``drop`` to ``drop + wall_height``) and ``wall`` thick: a base plate across the
pole's end (``plate_width`` along z, its front face at x = ``pole_length``) and two wings
from the base plate's ends, ``wing_length`` forward (+x), each standing out
``wing_spread`` beyond the base plate's end (0: parallel wings, a U; more: a funnel
whose mouth is ``plate_width + 2 wing_spread`` wide). Without wings (``wing_length`` 0)
the head is a straight blade.

The simulator holds it by the pole as it holds a hook by its handle
(``HANDLING = "handle"``): roll 0 turns +y down, so the head hangs below the pole with
its walls upright on the table and the base plate across the direction of a push along
+x; the wings run along x and meet a push along y. Its working point is the middle of
the space the walls enclose (the base plate's front face, ``wing_length / 2`` ahead,
half the wall height down); its reach (how far below the pole's axis it reaches) is
``drop + wall_height``.

The strength model is the pole as a cantilever from the grasp to the contact (the
square-handle model).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations

from creative_py.kinds.parts import (Box, Fact, Hull, Part, SquareBarTool, check_mass,
                                     check_name, check_positive)


@dataclass(frozen=True)
class PusherSpec(SquareBarTool):
    """A pusher: a square pole with a walled head hung below its far end.

    Parameters
    ----------
    name : str
        Unique object name (a Prolog atom).
    pole_length : float
        Length of the pole along +x, butt end to the base plate's front face, metres.
    pole_width : float
        Side of the pole's square section (and the neck's), metres.
    plate_width : float
        The base plate across the pole (tool z, the world's y at roll 0), metres.
    wing_length : float
        How far the wings run forward (+x) of the base plate, metres; 0 for none.
    wing_spread : float
        How far each wing's tip stands out sideways beyond the base plate's end, metres
        (0: parallel wings).
    drop : float
        The neck: from the pole's axis down to the head's top, metres.
    wall_height : float
        The head's walls' height, metres.
    wall : float
        The walls' thickness, metres.
    grip_offset : float
        Distance of the grip point from the butt end along +x, metres.
    mass : float or None
        Mass in kg; None means PLA density times volume (every created tool).
    """

    BAR = ("pole_length", "pole_width")
    FACT_FIELDS = {"pole_length_m": "pole_length", "pole_width_m": "pole_width",
                   "plate_width_m": "plate_width", "wing_length_m": "wing_length",
                   "wing_spread_m": "wing_spread"}
    RGBA = (0.3, 0.45, 0.8, 1.0)
    DRAWING_PLANE = "top"

    name: str
    pole_length: float
    pole_width: float
    plate_width: float
    wing_length: float = 0.0
    wing_spread: float = 0.0
    drop: float = 0.10
    wall_height: float = 0.06
    wall: float = 0.01
    grip_offset: float = 0.04
    mass: float | None = 0.2
    kind: str = field(default="pusher", init=False)

    def __post_init__(self) -> None:
        check_name(self.name)
        check_positive(self, "pole_length", "pole_width", "plate_width", "drop",
                       "wall_height", "wall")
        check_mass(self)
        if self.wing_length < 0 or self.wing_spread < 0:
            raise ValueError(f"{self.name}: wing_length and wing_spread must not be negative")
        if self.wing_spread > 0 and self.wing_length <= 0:
            raise ValueError(f"{self.name}: a wing_spread needs wings (wing_length > 0)")
        if self.plate_width < max(self.pole_width, 2 * self.wall):
            raise ValueError(f"{self.name}: plate_width must be at least the pole and two "
                             "walls wide")
        if not 0.0 <= self.grip_offset < self.pole_length - self.pole_width:
            raise ValueError(f"{self.name}: grip_offset must lie on the pole, before the neck")

    @classmethod
    def from_fields(cls, kind: str, data: dict) -> "PusherSpec":
        """Return the spec of an ``objects.toml`` table (``kind`` is ``pusher``)."""
        return cls(**data)

    # ------------------------------------------------------------- geometry
    def parts(self) -> list[Part]:
        """Return the pole, the neck, the base plate and the wings (hulls)."""
        L, w, t, H = self.pole_length, self.pole_width, self.wall, self.wall_height
        y0, y1 = self.drop, self.drop + H
        parts: list[Part] = [
            self.bar(),
            Box((L - w / 2, (y0 + w / 2) / 2, 0.0), (w, y0 + w / 2, w)),
            Box((L - t / 2, (y0 + y1) / 2, 0.0), (t, H, self.plate_width)),
        ]
        for corners in self._wing_sections():
            verts = tuple((x, y, z) for x, z in corners for y in (y0, y1))
            parts.append(Hull(verts, volume=H * _area(_convex(corners))))
        return parts

    def _wing_sections(self) -> list[list[tuple[float, float]]]:
        """Return each wing's section in (x, z), none without wings. The tip ends in a
        face across z (``wall`` long), so that a printed piece cut from the head can
        stand on it flat."""
        if self.wing_length <= 0:
            return []
        L, t, half = self.pole_length, self.wall, self.plate_width / 2
        wl, sp = self.wing_length, self.wing_spread
        return [[(L - t, s * half), (L - t, s * (half - t)),
                 (L + wl - t, s * (half + sp)), (L + wl, s * (half + sp)),
                 (L + wl, s * (half + sp - t))] for s in (1.0, -1.0)]

    def volume(self) -> float:
        """Return the solid volume, m^3, each overlap counted once: every part is an
        upright prism (its section in x-z over a span of y), so the volume is the
        integral over y of the area of the union of the sections there."""
        return _union_volume(self._prisms())

    def _prisms(self) -> list[tuple[float, float, list[tuple[float, float]]]]:
        """Return the parts as ``(y_low, y_high, section)``, the section a convex
        polygon in (x, z), counter-clockwise."""
        L, w, t, H = self.pole_length, self.pole_width, self.wall, self.wall_height
        y0, y1, half = self.drop, self.drop + self.wall_height, self.plate_width / 2
        prisms = [(-w / 2, w / 2, _rect(0.0, L, -w / 2, w / 2)),
                  (0.0, y0 + w / 2, _rect(L - w, L, -w / 2, w / 2)),
                  (y0, y1, _rect(L - t, L, -half, half))]
        prisms += [(y0, y1, _convex(corners)) for corners in self._wing_sections()]
        return prisms

    # -------------------- how the simulator holds it (by the pole: SquareBarTool)
    @property
    def head_width(self) -> float:
        """Return the head's extent back from the pole's end along the pole, metres
        (what the handling keeps the tool's pedestal clear of; not ``plate_width``)."""
        return max(self.pole_width, self.wall)

    def working_point(self) -> tuple[float, float, float]:
        """Return the middle of the space the walls enclose, tool frame, metres."""
        return (self.pole_length + self.wing_length / 2,
                self.drop + self.wall_height / 2, 0.0)

    def reach(self) -> float:
        """Return how far the head reaches below the pole's axis, metres."""
        return self.drop + self.wall_height

    def mouth_width(self) -> float:
        """Return the width between the wings' tips (the base plate's without wings), m."""
        return self.plate_width + 2 * self.wing_spread

    # ---------------------------------------------------------- the catalogue
    def catalogue_facts(self) -> list[Fact]:
        """Return kind, pole, head and wing facts (m)."""
        n = self.name
        return [("object_kind", n, "pusher"), ("pole_length_m", n, self.pole_length),
                ("pole_width_m", n, self.pole_width), ("plate_width_m", n, self.plate_width),
                ("wing_length_m", n, self.wing_length),
                ("wing_spread_m", n, self.wing_spread)]

    def quantities(self) -> dict[str, float]:
        """``reach`` (below the pole), ``length`` (the pole), ``width`` (the pole's),
        ``inner_half`` (half the room between parallel wings), ``mouth`` (the head's
        mouth), ``wing_length``, ``wall_height``, m."""
        return {"reach": self.reach(), "length": self.pole_length, "width": self.pole_width,
                "inner_half": self.plate_width / 2 - self.wall, "mouth": self.mouth_width(),
                "wing_length": self.wing_length, "wall_height": self.wall_height}

    # ---------------------------------------------------------- manufacturing
    def feature_dimensions(self) -> dict[str, float]:
        """Return the pole's, the head's and the wings' dimensions, metres: the wings'
        length only where there are wings, and never ``wing_spread``, which places the
        wings (0: parallel) and is no feature of the print."""
        fields = ("pole_length", "pole_width", "plate_width", "drop", "wall_height", "wall")
        if self.wing_length > 0:
            fields += ("wing_length",)
        return {f: getattr(self, f) for f in fields}

    def scad(self, mm, segments: int) -> tuple[str, str, list[str]]:
        """Return the OpenSCAD model (millimetres): pole, neck, base plate and wings."""
        frame = ("the pole runs along +x from its butt end (x = 0) on the x axis; the neck "
                 "and the head's walls hang along +y below its far end, the base plate "
                 "across z.")
        lines = [
            f"pole_length = {mm(self.pole_length)};  // butt end to the base plate's face [mm]",
            f"pole_width = {mm(self.pole_width)};  // side of the square pole [mm]",
            f"plate_width = {mm(self.plate_width)};  // the base plate across the pole [mm]",
            f"wing_length = {mm(self.wing_length)};  // the wings forward of the plate [mm]",
            f"wing_spread = {mm(self.wing_spread)};  // each wing's tip beyond the plate [mm]",
            f"drop = {mm(self.drop)};  // pole axis to the head's top [mm]",
            f"wall_height = {mm(self.wall_height)};  // the walls' height [mm]",
            f"wall = {mm(self.wall)};  // the walls' thickness [mm]",
            "",
            "union() {",
            *self.bar_scad(),
            "    translate([pole_length - pole_width, 0, -pole_width / 2])",
            "        cube([pole_width, drop + pole_width / 2, pole_width]);",
            "    translate([pole_length - wall, drop, -plate_width / 2])",
            "        cube([wall, wall_height, plate_width]);",
        ]
        if self.wing_length > 0:
            lines += [
                "    for (s = [1, -1])",
                "        hull() for (p = [[pole_length - wall, s * plate_width / 2],",
                "                         [pole_length - wall, s * (plate_width / 2 - wall)],",
                "                         [pole_length + wing_length - wall, s * (plate_width / 2 + wing_spread)],",
                "                         [pole_length + wing_length, s * (plate_width / 2 + wing_spread)],",
                "                         [pole_length + wing_length, s * (plate_width / 2 + wing_spread - wall)]])",
                "            translate([p[0], drop, p[1]]) cube([0.01, wall_height, 0.01]);",
            ]
        lines.append("}")
        return "a pusher, a walled head hung below the end of its pole", frame, lines

    def caption_extra(self) -> str:
        """Return the head's mouth in words."""
        return f", head mouth {self.mouth_width() * 1e3:.0f} mm"


CLASSES = {"pusher": PusherSpec}
"""The ontology class of this kind's tools and its spec class."""


# ------------------------------------------------ the volume of a union of prisms
Point = tuple[float, float]


def _rect(x0: float, x1: float, z0: float, z1: float) -> list[Point]:
    """Return the rectangle ``[x0, x1] x [z0, z1]``, counter-clockwise."""
    return [(x0, z0), (x1, z0), (x1, z1), (x0, z1)]


def _cross(o: Point, a: Point, b: Point) -> float:
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _convex(points: list[Point]) -> list[Point]:
    """Return the convex hull of ``points``, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(points))
    if len(pts) < 3:
        return pts
    lower: list[Point] = []
    upper: list[Point] = []
    for p in pts:
        while len(lower) >= 2 and _cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    for p in reversed(pts):
        while len(upper) >= 2 and _cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    return lower[:-1] + upper[:-1]


def _area(poly: list[Point]) -> float:
    """Return the area of a simple polygon (the shoelace formula)."""
    n = len(poly)
    return abs(sum(poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1]
                   for i in range(n))) / 2 if n >= 3 else 0.0


def _clip(subject: list[Point], clip: list[Point]) -> list[Point]:
    """Return the intersection of two convex counter-clockwise polygons
    (Sutherland-Hodgman)."""
    out = subject
    for i in range(len(clip)):
        a, b = clip[i], clip[(i + 1) % len(clip)]
        inp, out = out, []
        for j in range(len(inp)):
            p, q = inp[j], inp[(j + 1) % len(inp)]
            p_in, q_in = _cross(a, b, p) >= 0, _cross(a, b, q) >= 0
            if p_in:
                out.append(p)
            if p_in != q_in:
                dp, dq = _cross(a, b, p), _cross(a, b, q)
                f = dp / (dp - dq)
                out.append((p[0] + f * (q[0] - p[0]), p[1] + f * (q[1] - p[1])))
        if not out:
            return []
    return out


def _union_volume(prisms: list[tuple[float, float, list[Point]]]) -> float:
    """Return the volume of a union of upright prisms with convex sections: over each
    span of y where the same prisms stand, the span times the area of the union of
    their sections (inclusion-exclusion over the sections' intersections)."""
    levels = sorted({y for lo, hi, _ in prisms for y in (lo, hi)})
    total = 0.0
    for lo, hi in zip(levels, levels[1:]):
        here = [sec for a, b, sec in prisms if a <= lo and hi <= b]
        area = 0.0
        for k in range(1, len(here) + 1):
            for group in combinations(here, k):
                common = group[0]
                for sec in group[1:]:
                    common = _clip(common, sec)
                    if not common:
                        break
                area += (-1) ** (k + 1) * _area(common)
        total += (hi - lo) * area
    return total
