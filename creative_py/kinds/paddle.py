"""Paddles (``ontology/kinds/paddle.pl``): a flat blade at the end of a shaft, for pushing.

*Tool frame*: the shaft (square section, side ``shaft_width``) runs along +x from its
butt end at the origin, centred on the x axis, for ``shaft_length`` (the whole tool's
length). The blade is a flat plate at the far end, as thick as the shaft and centred on
it: ``blade_length`` along x (it ends where the shaft ends), ``blade_width`` across
(along y). The tool lies blade-flat with z up, which is also how it prints.

The simulator holds it by the shaft as it holds a hook by its handle
(``HANDLING = "handle"``): roll 0 turns the blade's +y half down (the blade stands
upright across the direction of travel, its face towards +x: the pushing pose); its
working point is the blade's centre, its reach half the blade's width.

The strength model is the shaft as a cantilever from the grasp to the contact (the
blade is shorter and no thinner, so the shaft governs).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from creative_py.kinds.parts import (Box, Fact, Part, SquareBarTool, check_mass, check_name,
                                     check_positive)


@dataclass(frozen=True)
class PaddleSpec(SquareBarTool):
    """A paddle: a square shaft with a flat blade across its far end.

    Parameters
    ----------
    name : str
        Unique object name (a Prolog atom).
    shaft_length : float
        Length of the tool along +x, butt end to the blade's edge, metres.
    shaft_width : float
        Side of the shaft's square section, and the blade's thickness, metres.
    blade_width : float
        The blade's extent across the shaft (along y), metres; at least ``shaft_width``.
    blade_length : float
        The blade's extent along the shaft (along x), metres; less than the shaft.
    grip_offset : float
        Distance of the grip point from the butt end along +x, metres (on the bare
        shaft).
    mass : float or None
        Mass in kg; None means PLA density times volume (every created tool).
    """

    BAR = ("shaft_length", "shaft_width")
    FACT_FIELDS = {"shaft_length_m": "shaft_length", "shaft_width_m": "shaft_width",
                   "blade_width_m": "blade_width", "blade_length_m": "blade_length"}
    RGBA = (0.25, 0.65, 0.35, 1.0)
    DRAWING_PLANE = "top"

    name: str
    shaft_length: float
    shaft_width: float
    blade_width: float
    blade_length: float
    grip_offset: float = 0.04
    mass: float | None = 0.1
    kind: str = field(default="paddle", init=False)

    def __post_init__(self) -> None:
        check_name(self.name)
        check_positive(self, "shaft_length", "shaft_width", "blade_width", "blade_length")
        check_mass(self)
        if self.blade_width < self.shaft_width:
            raise ValueError(f"{self.name}: blade_width ({self.blade_width:g} m) must be at "
                             f"least shaft_width ({self.shaft_width:g} m)")
        if not 0.0 <= self.grip_offset < self.shaft_length - self.blade_length:
            raise ValueError(f"{self.name}: grip_offset must lie on the bare shaft, before "
                             "the blade")

    @classmethod
    def from_fields(cls, kind: str, data: dict) -> "PaddleSpec":
        """Return the spec of an ``objects.toml`` table (``kind`` is ``paddle``)."""
        return cls(**data)

    # ------------------------------------------------------------- geometry
    def parts(self) -> list[Part]:
        """Return the shaft box (the whole length) and the blade box at its end."""
        w, L, b = self.shaft_width, self.shaft_length, self.blade_length
        blade = Box((L - b / 2, 0.0, 0.0), (b, self.blade_width, w))
        return [self.bar(), blade]

    def volume(self) -> float:
        """Return the solid volume, m^3 (the shaft inside the blade counted once)."""
        w = self.shaft_width
        return self.shaft_length * w * w + self.blade_length * (self.blade_width - w) * w

    # ------------------- how the simulator holds it (by the shaft: SquareBarTool)
    @property
    def head_width(self) -> float:
        """Return the blade's extent along the shaft, metres."""
        return self.blade_length

    def working_point(self) -> tuple[float, float, float]:
        """Return the blade's centre, tool frame, metres."""
        return (self.shaft_length - self.blade_length / 2, 0.0, 0.0)

    def reach(self) -> float:
        """Return how far the blade reaches from the shaft's axis, metres."""
        return self.blade_width / 2

    # ---------------------------------------------------------- the catalogue
    def catalogue_facts(self) -> list[Fact]:
        """Return kind, shaft and blade facts (m)."""
        n = self.name
        return [("object_kind", n, "paddle"), ("shaft_length_m", n, self.shaft_length),
                ("shaft_width_m", n, self.shaft_width), ("blade_width_m", n, self.blade_width),
                ("blade_length_m", n, self.blade_length)]

    def quantities(self) -> dict[str, float]:
        """``reach`` (half the blade's width), ``length``, ``width`` (the shaft's), m."""
        return {"reach": self.reach(), "length": self.shaft_length, "width": self.shaft_width}

    # ---------------------------------------------------------- manufacturing
    def feature_dimensions(self) -> dict[str, float]:
        """Return the shaft's and the blade's dimensions, metres."""
        return {f: getattr(self, f)
                for f in ("shaft_length", "shaft_width", "blade_width", "blade_length")}

    def scad(self, mm, segments: int) -> tuple[str, str, list[str]]:
        """Return the OpenSCAD model (millimetres): the shaft and the blade, united."""
        frame = ("the shaft runs along +x from its butt end (x = 0), centred on the x axis; "
                 "the blade lies flat (z up) at its far end, as it prints.")
        return "a paddle, a flat blade across the end of its shaft", frame, [
            f"shaft_length = {mm(self.shaft_length)};  // butt end to the blade's edge [mm]",
            f"shaft_width = {mm(self.shaft_width)};  // side of the square shaft, blade "
            "thickness [mm]",
            f"blade_width = {mm(self.blade_width)};  // the blade across the shaft [mm]",
            f"blade_length = {mm(self.blade_length)};  // the blade along the shaft [mm]",
            "",
            "union() {",
            *self.bar_scad(),
            "    translate([shaft_length - blade_length, -blade_width / 2, -shaft_width / 2])",
            "        cube([blade_length, blade_width, shaft_width]);",
            "}",
        ]

    def caption_extra(self) -> str:
        """Return the blade's size in words."""
        return f", blade {self.blade_width * 1e3:.1f} mm across"


CLASSES = {"paddle": PaddleSpec}
"""The ontology class of this kind's tools and its spec class."""
