"""Object poses and sizes from one or more depth cameras.

For each named body the points of every camera that sees it are unprojected to the
world frame and fused. The estimate describes the object's *bounding box in its own yaw
frame*:

* ``(x, y, z)`` is the centre of that box (world frame, metres). For a wedge whose
  block frame has its base on z = 0 this is the block origin raised by half the height.
* ``yaw`` (radians, about world +z) is the heading of the box's x axis, chosen by the
  object's symmetry (see below), and ``size = (dx, dy, dz)`` its extents (metres).

Why the extent and not the mean: a camera sees only the faces turned towards it, so the
mean of the visible points is pulled 9-18 mm towards the camera for a 3 cm cube seen from
1 m; the mid-point of the points' extent is not. With the sampling convention of
:mod:`creative_py.perception.unproject` the raw extents are unbiased (measured on a 3 cm
cube from 1 m: -0.2 mm mean, 0.35 mm s.d. at 320x240), so no pixel-size correction is
added.

Height: a camera looking down does not see the bottom face, and when walls (a tube) hide
the side faces the lowest visible point is not the bottom either. The bottom is, in
order of preference: the known support height ``support_z[name]`` (the table or floor top
the object rests on), the top surface minus the known height ``heights[name]``, or the
lowest observed point.

Yaw and symmetry (field ``symmetry`` of the estimate):

* ``"none"`` - a sloped top (a wedge): the height profile along the footprint's axes
  tells the length axis (the one the top slopes along) and its low end, the tip; ``yaw``
  is the heading of the tip direction (block +x), in (-pi, pi].
* ``"pi"`` - a flat rectangular footprint: x is the longer side, yaw in (-pi/2, pi/2].
* ``"half_pi"`` - a square footprint (a cube): yaw modulo pi/2, in (-pi/4, pi/4].
* ``"round"`` - a round footprint (an upright cylinder): yaw is meaningless and set to 0.

The footprint's axes come from the rectangle of least area around the points' top view
(a fine scan of headings over the convex hull), refined for square footprints (a cube,
a 5 x 5 cm wedge) by the fourth-order angular moment of the points seen from above,
which averages over all pixels instead of relying on a few edge pixels.

Depth noise (when a :class:`~creative_py.perception.noise.NoiseModel` is given, its
``depth_sigma_m`` is taken as the sensor's known noise): heights come from depth
median-filtered within each object's mask; the footprint from points seen along steep
rays (noise moves a point along its ray, so sideways only by sigma times the ray's
tilt); the top from the highest bin of the height profile rather than the maximum.

Measured (``bench/perception_error.py``, ``bench/results/perception.json``): the hook
world's cube at all variants and locations 0.6 mm mean, 1.5 mm worst, 2.3 degrees worst
(one pixel is 3.1 mm there, so an axis-aligned edge can lose half a pixel); the wedge
world's wedges 0.3 mm mean, 0.9 mm worst, 1.5 degrees worst without noise and 1.9 mm,
3.6 degrees worst with its 1 mm depth noise; no tip direction reversed.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Mapping, Sequence

import numpy as np
from scipy.spatial import ConvexHull, QhullError

from creative_py.perception.frame import Frame
from creative_py.perception.noise import NoiseModel
from creative_py.perception.segment import body_mask
from creative_py.perception.unproject import (camera_position, masked_median_depth,
                                              unproject_pixels)

log = logging.getLogger(__name__)


@dataclass(frozen=True)
class EstimatorConfig:
    """Tolerances of the estimator, all in one place.

    Attributes
    ----------
    min_points : int
        Fewest fused points for an object to be reported.
    min_pixels_per_camera : int
        Fewest pixels for a camera to count as seeing the object.
    extent_trim : float
        Fraction of points ignored at each end of every extent and of the heights
        (robustness to outliers), in [0, 0.5). Trimming shortens the extents of small
        objects (a 3 cm cube is 10 pixels across from 1 m at 320x240): the median
        filter is the better defence against depth noise.
    median_filter : bool or None
        Take heights (top, bottom, top-face band, slope profile) from the object's depth
        median-filtered over its 3x3 in-mask neighbourhood; the footprint (x, y) always
        comes from the raw depth, because at a silhouette the filter drags side-face
        pixels to the top face's depth and shifts them towards the camera (measured:
        1.0 mm mean centre error on a noise-free cube instead of 0.2 mm). None: on when
        a noise model with depth noise is given.
    yaw_step_deg : float
        Heading step of the minimum-area rectangle scan, degrees.
    profile_bins : int
        Bins of the height profile used to find a slope.
    slope_rise_fraction, slope_rise_min_m : float
        A footprint axis is sloped when the top rises across it by at least this
        fraction of the object's height and at least this many metres.
    square_tolerance : float
        Footprint sides differing by less than this fraction are a square.
    round_fill : float
        A square footprint whose hull fills less than this fraction of its rectangle
        is round (a disc fills pi/4 = 0.785).
    top_band_fraction : float
        Points within this fraction of the height below the top (or three times the
        remaining depth noise, if larger) form the top face.
    footprint_max_tilt : float
        With a noise model, only points whose camera ray has at most this horizontal
        fraction (sine of its angle from vertical; 0.5 = 30 degrees) shape the footprint,
        when there are enough of them: depth noise moves a point along its ray.
    """

    min_points: int = 12
    min_pixels_per_camera: int = 4
    extent_trim: float = 0.0
    median_filter: bool | None = None
    yaw_step_deg: float = 0.25
    profile_bins: int = 8
    slope_rise_fraction: float = 0.45
    slope_rise_min_m: float = 0.008
    square_tolerance: float = 0.12
    round_fill: float = 0.88
    top_band_fraction: float = 0.15
    footprint_max_tilt: float = 0.5


@dataclass(frozen=True)
class ObjectEstimate:
    """The estimated pose and size of one object (world frame, metres, radians).

    ``(x, y, z)`` is the centre of the object's bounding box in its yaw frame, ``yaw`` the
    heading of that frame's x axis (see the module docstring for the symmetry rules),
    ``size = (dx, dy, dz)`` the box's extents, ``n_points`` the number of fused points and
    ``cameras`` the names of the cameras that saw it.
    """

    name: str
    x: float
    y: float
    z: float
    yaw: float
    size: tuple[float, float, float]
    n_points: int
    cameras: tuple[str, ...]
    symmetry: str = "none"


def estimate_objects(frames: Sequence[Frame], bodies: Mapping[str, int],
                     noise: NoiseModel | None = None,
                     rng: np.random.Generator | None = None, *,
                     support_z: Mapping[str, float] | None = None,
                     heights: Mapping[str, float] | None = None,
                     config: EstimatorConfig = EstimatorConfig()) -> dict[str, ObjectEstimate]:
    """Estimate the pose and size of every named body that the cameras see.

    Parameters
    ----------
    frames : sequence of Frame
        Images of the same instant from one or more cameras.
    bodies : mapping of str to int
        Object name -> pybullet body id (as found in the segmentation images).
    noise : NoiseModel or None
        Sensor noise applied to each frame before estimation (needs ``rng``).
    rng : numpy.random.Generator or None
        Source of the noise; the same seed gives the same estimates.
    support_z : mapping of str to float, optional
        World z (metres) of the surface each object rests on; fixes the bottom face.
    heights : mapping of str to float, optional
        Known heights (metres), used when the support is not given.
    config : EstimatorConfig
        Tolerances.

    Returns
    -------
    dict of str to ObjectEstimate
        One entry per object seen by at least ``config.min_points`` points; objects
        not seen are left out (and logged).
    """
    _check_inputs(bodies, noise, rng, config)
    support_z = dict(support_z or {})
    heights = dict(heights or {})
    if noise is not None and not noise.is_zero:
        frames = [noise.apply(f, rng) for f in frames]
    smooth = (config.median_filter if config.median_filter is not None
              else noise is not None and noise.depth_sigma_m > 0.0)
    # The sensor's depth noise is known from its model; a 3x3 median leaves about half.
    sigma_z = 0.0 if noise is None else noise.depth_sigma_m * (0.5 if smooth else 1.0)
    out: dict[str, ObjectEstimate] = {}
    for name, bid in bodies.items():
        est = _estimate_body(frames, name, int(bid), smooth, sigma_z, support_z.get(name),
                             heights.get(name), config)
        if est is not None:
            out[name] = est
    return out


def _check_inputs(bodies: Mapping[str, int], noise: NoiseModel | None,
                  rng: np.random.Generator | None, config: EstimatorConfig) -> None:
    """Raise ValueError if a noise model comes without an rng, a body id is not an int
    >= 0 or ``config.extent_trim`` lies outside [0, 0.5)."""
    if noise is not None and not noise.is_zero and rng is None:
        raise ValueError("estimate_objects: a noise model needs an rng "
                         "(numpy.random.default_rng(seed)) so that results are reproducible")
    for name, bid in bodies.items():
        if isinstance(bid, bool) or not isinstance(bid, (int, np.integer)) or bid < 0:
            raise ValueError(f"estimate_objects: body id of {name!r} must be an int >= 0, "
                             f"got {bid!r}")
    trim = config.extent_trim
    if not 0.0 <= trim < 0.5:
        raise ValueError(f"estimate_objects: config field 'extent_trim' must lie in [0, 0.5), "
                         f"got {trim!r}")


def _estimate_body(frames: Sequence[Frame], name: str, bid: int, smooth: bool,
                   sigma_z: float, support_z: float | None, height: float | None,
                   config: EstimatorConfig) -> ObjectEstimate | None:
    """Fuse the points of body ``bid`` from every camera that sees it and estimate its
    pose and size, or return None (and log it) if fewer than ``config.min_points`` are
    seen. ``sigma_z`` is the depth noise left after smoothing (m)."""
    chunks, heights_f, tilts, cams = _body_points(frames, bid, smooth, config)
    n_pts = sum(len(c) for c in chunks)
    if n_pts < config.min_points:
        log.info("object %s not seen (%d points)", name, n_pts)
        return None
    pts, z, tilt = (np.concatenate(c) for c in (chunks, heights_f, tilts))
    # Depth noise moves a point along its ray, so sideways by sigma * tilt. With a
    # noise model, draw the footprint from steep rays (a downward camera sees the
    # whole footprint of an object on a surface) if there are enough of them.
    footprint = np.ones(len(pts), bool)
    steep = tilt <= config.footprint_max_tilt
    if sigma_z > 0.0 and steep.sum() >= config.min_points:
        footprint = steep
    return _estimate_one(name, pts, z, footprint, steep, cams, support_z, height,
                         config.extent_trim, sigma_z, config)


def _body_points(frames: Sequence[Frame], bid: int, smooth: bool, cfg: EstimatorConfig):
    """Return, from each camera that sees body ``bid`` with at least
    ``cfg.min_pixels_per_camera`` pixels, its points (N x 3, world frame, metres), their
    heights (median-filtered if ``smooth``) and the tilt of each point's ray from
    vertical (the sine), as three lists of arrays, and the cameras' names."""
    chunks, heights_f, tilts, cams = [], [], [], []
    for frame in frames:
        mask = body_mask(frame.seg, bid)
        n = int(mask.sum())
        if n < cfg.min_pixels_per_camera:
            continue
        rows, cols = np.nonzero(mask)
        pts = unproject_pixels(frame, rows, cols)
        chunks.append(pts)
        rays = pts - camera_position(frame)
        tilts.append(np.hypot(rays[:, 0], rays[:, 1]) / np.linalg.norm(rays, axis=1))
        if smooth:
            filtered = unproject_pixels(frame, rows, cols,
                                        masked_median_depth(frame.depth, mask))
            heights_f.append(filtered[:, 2])
        else:
            heights_f.append(pts[:, 2])
        cams.append(frame.name)
    return chunks, heights_f, tilts, tuple(cams)


