"""The shared specs: bad input is refused with the field named; volumes are exact."""

from __future__ import annotations

import math

import pytest

from creative_py.mesh.spec import spec_volume

from creative_py.kinds import spec_from_dict

from creative_py.kinds.block import BlockSpec

from creative_py.kinds.hook_like import HookSpec


@pytest.mark.parametrize("mass", [0, -0.1, math.nan, "heavy"])
def test_a_mass_that_is_not_positive_is_refused(mass):
    with pytest.raises(ValueError, match="h: mass must be a positive number of kg"):
        HookSpec("h", 0.3, mass=mass)


@pytest.mark.parametrize("data, message", [
    ({"kind": "block", "name": "w", "shape": "box", "length": -0.1, "width": 0.05,
      "height": 0.03}, "tools.toml: w: length must be a positive number of metres"),
    ({"kind": "hook", "name": "h", "handle_length": 0.3, "colour": "red"},
     "tools.toml: object 'h': unknown field.s. colour"),
    ({"kind": "stick", "name": "Stick", "handle_length": 0.3},
     "tools.toml: object name 'Stick' must be a Prolog atom"),
])
def test_bad_tables_name_the_source_and_the_field(data, message):
    with pytest.raises(ValueError, match=message):
        spec_from_dict(data, source="tools.toml")


@pytest.mark.parametrize("angle", [30.0, 60.0, 90.0, 120.0, 150.0])
def test_angled_hook_volume_counts_the_overlap_once(angle):
    w, hw, hl, L = 0.01, 0.01, 0.03, 0.3
    spec = HookSpec("h", L, handle_width=w, hook_width=hw, hook_length=hl,
                    hook_angle_deg=angle)
    a = math.radians(angle)
    prong = hw * (w / 2 + hl) * w
    if angle <= 90.0:
        # The prong's slab crosses the handle's near half: its footprint there is a
        # parallelogram of width hw / sin(a) and height w / 2.
        expected = L * w * w + prong - w * hw * (w / 2) / math.sin(a)
        assert spec_volume(spec) == pytest.approx(expected, rel=1e-12)
    else:
        assert spec_volume(spec) > L * w * w + prong - w * hw * (w / 2) / math.sin(a)


def test_block_volumes():
    assert spec_volume(BlockSpec("w", "triangular_prism", 0.1, 0.05, 0.03)) == pytest.approx(
        0.5 * 0.1 * 0.05 * 0.03)
    assert spec_volume(BlockSpec("c", "cylinder", 0.04, 0.04, 0.05)) == pytest.approx(
        math.pi * 0.02**2 * 0.05)


def test_a_blunted_prism_is_a_trapezoid_with_its_volume_and_centroid():
    spec = BlockSpec("w", "triangular_prism", 0.16, 0.085, 0.0275, tip_height=0.0024)
    (hull,) = spec.parts()
    assert len(hull.vertices) == 8
    assert (0.08, 0.0425, 0.0024) in hull.vertices
    assert spec_volume(spec) == pytest.approx(0.5 * (0.0275 + 0.0024) * 0.16 * 0.085)
    # Centroid of a trapezoid with parallel sides H (back) and T (tip), run L:
    # x = L (H + 2T) / (3 (H + T)) from the back, z = (H^2 + H T + T^2) / (3 (H + T)).
    H, T, L = 0.0275, 0.0024, 0.16
    assert hull.centroid == pytest.approx((L * (H + 2 * T) / (3 * (H + T)) - L / 2, 0.0,
                                           (H * H + H * T + T * T) / (3 * (H + T))))
    # A sharp prism keeps its six vertices (the catalogue's wedges are unchanged).
    sharp = BlockSpec("s", "triangular_prism", 0.16, 0.085, 0.0275)
    assert len(sharp.parts()[0].vertices) == 6 and sharp.parts()[0].centroid is None


@pytest.mark.parametrize("kwargs, match", [
    (dict(shape="triangular_prism", tip_height=0.03), "below the prism's height"),
    (dict(shape="triangular_prism", tip_height=-0.001), "tip_height must be"),
    (dict(shape="box", tip_height=0.001), "a box has no tip"),
])
def test_a_bad_tip_height_is_refused(kwargs, match):
    with pytest.raises(ValueError, match=match):
        BlockSpec("w", length=0.1, width=0.05, height=0.03, **kwargs)
