"""Printing a tool: split to fit the build volume, dowel-pin joints, PrusaSlicer G-code.

The split is checked on the solid (manifold3d) and again from the written files
(:func:`creative_py.mesh.check.check_print_files`: pieces moved back by their recorded
placement and united); the slicer is the real ``prusa-slicer``, on a few small pieces
only (the whole-tool slicing runs in ``tests/python/fabrication/test_manufacture.py``).
"""

from __future__ import annotations

import json
import shutil

import numpy as np
import pytest

from creative_py.mesh.check import check_print_files
from creative_py.mesh.export import write_tool_files
from creative_py.mesh.printability import PrintSettings
from creative_py.mesh.slicer import SliceError, parse_duration, read_gcode, slice_piece
from creative_py.mesh.solid import tool_solid
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec
from creative_py.mesh.split import SplitError, split_tool
from creative_py.mesh.tolerances import MM_PER_M, SPLIT_VOLUME_RTOL

needs_slicer = pytest.mark.skipif(shutil.which("prusa-slicer") is None,
                                  reason="prusa-slicer is not installed")

LONG_HOOK = HookSpec("long_hook", 0.60, handle_width=0.009, hook_length=0.030,
                     hook_width=0.009, mass=None)
"""The shape of the hook case's created hook: 600 x 39 x 9 mm."""

BED = np.array(PrintSettings().build_volume) * MM_PER_M


def test_a_tool_that_fits_is_one_piece_without_joint(tmp_path):
    spec = BlockSpec("prism", "triangular_prism", 0.16, 0.085, 0.0275, mass=None,
                     tip_height=0.0024)
    files = write_tool_files(spec, tmp_path, picture=False)
    entry = json.loads(files.manifest.read_text())["print"]
    assert entry["printable"] and entry["joint"] is None and entry["joints"] == []
    assert [p["name"] for p in entry["pieces"]] == ["prism_part1"]
    assert files.pieces == (files.directory / "prism_part1.stl",)
    assert entry["union_mismatch_pct"] == 0.0
    check = check_print_files(files)
    assert check.ok, check.problems
    assert check.union_mismatch < 1e-6


def test_the_600_mm_hook_is_split_into_parts_that_fit_joined_by_a_pin(tmp_path):
    assembly = split_tool(LONG_HOOK.name, tool_solid(LONG_HOOK))
    assert [p.role for p in assembly.pieces] == ["part", "part", "pin"]
    (joint,) = assembly.joints
    settings = PrintSettings()
    for piece in assembly.pieces:
        assert (np.array(piece.bed_extent(settings)) <= BED).all(), piece.name
    # The joint keeps two nozzle widths and the minimum feature everywhere.
    assert joint.pin_section_m >= settings.min_feature >= 2 * settings.nozzle_diameter
    assert joint.wall_m >= settings.min_feature
    assert joint.hole_section_m == pytest.approx(joint.pin_section_m + 2 * 0.0002)
    assert 0 < assembly.mismatch <= SPLIT_VOLUME_RTOL

    files = write_tool_files(LONG_HOOK, tmp_path, picture=False)
    assert not files.fits_build_volume
    entry = json.loads(files.manifest.read_text())["print"]
    assert entry["joint"] == "square_dowel_pin" and entry["clearance_mm"] == 0.2
    assert [p["stl"] for p in entry["pieces"]] == [
        "long_hook_part1.stl", "long_hook_part2.stl", "long_hook_pin1.stl"]
    assert entry["joints"][0]["joins"] == ["long_hook_part1", "long_hook_part2"]
    assert abs(entry["union_volume_error_pct"]) <= 100 * SPLIT_VOLUME_RTOL
    check = check_print_files(files)                   # from the files alone
    assert check.ok, check.problems
    assert check.pieces == 3 and check.fits
    assert check.union_mismatch == pytest.approx(assembly.mismatch, rel=0.02)
    for box, row in zip(check.bounding_boxes_mm, entry["pieces"]):
        assert box == pytest.approx(row["bounding_box_mm"], abs=1e-3)


def test_a_smaller_build_volume_makes_more_pieces():
    small = PrintSettings(build_volume=(0.15, 0.15, 0.15))
    assembly = split_tool(LONG_HOOK.name, tool_solid(LONG_HOOK), small)
    parts = [p for p in assembly.pieces if p.role == "part"]
    assert len(parts) > 2 and len(assembly.joints) == len(parts) - 1
    for piece in assembly.pieces:
        assert (np.array(piece.bed_extent(small)) <= 150.0).all()
    assert assembly.mismatch <= SPLIT_VOLUME_RTOL


def test_a_wedge_on_a_small_bed_gets_a_pin_that_keeps_clear_of_its_slope():
    wedge = BlockSpec("wedge", "triangular_prism", 0.16, 0.085, 0.0275, mass=None)
    small = PrintSettings(build_volume=(0.1, 0.1, 0.1))
    assembly = split_tool(wedge.name, tool_solid(wedge), small)
    (joint,) = assembly.joints
    # The deepest, widest pin would break through the slope: a smaller one is taken.
    assert joint.pin_length_m < 2 * 1.5 * 0.01375
    assert joint.pin_section_m >= small.min_feature
    assert assembly.mismatch <= SPLIT_VOLUME_RTOL
    for piece in assembly.pieces:
        assert (np.array(piece.bed_extent(small)) <= 100.0).all()


