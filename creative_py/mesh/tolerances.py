"""Every tolerance, resolution and printing limit of the mesh package, in one place.

Lengths are metres unless a name says ``_MM``; relative tolerances are fractions.
"""

from __future__ import annotations

# --- Geometry resolution -------------------------------------------------------------
CYLINDER_SEGMENTS = 128
"""Facets around a cylinder in the STL and the .scad (``$fn``). Vertices lie on the
circle, so the faceted volume is smaller than pi r^2 h by (2 pi / n)^2 / 6: 0.04 %."""

MM_PER_M = 1000.0
"""STL and OpenSCAD files are in millimetres; everything else is in metres."""

NUMERICAL_NOISE_RTOL = 1e-12
"""Centre-of-mass coordinates and inertia products smaller than this fraction of the
part's size (or of the largest inertia entry) are floating-point noise and written as 0."""

# --- Printability (a hobby FDM printer with a 0.4 mm nozzle) ---------------------------
MIN_FEATURE = 0.002
"""Smallest printable dimension of any part (wall, width, thickness, reach), metres:
five 0.4 mm extrusion widths. A spec with a smaller dimension is refused."""

NOZZLE_DIAMETER = 0.0004
"""The printer's nozzle, metres (the slicer profile ``profiles/generic_pla_0.4.ini``).
No feature of a printed piece, a joint's walls included, may be thinner than two nozzle
widths; :data:`MIN_FEATURE` is larger still."""

MIN_TIP = 2 * NOZZLE_DIAMETER
"""Thinnest a tapering edge may end, metres: two 0.4 mm extrusion widths, the least a
slicer lays down as solid perimeters. A wedge is blunted to at least this
(``BlockSpec.tip_height``; the block size model's ``min_tip_height_m``); a knife edge
(tip_height 0) is refused, since its last ``MIN_TIP / slope`` metres would not print."""

BUILD_VOLUME = (0.250, 0.210, 0.210)
"""Build volume x, y, z in metres (a Prusa i3 MK3S-class bed, that of the slicer profile).
A part that does not fit is split into pieces that do (:mod:`creative_py.mesh.split`)."""

JOINT_CLEARANCE = 0.0002
"""Gap between a dowel pin and the walls of its hole, on every side and at each end,
metres: a pin printed at its nominal size slides into a hole printed at pin + 2 x 0.2 mm."""

SPLIT_VOLUME_RTOL = 0.005
"""The pieces of a split tool, pins inserted, must make the designed solid within this
fraction of its volume (the symmetric difference, checked with manifold3d)."""

MAX_PIECES = 8
"""Most parts a tool is cut into to fit the build volume (pins not counted)."""

FIT_YAW_STEP_DEG = 1.0
"""Yaw step when searching a diagonal placement on the bed, degrees."""

FIT_MARGIN = 0.0005
"""Clearance kept to the build volume's edges when checking the fit, metres."""

# --- Checks --------------------------------------------------------------------------
STL_VOLUME_RTOL = 1e-3
"""The STL's volume must equal ``spec_volume`` within this fraction (facets included)."""

SCAD_VOLUME_RTOL = 1e-2
"""OpenSCAD's rendering of the .scad must match the STL's volume within this fraction."""

SCAD_MISMATCH_RTOL = 1e-3
"""Volume of the symmetric difference of the OpenSCAD mesh and the STL, as a fraction of
the STL's volume: catches a .scad of the right volume but the wrong shape or place."""

MASS_RTOL = 1e-9
"""The mass written into URDF and SDF must equal ``spec_mass`` within this fraction."""

OPENSCAD_TIMEOUT_S = 60.0
"""Longest a single ``openscad`` rendering may take, seconds."""
