"""Hook-like tools (``ontology/kinds/hook_like.pl``): a square handle, maybe a prong.

*Tool frame*: the handle runs along +x from its butt end at the origin, centred on the x
axis, z up when the tool lies prong-flat. A ``hook`` has a prong at the handle's tip
that reaches ``hook_length`` beyond the handle's side, on the left (+y) or right (-y),
at ``hook_angle_deg`` to the handle (90: perpendicular; smaller leans the prong back
towards the grip). A ``stick`` has no prong. The robot grips the handle at
``grip_point``; the simulator holds it as a handled tool (``HANDLING = "handle"``):
its *roll* is the turn about the handle axis, 0 with the prong down.

The strength model is a cantilever: the square handle from the grasp to the contact.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Literal

from creative_py.kinds.parts import (MIN_SAFETY_FACTOR, PLA_STRENGTH, Box, Fact, KindSpec, Part,
                                     check_mass, check_name,
                                     check_positive, footprint_overlap_area,
                                     square_handle_load)

HookSide = Literal["left", "right", "none"]


@dataclass(frozen=True)
class HookSpec(KindSpec):
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

    ``kind`` is the tool's ontology class: ``stick`` without a prong, else ``hook``.
    """

    HANDLING = "handle"
    FACT_FIELDS = {"handle_length_m": "handle_length", "handle_width_m": "handle_width",
                   "hook_length_m": "hook_length", "hook_width_m": "hook_width",
                   "hook_angle_deg": "hook_angle_deg"}
    RGBA = (0.90, 0.45, 0.10, 1.0)
    DRAWING_PLANE = "top"

    name: str
    handle_length: float
    handle_width: float = 0.01
    hook_length: float = 0.03
    hook_width: float = 0.01
    hook_side: HookSide = "right"
    hook_angle_deg: float = 90.0
    grip_offset: float = 0.04
    mass: float | None = 0.1
    kind: str = field(default="hook", init=False)

    def __post_init__(self) -> None:
        check_name(self.name)
        check_positive(self, "handle_length", "handle_width")
        check_mass(self)
        if self.hook_side == "none":
            if self.hook_length != 0.0:
                raise ValueError(f"{self.name}: a stick (hook_side 'none') has hook_length 0")
        else:
            if self.hook_side not in ("left", "right"):
                raise ValueError(f"{self.name}: hook_side must be left, right or none")
            check_positive(self, "hook_length", "hook_width")
            if not 30.0 <= self.hook_angle_deg <= 150.0:
                raise ValueError(f"{self.name}: hook_angle_deg must lie in [30, 150]")
        if not 0.0 <= self.grip_offset < self.handle_length:
            raise ValueError(f"{self.name}: grip_offset must lie on the handle")
        object.__setattr__(self, "kind", "stick" if self.is_stick else "hook")

    @classmethod
    def from_fields(cls, kind: str, data: dict) -> "HookSpec":
        """Return the spec of an ``objects.toml`` table of class ``kind`` (a stick's
        prong fields default to none)."""
        if kind == "stick":
            data = {"hook_side": "none", "hook_length": 0.0, **data}
        return cls(**data)

    # ------------------------------------------------------------- geometry
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

    def volume(self) -> float:
        """Return the solid volume, m^3 (the prong's overlap with the handle once)."""
        parts = self.parts()
        vol = sum(p.volume for p in parts)
        if not self.is_stick:
            # The prong box (same z extent as the handle) overlaps the handle; at angles
            # other than 90 degrees the overlap is not a plain half-width block, so clip
            # the prong's footprint by the handle's rectangle.
            w = self.handle_width
            vol -= w * footprint_overlap_area(parts[1], (0.0, self.handle_length),
                                              (-w / 2, w / 2))
        return vol

    # ---------------------------------------- how the simulator holds it ("handle")
    @property
    def roll_side(self) -> float:
        """Return +1 when roll is measured from the tool's +y side (a left prong, a
        stick), -1 from its -y side (a right prong)."""
        return -1.0 if self.hook_side == "right" else 1.0

    @property
    def has_head(self) -> bool:
        """Return whether something stands out sideways at the handle's end (a prong)."""
        return not self.is_stick

    @property
    def head_width(self) -> float:
        """Return the head's extent along the handle, metres (the prong's thickness)."""
        return 0.0 if self.is_stick else self.hook_width

    def working_point(self) -> tuple[float, float, float]:
        """Return the prong box's centre (a stick: its tip), tool frame, metres."""
        if self.is_stick:
            return (self.handle_length, 0.0, 0.0)
        prong = self.parts()[1]
        return prong.center

    def reach(self) -> float:
        """Return how far the prong reaches from the handle axis, metres (a stick: its
        radius)."""
        if self.is_stick:
            return self.handle_width / 2
        return self.handle_width / 2 + self.hook_length * math.sin(
            math.radians(self.hook_angle_deg))

    # ---------------------------------------------------------- the catalogue
    def catalogue_facts(self) -> list[Fact]:
        """Return kind, handle and prong facts (m, deg); a stick has no prong angle."""
        n = self.name
        facts: list[Fact] = [("object_kind", n, self.kind),
                             ("handle_length_m", n, self.handle_length),
                             ("handle_width_m", n, self.handle_width)]
        if self.is_stick:
            facts += [("hook_length_m", n, 0.0), ("hook_width_m", n, 0.0),
                      ("hook_side_is", n, "none")]
        else:
            facts += [("hook_length_m", n, self.hook_length),
                      ("hook_width_m", n, self.hook_width),
                      ("hook_side_is", n, self.hook_side),
                      ("hook_angle_deg", n, self.hook_angle_deg)]
        return facts

    def quantities(self) -> dict[str, float]:
        """``reach`` (prong reach from the handle axis), ``length``, ``width`` (m)."""
        return {"reach": self.reach(), "length": self.handle_length,
                "width": self.handle_width}

    # ---------------------------------------------------------- manufacturing
    def feature_dimensions(self) -> dict[str, float]:
        """Return the handle's (and the prong's) dimensions, metres."""
        fields = ["handle_length", "handle_width"]
        if not self.is_stick:
            fields += ["hook_length", "hook_width"]
        return {f: getattr(self, f) for f in fields}

    def scad(self, mm, segments: int) -> tuple[str, str, list[str]]:
        """Return the OpenSCAD model (millimetres): handle, and the prong turned at its
        angle."""
        what = ("a stick" if self.is_stick
                else f"a hook, prong to the {self.hook_side} at {self.hook_angle_deg:g} deg")
        frame = ("the handle runs along +x from its butt end (x = 0), centred on the x axis; "
                 "+y is the tool's left; lay it flat (z up) to print.")
        params = [
            f"handle_length = {mm(self.handle_length)};  // handle length along +x [mm]",
            f"handle_width = {mm(self.handle_width)};  // side of the square handle [mm]",
        ]
        if self.is_stick:
            return what, frame, params + [
                "",
                "translate([0, -handle_width / 2, -handle_width / 2])",
                "    cube([handle_length, handle_width, handle_width]);",
            ]
        side = 1 if self.hook_side == "left" else -1
        return what, frame, params + [
            f"hook_length = {mm(self.hook_length)};  // prong reach beyond the handle's side [mm]",
            f"hook_width = {mm(self.hook_width)};  // prong thickness along the handle [mm]",
            f"hook_side = {side};  // +1: prong to the left (+y), -1: to the right (-y)",
            f"hook_angle = {self.hook_angle_deg:.10g};  // angle between handle and prong [deg]",
            "",
            "span = handle_width / 2 + hook_length;  // prong length from the handle's axis",
            "",
            "union() {",
            "    // the handle, butt end at x = 0",
            "    translate([0, -handle_width / 2, -handle_width / 2])",
            "        cube([handle_length, handle_width, handle_width]);",
            "    // the prong, from the handle's axis at its tip out to the side",
            "    translate([handle_length - hook_width / 2, 0, 0])",
            "        rotate([0, 0, hook_side * (90 - hook_angle)])",
            "            translate([-hook_width / 2, hook_side > 0 ? 0 : -span, -handle_width / 2])",
            "                cube([hook_width, span, handle_width]);",
            "}",
        ]

    def caption_extra(self) -> str:
        """Return the prong's side and angle (nothing for a stick)."""
        if self.is_stick:
            return ""
        return f", prong {self.hook_side} at {self.hook_angle_deg:g} deg"

    # ---------------------------------------------------------------- strength
    def load_model(self, force_n: float, point: tuple | None, grasp: tuple | None, *,
                   strength_pa: float = PLA_STRENGTH,
                   safety_factor: float = MIN_SAFETY_FACTOR) -> dict[str, Any]:
        """Return the cantilever model of the square handle from the grasp to the
        contact (:func:`creative_py.kinds.parts.square_handle_load`)."""
        return square_handle_load(force_n, point, grasp or self.grip_point,
                                  self.handle_width, strength_pa, safety_factor)


CLASSES = {"hook": HookSpec, "stick": HookSpec}
"""The ontology classes of this kind's tools (the ``kind`` of an ``objects.toml`` table,
the class literal of a new tool) and the spec class of each."""
