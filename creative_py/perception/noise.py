"""A simple sensor-noise model for depth cameras, deterministic per random generator.

Gaussian noise is added to the metric depth (distance along the optical axis) of every
pixel, and a fraction of pixels is dropped (their segmentation set to -1, as if the
sensor returned nothing there). The same ``numpy.random.Generator`` state gives the
same noisy frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Mapping

import numpy as np

from creative_py.perception.frame import Frame
from creative_py.perception.unproject import (depth_buffer_to_metres, metres_to_depth_buffer,
                                              near_far_from_projection)


@dataclass(frozen=True)
class NoiseModel:
    """Depth-camera noise.

    Attributes
    ----------
    depth_sigma_m : float
        Standard deviation of the Gaussian noise on depth, metres (>= 0).
    dropout : float
        Probability in [0, 1) that a pixel returns nothing.
    """

    depth_sigma_m: float = 0.0
    dropout: float = 0.0

    def __post_init__(self) -> None:
        if not (isinstance(self.depth_sigma_m, (int, float)) and math.isfinite(self.depth_sigma_m)
                and self.depth_sigma_m >= 0.0):
            raise ValueError(f"noise field 'depth_sigma_m' must be a finite number >= 0 metres, "
                             f"got {self.depth_sigma_m!r}")
        if not (isinstance(self.dropout, (int, float)) and 0.0 <= self.dropout < 1.0):
            raise ValueError(f"noise field 'dropout' must lie in [0, 1), got {self.dropout!r}")

    @classmethod
    def from_dict(cls, table: Mapping[str, Any], source: str = "<dict>") -> "NoiseModel":
        """Build a noise model from a TOML table; errors name ``source`` and the field."""
        unknown = sorted(set(table) - set(cls.__dataclass_fields__))
        if unknown:
            raise ValueError(f"{source}: noise: unknown field(s) {', '.join(unknown)}; "
                             f"expected some of depth_sigma_m, dropout")
        try:
            return cls(**dict(table))
        except ValueError as exc:
            raise ValueError(f"{source}: {exc}") from None

    @property
    def is_zero(self) -> bool:
        """Return whether the model changes nothing."""
        return self.depth_sigma_m == 0.0 and self.dropout == 0.0

    def apply(self, frame: Frame, rng: np.random.Generator) -> Frame:
        """Return a noisy copy of ``frame``; the input is not modified."""
        if self.is_zero:
            return frame
        near, far = near_far_from_projection(frame.proj)
        depth = frame.depth
        seg = frame.seg
        if self.depth_sigma_m > 0.0:
            z = depth_buffer_to_metres(depth, near, far)
            z = np.clip(z + rng.normal(0.0, self.depth_sigma_m, size=z.shape), near, far)
            depth = metres_to_depth_buffer(z, near, far).astype(np.float32)
        if self.dropout > 0.0:
            seg = np.where(rng.random(size=seg.shape) < self.dropout, np.int32(-1), seg)
            seg = seg.astype(np.int32)
        return frame.replace(depth=depth, seg=seg)
