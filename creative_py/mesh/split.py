"""Split a tool larger than the printer's build volume into pieces joined by dowel pins.

A tool that fits the build volume (:func:`creative_py.mesh.printability.bed_placement`)
is one piece. A larger one is cut by planes across its longest axis (a hook's handle)
into the fewest equal parts that each fit, at most :data:`MAX_PIECES`; each cut is
joined by a **square dowel pin**: a separate printed piece of square section, half in
each part, in a blind hole of the pin's section plus twice the joint clearance
(:data:`JOINT_CLEARANCE`, 0.2 mm per side) and as much longer at each end. A square pin
lies flat on the bed with its layers along its length (strong in bending across the
joint) and its hole is bridged by a flat ceiling, so both print without supports. The
pin is as wide as the section allows while the hole's walls stay at least
``settings.min_feature`` thick (and a quarter of the section), and it reaches 1.5 times the
section's size into each part; where the section changes near the cut (a wedge's slope)
a shallower or narrower pin is taken (:data:`_PIN_CHOICES`).

Checks (manifold3d booleans, tool frame, metres): every hole lies inside the designed
solid with walls of at least ``min_feature`` on every side and at its end; every piece is
one solid that fits the build volume in some flat placement; the union of the parts and
the inserted pins equals the designed solid within :data:`SPLIT_VOLUME_RTOL` of its
volume (the symmetric difference: the clearance gaps, about 0.1-0.2 % for a 9 mm handle).
A tool that cannot be split so raises :class:`SplitError`.

Each piece is written in its print placement (:meth:`Piece.print_mesh`: lying on the bed
in the placement found, centred on the bed, millimetres); :meth:`Piece.placement` is the
transform from the tool frame to the bed, so the assembly can be rebuilt from the files.
"""

from __future__ import annotations

from dataclasses import dataclass

import manifold3d
import numpy as np
import trimesh

from creative_py.mesh.printability import PrintSettings, bed_placement, placement_rotation
from creative_py.mesh.solid import mesh_from_solid
from creative_py.mesh.tolerances import MAX_PIECES, MM_PER_M, SPLIT_VOLUME_RTOL

JOINT_KIND = "square_dowel_pin"
"""The joint of a split tool (the ``"joint"`` of the tool's JSON ``"print"`` entry)."""

_AXES = "xyz"

_PIN_CHOICES = tuple((depth, shrink) for shrink in (1.0, 0.75, 0.5)
                     for depth in (1.5, 1.0, 0.75))
"""Pins tried at a cut, in order: (depth into each part / section size, fraction of the
widest pin the section allows)."""


class SplitError(ValueError):
    """A tool larger than the build volume cannot be cut into printable pieces; the
    message names the tool and the reason."""


@dataclass(frozen=True)
class Piece:
    """One printed piece of a tool.

    Attributes
    ----------
    name : str
        ``<tool>_part<k>`` (a part of the tool) or ``<tool>_pin<k>`` (a dowel pin).
    role : {"part", "pin"}
        What it is.
    solid : manifold3d.Manifold
        The piece where it sits in the assembled tool, tool frame, metres.
    up_axis : str
        Tool-frame axis pointing up on the bed.
    yaw_deg : float
        Turn about the bed's normal, degrees.
    """

    name: str
    role: str
    solid: manifold3d.Manifold
    up_axis: str
    yaw_deg: float

    @property
    def volume(self) -> float:
        """Return the piece's volume, m^3."""
        return float(self.solid.volume())

    def placement(self, settings: PrintSettings) -> np.ndarray:
        """Return the 4x4 transform from the tool frame (metres) to the bed (millimetres):
        turned into its placement, lying on z = 0, centred on the bed."""
        rot = placement_rotation(self.up_axis, self.yaw_deg)
        lo, hi = _bounds(self.solid.transform(_affine(rot, np.zeros(3))))
        centre = np.array([settings.build_volume[0] / 2 - (lo[0] + hi[0]) / 2,
                           settings.build_volume[1] / 2 - (lo[1] + hi[1]) / 2, -lo[2]])
        out = np.eye(4)
        out[:3, :3] = rot * MM_PER_M
        out[:3, 3] = centre * MM_PER_M
        return out

    def print_mesh(self, settings: PrintSettings) -> trimesh.Trimesh:
        """Return the piece in its print placement, millimetres (for its STL)."""
        mesh = mesh_from_solid(self.solid)
        mesh.apply_transform(self.placement(settings))
        return mesh

    def bed_extent(self, settings: PrintSettings) -> tuple[float, float, float]:
        """Return the piece's size along the bed's x, y, z in its placement, mm."""
        mesh = self.print_mesh(settings)
        return tuple(float(v) for v in mesh.bounds[1] - mesh.bounds[0])