def _estimate_one(name: str, pts: np.ndarray, z: np.ndarray, footprint: np.ndarray,
                  steep: np.ndarray, cams: tuple[str, ...], support: float | None, height: float | None,
                  trim: float, sigma_z: float, cfg: EstimatorConfig) -> ObjectEstimate:
    """Estimate one object from its fused points (N x 3) and their (filtered) heights z.

    ``footprint`` marks the points that may shape the footprint, ``steep`` those seen
    along rays within ``cfg.footprint_max_tilt`` of vertical.
    """
    xy_all = pts[:, :2]
    xy, z_fp = xy_all[footprint], z[footprint]
    theta = _min_area_heading(xy, cfg.yaw_step_deg)
    # The top surface along both footprint axes: its rise (a slope) and its highest part.
    profiles = [_profile(xy_all, z, theta + k * math.pi / 2, cfg) for k in (0, 1)]
    rises = [rise for rise, _ in profiles]
    top, bottom = _top_bottom(z, profiles, support, height, trim, sigma_z)
    dz = max(top - bottom, 0.0)
    ext = _extents(xy, theta, trim)
    du, dv = ext[1] - ext[0], ext[3] - ext[2]
    # Which footprint axis, if any, does the top slope along?
    k_slope = int(np.argmax([abs(r) for r in rises]))
    sloped = abs(rises[k_slope]) >= max(cfg.slope_rise_fraction * dz, cfg.slope_rise_min_m)
    square = max(du, dv) - min(du, dv) <= cfg.square_tolerance * max(du, dv)
    if sloped:
        symmetry = "none"
        from_above = xy_all[steep] if steep.sum() >= 8 else xy
        yaw = _sloped_yaw(from_above, theta, rises[k_slope], k_slope, square)
    else:
        band = z_fp >= top - max(cfg.top_band_fraction * dz, 3.0 * sigma_z, 1e-6)
        yaw, symmetry = _level_yaw(xy, band, theta, du, dv, square, cfg)
    ext = _extents(xy, yaw, trim)
    c_u, c_v = (ext[0] + ext[1]) / 2, (ext[2] + ext[3]) / 2
    cy, sy = math.cos(yaw), math.sin(yaw)
    x = c_u * cy - c_v * sy
    y = c_u * sy + c_v * cy
    dx = ext[1] - ext[0]
    dy = ext[3] - ext[2]
    return ObjectEstimate(name=name, x=float(x), y=float(y), z=float((top + bottom) / 2),
                          yaw=float(yaw), size=(float(dx), float(dy), float(dz)),
                          n_points=int(len(pts)), cameras=cams, symmetry=symmetry)


