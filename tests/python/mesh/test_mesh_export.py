"""write_tool_files: the tool folder, its file formats and units, and atomicity."""

from __future__ import annotations

import itertools
import json
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
import trimesh

from creative_py.mesh import export
from creative_py.mesh.export import read_tool_files, write_tool_files
from creative_py.mesh.spec import Box, Cylinder, spec_mass
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec


def test_every_file_is_written_in_its_own_folder(written, kind):
    files = written[kind]
    assert files.directory.name == files.spec.name
    for path in files.paths():
        assert path.is_file() and path.stat().st_size > 0, path
    assert _files_in(files.directory) == sorted(
        str(p.relative_to(files.directory)) for p in files.paths())
    assert files.png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def _files_in(folder) -> list[str]:
    """Return every file below ``folder``, relative to it, sorted."""
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*") if p.is_file())


def _contents(folder) -> dict[str, bytes]:
    """Return every file below ``folder`` (relative path -> bytes)."""
    return {name: (folder / name).read_bytes() for name in _files_in(folder)}


def test_stl_is_in_millimetres_and_in_the_tool_frame(written, kind):
    files = written[kind]
    stl = trimesh.load_mesh(files.stl)
    mesh_mm = files.mass.volume * 1e9
    assert stl.volume == pytest.approx(mesh_mm, rel=1e-5)
    np.testing.assert_allclose(stl.bounds, _part_bounds(files.spec) * 1000, atol=1e-3)


def _part_bounds(spec) -> np.ndarray:
    """Return the tool-frame bounds (metres) of the spec's parts, from their corners."""
    points = []
    for part in spec.parts():
        if isinstance(part, Box):
            c, s = math.cos(part.yaw), math.sin(part.yaw)
            for dx, dy, dz in itertools.product(*[(-h / 2, h / 2) for h in part.size]):
                points.append((part.center[0] + c * dx - s * dy,
                               part.center[1] + s * dx + c * dy, part.center[2] + dz))
        elif isinstance(part, Cylinder):
            x, y, z = part.center
            r, h = part.radius, part.height / 2
            points += [(x - r, y - r, z - h), (x + r, y + r, z + h)]
        else:
            points += list(part.vertices)
    points = np.asarray(points)
    return np.array([points.min(axis=0), points.max(axis=0)])


def test_urdf_has_one_link_with_the_spec_mass_and_the_centre_of_mass(written, kind):
    files = written[kind]
    root = ET.parse(files.urdf).getroot()
    (link,) = root.findall("link")
    inertial = link.find("inertial")
    assert float(inertial.find("mass").get("value")) == pytest.approx(spec_mass(files.spec))
    com = [float(v) for v in inertial.find("origin").get("xyz").split()]
    assert com == pytest.approx(list(files.mass.center_of_mass), abs=1e-12)
    assert len(link.findall("collision")) == len(files.spec.parts())


def test_scad_starts_with_named_parameters_in_millimetres(written):
    text = written["hook_angled"].scad.read_text()
    for line in ("handle_length = 250;", "handle_width = 10;", "hook_length = 30;",
                 "hook_width = 8;", "hook_side = -1;", "hook_angle = 60;"):
        assert line in text
    assert "linear_extrude" in written["prism"].scad.read_text()
    assert "cylinder(h = height, d = diameter" in written["cylinder"].scad.read_text()


def test_an_oversize_tool_is_written_and_flagged(tmp_path):
    files = write_tool_files(HookSpec("hook_long", 0.55), tmp_path, picture=False)
    assert not files.fits_build_volume
    assert "printed in pieces (too large for the build volume in one)" in \
        files.scad.read_text()
    manifest = json.loads(files.manifest.read_text())
    assert manifest["printability"]["fits_build_volume"] is False
    assert "split" in manifest["printability"]["reason"]


def test_manifest_reads_back_into_the_same_tool_files(written, kind):
    files = written[kind]
    again = read_tool_files(files.directory)
    assert again.spec == files.spec
    assert again.paths() == files.paths()
    assert again.mass == files.mass
    assert again.printability == files.printability


def test_a_spec_below_the_minimum_wall_leaves_nothing_behind(tmp_path):
    with pytest.raises(ValueError, match="thin: hook_width is 1.00 mm"):
        write_tool_files(HookSpec("thin", 0.3, hook_width=0.001), tmp_path)
    assert list(tmp_path.iterdir()) == []


def test_an_existing_tool_folder_is_kept_unless_overwrite(tmp_path):
    first = write_tool_files(BlockSpec("w", "box", 0.04, 0.05, 0.03), tmp_path, picture=False)
    with pytest.raises(FileExistsError, match="overwrite=True"):
        write_tool_files(BlockSpec("w", "box", 0.08, 0.05, 0.03), tmp_path, picture=False)
    assert read_tool_files(first.directory).spec.length == 0.04
    write_tool_files(BlockSpec("w", "box", 0.08, 0.05, 0.03), tmp_path, picture=False,
                     overwrite=True)
    assert read_tool_files(first.directory).spec.length == 0.08
    assert [p.name for p in tmp_path.iterdir()] == ["w"]


def test_a_failure_while_writing_leaves_no_partial_files(tmp_path, monkeypatch):
    """Fault injection: the picture step fails after URDF, SDF, SCAD and STL are written."""
    def broken_render(*args, **kwargs):
        raise OSError("disk full while writing the picture")

    old = write_tool_files(HookSpec("hook1", 0.3), tmp_path, picture=False)
    before = _contents(old.directory)
    monkeypatch.setattr(export, "render_png", broken_render)
    with pytest.raises(OSError, match="disk full"):
        write_tool_files(HookSpec("hook1", 0.4), tmp_path, overwrite=True)
    with pytest.raises(OSError, match="disk full"):
        write_tool_files(HookSpec("hook2", 0.4), tmp_path)
    assert [p.name for p in tmp_path.iterdir()] == ["hook1"]
    assert _contents(old.directory) == before


def test_a_failed_final_rename_restores_the_previous_tool(tmp_path, monkeypatch):
    """Fault injection at the last step: the old folder is moved back, nothing is left."""
    old = write_tool_files(HookSpec("hook1", 0.3), tmp_path, picture=False)
    before = _contents(old.directory)
    real_rename = export.os.rename

    def rename(src, dst):
        if ".tmp" in str(src):
            raise OSError("rename refused")
        real_rename(src, dst)

    monkeypatch.setattr(export.os, "rename", rename)
    with pytest.raises(OSError, match="rename refused"):
        write_tool_files(HookSpec("hook1", 0.4), tmp_path, picture=False, overwrite=True)
    assert [p.name for p in tmp_path.iterdir()] == ["hook1"]
    assert _contents(old.directory) == before


def test_a_file_in_the_way_is_never_replaced(tmp_path):
    (tmp_path / "hook1").write_text("not a folder")
    with pytest.raises(FileExistsError, match="not a tool folder"):
        write_tool_files(HookSpec("hook1", 0.3), tmp_path, picture=False, overwrite=True)
    assert [p.name for p in tmp_path.iterdir()] == ["hook1"]
    assert (tmp_path / "hook1").read_text() == "not a folder"


def test_a_malformed_manifest_is_reported_with_its_file(tmp_path):
    files = write_tool_files(BlockSpec("w", "box", 0.04, 0.05, 0.03), tmp_path, picture=False)
    files.manifest.write_text('{"spec": {"kind": "block"}}')
    with pytest.raises(ValueError, match=r"w\.json"):
        read_tool_files(files.directory)
