"""OpenSCAD text for a tool: a parametric model in millimetres, same solid as the STL.

The named parameters at the top of the file are the spec's dimensions in millimetres;
the geometry below is written in terms of them, so a user can edit a number and
re-render (``openscad -o tool.stl tool.scad``). The frame is the spec's tool frame.
"""

from __future__ import annotations

from creative_py.mesh.printability import Printability
from creative_py.mesh.spec import KindSpec
from creative_py.mesh.tolerances import CYLINDER_SEGMENTS, MM_PER_M


def _mm(metres: float) -> str:
    return f"{round(metres * MM_PER_M, 6):.10g}"


def _header(spec: KindSpec, what: str, frame: str, verdict: Printability) -> list[str]:
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


def scad_text(spec: KindSpec, verdict: Printability) -> str:
    """Return the OpenSCAD source of a spec (millimetres) with its printability verdict.

    Parameters
    ----------
    spec : KindSpec
        The tool (its kind writes the model: :meth:`KindSpec.scad`).
    verdict : Printability
        The build-volume verdict, repeated in a comment at the top.
    """
    what, frame, body = spec.scad(_mm, CYLINDER_SEGMENTS)
    return "\n".join(_header(spec, what, frame, verdict) + body) + "\n"
