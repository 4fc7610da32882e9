"""Check a tool's written files: the checker the tool-creation tests run on every tool.

It reads the files back (nothing is taken from memory): the STL must be one watertight
shell whose volume equals ``spec_volume``; URDF and SDF must name every file they use and
carry the spec's mass and a physically valid inertia tensor; the .scad, rendered by the
``openscad`` program, must give the same solid as the STL (volume and symmetric
difference). Loading into pybullet is the simulator's business and is tested there.
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

import manifold3d
import numpy as np
import trimesh

from creative_py.mesh.export import ToolFiles, read_tool_files
from creative_py.mesh.slicer import SliceError, read_gcode
from creative_py.mesh.printability import PrintSettings
from creative_py.mesh.spec import spec_mass, spec_volume
from creative_py.mesh.tolerances import (FIT_MARGIN, MASS_RTOL, MM_PER_M, OPENSCAD_TIMEOUT_S,
                                         SCAD_MISMATCH_RTOL, SCAD_VOLUME_RTOL,
                                         SPLIT_VOLUME_RTOL, STL_VOLUME_RTOL)

MM3_PER_M3 = MM_PER_M**3


@dataclass(frozen=True)
class ToolCheck:
    """What the files of one tool were found to be. Volumes in m^3, masses in kg.

    ``problems`` lists every failed check in words; ``ok`` is true when it is empty.
    The ``scad_*`` fields are None when OpenSCAD was not run.
    """

    name: str
    stl_watertight: bool
    stl_shells: int
    stl_volume: float
    spec_volume: float
    stl_volume_rel_err: float
    urdf_mass: float | None
    sdf_mass: float | None
    inertia_valid: bool
    fits_build_volume: bool
    scad_volume: float | None = None
    scad_volume_rel_err: float | None = None
    scad_mismatch_rel: float | None = None
    scad_seconds: float | None = None
    problems: tuple[str, ...] = field(default=())

    @property
    def ok(self) -> bool:
        """Return whether every check passed."""
        return not self.problems


@dataclass(frozen=True)
class PrintCheck:
    """What a tool's printed pieces were found to be, read back from their files.

    Attributes
    ----------
    pieces : int
        Number of pieces (parts and pins).
    bounding_boxes_mm : tuple of tuple of float
        Each piece's STL extent on the bed (x, y, z), mm.
    fits : bool
        Every piece's STL lies inside the build volume.
    union_mismatch : float or None
        Symmetric difference of the pieces, moved back into the tool frame and united
        (manifold3d), and the tool's STL, as a fraction of the STL's volume.
    sliced : int
        Pieces with a G-code file whose estimates read back and whose extrusions lie on
        the bed.
    problems : tuple of str
        Every failed check in words.
    """

    pieces: int
    bounding_boxes_mm: tuple[tuple[float, float, float], ...]
    fits: bool
    union_mismatch: float | None
    sliced: int
    problems: tuple[str, ...] = field(default=())

    @property
    def ok(self) -> bool:
        """Return whether every check passed."""
        return not self.problems


def check_print_files(files: ToolFiles | Path | str) -> PrintCheck:
    """Check a tool's printed pieces from their files (the manifest's ``"print"`` entry).

    Each piece's STL (millimetres, print placement) must be one watertight solid inside
    the build volume; moved back into the tool frame by the inverse of its recorded
    placement, the pieces must unite (manifold3d) into the tool's STL within
    :data:`~creative_py.mesh.tolerances.SPLIT_VOLUME_RTOL` of its volume; every G-code
    named must exist, give a positive print time and filament, and extrude on the bed.
    """
    if not isinstance(files, ToolFiles):
        files = read_tool_files(files)
    entry = files.assembly
    problems: list[str] = []
    if not entry:
        return PrintCheck(0, (), False, None, 0, (f"{files.manifest}: no \"print\" entry",))
    if not entry.get("printable", False):
        return PrintCheck(0, (), False, None, 0,
                          (f"{files.spec.name}: not printable: {entry.get('reason')}",))
    bed = np.asarray(entry["build_volume_mm"], dtype=float)
    settings = PrintSettings(build_volume=tuple(bed / MM_PER_M))
    boxes, solids, sliced = [], [], 0
    for row in entry["pieces"]:
        path = files.directory / row["stl"]
        if not path.is_file():
            problems.append(f"{path}: file missing")
            continue
        mesh = _load_mm_mesh(path)
        boxes.append(_check_piece_mesh(path, mesh, bed, problems))
        solids.append(_in_tool_frame(mesh, np.asarray(row["placement"], dtype=float)))
        if row.get("gcode"):
            sliced += _check_gcode(files, row, settings, problems)
    mismatch = _union_mismatch(files, solids, problems) if solids else None
    fits = len(boxes) == len(entry["pieces"]) and not any("outside" in p for p in problems)
    return PrintCheck(len(entry["pieces"]), tuple(boxes), fits, mismatch, sliced,
                      tuple(problems))


def _check_piece_mesh(path: Path, mesh: trimesh.Trimesh, bed: np.ndarray,
                      problems: list[str]) -> tuple[float, float, float]:
    """Add to ``problems`` if a piece's STL ``mesh`` (mm) is not one watertight solid or
    lies outside the build volume ``bed`` (mm); return its extent (x, y, z), mm."""
    slack = FIT_MARGIN * MM_PER_M / 2
    if not mesh.is_watertight or mesh.body_count != 1:
        problems.append(f"{path}: not one watertight solid")
    lo, hi = mesh.bounds
    if (lo < -slack).any() or (hi > bed + slack).any():
        problems.append(f"{path}: outside the {' x '.join(f'{v:g}' for v in bed)} mm "
                        f"build volume (bounds {lo.round(2)} .. {hi.round(2)})")
    return tuple(float(v) for v in hi - lo)


def _in_tool_frame(mesh: trimesh.Trimesh, placement: np.ndarray) -> manifold3d.Manifold:
    """Return a piece's STL ``mesh`` (mm, as placed on the bed) moved back into the tool
    frame by the inverse of its ``placement`` (4 x 4, tool frame in m to bed in mm)."""
    rot = placement[:3, :3] / MM_PER_M
    back = (np.asarray(mesh.vertices) - placement[:3, 3]) @ rot  # rot^T per row
    return _manifold(trimesh.Trimesh(back, mesh.faces, process=False))


def _check_gcode(files: ToolFiles, row: Mapping[str, Any], settings: PrintSettings,
                 problems: list[str]) -> bool:
    """Return whether a piece's G-code reads back with a positive print time and
    filament (else add why to ``problems``)."""
    try:
        est = read_gcode(files.directory / row["gcode"], settings, piece=row["name"])
    except (SliceError, OSError) as exc:
        problems.append(str(exc))
        return False
    if est.print_time_s > 0 and est.filament_g > 0 and est.filament_mm > 0:
        return True
    problems.append(f"{row['gcode']}: no positive print time or filament")
    return False


def _union_mismatch(files: ToolFiles, solids: list[manifold3d.Manifold],
                    problems: list[str]) -> float | None:
    """Return the symmetric difference of the pieces ``solids`` united and the tool's
    STL, as a fraction of the STL's volume (None without the STL); add to
    ``problems`` if it exceeds :data:`~creative_py.mesh.tolerances.SPLIT_VOLUME_RTOL`."""
    if not files.stl.is_file():
        return None
    design = _manifold(_load_mm_mesh(files.stl))
    union = manifold3d.Manifold.batch_boolean(solids, manifold3d.OpType.Add)
    mismatch = float(((design - union).volume() + (union - design).volume())
                     / design.volume())
    if mismatch > SPLIT_VOLUME_RTOL:
        problems.append(f"{files.spec.name}: the pieces united differ from the tool's STL "
                        f"by {mismatch:.2%} of its volume")
    return mismatch


def _load_mm_mesh(path: Path) -> trimesh.Trimesh:
    mesh = trimesh.load_mesh(path, file_type="stl", process=True)
    mesh.merge_vertices()
    return mesh


def _manifold(mesh: trimesh.Trimesh) -> manifold3d.Manifold:
    return manifold3d.Manifold(manifold3d.Mesh(
        vert_properties=np.asarray(mesh.vertices, dtype=np.float32),
        tri_verts=np.asarray(mesh.faces, dtype=np.uint32)))


def _inertia_problems(tensor: np.ndarray) -> list[str]:
    if not np.allclose(tensor, tensor.T, rtol=0, atol=1e-12 * np.abs(tensor).max()):
        return ["inertia tensor is not symmetric"]
    moments = np.linalg.eigvalsh(tensor)
    if moments.min() <= 0:
        return [f"inertia tensor is not positive definite (principal moments {moments})"]
    a, b, c = sorted(moments)
    if a + b < c * (1 - 1e-9):
        return [f"principal moments {moments} violate the triangle inequality"]
    return []


def _urdf_mass_inertia(path: Path) -> tuple[float, np.ndarray, list[str]]:
    root = ET.parse(path).getroot()
    links = root.findall("link")
    if len(links) != 1:
        raise ValueError(f"{path}: expected one <link>, found {len(links)}")
    inertial = links[0].find("inertial")
    mass = float(inertial.find("mass").get("value"))
    i = {k: float(v) for k, v in inertial.find("inertia").attrib.items()}
    tensor = np.array([[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]],
                       [i["ixz"], i["iyz"], i["izz"]]])
    meshes = [m.get("filename") for m in root.iter("mesh")]
    return mass, tensor, meshes


def _sdf_mass(path: Path) -> tuple[float, list[str]]:
    root = ET.parse(path).getroot()
    masses = root.findall("./model/link/inertial/mass")
    if len(masses) != 1:
        raise ValueError(f"{path}: expected one model/link/inertial/mass, found {len(masses)}")
    meshes = [u.text for u in root.iter("uri")]
    return float(masses[0].text), meshes


def render_scad(scad: Path, out_stl: Path, *, openscad: str = "openscad") -> float:
    """Render a .scad file to STL with the ``openscad`` program; return the seconds taken.

    Raises
    ------
    FileNotFoundError
        The program is not installed.
    RuntimeError
        OpenSCAD failed; the message carries its error output.
    """
    exe = shutil.which(openscad)
    if exe is None:
        raise FileNotFoundError(f"{openscad}: program not found (install the openscad package)")
    start = time.perf_counter()
    done = subprocess.run([exe, "-o", str(out_stl), str(scad)], capture_output=True, text=True,
                          timeout=OPENSCAD_TIMEOUT_S, check=False)
    seconds = time.perf_counter() - start
    if done.returncode != 0 or not out_stl.exists():
        raise RuntimeError(f"{scad}: openscad failed (exit {done.returncode}): "
                           f"{done.stderr.strip()[-2000:]}")
    return seconds


def check_tool_files(files: ToolFiles | Path | str, *, openscad: bool = True,
                     openscad_program: str = "openscad") -> ToolCheck:
    """Check the files of one tool and return a report.

    Parameters
    ----------
    files : ToolFiles or path
        What :func:`~creative_py.mesh.export.write_tool_files` returned, or the tool's
        folder (read through its manifest).
    openscad : bool
        Render the .scad with OpenSCAD and compare it with the STL (0.04-0.5 s).
    openscad_program : str
        Name or path of the OpenSCAD program.

    Returns
    -------
    ToolCheck
        Volumes, masses, the OpenSCAD agreement and the list of problems found.
    """
    if not isinstance(files, ToolFiles):
        files = read_tool_files(files)
    spec = files.spec
    problems: list[str] = []
    for path in files.paths():
        if not path.is_file():
            problems.append(f"{path}: file missing")
    if not (files.stl.is_file() and files.urdf.is_file() and files.sdf.is_file()):
        return ToolCheck(spec.name, False, 0, 0.0, spec_volume(spec), 1.0, None, None, False,
                         files.fits_build_volume, problems=tuple(problems))

    stl = _load_mm_mesh(files.stl)
    expected_volume = spec_volume(spec)
    stl_volume, stl_err, shells = _stl_against_spec(files, stl, expected_volume, problems)
    urdf_mass, sdf_mass, inertia_problems = _descriptions_against_spec(files, problems)
    report = dict(name=spec.name, stl_watertight=bool(stl.is_watertight), stl_shells=shells,
                  stl_volume=stl_volume, spec_volume=expected_volume,
                  stl_volume_rel_err=stl_err, urdf_mass=urdf_mass, sdf_mass=sdf_mass,
                  inertia_valid=not inertia_problems,
                  fits_build_volume=files.fits_build_volume)
    if openscad and files.scad.is_file():
        report.update(_scad_against_stl(files, stl, stl_volume, openscad_program, problems))
    return ToolCheck(**report, problems=tuple(problems))


def _stl_against_spec(files: ToolFiles, stl, expected_volume: float,
                      problems: list[str]) -> tuple[float, float, int]:
    """Return the STL's volume (m^3), its relative error against the spec's and its
    shell count; append to ``problems`` what is wrong (not watertight, not one shell,
    a volume off by more than :data:`STL_VOLUME_RTOL`)."""
    stl_volume = float(stl.volume) / MM3_PER_M3
    stl_err = abs(stl_volume - expected_volume) / expected_volume
    shells = int(stl.body_count)
    if not stl.is_watertight:
        problems.append(f"{files.stl}: not watertight")
    if shells != 1:
        problems.append(f"{files.stl}: {shells} shells, expected one")
    if stl_err > STL_VOLUME_RTOL:
        problems.append(f"{files.stl}: volume {stl_volume:.6g} m^3 differs from spec_volume "
                        f"{expected_volume:.6g} m^3 by {stl_err:.2%}")
    return stl_volume, stl_err, shells


def _descriptions_against_spec(files: ToolFiles, problems: list[str]):
    """Return the URDF's and the SDF's mass (kg; None if unreadable) and the URDF's
    inertia problems; append to ``problems`` what is wrong (an unreadable file, a mass
    off the spec's by more than :data:`MASS_RTOL`, a bad inertia, a missing mesh)."""
    mass = spec_mass(files.spec)
    urdf_mass = sdf_mass = None
    inertia_problems = ["not read"]
    meshes: list[str] = []
    try:
        urdf_mass, tensor, urdf_meshes = _urdf_mass_inertia(files.urdf)
        inertia_problems = _inertia_problems(tensor)
        meshes += urdf_meshes
    except (ET.ParseError, AttributeError, KeyError, TypeError, ValueError) as exc:
        problems.append(f"{files.urdf}: unreadable link description ({exc!r})")
    try:
        sdf_mass, sdf_meshes = _sdf_mass(files.sdf)
        meshes += sdf_meshes
    except (ET.ParseError, AttributeError, TypeError, ValueError) as exc:
        problems.append(f"{files.sdf}: unreadable model description ({exc!r})")
    for label, value in (("URDF", urdf_mass), ("SDF", sdf_mass)):
        if value is not None and abs(value - mass) > MASS_RTOL * mass:
            problems.append(f"{label} mass {value} kg differs from spec_mass {mass} kg")
    if urdf_mass is not None:
        problems += [f"{files.urdf}: {p}" for p in inertia_problems]
    for name in meshes:
        if not (name and (files.directory / name).is_file()):
            problems.append(f"mesh {name!r} referenced by URDF/SDF is missing")
    return urdf_mass, sdf_mass, inertia_problems


def _scad_against_stl(files: ToolFiles, stl, stl_volume: float, program: str,
                      problems: list[str]) -> dict:
    """Render the tool's .scad with OpenSCAD ``program`` and return its volume (m^3),
    its relative error and mismatch against the STL, and the render's seconds (empty
    if it did not render); append to ``problems`` what is wrong."""
    with tempfile.TemporaryDirectory(prefix="creative_scad_") as tmp:
        out = Path(tmp) / "scad.stl"
        try:
            seconds = render_scad(files.scad, out, openscad=program)
        except (FileNotFoundError, RuntimeError, subprocess.TimeoutExpired) as exc:
            problems.append(str(exc))
            return {}
        scad_mesh = _load_mm_mesh(out)
        scad_volume = float(scad_mesh.volume) / MM3_PER_M3
        scad_err = abs(scad_volume - stl_volume) / stl_volume
        a, b = _manifold(stl), _manifold(scad_mesh)
        mismatch = ((a - b).volume() + (b - a).volume()) / MM3_PER_M3 / stl_volume
        if scad_err > SCAD_VOLUME_RTOL:
            problems.append(f"{files.scad}: OpenSCAD volume {scad_volume:.6g} m^3 "
                            f"differs from the STL's by {scad_err:.2%}")
        if mismatch > SCAD_MISMATCH_RTOL:
            problems.append(f"{files.scad}: OpenSCAD solid and STL differ by "
                            f"{mismatch:.2%} of the volume (wrong shape or place)")
        return dict(scad_volume=scad_volume, scad_volume_rel_err=scad_err,
                    scad_mismatch_rel=mismatch, scad_seconds=seconds)
