"""OpenSCAD text for a tool: a parametric model in millimetres, same solid as the STL.

The named parameters at the top of the file are the spec's dimensions in millimetres;
the geometry below is written in terms of them, so a user can edit a number and
re-render (``openscad -o tool.stl tool.scad``). The frame is the spec's tool frame.
"""

from __future__ import annotations

from creative_py.mesh.printability import Printability
from creative_py.mesh.spec import BlockSpec, HookSpec, ToolSpec
from creative_py.mesh.tolerances import CYLINDER_SEGMENTS, MM_PER_M


def _mm(metres: float) -> str:
    return f"{round(metres * MM_PER_M, 6):.10g}"


def _header(spec: ToolSpec, what: str, frame: str, verdict: Printability) -> list[str]:
    lines = [
        f"// CREATIVE-py tool {spec.name}: {what}.",
        "// Written by creative_py.mesh. Units: millimetres, degrees.",
        f"// Render: openscad -o {spec.name}.stl {spec.name}.scad",
        f"// Frame: {frame}",
        f"// Printability: {verdict.summary()}.",
    ]
    if not verdict.fits_build_volume:
        lines.append("// WARNING: split this part before printing it on that printer.")
    return lines + [""]


def _hook(spec: HookSpec) -> list[str]:
    params = [
        f"handle_length = {_mm(spec.handle_length)};  // handle length along +x [mm]",
        f"handle_width = {_mm(spec.handle_width)};  // side of the square handle [mm]",
    ]
    if spec.is_stick:
        return params + [
            "",
            "translate([0, -handle_width / 2, -handle_width / 2])",
            "    cube([handle_length, handle_width, handle_width]);",
        ]
    side = 1 if spec.hook_side == "left" else -1
    return params + [
        f"hook_length = {_mm(spec.hook_length)};  // prong reach beyond the handle's side [mm]",
        f"hook_width = {_mm(spec.hook_width)};  // prong thickness along the handle [mm]",
        f"hook_side = {side};  // +1: prong to the left (+y), -1: to the right (-y)",
        f"hook_angle = {spec.hook_angle_deg:.10g};  // angle between handle and prong [deg]",
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


def _block(spec: BlockSpec) -> list[str]:
    if spec.shape == "cylinder":
        return [
            f"diameter = {_mm(spec.length)};  // [mm]",
            f"height = {_mm(spec.height)};  // [mm]",
            f"segments = {CYLINDER_SEGMENTS};  // facets around the circle",
            "",
            "cylinder(h = height, d = diameter, $fn = segments);",
        ]
    params = [
        f"length = {_mm(spec.length)};  // extent along x [mm]",
        f"width = {_mm(spec.width)};  // extent along y [mm]",
        f"height = {_mm(spec.height)};  // extent along z{' at the back' if spec.shape == 'triangular_prism' else ''} [mm]",
        "",
    ]
    if spec.shape == "box":
        return params + ["translate([0, 0, height / 2]) cube([length, width, height], center = true);"]
    if spec.tip_height > 0:
        return params[:-1] + [
            f"tip_height = {_mm(spec.tip_height)};  // height of the blunted tip at +x [mm]",
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


def scad_text(spec: ToolSpec, verdict: Printability) -> str:
    """Return the OpenSCAD source of a spec (millimetres) with its printability verdict.

    Parameters
    ----------
    spec : HookSpec or BlockSpec
        The tool.
    verdict : Printability
        The build-volume verdict, repeated in a comment at the top.
    """
    if isinstance(spec, HookSpec):
        what = ("a stick" if spec.is_stick
                else f"a hook, prong to the {spec.hook_side} at {spec.hook_angle_deg:g} deg")
        frame = ("the handle runs along +x from its butt end (x = 0), centred on the x axis; "
                 "+y is the tool's left; lay it flat (z up) to print.")
        body = _hook(spec)
    elif isinstance(spec, BlockSpec):
        what = {"triangular_prism": ("a wedge (triangular prism), thin edge at +x"
                                     + (", blunted" if spec.tip_height > 0 else "")),
                "box": "a box", "cylinder": "an upright cylinder"}[spec.shape]
        frame = "the base lies on z = 0, centred on the origin in x and y."
        body = _block(spec)
    else:
        raise TypeError(f"expected a HookSpec or BlockSpec, got {type(spec).__name__}")
    return "\n".join(_header(spec, what, frame, verdict) + body) + "\n"
