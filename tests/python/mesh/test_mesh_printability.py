"""Printability: refuse features a hobby FDM printer cannot make; flag oversize parts."""

from __future__ import annotations

import pytest

from creative_py.mesh.printability import PrintSettings, check_min_feature, printability
from creative_py.mesh.solid import tool_mesh
from creative_py.mesh.spec import BlockSpec, HookSpec


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
