"""Blocks (``ontology/kinds/block.pl``): wedges (triangular prisms), boxes, cylinders.

*Block frame*: the base lies on z = 0, centred on the origin in x and y. A triangular
prism runs along x with its thin edge (the tip) at x = +length/2 and its back face, of
height ``height``, at x = -length/2; ``width`` is its lateral extent along y. A prism may
be blunted: ``tip_height`` is the height of a vertical flat at its tip (0, the default,
is a knife edge), so that in side view it is a trapezoid with parallel sides ``height``
(back) and ``tip_height`` (tip). A box is length x width x height. A cylinder stands
upright with diameter ``length`` and height ``height`` (``width`` must equal
``length``). The simulator grips a block from above (``HANDLING = "top"``).

The strength model is compression over the footprint: nothing cantilevers.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, Literal, Mapping

from creative_py.kinds.parts import (MIN_SAFETY_FACTOR, PLA_STRENGTH, Box, Cylinder, Fact, Hull,
                                     KindSpec, Part, check_mass,
                                     check_name, check_positive)

BlockShape = Literal["triangular_prism", "box", "cylinder"]


@dataclass(frozen=True)
class BlockSpec(KindSpec):
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

    HANDLING = "top"
    FACT_FIELDS = {"block_length_m": "length", "block_width_m": "width",
                   "block_height_m": "height"}
    RGBA = (0.20, 0.45, 0.85, 1.0)
    DRAWING_PLANE = "side"

    name: str
    shape: BlockShape
    length: float
    width: float
    height: float
    mass: float | None = 0.1
    tip_height: float = 0.0
    kind: str = field(default="block", init=False)

    def __post_init__(self) -> None:
        check_name(self.name)
        if self.shape not in ("triangular_prism", "box", "cylinder"):
            raise ValueError(f"{self.name}: shape must be triangular_prism, box or cylinder")
        check_positive(self, "length", "width", "height")
        check_mass(self)
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

    @classmethod
    def from_fields(cls, kind: str, data: dict) -> "BlockSpec":
        """Return the spec of an ``objects.toml`` table (``kind`` is ``block``)."""
        return cls(**data)

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

    # ------------------------------------------- how the simulator holds it ("top")
    def centre(self) -> tuple[float, float, float]:
        """Return the centre of the block's box, (0, 0, height / 2) in its frame."""
        return (0.0, 0.0, self.height / 2)

    # ---------------------------------------------------------- the catalogue
    def catalogue_facts(self) -> list[Fact]:
        """Return kind, shape, length, width and height facts (m)."""
        n = self.name
        return [("object_kind", n, "block"), ("block_shape", n, self.shape),
                ("block_length_m", n, self.length), ("block_width_m", n, self.width),
                ("block_height_m", n, self.height)]

    def quantities(self) -> dict[str, float]:
        """``length``, ``width``, ``height`` (m)."""
        return {"length": self.length, "width": self.width, "height": self.height}

    def redrawn(self, values: Mapping[str, float]) -> "BlockSpec":
        """A cylinder's width is its length (its diameter): the drawn length sets both."""
        values = dict(values)
        if self.shape == "cylinder" and "length" in values:
            values["width"] = values["length"]
        return replace(self, **values)

    # ---------------------------------------------------------- manufacturing
    def feature_dimensions(self) -> dict[str, float]:
        """Return length, width, height (and a blunted wedge's ``tip_height``), metres."""
        fields = ["length", "width", "height"]
        if self.shape == "triangular_prism" and self.tip_height > 0:
            fields.append("tip_height")
        return {f: getattr(self, f) for f in fields}

    def thin_tip_length(self, min_tip: float) -> float:
        """Return how far (metres) from its tip a wedge is thinner than ``min_tip``.

        0.0 for a blunted wedge whose tip reaches ``min_tip`` and for every other shape;
        for a prism whose tip is lower, the run over which its height (falling linearly
        from ``height`` at the back to ``tip_height`` at the tip) is below ``min_tip``.
        """
        if self.shape != "triangular_prism" or self.tip_height >= min_tip:
            return 0.0
        slope = (self.height - self.tip_height) / self.length
        return min(self.length, (min_tip - self.tip_height) / slope)

    def scad(self, mm, segments: int) -> tuple[str, str, list[str]]:
        """Return the OpenSCAD model (millimetres): a cylinder, a cube or the wedge's
        side profile extruded along y."""
        what = {"triangular_prism": ("a wedge (triangular prism), thin edge at +x"
                                     + (", blunted" if self.tip_height > 0 else "")),
                "box": "a box", "cylinder": "an upright cylinder"}[self.shape]
        frame = "the base lies on z = 0, centred on the origin in x and y."
        return what, frame, self._scad_body(mm, segments)

    def _scad_body(self, mm, segments: int) -> list[str]:
        if self.shape == "cylinder":
            return [
                f"diameter = {mm(self.length)};  // [mm]",
                f"height = {mm(self.height)};  // [mm]",
                f"segments = {segments};  // facets around the circle",
                "",
                "cylinder(h = height, d = diameter, $fn = segments);",
            ]
        back = " at the back" if self.shape == "triangular_prism" else ""
        params = [
            f"length = {mm(self.length)};  // extent along x [mm]",
            f"width = {mm(self.width)};  // extent along y [mm]",
            f"height = {mm(self.height)};  // extent along z{back} [mm]",
            "",
        ]
        if self.shape == "box":
            return params + ["translate([0, 0, height / 2]) cube([length, width, height], "
                             "center = true);"]
        if self.tip_height > 0:
            return params[:-1] + [
                f"tip_height = {mm(self.tip_height)};  // height of the blunted tip at +x [mm]",
                "",
                "// the wedge's side profile in the xz plane (a trapezoid), extruded along y",
                "rotate([90, 0, 0])",
                "    linear_extrude(height = width, center = true)",
                "        polygon([[-length / 2, 0], [length / 2, 0], [length / 2, tip_height],",
                "                 [-length / 2, height]]);",
            ]
        return params + [
            "// the wedge's side profile in the xz plane, extruded along y",
            "rotate([90, 0, 0])",
            "    linear_extrude(height = width, center = true)",
            "        polygon([[-length / 2, 0], [length / 2, 0], [-length / 2, height]]);",
        ]

    def title(self) -> str:
        """Return the block's shape."""
        return self.shape

    # ---------------------------------------------------------------- strength
    def load_model(self, force_n: float, point: tuple | None, grasp: tuple | None, *,
                   strength_pa: float = PLA_STRENGTH,
                   safety_factor: float = MIN_SAFETY_FACTOR) -> dict[str, Any]:
        """Return compression over the footprint (length x width; pi d^2 / 4 for a
        cylinder): the beam check does not apply to a block."""
        if self.shape == "cylinder":
            section, area = (self.length, self.length), math.pi * self.length ** 2 / 4
        else:
            section, area = (self.length, self.width), self.length * self.width
        return dict(model="compression", lever_arm_m=None, section_m=section, area_m2=area,
                    second_moment_m4=None, section_modulus_m3=None, moment_nm=None,
                    stress_pa=force_n / area, grasp_point_m=None,
                    required_handle_width_m=None,
                    note="the beam check does not apply to a block (nothing "
                         "cantilevers); compression over its footprint instead")


CLASSES = {"block": BlockSpec}
"""The ontology classes of this kind's tools and the spec class of each."""
