"""A PNG picture of a tool: a shaded 3D view and a dimensioned drawing (millimetres).

Drawn with matplotlib's object API on an Agg canvas (no pyplot state, no display).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import trimesh
from matplotlib.collections import PolyCollection
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from creative_py.mesh.printability import Printability, feature_dimensions
from creative_py.mesh.solid import MassProperties
from creative_py.mesh.spec import KindSpec
from creative_py.mesh.tolerances import MM_PER_M

LIGHT_DIRECTION = np.array([0.4, -0.5, 0.75]) / np.linalg.norm([0.4, -0.5, 0.75])
"""Direction towards the light for the 3D shading (tool frame, unit vector)."""


def _shaded_view(ax, mesh_mm: trimesh.Trimesh, rgb: np.ndarray) -> None:
    triangles = mesh_mm.triangles
    brightness = 0.35 + 0.65 * np.clip(mesh_mm.face_normals @ LIGHT_DIRECTION, 0.0, 1.0)
    colours = np.clip(rgb[None, :] * brightness[:, None], 0.0, 1.0)
    ax.add_collection3d(Poly3DCollection(triangles, facecolors=colours, edgecolors=colours,
                                        linewidths=0.3))
    lo, hi = mesh_mm.bounds
    centre, half = (lo + hi) / 2, float((hi - lo).max()) / 2
    ax.set_xlim(centre[0] - half, centre[0] + half)
    ax.set_ylim(centre[1] - half, centre[1] + half)
    ax.set_zlim(centre[2] - half, centre[2] + half)
    ax.set_box_aspect((1, 1, 1))
    ax.view_init(elev=28, azim=-60)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm]")
    ax.set_zlabel("z [mm]")
    ax.tick_params(labelsize=7)


def _dimension(ax, start, end, label: str, offset) -> None:
    start, end, offset = np.asarray(start), np.asarray(end), np.asarray(offset)
    a, b = start + offset, end + offset
    for p, q in ((start, a), (end, b)):
        ax.plot([p[0], q[0]], [p[1], q[1]], color="0.4", lw=0.6)
    ax.annotate("", xy=tuple(b), xytext=tuple(a),
                arrowprops={"arrowstyle": "<->", "color": "0.2", "lw": 0.8})
    mid = (a + b) / 2 + 0.6 * offset
    ax.text(mid[0], mid[1], label, ha="center", va="center", fontsize=8,
            bbox={"fc": "white", "ec": "none", "pad": 0.5})


def _drawing(ax, mesh_mm: trimesh.Trimesh, axes: tuple[int, int], names: tuple[str, str],
             rgb: np.ndarray) -> None:
    i, j = axes
    polygons = mesh_mm.triangles[:, :, [i, j]]
    ax.add_collection(PolyCollection(polygons, facecolors=[tuple(rgb)], edgecolors="none"))
    lo, hi = mesh_mm.bounds[0][[i, j]], mesh_mm.bounds[1][[i, j]]
    size = hi - lo
    gap = 0.12 * float(size.max())
    _dimension(ax, (lo[0], lo[1]), (hi[0], lo[1]), f"{size[0]:.1f}", (0.0, -gap))
    _dimension(ax, (lo[0], lo[1]), (lo[0], hi[1]), f"{size[1]:.1f}", (-gap, 0.0))
    ax.set_xlim(lo[0] - 2.5 * gap, hi[0] + gap)
    ax.set_ylim(lo[1] - 2.5 * gap, hi[1] + gap)
    ax.set_aspect("equal")
    ax.set_xlabel(f"{names[0]} [mm]")
    ax.set_ylabel(f"{names[1]} [mm]")
    ax.tick_params(labelsize=7)


def _caption(spec: KindSpec, mass: MassProperties, verdict: Printability) -> str:
    dims = ", ".join(f"{k} {v * MM_PER_M:.1f}" for k, v in feature_dimensions(spec).items())
    extra = spec.caption_extra()
    return (f"{dims} mm{extra}\nmass {mass.mass * 1000:.1f} g, volume "
            f"{mass.volume * 1e6:.2f} cm^3; {verdict.summary()}")


def render_png(spec: KindSpec, mesh: trimesh.Trimesh, mass: MassProperties,
               verdict: Printability, path: Path, *, dpi: int = 100) -> Path:
    """Draw the tool and write it as a PNG.

    Parameters
    ----------
    spec : KindSpec
        The tool (its dimensions are listed in the caption; its kind's colour, drawing
        plane and title).
    mesh : trimesh.Trimesh
        The tool's solid, tool frame, metres (drawn in millimetres).
    mass : MassProperties
        Mass and volume for the caption.
    verdict : Printability
        Build-volume verdict for the caption.
    path : pathlib.Path
        Output file.
    dpi : int
        Resolution of the 10 x 4.6 inch figure.

    Returns
    -------
    pathlib.Path
        ``path``.
    """
    mesh_mm = mesh.copy()
    mesh_mm.apply_scale(MM_PER_M)
    rgb = np.asarray(spec.RGBA[:3])
    fig = Figure(figsize=(10, 4.6))
    FigureCanvasAgg(fig)
    _shaded_view(fig.add_subplot(1, 2, 1, projection="3d"), mesh_mm, rgb)
    top = spec.DRAWING_PLANE == "top"
    ax2 = fig.add_subplot(1, 2, 2)
    _drawing(ax2, mesh_mm, (0, 1) if top else (0, 2), ("x", "y") if top else ("x", "z"), rgb)
    ax2.set_title("top view" if top else "side view", fontsize=9)
    fig.suptitle(f"{spec.name} ({spec.title()})", fontsize=11)
    fig.text(0.5, 0.015, _caption(spec, mass, verdict), ha="center", va="bottom", fontsize=8,
             wrap=True)
    fig.subplots_adjust(left=0.02, right=0.98, top=0.9, bottom=0.2, wspace=0.15)
    fig.savefig(path, dpi=dpi, format="png")
    return path
