"""The shared specs: bad input is refused with the field named; volumes are exact."""

from __future__ import annotations

import math

import pytest

from creative_py.mesh.spec import BlockSpec, HookSpec, spec_from_dict, spec_volume


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
