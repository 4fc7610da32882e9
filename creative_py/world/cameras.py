"""The cameras of a world: ``[[camera]]`` tables and the clips' ``[video]`` table.

A :class:`CameraSpec` comes from a ``[[camera]]`` table of a world's ``scene.toml``
(:func:`cameras_from_tables`); a backend renders it (the pybullet backend's
:func:`creative_py.backends.pybullet.camera.capture`) into a
:class:`~creative_py.perception.frame.Frame` that the pure-numpy perception stage turns
into facts.

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

The ``[video]`` table of a world's ``scene.toml`` places the camera of the clips
(:class:`VideoSpec`)::

    [video]
    eye = [1.0, -1.05, 0.75]
    target = [0.93, -0.32, -0.10]
    fov_deg = 50.0
    width = 320
    height = 240
    fps = 5.0             # frames per second of simulated time
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Iterable, Mapping

import numpy as np


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


def cameras_from_tables(tables: Iterable[Mapping[str, Any]], source: str) -> tuple[CameraSpec, ...]:
    """Build the cameras of a world from its ``[[camera]]`` tables; names must be unique."""
    specs = tuple(CameraSpec.from_dict(t, source) for t in tables)
    seen: set[str] = set()
    for s in specs:
        if s.name in seen:
            raise ValueError(f"{source}: camera name {s.name!r} is used twice")
        seen.add(s.name)
    return specs


@dataclass(frozen=True)
class VideoSpec:
    """The fixed camera of a world's clips and their frame rate.

    Attributes
    ----------
    camera : CameraSpec
        The camera (eye, target, field of view, size in pixels).
    fps : float
        Frames per second of simulated time, in (0, 60].
    """

    camera: CameraSpec
    fps: float = 5.0

    def __post_init__(self) -> None:
        if (isinstance(self.fps, bool) or not isinstance(self.fps, (int, float))
                or not 0.0 < self.fps <= 60.0):
            raise ValueError(f"[video]: field 'fps' must lie in (0, 60] frames per second "
                             f"of simulated time, got {self.fps!r}")

    @classmethod
    def from_table(cls, table: Mapping[str, Any], source: str) -> "VideoSpec":
        """Build the spec from a ``[video]`` table (camera fields plus ``fps``)."""
        if not isinstance(table, Mapping):
            raise ValueError(f"{source}: [video] must be a table")
        cam = {k: v for k, v in table.items() if k != "fps"}
        cam.setdefault("name", "video")
        camera = CameraSpec.from_dict(cam, f"{source}: [video]")
        fps = table.get("fps", 5.0)
        try:
            return cls(camera, fps)
        except ValueError as exc:
            raise ValueError(f"{source}: {exc}") from None


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
