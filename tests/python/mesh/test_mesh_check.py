"""check_tool_files: every kind passes, including OpenSCAD's rendering; tampering is caught."""

from __future__ import annotations

import shutil

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from creative_py.mesh.check import check_tool_files
from creative_py.mesh.export import write_tool_files
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec
from creative_py.mesh.tolerances import SCAD_VOLUME_RTOL, STL_VOLUME_RTOL

needs_openscad = pytest.mark.skipif(shutil.which("openscad") is None,
                                    reason="the openscad program is not installed")


@needs_openscad
def test_every_kind_passes_every_check(written, kind):
    report = check_tool_files(written[kind])
    assert report.problems == ()
    assert report.stl_watertight and report.stl_shells == 1
    assert report.stl_volume_rel_err <= STL_VOLUME_RTOL
    assert report.scad_volume_rel_err <= SCAD_VOLUME_RTOL
    assert report.scad_mismatch_rel < 1e-4
    assert report.inertia_valid


def test_a_tool_folder_can_be_checked_without_openscad(written):
    report = check_tool_files(written["prism"].directory, openscad=False)
    assert report.ok and report.scad_volume is None




@needs_openscad
def test_an_edited_scad_of_another_shape_is_caught(tmp_path):
    files = write_tool_files(HookSpec("hook1", 0.2), tmp_path, picture=False)
    text = files.scad.read_text().replace("hook_angle = 90;", "hook_angle = 89;")
    files.scad.write_text(text)
    report = check_tool_files(files)
    assert not report.ok
    assert any("OpenSCAD solid and STL differ" in p for p in report.problems)


@needs_openscad
def test_a_scad_that_does_not_render_is_reported(tmp_path):
    files = write_tool_files(BlockSpec("w", "box", 0.04, 0.05, 0.03), tmp_path, picture=False)
    files.scad.write_text("cube([1, 2, 3]")
    report = check_tool_files(files)
    assert any("openscad failed" in p for p in report.problems)


def test_a_wrong_mass_and_a_missing_mesh_are_reported(tmp_path):
    files = write_tool_files(BlockSpec("w", "triangular_prism", 0.1, 0.05, 0.03,
                                       tip_height=0.001), tmp_path, picture=False)
    files.urdf.write_text(files.urdf.read_text().replace('<mass value="0.1"/>',
                                                         '<mass value="0.2"/>'))
    files.meshes[0].unlink()
    report = check_tool_files(files, openscad=False)
    assert any("URDF mass 0.2 kg differs" in p for p in report.problems)
    assert any("file missing" in p for p in report.problems)


def test_a_truncated_stl_is_reported(tmp_path):
    files = write_tool_files(HookSpec("hook1", 0.2), tmp_path, picture=False)
    data = files.stl.read_bytes()
    n = int.from_bytes(data[80:84], "little") - 2
    files.stl.write_bytes(data[:80] + n.to_bytes(4, "little") + data[84:84 + 50 * n])
    report = check_tool_files(files, openscad=False)
    assert not report.stl_watertight
    assert any("not watertight" in p for p in report.problems)


@needs_openscad
@settings(max_examples=12, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(length=st.floats(0.05, 0.4), width=st.floats(0.003, 0.02),
       hook_length=st.floats(0.003, 0.06), hook_width=st.floats(0.003, 0.02),
       angle=st.floats(30.0, 150.0), side=st.sampled_from(["left", "right"]))
def test_the_scad_of_any_hook_is_the_same_solid_as_its_stl(tmp_path, length, width,
                                                           hook_length, hook_width, angle,
                                                           side):
    spec = HookSpec("h", length, handle_width=width, hook_length=hook_length,
                    hook_width=hook_width, hook_side=side, hook_angle_deg=angle,
                    grip_offset=0.01)
    files = write_tool_files(spec, tmp_path, picture=False, overwrite=True)
    report = check_tool_files(files)
    assert report.problems == ()
    assert report.scad_mismatch_rel < 1e-4
