"""The solid: one watertight shell whose volume and inertia match the spec."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from creative_py.mesh.solid import mass_properties, tool_mesh
from creative_py.mesh.spec import spec_mass, spec_volume
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec
from creative_py.mesh.tolerances import STL_VOLUME_RTOL


def test_solid_is_one_watertight_shell_of_the_spec_volume(specs, kind):
    spec = specs[kind]
    mesh = tool_mesh(spec)
    assert mesh.is_watertight
    assert mesh.body_count == 1
    assert mesh.volume == pytest.approx(spec_volume(spec), rel=STL_VOLUME_RTOL)


def test_box_inertia_matches_the_closed_form(specs):
    spec = specs["box"]
    props = mass_properties(spec)
    m, (a, b, c) = spec.mass, (spec.length, spec.width, spec.height)
    expected = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12,
                        m * (a * a + b * b) / 12])
    np.testing.assert_allclose(props.inertia, expected, rtol=1e-9, atol=1e-15)
    assert props.center_of_mass == pytest.approx((0.0, 0.0, spec.height / 2))


def test_stick_inertia_and_centre_of_mass_match_the_closed_form(specs):
    spec = specs["stick"]
    props = mass_properties(spec)
    m, L, w = spec.mass, spec.handle_length, spec.handle_width
    np.testing.assert_allclose(np.diag(props.inertia),
                               [m * w * w / 6, m * (L * L + w * w) / 12, m * (L * L + w * w) / 12],
                               rtol=1e-9)
    assert props.center_of_mass == pytest.approx((L / 2, 0.0, 0.0))


def test_prong_side_shows_in_the_centre_of_mass_and_the_inertia_product():
    right = mass_properties(HookSpec("r", 0.3, hook_side="right"))
    left = mass_properties(HookSpec("l", 0.3, hook_side="left"))
    assert right.center_of_mass[1] < 0 < left.center_of_mass[1]
    assert right.inertia[0][1] == pytest.approx(-left.inertia[0][1])
    assert abs(right.inertia[0][1]) > 1e-7


def test_mass_defaults_to_pla_density_times_volume(specs):
    spec = specs["hook_left"]
    assert mass_properties(spec).mass == pytest.approx(1240.0 * spec_volume(spec))
    assert spec_mass(spec) == pytest.approx(1240.0 * spec_volume(spec))


@settings(max_examples=40, deadline=None)
@given(length=st.floats(0.05, 0.6), width=st.floats(0.004, 0.03),
       hook_length=st.floats(0.005, 0.08), hook_width=st.floats(0.003, 0.03),
       angle=st.floats(30.0, 150.0), side=st.sampled_from(["left", "right"]))
def test_any_hook_is_one_shell_with_the_spec_volume(length, width, hook_length, hook_width,
                                                     angle, side):
    spec = HookSpec("h", length, handle_width=width, hook_length=hook_length,
                    hook_width=hook_width, hook_side=side, hook_angle_deg=angle,
                    grip_offset=0.01)
    mesh = tool_mesh(spec)
    assert mesh.is_watertight and mesh.body_count == 1
    assert mesh.volume == pytest.approx(spec_volume(spec), rel=1e-9)


@settings(max_examples=20, deadline=None)
@given(length=st.floats(0.01, 0.3), width=st.floats(0.01, 0.2), height=st.floats(0.005, 0.1))
def test_any_prism_has_the_spec_volume(length, width, height):
    spec = BlockSpec("w", "triangular_prism", length, width, height)
    mesh = tool_mesh(spec)
    assert mesh.is_watertight
    assert mesh.volume == pytest.approx(spec_volume(spec), rel=1e-9)


def test_cylinder_facet_deficit_is_as_documented(specs):
    spec = specs["cylinder"]
    n = 128
    polygon_over_circle = n * math.sin(2 * math.pi / n) / (2 * math.pi)
    assert tool_mesh(spec).volume / spec_volume(spec) == pytest.approx(polygon_over_circle,
                                                                       rel=1e-9)


def test_a_blunted_prism_solid_has_the_spec_volume_and_centroid():
    spec = BlockSpec("w", "triangular_prism", 0.16, 0.085, 0.0275, tip_height=0.0024)
    mesh = tool_mesh(spec)
    assert mesh.is_watertight
    assert mesh.volume == pytest.approx(spec_volume(spec), rel=1e-9)
    assert tuple(mesh.center_mass) == pytest.approx(spec.parts()[0].centroid, abs=1e-12)
    assert mesh.bounds[1][2] == pytest.approx(0.0275)
