"""Simulated cameras: the only camera code that talks to pybullet.

A :class:`CameraSpec` comes from a ``[[camera]]`` table of a world's ``scene.toml``;
:func:`capture` renders it with pybullet's CPU renderer (``ER_TINY_RENDERER``, no GPU
needed) into a :class:`~creative_py.perception.frame.Frame` that the pure-numpy
perception stage turns into facts.

Example ``[[camera]]`` table (world frame, metres, degrees)::

    [[camera]]
    name = "top"
    eye = [0.9, -0.1, 1.0]
    target = [0.9, -0.1, -0.1]
    up = [1.0, 0.0, 0.0]        # image "up" points along +x world
    fov_deg = 40.0              # vertical field of view
    width = 320
    height = 240
    near = 0.1
    far = 3.0
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

import numpy as np
import pybullet as p

from creative_py.perception.frame import Frame

__all__ = ["CameraSpec", "Frame", "capture", "capture_all", "cameras_from_tables"]


@dataclass(frozen=True)
class CameraSpec:
    """A pinhole camera looking from ``eye`` at ``target``.

    Attributes
    ----------
    name : str
        Unique camera name within a world.
    eye, target : tuple of 3 floats
        Camera position and the point it looks at, world frame, metres.
    up : tuple of 3 floats
        The world direction that appears upwards in the image; must not be parallel
        to ``target - eye``. Default +z.
    fov_deg : float
        Vertical field of view, degrees, in (0, 180).
    width, height : int
        Image size in pixels.
    near, far : float
        Clipping planes, metres, 0 < near < far.
    """

    name: str
    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    up: tuple[float, float, float] = (0.0, 0.0, 1.0)
    fov_deg: float = 45.0
    width: int = 320
    height: int = 240
    near: float = 0.05
    far: float = 5.0

    def __post_init__(self) -> None:
        self._validate()

    @classmethod
    def from_dict(cls, table: Mapping[str, Any], source: str = "<dict>") -> "CameraSpec":
        """Build a spec from a ``[[camera]]`` TOML table.

        Errors are ``ValueError`` naming ``source`` (the file), the camera and the
        offending field, e.g. ``scene.toml: camera 'top': field 'fov_deg' must ...``.
        """
        if not isinstance(table, Mapping):
            raise ValueError(f"{source}: a [[camera]] entry must be a table, "
                             f"got {type(table).__name__}")
        name = table.get("name")
        where = f"{source}: camera {name!r}"
        if not isinstance(name, str) or not name:
            raise ValueError(f"{source}: camera table: field 'name' must be a non-empty "
                             f"string, got {name!r}")
        known = set(cls.__dataclass_fields__)
        unknown = sorted(set(table) - known)
        if unknown:
            raise ValueError(f"{where}: unknown field(s) {', '.join(unknown)}; expected "
                             f"some of {', '.join(sorted(known))}")
        for required in ("eye", "target"):
            if required not in table:
                raise ValueError(f"{where}: field {required!r} is missing")
        values: dict[str, Any] = {"name": name}
        for key in ("eye", "target", "up"):
            if key in table:
                values[key] = _vec3(table[key], where, key)
        for key in ("fov_deg", "near", "far"):
            if key in table:
                values[key] = _number(table[key], where, key)
        for key in ("width", "height"):
            if key in table:
                v = table[key]
                if isinstance(v, bool) or not isinstance(v, int):
                    raise ValueError(f"{where}: field {key!r} must be an integer number "
                                     f"of pixels, got {v!r}")
                values[key] = v
        try:
            return cls(**values)
        except ValueError as exc:
            raise ValueError(f"{source}: {exc}") from None

    def _validate(self) -> None:
        where = f"camera {self.name!r}"
        if not isinstance(self.name, str) or not self.name:
            raise ValueError(f"camera field 'name' must be a non-empty string, got {self.name!r}")
        for key in ("eye", "target", "up"):
            _vec3(getattr(self, key), where, key)
        if not 0.0 < self.fov_deg < 180.0:
            raise ValueError(f"{where}: field 'fov_deg' must lie in (0, 180) degrees, "
                             f"got {self.fov_deg!r}")
        for key in ("width", "height"):
            v = getattr(self, key)
            if isinstance(v, bool) or not isinstance(v, int) or not 1 <= v <= 4096:
                raise ValueError(f"{where}: field {key!r} must be an integer in [1, 4096] "
                                 f"pixels, got {v!r}")
        if not 0.0 < self.near < self.far:
            raise ValueError(f"{where}: fields 'near' and 'far' must satisfy "
                             f"0 < near < far metres, got near={self.near!r}, far={self.far!r}")
        look = np.subtract(self.target, self.eye)
        dist = float(np.linalg.norm(look))
        if dist < 1e-6:
            raise ValueError(f"{where}: fields 'eye' and 'target' coincide")
        if not self.near < dist < self.far:
            raise ValueError(f"{where}: the target lies {dist:.3f} m from the eye, outside "
                             f"[near, far] = [{self.near}, {self.far}] m")
        up = np.asarray(self.up, dtype=float)
        up_norm = float(np.linalg.norm(up))
        if up_norm < 1e-9 or np.linalg.norm(np.cross(look / dist, up / up_norm)) < 1e-3:
            raise ValueError(f"{where}: field 'up' {self.up} is zero or parallel to the "
                             "viewing direction target - eye; give a direction across it "
                             "(for a downward camera e.g. [1, 0, 0])")

    def view_matrix(self) -> tuple[float, ...]:
        """Return the 4x4 view matrix, 16 floats, column-major."""
        return tuple(p.computeViewMatrix(self.eye, self.target, self.up))

    def projection_matrix(self) -> tuple[float, ...]:
        """Return the 4x4 perspective projection matrix, 16 floats, column-major."""
        return tuple(p.computeProjectionMatrixFOV(self.fov_deg, self.width / self.height,
                                                  self.near, self.far))


def cameras_from_tables(tables: Iterable[Mapping[str, Any]], source: str) -> tuple[CameraSpec, ...]:
    """Build the cameras of a world from its ``[[camera]]`` tables; names must be unique."""
    specs = tuple(CameraSpec.from_dict(t, source) for t in tables)
    seen: set[str] = set()
    for s in specs:
        if s.name in seen:
            raise ValueError(f"{source}: camera name {s.name!r} is used twice")
        seen.add(s.name)
    return specs


def capture(client_id: int, spec: CameraSpec) -> Frame:
    """Render one image of the scene in client ``client_id`` with the CPU renderer.

    Returns a :class:`Frame` with RGB (uint8, HxWx3), the non-linear depth buffer
    (float32, HxW, in [0, 1]), the segmentation (int32, HxW; body id in the low 24 bits,
    link index + 1 above, -1 for background), both matrices and the render time.
    """
    view = spec.view_matrix()
    proj = spec.projection_matrix()
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


def _vec3(value: Any, where: str, key: str) -> tuple[float, float, float]:
    if (not isinstance(value, (list, tuple)) or len(value) != 3
            or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                       and math.isfinite(v) for v in value)):
        raise ValueError(f"{where}: field {key!r} must be a list of 3 finite numbers "
                         f"(metres, world frame), got {value!r}")
    return tuple(float(v) for v in value)  # type: ignore[return-value]


def _number(value: Any, where: str, key: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"{where}: field {key!r} must be a finite number, got {value!r}")
    return float(value)
