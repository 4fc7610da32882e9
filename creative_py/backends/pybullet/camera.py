"""Simulated cameras: the only camera code that talks to pybullet.

A :class:`~creative_py.world.cameras.CameraSpec` (a ``[[camera]]`` table of a world's
``scene.toml``, read by :mod:`creative_py.world.cameras`) is rendered by :func:`capture`
with pybullet's CPU renderer (``ER_TINY_RENDERER``, no GPU needed) into a
:class:`~creative_py.perception.frame.Frame` that the pure-numpy perception stage turns
into facts; :func:`view_matrix` and :func:`projection_matrix` give its matrices.
"""

from __future__ import annotations

import time
from typing import Iterable

import numpy as np
import pybullet as p

from creative_py.perception.frame import Frame
from creative_py.world.cameras import CameraSpec

__all__ = ["Frame", "capture", "capture_all", "projection_matrix", "view_matrix"]


def view_matrix(spec: CameraSpec) -> tuple[float, ...]:
    """Return the 4x4 view matrix of camera ``spec``, 16 floats, column-major."""
    return tuple(p.computeViewMatrix(spec.eye, spec.target, spec.up))


def projection_matrix(spec: CameraSpec) -> tuple[float, ...]:
    """Return the 4x4 perspective projection matrix of camera ``spec``, 16 floats,
    column-major."""
    return tuple(p.computeProjectionMatrixFOV(spec.fov_deg, spec.width / spec.height,
                                              spec.near, spec.far))


def capture(client_id: int, spec: CameraSpec) -> Frame:
    """Render one image of the scene in client ``client_id`` with the CPU renderer.

    Returns a :class:`Frame` with RGB (uint8, HxWx3), the non-linear depth buffer
    (float32, HxW, in [0, 1]), the segmentation (int32, HxW; body id in the low 24 bits,
    link index + 1 above, -1 for background), both matrices and the render time.
    """
    view = view_matrix(spec)
    proj = projection_matrix(spec)
    t0 = time.perf_counter()
    _, _, rgba, depth, seg = p.getCameraImage(
        spec.width, spec.height, viewMatrix=view, projectionMatrix=proj,
        renderer=p.ER_TINY_RENDERER,
        flags=p.ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX,
        physicsClientId=client_id)
    elapsed = time.perf_counter() - t0
    h, w = spec.height, spec.width
    rgb = np.asarray(rgba, dtype=np.uint8).reshape(h, w, 4)[:, :, :3].copy()
    depth_arr = np.asarray(depth, dtype=np.float32).reshape(h, w)
    seg_arr = np.asarray(seg, dtype=np.int64).reshape(h, w).astype(np.int32)
    return Frame(name=spec.name, rgb=rgb, depth=depth_arr, seg=seg_arr, view=view, proj=proj,
                 width=w, height=h, render_time_s=elapsed)


def capture_all(client_id: int, specs: Iterable[CameraSpec]) -> list[Frame]:
    """Render every camera in ``specs``; return the frames in the same order."""
    return [capture(client_id, s) for s in specs]


def capture_frames(client_id: int, specs: Iterable[CameraSpec], images_dir=None,
                   shot: int = 0, step: str = "") -> tuple[Frame, ...]:
    """Render every camera; with ``images_dir``, also save each RGB image there as
    ``<shot>_<step>_<camera>.png`` (two digits for ``shot``; ``step`` says when the
    picture was taken, e.g. ``after_pick_up``; left out when empty)."""
    frames = tuple(capture_all(client_id, specs))
    if images_dir is not None:
        import matplotlib.image

        images_dir.mkdir(parents=True, exist_ok=True)
        for f in frames:
            matplotlib.image.imsave(images_dir / f"{shot:02d}_{step + '_' if step else ''}{f.name}.png", f.rgb)
    return frames