def _top_bottom(z: np.ndarray, profiles: list[tuple[float, float]], support: float | None,
                height: float | None, trim: float, sigma_z: float) -> tuple[float, float]:
    """Return the object's top and bottom heights (world z, metres): the top from the
    heights ``z`` (or, with noisy heights, the highest bin of the top's ``profiles``), the
    bottom from its support, its known height or the heights, in that order."""
    if sigma_z > 0.0:
        # With noisy heights the maximum is an outlier; a high quantile of the whole
        # object would cut a wedge's top: take the highest bin's quantile instead.
        top = max(high for _, high in profiles)
    else:
        top = _quantile(z, 1.0 - trim)
    if support is not None:
        bottom = float(support)
    elif height is not None:
        bottom = top - float(height)
    else:
        bottom = _quantile(z, trim)
    return top, bottom


def _sloped_yaw(from_above: np.ndarray, theta: float, rise: float, k_slope: int,
                square: bool) -> float:
    """Return the yaw (radians) of an object whose top slopes along footprint axis
    ``k_slope`` of heading ``theta`` by ``rise``: its tip (the low end) ahead. A square
    footprint's heading is refined from the points seen from above (x, y)."""
    if square:
        # A square footprint leaves the least-area heading loose (a 5 cm wedge is
        # 9 pixels across from 1.4 m): refine it with the angular moment of the
        # points seen from above, which cover the footprint evenly.
        fine = _square_heading(from_above, theta)
        theta += _wrap(fine - theta, math.pi / 4)
    yaw = theta + k_slope * math.pi / 2
    if rise > 0:  # the top rises towards +axis: the tip (low end) is behind
        yaw += math.pi
    return _wrap(yaw, math.pi)