@dataclass(frozen=True)
class Joint:
    """A square dowel pin joining two parts across a cut.

    Attributes
    ----------
    pin : str
        The pin piece's name.
    joins : tuple of str
        The two parts it joins.
    axis : str
        Tool-frame axis the cut is across (and the pin along).
    cut_m : float
        The cut plane's coordinate on ``axis``, metres.
    centre_m : tuple of float
        The pin's centre in the tool frame, metres.
    pin_section_m : float
        Side of the pin's square section, metres.
    pin_length_m : float
        Pin length (half in each part), metres.
    hole_section_m, hole_depth_m : float
        Side of each hole's square section and its depth from the cut face, metres.
    wall_m : float
        Wall around the hole at the cut face, metres (everywhere along the hole at
        least ``settings.min_feature``: checked).
    """

    pin: str
    joins: tuple[str, str]
    axis: str
    cut_m: float
    centre_m: tuple[float, float, float]
    pin_section_m: float
    pin_length_m: float
    hole_section_m: float
    hole_depth_m: float
    wall_m: float


@dataclass(frozen=True)
class Assembly:
    """A tool as printed pieces.

    Attributes
    ----------
    name : str
        The tool.
    pieces : tuple of Piece
        Parts first (in order along the cut axis), then pins.
    joints : tuple of Joint
        One per cut (empty for a one-piece tool).
    design_volume_m3 : float
        Volume of the designed solid.
    union_volume_m3 : float
        Volume of the union of every piece (pins inserted).
    mismatch : float
        Volume of the symmetric difference of that union and the design, as a fraction
        of the design's volume.
    """

    name: str
    pieces: tuple[Piece, ...]
    joints: tuple[Joint, ...]
    design_volume_m3: float
    union_volume_m3: float
    mismatch: float

    @property
    def union_volume_error(self) -> float:
        """Return (union volume - design volume) / design volume."""
        return (self.union_volume_m3 - self.design_volume_m3) / self.design_volume_m3


def split_tool(name: str, design: manifold3d.Manifold,
               settings: PrintSettings = PrintSettings()) -> Assembly:
    """Return the printed pieces of a tool's solid.

    Parameters
    ----------
    name : str
        The tool's name (the pieces are ``<name>_part<k>`` and ``<name>_pin<k>``).
    design : manifold3d.Manifold
        The designed solid, tool frame, metres (:func:`creative_py.mesh.solid.tool_solid`).
    settings : PrintSettings
        The printer: build volume, minimum feature, joint clearance.

    Raises
    ------
    SplitError
        No cut into at most :data:`MAX_PIECES` parts fits, a joint would have a wall
        thinner than the minimum feature, or the pieces do not make the design.
    """
    volume = float(design.volume())
    whole = _placed(f"{name}_part1", "part", design, settings)
    if whole is not None:
        return Assembly(name, (whole,), (), volume, volume, 0.0)
    lo, hi = _bounds(design)
    axis = int(np.argmax(hi - lo))
    bed = " x ".join(f"{b * MM_PER_M:.0f}" for b in settings.build_volume)
    for n in range(2, MAX_PIECES + 1):
        cuts = [lo[axis] + k * (hi[axis] - lo[axis]) / n for k in range(1, n)]
        slabs = _slabs(design, axis, cuts)
        if any(_placement_of(s, settings) is None for s in slabs):
            continue
        joints, holes, pins = [], [], []
        for k, cut in enumerate(cuts, start=1):
            joint, hole, pin = _joint(name, design, axis, cut, k, settings)
            joints.append(joint)
            holes.append(hole)
            pins.append(pin)
        all_holes = manifold3d.Manifold.batch_boolean(holes, manifold3d.OpType.Add)
        pieces = []
        for k, slab in enumerate(slabs, start=1):
            piece = _placed(f"{name}_part{k}", "part", slab - all_holes, settings)
            if piece is None:
                break
            pieces.append(piece)
        else:
            for k, pin in enumerate(pins, start=1):
                placed = _placed(f"{name}_pin{k}", "pin", pin, settings)
                if placed is None:
                    raise SplitError(f"{name}: dowel pin {k} does not fit the {bed} mm "
                                     "build volume")
                pieces.append(placed)
            return _checked(name, design, volume, pieces, joints)
    size = " x ".join(f"{v * MM_PER_M:.1f}" for v in hi - lo)
    raise SplitError(f"{name}: the tool is {size} mm; cut across its {_AXES[axis]} axis "
                     f"into up to {MAX_PIECES} parts, some part still does not fit the {bed} "
                     "mm build volume")


def _checked(name: str, design: manifold3d.Manifold, volume: float, pieces: list[Piece],
             joints: list[Joint]) -> Assembly:
    union = manifold3d.Manifold.batch_boolean([p.solid for p in pieces],
                                              manifold3d.OpType.Add)
    mismatch = (float((design - union).volume()) + float((union - design).volume())) / volume
    if mismatch > SPLIT_VOLUME_RTOL:
        raise SplitError(f"{name}: the pieces with their pins inserted differ from the "
                         f"designed solid by {100 * mismatch:.2f} % of its volume (at most "
                         f"{100 * SPLIT_VOLUME_RTOL:g} % allowed)")
    return Assembly(name, tuple(pieces), tuple(joints), volume, float(union.volume()),
                    mismatch)


