"""Write a sized tool spec as files: URDF, SDF, OpenSCAD, STL, a picture and a manifest.

``write_tool_files(spec, out_dir)`` creates the folder ``out_dir/<name>/`` holding

==================  =====================================================================
``<name>.urdf``     one link, tool frame, metres; primitives, mass and full inertia
``<name>.sdf``      the same link as an SDF 1.6 model
``<name>.scad``     parametric OpenSCAD model, millimetres
``<name>.stl``      the printable solid (manifold3d union of the parts), millimetres
``<name>.png``      shaded 3D view and dimensioned drawing
``<name>.json``     manifest: spec, mass properties, printability, file names, and under
                    ``"print"`` the printed pieces, their joint and their G-code figures
``<name>_hull<i>.obj``  convex-hull parts (the wedge's prism) in metres, for URDF/SDF
``gazebo/<name>/``  Gazebo model folder; ``ros/<name>_description/``: ROS 2 package
                    (:mod:`creative_py.mesh.gazebo`)
``<name>_part<k>.stl``  each printed part in its print placement, millimetres (one part
                    when the tool fits the build volume); ``<name>_pin<k>.stl`` the dowel
                    pins joining the parts of a split tool (:mod:`creative_py.mesh.split`)
``<name>_part<k>.gcode``  each piece sliced with PrusaSlicer (``gcode=True``;
                    :mod:`creative_py.mesh.slicer`)
==================  =====================================================================

The folder appears complete or not at all: everything is written into a hidden temporary
folder inside ``out_dir`` and renamed into place at the end; on any error the temporary
folder is removed and nothing else changes.
"""

from __future__ import annotations

import dataclasses
import json
import logging
import os
import shutil
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from creative_py.mesh.gazebo import sim_model_paths, write_sim_models
from creative_py.mesh.link import hull_meshes, tool_link
from creative_py.mesh.printability import (PrintSettings, Printability, check_min_feature,
                                           printability)
from creative_py.mesh.render import render_png
from creative_py.mesh.scad import scad_text
from creative_py.mesh.sdf import sdf_text
from creative_py.mesh.slicer import PROFILE, slice_piece
from creative_py.mesh.solid import MassProperties, mass_properties, mesh_from_solid, tool_solid
from creative_py.mesh.spec import KindSpec, spec_from_dict, spec_volume
from creative_py.mesh.split import JOINT_KIND, Assembly, SplitError, split_tool
from creative_py.mesh.tolerances import MM_PER_M
from creative_py.mesh.urdf import urdf_text

log = logging.getLogger(__name__)

MANIFEST_VERSION = 1
FOLDER_MODE = 0o755
"""Permissions of a tool folder (``mkdtemp`` makes it private)."""


@dataclass(frozen=True)
class ToolFiles:
    """The files written for one tool and the figures computed on the way.

    Attributes
    ----------
    spec : KindSpec
        The tool.
    directory : pathlib.Path
        The tool's folder, ``out_dir/<name>``.
    urdf, sdf, scad, stl, manifest : pathlib.Path
        The files (STL and SCAD in millimetres; URDF, SDF and OBJ in metres).
    png : pathlib.Path or None
        The picture; None when it was not drawn.
    meshes : tuple of pathlib.Path
        OBJ files (metres) the URDF and SDF refer to; empty for hooks, boxes, cylinders.
    mass : MassProperties
        Mass, volume, centre of mass and inertia written into URDF and SDF.
    printability : Printability
        The build-volume verdict (also in the .scad header and the manifest).
    sim_models : tuple of pathlib.Path
        The files of the Gazebo model folder and the ROS package
        (:mod:`creative_py.mesh.gazebo`).
    assembly : dict
        The manifest's ``"print"`` entry: pieces, joint, volume check, G-code figures.
    pieces : tuple of pathlib.Path
        Each printed piece's STL (millimetres, print placement).
    gcode : tuple of pathlib.Path
        Each piece's G-code; empty when the tool was not sliced.
    """

    spec: KindSpec
    directory: Path
    urdf: Path
    sdf: Path
    scad: Path
    stl: Path
    png: Path | None
    manifest: Path
    meshes: tuple[Path, ...]
    mass: MassProperties
    printability: Printability
    sim_models: tuple[Path, ...] = ()
    assembly: dict = dataclasses.field(default_factory=dict)
    pieces: tuple[Path, ...] = ()
    gcode: tuple[Path, ...] = ()

    @property
    def fits_build_volume(self) -> bool:
        """Return whether the part fits the printer's build volume."""
        return self.printability.fits_build_volume

    def paths(self) -> tuple[Path, ...]:
        """Return every file of the tool."""
        picture = () if self.png is None else (self.png,)
        return ((self.urdf, self.sdf, self.scad, self.stl, self.manifest) + picture
                + self.meshes + self.sim_models + self.pieces + self.gcode)