def _level_yaw(xy: np.ndarray, band: np.ndarray, theta: float, du: float, dv: float,
               square: bool, cfg: EstimatorConfig) -> tuple[float, str]:
    """Return the yaw (radians) and symmetry of an object with a level top, from its
    footprint points ``xy`` (those of its top face marked by ``band``), the least-area
    heading ``theta`` and the footprint's sides ``du``, ``dv`` (metres): a round one has
    yaw 0, a square one its top face's heading (modulo pi/2), another its long side's
    (modulo pi)."""
    if square:
        if _fill_ratio(xy, du * dv) < cfg.round_fill:
            return 0.0, "round"
        yaw = _square_heading(xy[band], theta)
        return _wrap(yaw, math.pi / 4), "half_pi"
    yaw = theta if du >= dv else theta + math.pi / 2
    return _wrap(yaw, math.pi / 2), "pi"


def _quantile(values: np.ndarray, q: float) -> float:
    if q >= 1.0:
        return float(values.max())
    if q <= 0.0:
        return float(values.min())
    return float(np.quantile(values, q))


def _hull_points(xy: np.ndarray) -> np.ndarray:
    try:
        return xy[ConvexHull(xy).vertices]
    except (QhullError, ValueError):  # degenerate (collinear or too few) points
        return xy


