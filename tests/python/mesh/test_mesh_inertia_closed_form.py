"""A hook's inertia tensor in its URDF equals the closed form of its parts.

The hook at a right angle is three axis-aligned boxes of one density: the handle plus
the prong minus their overlap (the prong runs from the handle's axis). Each box's own
tensor plus the parallel-axis term, summed with those signs, gives the tensor about the
centre of mass; the products of inertia (``ixy``) carry the prong's side, so a sign
error there changes no eigenvalue but fails this test.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest

from creative_py.mesh.export import write_tool_files
from creative_py.kinds.hook_like import HookSpec


def _box(center, size, density):
    m = density * size[0] * size[1] * size[2]
    a, b, c = size
    own = np.diag([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12])
    return m, np.asarray(center, float), own


def closed_form(spec: HookSpec, density: float) -> tuple[float, np.ndarray, np.ndarray]:
    """Return mass, centre of mass and inertia tensor (about the centre) of a 90 degree hook."""
    L, w, hw, hl = spec.handle_length, spec.handle_width, spec.hook_width, spec.hook_length
    s = 1.0 if spec.hook_side == "left" else -1.0
    span = w / 2 + hl
    parts = [(+1, _box((L / 2, 0, 0), (L, w, w), density)),
             (+1, _box((L - hw / 2, s * span / 2, 0), (hw, span, w), density)),
             (-1, _box((L - hw / 2, s * w / 4, 0), (hw, w / 2, w), density))]
    mass = sum(k * m for k, (m, _, _) in parts)
    com = sum(k * m * c for k, (m, c, _) in parts) / mass
    tensor = np.zeros((3, 3))
    for k, (m, c, own) in parts:
        d = c - com
        tensor += k * (own + m * (d @ d * np.eye(3) - np.outer(d, d)))
    return mass, com, tensor


@pytest.mark.parametrize("side", ["left", "right"])
def test_urdf_inertia_of_a_hook_is_the_closed_form(tmp_path, side):
    spec = HookSpec("h", handle_length=0.35, handle_width=0.01, hook_length=0.035,
                    hook_width=0.012, hook_side=side, hook_angle_deg=90.0)
    files = write_tool_files(spec, tmp_path, picture=False)
    inertial = ET.parse(files.urdf).getroot().find("link").find("inertial")
    mass = float(inertial.find("mass").get("value"))
    com = [float(v) for v in inertial.find("origin").get("xyz").split()]
    i = {k: float(v) for k, v in inertial.find("inertia").attrib.items()}
    urdf = np.array([[i["ixx"], i["ixy"], i["ixz"]], [i["ixy"], i["iyy"], i["iyz"]],
                     [i["ixz"], i["iyz"], i["izz"]]])
    volume = (0.35 * 0.01 * 0.01 + 0.012 * (0.005 + 0.035) * 0.01 - 0.012 * 0.005 * 0.01)
    m, c, tensor = closed_form(spec, mass / volume)
    assert mass == pytest.approx(m, rel=1e-9)
    np.testing.assert_allclose(com, c, atol=1e-6)
    np.testing.assert_allclose(urdf, tensor, rtol=1e-3, atol=1e-10)
    assert (urdf[0, 1] < 0) == (side == "left")    # I_xy = -sum(m dx dy): prong at +x, +y
