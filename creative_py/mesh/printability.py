"""Can a hobby FDM printer make this tool? Minimum feature size and build-volume fit.

A dimension below :data:`~creative_py.mesh.tolerances.MIN_FEATURE` makes the spec
unprintable and is refused with a ``ValueError`` naming the field; so does a wedge whose
tip is thinner than :data:`~creative_py.mesh.tolerances.MIN_TIP` (two nozzle widths: a
knife edge, ``tip_height`` 0, tapers below it for its last ``MIN_TIP / slope``). A part that does not
fit the build volume in any flat placement (any of its three axes up, any yaw on the bed,
diagonals included) is *not* refused: the files are still written and the result says
``fits_build_volume = False`` with the reason (the design must be split into pieces or
printed on a larger machine). The .scad file repeats the verdict in a comment.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:  # only a type here; importing trimesh costs the command line seconds
    import trimesh

from creative_py.mesh.spec import KindSpec
from creative_py.mesh.tolerances import (BUILD_VOLUME, FIT_MARGIN, FIT_YAW_STEP_DEG,
                                         JOINT_CLEARANCE, MIN_FEATURE, MIN_TIP, MM_PER_M,
                                         NOZZLE_DIAMETER)

Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class PrintSettings:
    """The printer a tool is checked against.

    Attributes
    ----------
    min_feature : float
        Smallest printable dimension of any part, metres (at least two nozzle widths).
    build_volume : tuple of float
        Build volume along the printer's x, y, z, metres (default 250 x 210 x 210 mm, the
        bed of the slicer profile). A larger tool is split into pieces that fit
        (:mod:`creative_py.mesh.split`).
    nozzle_diameter : float
        The nozzle, metres.
    joint_clearance : float
        Gap between a split tool's dowel pin and its hole, per side, metres.
    min_tip : float
        Thinnest end of a tapering part (a wedge's tip height), metres.
    """

    min_feature: float = MIN_FEATURE
    build_volume: Vec3 = BUILD_VOLUME
    nozzle_diameter: float = NOZZLE_DIAMETER
    joint_clearance: float = JOINT_CLEARANCE
    min_tip: float = MIN_TIP

    def __post_init__(self) -> None:
        values = (self.min_feature, self.nozzle_diameter, self.joint_clearance,
                  *self.build_volume)
        if len(self.build_volume) != 3 or not all(
                isinstance(v, (int, float)) and np.isfinite(v) and v > 0 for v in values):
            raise ValueError(f"print settings: every length must be a positive number of "
                             f"metres and the build volume three of them, got {self}")
        if self.min_feature < 2 * self.nozzle_diameter - 1e-12:
            raise ValueError(f"print settings: min_feature {self.min_feature * MM_PER_M:g} mm "
                             f"is below two nozzle widths "
                             f"({2 * self.nozzle_diameter * MM_PER_M:g} mm)")


@dataclass(frozen=True)
class Printability:
    """The verdict on printing one tool.

    Attributes
    ----------
    fits_build_volume : bool
        Whether the part fits the build volume lying on one of its faces.
    extent : tuple of float
        Axis-aligned size of the part in the tool frame (x, y, z), metres.
    up_axis : str or None
        Tool-frame axis pointing up on the bed ("z", "x" or "y") when it fits.
    yaw_deg : float or None
        Rotation of the part about the bed's normal when it fits, degrees
        (0: the part's first horizontal axis along the printer's x).
    reason : str
        Why it does not fit (empty when it does).
    """

    fits_build_volume: bool
    extent: Vec3
    up_axis: str | None
    yaw_deg: float | None
    reason: str

    def summary(self) -> str:
        """Return a one-line human-readable verdict (millimetres)."""
        ex = " x ".join(f"{v * MM_PER_M:.1f}" for v in self.extent)
        if self.fits_build_volume:
            return (f"fits the build volume: {ex} mm, lying with its {self.up_axis} axis up, "
                    f"turned {self.yaw_deg:g} deg on the bed")
        return f"printed in pieces (too large for the build volume in one): {self.reason}"


def feature_dimensions(spec: KindSpec) -> dict[str, float]:
    """Return the spec's printable dimensions by field name, metres (a blunted wedge's
    ``tip_height`` too: it is held to ``PrintSettings.min_tip``, the rest to
    ``min_feature``)."""
    return spec.feature_dimensions()


def check_min_feature(spec: KindSpec, settings: PrintSettings = PrintSettings()) -> None:
    """Raise ``ValueError`` naming the first dimension a hobby printer cannot print.

    Every dimension of :func:`feature_dimensions` must reach ``settings.min_feature``;
    a wedge's tip (``tip_height``, its thinnest section) must reach ``settings.min_tip``.

    Parameters
    ----------
    spec : KindSpec
        The tool.
    settings : PrintSettings
        The printer (``min_feature`` and ``min_tip`` in metres).
    """
    for field_name, value in feature_dimensions(spec).items():
        if not (isinstance(value, (int, float)) and np.isfinite(value) and value > 0):
            raise ValueError(f"{spec.name}: {field_name} must be a positive number of metres, "
                             f"got {value!r}")
        if field_name != "tip_height" and value < settings.min_feature:
            raise ValueError(
                f"{spec.name}: {field_name} is {value * MM_PER_M:.2f} mm, below the "
                f"{settings.min_feature * MM_PER_M:.2f} mm minimum feature a hobby FDM "
                "printer can print")
    thin = thin_tip_length(spec, settings.min_tip)
    if thin > 0:
        raise ValueError(
            f"{spec.name}: the wedge's tip is {spec.tip_height * MM_PER_M:.2f} mm high, so it "
            f"is thinner than {settings.min_tip * MM_PER_M:.2f} mm (two nozzle widths) for its "
            f"last {thin * MM_PER_M:.1f} mm; blunt it (tip_height >= "
            f"{settings.min_tip * MM_PER_M:.2f} mm)")


def thin_tip_length(spec: KindSpec, min_tip: float = MIN_TIP) -> float:
    """Return how far (metres) from its tip a wedge is thinner than ``min_tip``.

    0.0 for a blunted wedge whose tip reaches ``min_tip`` and for every other shape; for
    a prism whose tip is lower, the run over which its height (falling linearly from
    ``height`` at the back to ``tip_height`` at the tip) is below ``min_tip``.
    """
    return spec.thin_tip_length(min_tip)


def printability(spec: KindSpec, mesh: trimesh.Trimesh,
                 settings: PrintSettings = PrintSettings()) -> Printability:
    """Return whether the tool's mesh fits the build volume, and how to place it.

    Parameters
    ----------
    spec : KindSpec
        The tool (its minimum features are checked first; see :func:`check_min_feature`).
    mesh : trimesh.Trimesh
        The tool's solid in the tool frame, metres.
    settings : PrintSettings
        The printer.
    """
    check_min_feature(spec, settings)
    points = np.asarray(mesh.convex_hull.vertices, dtype=float)
    extent = tuple(float(v) for v in points.max(axis=0) - points.min(axis=0))
    placement = bed_placement(points, settings)
    if placement is not None:
        up, yaw = placement
        return Printability(True, extent, up, yaw, "")  # type: ignore[arg-type]
    size = " x ".join(f"{v * MM_PER_M:.1f}" for v in extent)
    bed = " x ".join(f"{v * MM_PER_M:.0f}" for v in settings.build_volume)
    reason = (f"the part is {size} mm and fits no flat or diagonal placement in the {bed} mm "
              "build volume; it is split into pieces joined by dowel pins, each printed on "
              "its own (the pieces are listed with the tool's print figures)")
    return Printability(False, extent, None, None, reason)  # type: ignore[arg-type]


UP_AXES = (("z", (0, 1, 2)), ("x", (1, 2, 0)), ("y", (2, 0, 1)))
"""The flat placements tried, in order: the tool-frame axis that points up on the bed,
and the tool-frame axes that become the bed's x, y and z (cyclic: a proper rotation)."""