def _manifest(spec: KindSpec, mass: MassProperties, verdict: Printability,
              names: dict[str, object]) -> dict:
    return {
        "manifest_version": MANIFEST_VERSION,
        "name": spec.name,
        "units": {"length": "m (STL and SCAD: mm)", "mass": "kg", "inertia": "kg m^2",
                  "angle": "deg"},
        "spec": dataclasses.asdict(spec),
        "spec_volume_m3": spec_volume(spec),
        "mass_kg": mass.mass,
        "mesh_volume_m3": mass.volume,
        "center_of_mass_m": list(mass.center_of_mass),
        "inertia_kg_m2": [list(row) for row in mass.inertia],
        "printability": dataclasses.asdict(verdict),
        "files": names,
    }


def _write_all(spec: KindSpec, folder: Path, settings: PrintSettings, picture: bool,
               gcode: bool = False) -> tuple[MassProperties, Printability, dict]:
    solid = tool_solid(spec)
    mesh = mesh_from_solid(solid)
    mass = mass_properties(spec, mesh)
    verdict = printability(spec, mesh, settings)
    link = tool_link(spec, mass)
    name = spec.name
    (folder / f"{name}.urdf").write_text(urdf_text(link), encoding="utf-8")
    (folder / f"{name}.sdf").write_text(sdf_text(link), encoding="utf-8")
    (folder / f"{name}.scad").write_text(scad_text(spec, verdict), encoding="utf-8")
    (folder / f"{name}.stl").write_bytes(mesh_from_solid(solid, MM_PER_M).export(file_type="stl"))
    hulls = hull_meshes(spec)
    for file_name, hull in hulls.items():
        (folder / file_name).write_text(hull.export(file_type="obj", include_normals=False),
                                        encoding="utf-8")
    if picture:
        render_png(spec, mesh, mass, verdict, folder / f"{name}.png")
    names = {"urdf": f"{name}.urdf", "sdf": f"{name}.sdf", "scad": f"{name}.scad",
             "stl": f"{name}.stl", "png": f"{name}.png" if picture else None,
             "meshes": sorted(hulls)}
    names.update(write_sim_models(spec, mass, mesh, folder))
    manifest = _manifest(spec, mass, verdict, names)
    manifest["print"] = write_print_files(spec, solid, folder, settings, gcode=gcode)
    (folder / f"{name}.json").write_text(json.dumps(manifest, indent=2) + "\n", encoding="utf-8")
    return mass, verdict, manifest["print"]


def write_print_files(spec: KindSpec, solid, folder: Path, settings: PrintSettings, *,
                      gcode: bool = False) -> dict:
    """Split the tool into printable pieces, write each as an STL and (``gcode``) slice it.

    Parameters
    ----------
    spec : KindSpec
        The tool.
    solid : manifold3d.Manifold
        Its designed solid (:func:`creative_py.mesh.solid.tool_solid`), metres.
    folder : pathlib.Path
        The tool's folder.
    settings : PrintSettings
        The printer.
    gcode : bool
        Slice every piece with PrusaSlicer (:func:`creative_py.mesh.slicer.slice_piece`).

    Returns
    -------
    dict
        The manifest's ``"print"`` entry (millimetres, seconds, grams): the build volume,
        the joint, the pieces with their STL, bounding box in the print placement,
        volume and placement (tool frame in metres -> bed in millimetres), and with
        ``gcode`` their G-code, print time and filament; the volume check of the union.
        Without ``gcode``, a tool that cannot be split into pieces that fit gets
        ``"printable": false`` and the reason, and no piece.

    Raises
    ------
    SplitError
        With ``gcode``: the tool cannot be cut into pieces that fit.
    SliceError
        The slicer rejected a piece.
    """
    start = time.perf_counter()
    try:
        assembly = split_tool(spec.name, solid, settings)
    except SplitError as exc:
        if gcode:
            raise
        # Only the design was asked for: say why it cannot be printed, write no piece.
        return {"printable": False, "reason": str(exc), "sliced": False, "pieces": [],
                "joints": []}
    entry = print_entry(assembly, settings)
    for piece, row in zip(assembly.pieces, entry["pieces"]):
        (folder / row["stl"]).write_bytes(
            piece.print_mesh(settings).export(file_type="stl"))
        if gcode:
            row.update(slice_piece(folder / row["stl"], folder / f"{piece.name}.gcode",
                                   settings).as_dict())
    entry["sliced"] = gcode
    if gcode:
        for key in ("print_time_s", "filament_mm", "filament_g"):
            entry[key] = round(sum(row[key] for row in entry["pieces"]), 3)
    entry["wall_time_s"] = round(time.perf_counter() - start, 3)  # split, write, slice
    return entry


