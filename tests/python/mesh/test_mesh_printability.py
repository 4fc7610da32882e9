"""Printability: refuse features a hobby FDM printer cannot make; flag oversize parts."""

from __future__ import annotations

import pytest

from creative_py.mesh.printability import (PrintSettings, check_min_feature, feature_dimensions,
                                           printability, thin_tip_length)
from creative_py.mesh.solid import tool_mesh
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec


@pytest.mark.parametrize("spec, field", [
    (HookSpec("thin_handle", 0.3, handle_width=0.0015), "handle_width"),
    (HookSpec("thin_prong", 0.3, hook_width=0.0019), "hook_width"),
    (HookSpec("stub_prong", 0.3, hook_length=0.001), "hook_length"),
    (BlockSpec("flat_wedge", "triangular_prism", 0.1, 0.05, 0.001), "height"),
    (BlockSpec("narrow_box", "box", 0.04, 0.0005, 0.03), "width"),
])
def test_a_dimension_below_the_minimum_feature_is_refused_by_name(spec, field):
    with pytest.raises(ValueError, match=rf"{spec.name}: {field} is .* below the 2.00 mm"):
        check_min_feature(spec)


def test_a_stick_has_no_prong_dimensions_to_check():
    check_min_feature(HookSpec("stick", 0.3, hook_side="none", hook_length=0.0,
                               hook_width=0.0001))


def test_a_larger_minimum_feature_is_honoured():
    with pytest.raises(ValueError, match="handle_width is 10.00 mm, below the 12.00 mm"):
        check_min_feature(HookSpec("h", 0.3), PrintSettings(min_feature=0.012))


def test_a_short_hook_fits_straight_on_the_bed():
    spec = HookSpec("h", 0.2)
    verdict = printability(spec, tool_mesh(spec))
    assert verdict.fits_build_volume and verdict.up_axis == "z" and verdict.yaw_deg == 0.0
    assert verdict.extent == pytest.approx((0.2, 0.04, 0.01))


def test_a_300_mm_hook_fits_only_diagonally():
    spec = HookSpec("h", 0.3)
    verdict = printability(spec, tool_mesh(spec))
    assert verdict.fits_build_volume
    assert 20.0 < verdict.yaw_deg < 160.0


def test_a_550_mm_hook_does_not_fit_and_says_why():
    spec = HookSpec("h", 0.55)
    verdict = printability(spec, tool_mesh(spec))
    assert not verdict.fits_build_volume
    assert verdict.up_axis is None and verdict.yaw_deg is None
    assert "550.0 x 40.0 x 10.0 mm" in verdict.reason and "split" in verdict.reason


def test_a_tall_block_is_laid_on_its_side_to_fit():
    spec = BlockSpec("post", "box", 0.03, 0.03, 0.24)
    verdict = printability(spec, tool_mesh(spec))
    assert verdict.fits_build_volume and verdict.up_axis in ("x", "y")


def test_a_knife_edge_wedge_is_refused_with_its_thin_run():
    # The wedge the hook-and-door run created before blunting: under 0.8 mm (two
    # nozzle widths) for its last 0.8 / (27.5 / 160) = 4.65 mm.
    sharp = BlockSpec("wedge_new1", "triangular_prism", 0.16, 0.085, 0.0275)
    with pytest.raises(ValueError, match=r"wedge_new1: the wedge's tip is 0.00 mm high, so it "
                                         r"is thinner than 0.80 mm .* for its last 4.7 mm"):
        check_min_feature(sharp)


def test_a_blunted_wedge_prints_and_a_lower_tip_is_refused():
    blunt = BlockSpec("w", "triangular_prism", 0.16, 0.085, 0.0275, tip_height=0.0024)
    check_min_feature(blunt)
    assert "tip_height" in feature_dimensions(blunt)
    low = BlockSpec("w", "triangular_prism", 0.16, 0.085, 0.0275, tip_height=0.0005)
    assert thin_tip_length(low) == pytest.approx(0.0003 / (0.027 / 0.16))
    with pytest.raises(ValueError, match="tip is 0.50 mm high"):
        check_min_feature(low)
    # A tip below min_feature (2 mm) but above min_tip (0.8 mm) prints.
    check_min_feature(BlockSpec("w", "triangular_prism", 0.16, 0.085, 0.0275,
                                tip_height=0.001))
    check_min_feature(BlockSpec("b", "box", 0.04, 0.05, 0.03))