def _min_area_heading(xy: np.ndarray, step_deg: float) -> float:
    """Return the heading in [0, pi/2) of the least-area rectangle around the points."""
    hull = _hull_points(xy)
    angles = np.radians(np.arange(0.0, 90.0, step_deg))
    c, s = np.cos(angles)[:, None], np.sin(angles)[:, None]
    u = hull[:, 0][None, :] * c + hull[:, 1][None, :] * s
    v = -hull[:, 0][None, :] * s + hull[:, 1][None, :] * c
    area = (u.max(axis=1) - u.min(axis=1)) * (v.max(axis=1) - v.min(axis=1))
    return float(angles[int(np.argmin(area))])


def _extents(xy: np.ndarray, heading: float, trim: float) -> tuple[float, float, float, float]:
    """Return (u_min, u_max, v_min, v_max) of the points in the frame rotated by heading."""
    c, s = math.cos(heading), math.sin(heading)
    u = xy[:, 0] * c + xy[:, 1] * s
    v = -xy[:, 0] * s + xy[:, 1] * c
    return (_quantile(u, trim), _quantile(u, 1.0 - trim),
            _quantile(v, trim), _quantile(v, 1.0 - trim))


def _profile(xy: np.ndarray, z: np.ndarray, heading: float,
             cfg: EstimatorConfig) -> tuple[float, float]:
    """Return the top surface's rise (metres) from the -axis to the +axis end, and its height.

    The top surface is a high quantile (0.9) of the heights in each of
    ``cfg.profile_bins`` bins along the axis; a straight line fitted to those gives the
    rise across the footprint, and the highest bin the top's height (world z, metres).
    """
    u = xy[:, 0] * math.cos(heading) + xy[:, 1] * math.sin(heading)
    lo, hi = float(u.min()), float(u.max())
    if hi - lo < 1e-9:
        return 0.0, float(np.quantile(z, 0.9))
    idx = np.minimum(((u - lo) / (hi - lo) * cfg.profile_bins).astype(int), cfg.profile_bins - 1)
    centres, tops = [], []
    for b in range(cfg.profile_bins):
        sel = idx == b
        if sel.sum() >= 2:
            centres.append(lo + (b + 0.5) * (hi - lo) / cfg.profile_bins)
            tops.append(float(np.quantile(z[sel], 0.9)))
    if len(centres) < 3:
        return 0.0, float(np.quantile(z, 0.9))
    slope = np.polyfit(centres, tops, 1)[0]
    return float(slope * (hi - lo)), max(tops)


def _fill_ratio(xy: np.ndarray, rect_area: float) -> float:
    if rect_area <= 0:
        return 1.0
    try:
        return float(ConvexHull(xy).volume / rect_area)  # 2-D hull: volume is the area
    except (QhullError, ValueError):
        return 1.0


def _square_heading(xy: np.ndarray, fallback: float) -> float:
    """Return the heading (mod pi/2) of a square from the 4th angular moment of its points.

    Points spread evenly over a square centred at the origin and aligned with the axes
    have ``sum r^4 exp(4 i phi)`` real and negative (the corners lie at 45 degrees).
    """
    if len(xy) < 8:
        return fallback
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    # Centre from a first extent along the fallback heading keeps the moment unbiased.
    c, s = math.cos(fallback), math.sin(fallback)
    u = xy[:, 0] * c + xy[:, 1] * s
    v = -xy[:, 0] * s + xy[:, 1] * c
    cu, cv = (u.min() + u.max()) / 2, (v.min() + v.max()) / 2
    centre = np.array([cu * c - cv * s, cu * s + cv * c])
    if not np.all((centre >= lo - 1e-9) & (centre <= hi + 1e-9)):
        return fallback
    d = xy - centre
    r2 = (d ** 2).sum(axis=1)
    phi = np.arctan2(d[:, 1], d[:, 0])
    m4 = np.sum(r2 ** 2 * np.exp(4j * phi))
    if abs(m4) < 1e-18:
        return fallback
    return float((np.angle(m4) - math.pi) / 4.0)


def _wrap(angle: float, half_period: float) -> float:
    """Wrap ``angle`` into (-half_period, half_period]."""
    period = 2.0 * half_period
    a = math.fmod(angle + half_period, period)
    if a <= 0.0:
        a += period
    return a - half_period