def print_entry(assembly: Assembly, settings: PrintSettings) -> dict:
    """Return the manifest's ``"print"`` entry of an assembly, before slicing (mm, mm^3)."""
    mm, mm3 = MM_PER_M, MM_PER_M ** 3
    parts = [p for p in assembly.pieces if p.role == "part"]
    if assembly.joints:
        how = (f"{len(parts)} parts cut across the tool's {assembly.joints[0].axis} axis, "
               f"in order; each cut is joined by a square dowel pin pushed half into each "
               f"part's blind hole (hole = pin + 2 x {settings.joint_clearance * mm:g} mm, "
               f"{settings.joint_clearance * mm:g} mm deeper than half the pin); glue "
               "optional")
    else:
        how = "one piece: the tool fits the build volume"
    return {
        "printable": True,
        "build_volume_mm": [round(v * mm, 6) for v in settings.build_volume],
        "nozzle_mm": round(settings.nozzle_diameter * mm, 6),
        "min_feature_mm": round(settings.min_feature * mm, 6),
        "profile": PROFILE.name,
        "joint": JOINT_KIND if assembly.joints else None,
        "clearance_mm": round(settings.joint_clearance * mm, 6) if assembly.joints else None,
        "how_they_join": how,
        "design_volume_mm3": assembly.design_volume_m3 * mm3,
        "union_volume_mm3": assembly.union_volume_m3 * mm3,
        "union_volume_error_pct": 100 * assembly.union_volume_error,
        "union_mismatch_pct": 100 * assembly.mismatch,
        "pieces": [{
            "name": p.name, "role": p.role, "stl": f"{p.name}.stl",
            "volume_mm3": p.volume * mm3,
            "bounding_box_mm": [round(v, 4) for v in p.bed_extent(settings)],
            "up_axis": p.up_axis, "yaw_deg": p.yaw_deg,
            "placement": p.placement(settings).round(9).tolist(),
        } for p in assembly.pieces],
        "joints": [{
            "pin": j.pin, "joins": list(j.joins), "axis": j.axis, "cut_mm": j.cut_m * mm,
            "centre_mm": [v * mm for v in j.centre_m],
            "pin_section_mm": j.pin_section_m * mm, "pin_length_mm": j.pin_length_m * mm,
            "hole_section_mm": j.hole_section_m * mm, "hole_depth_mm": j.hole_depth_m * mm,
            "wall_mm": j.wall_m * mm,
        } for j in assembly.joints],
    }


def tool_files_in(directory: Path, spec: KindSpec, mass: MassProperties,
                  verdict: Printability, *, picture: bool = True,
                  assembly: dict | None = None) -> ToolFiles:
    """Return the :class:`ToolFiles` naming a tool's files inside ``directory``
    (``assembly``: the manifest's ``"print"`` entry, naming the pieces and G-code)."""
    name = spec.name
    assembly = assembly or {}
    rows = assembly.get("pieces", [])
    return ToolFiles(
        spec=spec, directory=directory,
        urdf=directory / f"{name}.urdf", sdf=directory / f"{name}.sdf",
        scad=directory / f"{name}.scad", stl=directory / f"{name}.stl",
        png=directory / f"{name}.png" if picture else None,
        manifest=directory / f"{name}.json",
        meshes=tuple(directory / f for f in sorted(hull_meshes(spec))),
        mass=mass, printability=verdict, sim_models=sim_model_paths(directory, spec),
        assembly=assembly,
        pieces=tuple(directory / r["stl"] for r in rows),
        gcode=tuple(directory / r["gcode"] for r in rows if r.get("gcode")))


def _missing_folders(folder: Path) -> list[Path]:
    """Return ``folder`` and its ancestors that do not exist yet, deepest first."""
    missing = []
    for p in (folder, *folder.parents):
        if p.exists():
            break
        missing.append(p)
    return missing


def _remove_empty(folders: list[Path]) -> None:
    """Remove each of ``folders`` (deepest first) that is still empty: a refused tool
    leaves no empty output folder behind."""
    for p in folders:
        try:
            p.rmdir()
        except OSError:
            break


