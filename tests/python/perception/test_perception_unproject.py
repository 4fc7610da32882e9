"""Unprojection: a projected world point comes back, and depth conversions invert."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from creative_py.perception.frame import Frame
from creative_py.perception.unproject import (SAMPLE_COL, SAMPLE_ROW, camera_position,
                                              depth_buffer_to_metres, masked_median_depth,
                                              matrix_from_column_major, metres_to_depth_buffer,
                                              near_far_from_projection, unproject_pixels)

W, H, NEAR, FAR = 64, 48, 0.1, 3.0


def look_at(eye, target, up) -> np.ndarray:
    """Return a 4x4 OpenGL view matrix (row-major numpy)."""
    eye, target, up = (np.asarray(v, dtype=float) for v in (eye, target, up))
    f = target - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def perspective(fov_deg: float, aspect: float, near: float, far: float) -> np.ndarray:
    """Return a 4x4 OpenGL perspective matrix (row-major numpy)."""
    t = 1.0 / math.tan(math.radians(fov_deg) / 2)
    return np.array([[t / aspect, 0, 0, 0], [0, t, 0, 0],
                     [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                     [0, 0, -1, 0]])


def make_frame(eye=(0.2, -0.3, 1.0), target=(0.0, 0.1, 0.0), up=(0, 0, 1)) -> Frame:
    view = tuple(look_at(eye, target, up).T.ravel())  # column-major, as pybullet gives it
    proj = tuple(perspective(50.0, W / H, NEAR, FAR).T.ravel())
    return Frame("cam", np.zeros((H, W, 3), np.uint8), np.zeros((H, W), np.float32),
                 np.full((H, W), -1, np.int32), view, proj, W, H)


def project(frame: Frame, point) -> tuple[float, float, float]:
    """Return (row, col, depth-buffer value) of a world point (inverse of unprojection)."""
    pv = matrix_from_column_major(frame.proj) @ matrix_from_column_major(frame.view)
    clip = pv @ np.append(point, 1.0)
    ndc = clip[:3] / clip[3]
    col = (ndc[0] + 1) * W / 2 - SAMPLE_COL
    row = (1 - ndc[1]) * H / 2 - SAMPLE_ROW
    return row, col, (ndc[2] + 1) / 2


coord = st.floats(-0.3, 0.3, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(coord, coord, st.floats(-0.2, 0.2, allow_nan=False))
def test_projected_points_unproject_to_themselves(x, y, z):
    frame = make_frame()
    row, col, d = project(frame, (x, y, z))
    back = unproject_pixels(frame, np.array([row]), np.array([col]), np.array([d]))[0]
    assert np.allclose(back, (x, y, z), atol=1e-6)


@settings(max_examples=60, deadline=None)
@given(st.floats(0.11, 2.9, allow_nan=False))
def test_depth_buffer_and_metres_invert(z):
    d = metres_to_depth_buffer(z, NEAR, FAR)
    assert 0.0 <= d <= 1.0
    assert math.isclose(depth_buffer_to_metres(d, NEAR, FAR), z, rel_tol=1e-9)


def test_near_far_and_camera_position_come_back_from_the_matrices():
    frame = make_frame(eye=(0.2, -0.3, 1.0))
    assert np.allclose(near_far_from_projection(frame.proj), (NEAR, FAR))
    assert np.allclose(camera_position(frame), (0.2, -0.3, 1.0))


def test_pixel_rows_grow_downwards_in_the_image():
    frame = make_frame(eye=(0, 0, 1), target=(0, 0, 0), up=(1, 0, 0))  # image up = +x
    d = metres_to_depth_buffer(1.0, NEAR, FAR)
    top, bottom = unproject_pixels(frame, np.array([0, H - 1]), np.array([W // 2, W // 2]),
                                   np.array([d, d]))
    assert top[0] > bottom[0]


def test_masked_median_keeps_a_plane_and_ignores_other_bodies():
    rows, cols = np.mgrid[0:10, 0:10]
    depth = 0.5 + 0.01 * rows + 0.002 * cols  # a plane in depth-buffer units
    mask = np.zeros((10, 10), bool)
    mask[2:8, 2:8] = True
    depth_with_spike = depth.copy()
    depth_with_spike[1, 4] = 0.99  # another body next to the mask
    out = masked_median_depth(depth_with_spike, mask)
    r, c = np.nonzero(mask)
    interior = (r > 2) & (r < 7) & (c > 2) & (c < 7)
    assert np.allclose(out[interior], depth[r, c][interior])
    assert out.max() < 0.7
    noisy = depth + np.random.default_rng(0).normal(0, 0.01, depth.shape)
    err_raw = np.std(noisy[r, c] - depth[r, c])
    err_med = np.std(masked_median_depth(noisy, mask)[interior] - depth[r, c][interior])
    assert err_med < 0.7 * err_raw
