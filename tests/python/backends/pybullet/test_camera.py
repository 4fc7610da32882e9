"""Camera specs from TOML tables and frames from pybullet's CPU renderer."""

from __future__ import annotations

import time

import numpy as np
import pybullet as p
import pytest

from creative_py.backends.pybullet.camera import capture
from creative_py.world.cameras import CameraSpec, cameras_from_tables

GOOD = {"name": "top", "eye": [0.9, -0.1, 0.8], "target": [0.9, -0.1, -0.2], "up": [1, 0, 0],
        "fov_deg": 40, "width": 320, "height": 240, "near": 0.1, "far": 3.0}


def test_a_good_table_gives_a_spec_with_floats():
    spec = CameraSpec.from_dict(GOOD, "worlds/hook_tube/scene.toml")
    assert spec.eye == (0.9, -0.1, 0.8) and spec.up == (1.0, 0.0, 0.0)
    assert (spec.width, spec.height, spec.fov_deg) == (320, 240, 40.0)
    assert CameraSpec.from_dict({"name": "side", "eye": [1, 0, 1], "target": [0, 0, 0]}, "s").up == (0, 0, 1)


@pytest.mark.parametrize("change, message", [
    ({"eye": None}, r"camera 'top': field 'eye' is missing"),
    ({"eye": [0, 0]}, r"camera 'top': field 'eye' must be a list of 3 finite numbers"),
    ({"target": [0, 0, "x"]}, r"field 'target' must be a list of 3"),
    ({"fov_deg": 200}, r"camera 'top': field 'fov_deg' must lie in \(0, 180\)"),
    ({"fov_deg": "wide"}, r"field 'fov_deg' must be a finite number"),
    ({"width": 320.5}, r"field 'width' must be an integer"),
    ({"height": 0}, r"field 'height' must be an integer in \[1, 4096\]"),
    ({"near": 5.0}, r"0 < near < far"),
    ({"up": [0, 0, 1]}, r"field 'up' .* parallel to the viewing direction"),
    ({"far": 0.5}, r"the target lies 1.000 m from the eye, outside"),
    ({"colour": "red"}, r"unknown field\(s\) colour"),
    ({"name": ""}, r"field 'name' must be a non-empty string"),
])
def test_a_bad_table_is_refused_naming_file_camera_and_field(change, message):
    table = {k: v for k, v in {**GOOD, **change}.items() if v is not None}
    with pytest.raises(ValueError, match=message) as info:
        CameraSpec.from_dict(table, "worlds/hook_tube/scene.toml")
    assert str(info.value).startswith("worlds/hook_tube/scene.toml: ")


def test_camera_names_must_be_unique_in_a_world():
    with pytest.raises(ValueError, match="scene.toml: camera name 'top' is used twice"):
        cameras_from_tables([GOOD, GOOD], "scene.toml")
    with pytest.raises(ValueError, match="scene.toml: a \\[\\[camera\\]\\] entry must be a table"):
        cameras_from_tables([["top"]], "scene.toml")


@pytest.fixture(scope="module")
def client():
    cid = p.connect(p.DIRECT)
    yield cid
    p.disconnect(cid)


@pytest.mark.sim
def test_capture_returns_typed_arrays_with_the_body_in_the_segmentation(client):
    half = [0.015] * 3
    body = p.createMultiBody(0, p.createCollisionShape(p.GEOM_BOX, halfExtents=half,
                                                       physicsClientId=client),
                             p.createVisualShape(p.GEOM_BOX, halfExtents=half,
                                                 rgbaColor=[1, 0, 0, 1], physicsClientId=client),
                             basePosition=[0.9, -0.1, -0.185], physicsClientId=client)
    spec = CameraSpec.from_dict(GOOD, "test")
    frame = capture(client, spec)
    assert frame.rgb.shape == (240, 320, 3) and frame.rgb.dtype == np.uint8
    assert frame.depth.shape == (240, 320) and frame.depth.dtype == np.float32
    assert frame.seg.shape == (240, 320) and frame.seg.dtype == np.int32
    assert len(frame.view) == 16 and len(frame.proj) == 16
    assert frame.name == "top" and frame.render_time_s > 0
    hit = (frame.seg & 0xFFFFFF) == body
    # 3 cm seen from 0.985 m with 40 degrees over 240 rows: about 10 x 10 pixels.
    assert 80 <= hit.sum() <= 130
    assert hit[120, 160]                             # the cube is in the image centre
    assert (frame.seg[~hit] == -1).all()             # nothing else in the scene
    assert (frame.rgb[hit][:, 0] > 150).all()        # and it is red
    assert frame.depth[hit].max() < frame.depth[~hit].min()


@pytest.mark.sim
def test_render_time_at_320_by_240_is_well_under_a_tenth_of_a_second(client):
    spec = CameraSpec.from_dict(GOOD, "test")
    capture(client, spec)
    t0 = time.perf_counter()
    frames = [capture(client, spec) for _ in range(5)]
    per_frame = (time.perf_counter() - t0) / 5
    # Measured 25-55 ms per frame on a shared 2-core machine; 0.25 s leaves room for load.
    assert per_frame < 0.25
    assert all(f.render_time_s <= per_frame * 5 for f in frames)