def write_tool_files(spec: KindSpec, out_dir: Path | str, *,
                     settings: PrintSettings = PrintSettings(), overwrite: bool = False,
                     picture: bool = True, gcode: bool = False) -> ToolFiles:
    """Write a tool's URDF, SDF, OpenSCAD, STL, picture and manifest into ``out_dir/<name>/``.

    Parameters
    ----------
    spec : KindSpec
        The sized tool (metres).
    out_dir : path
        Parent folder (created if missing); the tool gets its own folder inside it.
    settings : PrintSettings
        The printer: minimum feature (refused below it) and build volume (a larger tool
        is split into pieces that fit, :func:`write_print_files`).
    overwrite : bool
        Replace an existing ``out_dir/<name>/``; otherwise that is a ``FileExistsError``.
    picture : bool
        Draw the PNG (about 0.4 s); without it the result's ``png`` is None.
    gcode : bool
        Slice every printed piece with PrusaSlicer (about 0.5-2 s a piece); runs and
        ``creative make-tool`` do.

    Returns
    -------
    ToolFiles
        The paths, the mass properties and the printability verdict.

    Raises
    ------
    ValueError
        A dimension below ``settings.min_feature`` or a spec whose parts do not make one
        solid; the message names the tool and the field. A :class:`SplitError` when the
        tool cannot be split into pieces that fit.
    SliceError
        The slicer rejected a piece (``gcode``); nothing is written.
    FileExistsError
        ``out_dir/<name>`` exists and ``overwrite`` is false, or it is not a folder.
    """
    check_min_feature(spec, settings)
    out_dir = Path(out_dir)
    made = _missing_folders(out_dir)  # removed again (if still empty) when this fails
    target = out_dir / spec.name
    try:  # a name or path the file system refuses (ENAMETOOLONG) leaves nothing either
        out_dir.mkdir(parents=True, exist_ok=True)
        if target.exists() and not target.is_dir():
            raise FileExistsError(f"{target}: exists and is not a tool folder; not "
                                  "replacing it")
        if target.exists() and not overwrite:
            raise FileExistsError(f"{target}: tool folder exists (pass overwrite=True to "
                                  "replace it)")
        tmp = Path(tempfile.mkdtemp(prefix=f".{spec.name}.", suffix=".tmp", dir=out_dir))
    except BaseException:
        _remove_empty(made)
        raise
    old: Path | None = None
    try:
        tmp.chmod(FOLDER_MODE)
        mass, verdict, assembly = _write_all(spec, tmp, settings, picture, gcode)
        if target.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{spec.name}.", suffix=".old", dir=out_dir))
            os.rename(target, old / spec.name)
        os.rename(tmp, target)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        if old is not None:
            if not target.exists():
                os.rename(old / spec.name, target)
            shutil.rmtree(old, ignore_errors=True)
        _remove_empty(made)
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)
    files = tool_files_in(target, spec, mass, verdict, picture=picture, assembly=assembly)
    log.info("wrote tool %s to %s (%s; %d printed pieces)", spec.name, target,
             verdict.summary(), len(files.pieces))
    return files


def read_tool_files(directory: Path | str) -> ToolFiles:
    """Return the :class:`ToolFiles` of a tool folder written by :func:`write_tool_files`.

    Raises
    ------
    ValueError
        The folder has no readable manifest, or the manifest is malformed.
    """
    directory = Path(directory)
    manifests = sorted(directory.glob("*.json"))
    if len(manifests) != 1:
        raise ValueError(f"{directory}: expected exactly one <name>.json manifest, "
                         f"found {len(manifests)}")
    source = str(manifests[0])
    try:
        data = json.loads(manifests[0].read_text(encoding="utf-8"))
        spec = spec_from_dict(data["spec"], source=source)
        mass = MassProperties(
            mass=float(data["mass_kg"]), volume=float(data["mesh_volume_m3"]),
            center_of_mass=tuple(data["center_of_mass_m"]),
            inertia=tuple(tuple(r) for r in data["inertia_kg_m2"]))
        p = data["printability"]
        verdict = Printability(bool(p["fits_build_volume"]), tuple(p["extent"]),
                               p["up_axis"], p["yaw_deg"], p["reason"])
        picture = data["files"]["png"] is not None
        assembly = data.get("print") or {}
    except (KeyError, TypeError, json.JSONDecodeError) as exc:
        raise ValueError(f"{source}: malformed tool manifest ({exc!r})") from None
    return tool_files_in(directory, spec, mass, verdict, picture=picture, assembly=assembly)
