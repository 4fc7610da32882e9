"""One camera image as the perception stage sees it: colour, depth buffer, segmentation.

The dataclass lives here, in pure numpy, so that perception never imports pybullet;
:func:`creative_py.backends.pybullet.camera.capture` is the only code that fills it from a renderer.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, eq=False)
class Frame:
    """A rendered camera image with the matrices that made it.

    Attributes
    ----------
    name : str
        The camera's name (from its ``[[camera]]`` table).
    rgb : numpy.ndarray
        ``uint8`` array of shape (height, width, 3).
    depth : numpy.ndarray
        ``float32`` array of shape (height, width): the renderer's non-linear depth
        buffer in [0, 1] (0 at the near plane, 1 at the far plane), not metres.
    seg : numpy.ndarray
        ``int32`` array of shape (height, width): body id in the low 24 bits, link
        index + 1 in the high bits, -1 where no body was hit.
    view : tuple of float
        The 4x4 view matrix, 16 floats, column-major (OpenGL/pybullet order).
    proj : tuple of float
        The 4x4 projection matrix, 16 floats, column-major.
    width, height : int
        Image size in pixels.
    render_time_s : float
        Wall-clock time the renderer took, seconds.
    """

    name: str
    rgb: np.ndarray
    depth: np.ndarray
    seg: np.ndarray
    view: tuple[float, ...]
    proj: tuple[float, ...]
    width: int
    height: int
    render_time_s: float = 0.0

    def __post_init__(self) -> None:
        shape = (self.height, self.width)
        for field_name, arr in (("depth", self.depth), ("seg", self.seg)):
            if getattr(arr, "shape", None) != shape:
                raise ValueError(f"frame {self.name!r}: {field_name} has shape "
                                 f"{getattr(arr, 'shape', None)}, expected {shape}")
        if getattr(self.rgb, "shape", None) != shape + (3,):
            raise ValueError(f"frame {self.name!r}: rgb has shape "
                             f"{getattr(self.rgb, 'shape', None)}, expected {shape + (3,)}")
        for field_name, mat in (("view", self.view), ("proj", self.proj)):
            if len(mat) != 16:
                raise ValueError(f"frame {self.name!r}: {field_name} must have 16 floats, "
                                 f"got {len(mat)}")

    def replace(self, **changes) -> "Frame":
        """Return a copy with some fields replaced (e.g. a noisy depth buffer)."""
        fields = {k: getattr(self, k) for k in self.__dataclass_fields__}
        fields.update(changes)
        return Frame(**fields)