def test_a_handle_too_thin_for_a_pin_cannot_be_printed_in_pieces(tmp_path):
    thin = HookSpec("thin", 0.5, handle_width=0.005, hook_length=0.02, hook_width=0.005)
    with pytest.raises(SplitError, match="too small for a dowel pin"):
        split_tool(thin.name, tool_solid(thin))
    # Asked to print it, nothing is written; asked for the design only, it says why.
    with pytest.raises(SplitError):
        write_tool_files(thin, tmp_path / "print", picture=False, gcode=True)
    assert not (tmp_path / "print" / "thin").exists()
    files = write_tool_files(thin, tmp_path / "design", picture=False)
    entry = json.loads(files.manifest.read_text())["print"]
    assert entry["printable"] is False and "dowel pin" in entry["reason"]
    assert files.pieces == () and not check_print_files(files).ok


def test_print_settings_refuse_a_minimum_feature_under_two_nozzle_widths():
    with pytest.raises(ValueError, match="two nozzle widths"):
        PrintSettings(min_feature=0.0006)
    with pytest.raises(ValueError, match="build volume"):
        PrintSettings(build_volume=(0.2, -0.1, 0.2))


@pytest.mark.parametrize("text,seconds", [("47m 58s", 2878), ("1h 2m 3s", 3723),
                                          ("1d 0h 0m 5s", 86405), ("9s", 9)])
def test_slicer_durations_are_read(text, seconds):
    assert parse_duration(text) == seconds


@needs_slicer
def test_a_pin_and_a_small_wedge_slice_to_gcode_on_the_bed(tmp_path):
    assembly = split_tool(LONG_HOOK.name, tool_solid(LONG_HOOK))
    pin = assembly.pieces[-1]
    stl = tmp_path / "pin.stl"
    stl.write_bytes(pin.print_mesh(PrintSettings()).export(file_type="stl"))
    result = slice_piece(stl, tmp_path / "pin.gcode")
    assert result.gcode.is_file() and result.print_time_s > 0
    # 100 % infill: the filament weighs about PLA density times the pin's volume.
    assert result.filament_g == pytest.approx(1240.0 * pin.volume * 1e3, rel=0.15)
    x0, y0, z0, x1, y1, z1 = result.extrusion_bounds_mm
    assert 0 <= x0 < x1 <= BED[0] and 0 <= y0 < y1 <= BED[1] and z1 <= BED[2]
    assert read_gcode(result.gcode).filament_mm == result.filament_mm

    wedge = BlockSpec("wedge_small", "triangular_prism", 0.06, 0.03, 0.02, mass=None,
                      tip_height=0.001)
    files = write_tool_files(wedge, tmp_path, picture=False, gcode=True)
    entry = json.loads(files.manifest.read_text())["print"]
    (row,) = entry["pieces"]
    assert entry["sliced"] and row["print_time_s"] > 0 and row["filament_g"] > 0
    assert files.gcode == (files.directory / "wedge_small_part1.gcode",)
    check = check_print_files(files)
    assert check.ok and check.sliced == 1, check.problems


@needs_slicer
def test_a_piece_off_the_bed_or_unreadable_is_a_slice_error(tmp_path):
    assembly = split_tool(LONG_HOOK.name, tool_solid(LONG_HOOK))
    mesh = assembly.pieces[-1].print_mesh(PrintSettings())
    mesh.apply_translation((230.0, 0.0, 0.0))        # past the bed's right edge
    stl = tmp_path / "off.stl"
    stl.write_bytes(mesh.export(file_type="stl"))
    with pytest.raises(SliceError, match="prints outside the 250 x 210 x 210 mm build volume"):
        slice_piece(stl, tmp_path / "off.gcode")
    bad = tmp_path / "bad.stl"
    bad.write_text("solid nothing\nendsolid nothing\n")
    with pytest.raises(SliceError, match="bad.stl"):
        slice_piece(bad, tmp_path / "bad.gcode")


@needs_slicer
def test_one_piece_sliced_four_times_gives_one_gcode_and_one_print_time(tmp_path):
    # Issue 25: two identical runs gave print times 1-2 s apart. PrusaSlicer 2.5 orders
    # some toolpaths by thread timing and memory addresses; the slicer now runs on one
    # CPU without address randomisation. (Before: 4 slicings of this piece gave 3-4
    # different files and print times 7630-7632 s.)
    assembly = split_tool(LONG_HOOK.name, tool_solid(LONG_HOOK))
    stl = tmp_path / "piece.stl"
    stl.write_bytes(assembly.pieces[0].print_mesh(PrintSettings()).export(file_type="stl"))
    results = [slice_piece(stl, tmp_path / f"piece{i}.gcode") for i in range(4)]

    def body(r):
        return [line for line in r.gcode.read_text().splitlines()
                if not line.startswith("; generated by")]

    assert len({r.print_time_s for r in results}) == 1, [r.print_time_s for r in results]
    assert all(body(r) == body(results[0]) for r in results[1:])