def _joint(name: str, design: manifold3d.Manifold, axis: int, cut: float, k: int,
           settings: PrintSettings) -> tuple[Joint, manifold3d.Manifold, manifold3d.Manifold]:
    """Return the joint at one cut, its hole (both halves) and its pin."""
    clearance = settings.joint_clearance
    lo, hi = _section_bounds(design, axis, cut)
    others = [i for i in range(3) if i != axis]
    side = float(min(hi[i] - lo[i] for i in others))
    wall = max(settings.min_feature, side / 4)
    largest = side - 2 * wall - 2 * clearance
    if largest < settings.min_feature:
        raise SplitError(
            f"{name}: the section at the cut {_AXES[axis]} = {cut * MM_PER_M:.1f} mm is "
            f"{side * MM_PER_M:.1f} mm across: too small for a dowel pin of at least "
            f"{settings.min_feature * MM_PER_M:.1f} mm in walls of "
            f"{settings.min_feature * MM_PER_M:.1f} mm")
    centre = np.zeros(3)
    centre[axis] = cut
    for i in others:
        centre[i] = (lo[i] + hi[i]) / 2
    # The largest pin, deepest first, whose hole keeps its walls inside the design (a
    # section that changes near the cut, like a wedge's slope, needs a smaller one).
    for depth_factor, shrink in _PIN_CHOICES:
        depth, pin_side = depth_factor * side, shrink * largest
        if pin_side < settings.min_feature:
            continue
        hole_side = pin_side + 2 * clearance
        # Walls: the hole grown by the minimum feature on every side must lie in the design.
        grown = _box(centre, axis, 2 * (depth + clearance + settings.min_feature),
                     hole_side + 2 * settings.min_feature)
        if float((grown - design).volume()) <= 1e-6 * float(grown.volume()):
            break
    else:
        raise SplitError(
            f"{name}: no dowel pin of at least {settings.min_feature * MM_PER_M:.1f} mm fits "
            f"the cut at {_AXES[axis]} = {cut * MM_PER_M:.1f} mm with walls of "
            f"{settings.min_feature * MM_PER_M:.1f} mm (the section changes too near it)")
    pin = _box(centre, axis, 2 * depth, pin_side)
    hole = _box(centre, axis, 2 * (depth + clearance), hole_side)
    joint = Joint(
        pin=f"{name}_pin{k}", joins=(f"{name}_part{k}", f"{name}_part{k + 1}"),
        axis=_AXES[axis], cut_m=float(cut), centre_m=tuple(float(v) for v in centre),
        pin_section_m=float(pin_side), pin_length_m=float(2 * depth),
        hole_section_m=float(hole_side), hole_depth_m=float(depth + clearance),
        wall_m=float((side - hole_side) / 2))
    return joint, hole, pin


def _slabs(design: manifold3d.Manifold, axis: int, cuts: list[float],
           ) -> list[manifold3d.Manifold]:
    """Return the design cut by planes across ``axis`` at ``cuts``, in order."""
    normal = [0.0, 0.0, 0.0]
    normal[axis] = 1.0
    out, rest = [], design
    for cut in cuts:
        above, below = rest.split_by_plane(normal, cut)
        out.append(below)
        rest = above
    out.append(rest)
    return out


def _section_bounds(design: manifold3d.Manifold, axis: int, cut: float,
                    ) -> tuple[np.ndarray, np.ndarray]:
    """Return the tool-frame bounds of the design's section at a cut (a slab a micrometre
    thick); their coordinates on ``axis`` are the cut's, within that."""
    lo, hi = _bounds(design)
    size = (hi - lo) + 1.0
    size[axis] = 2e-6
    centre = (lo + hi) / 2
    centre[axis] = cut
    slab = design ^ manifold3d.Manifold.cube(tuple(size), center=True).translate(
        tuple(centre))
    if slab.is_empty():
        raise SplitError(f"cut at {_AXES[axis]} = {cut * MM_PER_M:.1f} mm misses the solid")
    return _bounds(slab)


def _box(centre: np.ndarray, axis: int, length: float, side: float) -> manifold3d.Manifold:
    size = [side, side, side]
    size[axis] = length
    return manifold3d.Manifold.cube(size, center=True).translate(tuple(centre))


def _bounds(solid: manifold3d.Manifold) -> tuple[np.ndarray, np.ndarray]:
    b = solid.bounding_box()
    return np.array(b[:3]), np.array(b[3:])


def _affine(rot: np.ndarray, shift: np.ndarray) -> list[list[float]]:
    return np.hstack([rot, shift[:, None]]).tolist()


def _placement_of(solid: manifold3d.Manifold, settings: PrintSettings):
    if solid.is_empty():
        return None
    mesh = mesh_from_solid(solid)
    return bed_placement(mesh.convex_hull.vertices, settings)


def _placed(name: str, role: str, solid: manifold3d.Manifold,
            settings: PrintSettings) -> Piece | None:
    """Return ``solid`` as a piece in its first fitting placement, or None."""
    if len(solid.decompose()) != 1:
        raise SplitError(f"{name}: the piece falls apart into {len(solid.decompose())} "
                         "solids")
    placement = _placement_of(solid, settings)
    if placement is None:
        return None
    return Piece(name, role, solid, *placement)