def bed_placement(points: np.ndarray, settings: PrintSettings = PrintSettings(),
                  ) -> tuple[str, float] | None:
    """Return the first flat placement in which ``points`` fit the build volume.

    Parameters
    ----------
    points : array of shape (n, 3)
        The part's points (its convex hull's vertices suffice), tool frame, metres.
    settings : PrintSettings
        The printer (build volume; :data:`FIT_MARGIN` is kept to every edge).

    Returns
    -------
    (up_axis, yaw_deg) or None
        The tool-frame axis pointing up ("z", "x" or "y", tried in that order) and the
        turn about the bed's normal (degrees, 0 to 179 in steps of
        :data:`FIT_YAW_STEP_DEG`); None when no placement fits.
    """
    points = np.asarray(points, dtype=float)
    extent = points.max(axis=0) - points.min(axis=0)
    bx, by, bz = (b - 2 * FIT_MARGIN for b in settings.build_volume)
    yaws = np.radians(np.arange(0.0, 180.0, FIT_YAW_STEP_DEG))
    cos, sin = np.cos(yaws)[:, None], np.sin(yaws)[:, None]
    for up, (i, j, k) in UP_AXES:
        if extent[k] > bz:
            continue
        u, v = points[:, i][None, :], points[:, j][None, :]
        ru, rv = u * cos - v * sin, u * sin + v * cos
        du = ru.max(axis=1) - ru.min(axis=1)
        dv = rv.max(axis=1) - rv.min(axis=1)
        ok = np.flatnonzero((du <= bx) & (dv <= by))
        if ok.size:
            return up, round(float(np.degrees(yaws[ok[0]])), 6)
    return None


def placement_rotation(up_axis: str, yaw_deg: float) -> np.ndarray:
    """Return the 3x3 rotation taking tool-frame vectors to the bed's frame for a
    placement of :func:`bed_placement` (the ``up_axis`` becomes the bed's z, then the
    part turns by ``yaw_deg`` about it)."""
    order = dict(UP_AXES)[up_axis]
    permute = np.eye(3)[list(order)]
    a = np.radians(yaw_deg)
    yaw = np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0],
                    [0.0, 0.0, 1.0]])
    return yaw @ permute
