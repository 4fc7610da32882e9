"""Per-body masks from pybullet's segmentation image.

With ``ER_SEGMENTATION_MASK_OBJECT_AND_LINKINDEX`` each pixel holds
``body_id + ((link_index + 1) << 24)``, and -1 where no body was hit. A body's mask
gathers all of its links.
"""

from __future__ import annotations

import numpy as np

from creative_py.perception.frame import Frame

BODY_MASK = 0xFFFFFF
"""Bits of a segmentation value that carry the body id."""


def body_mask(seg: np.ndarray, body_id: int) -> np.ndarray:
    """Return a boolean mask of the pixels showing body ``body_id`` (any link)."""
    if body_id < 0 or body_id > BODY_MASK:
        raise ValueError(f"body id must lie in [0, {BODY_MASK}], got {body_id}")
    seg = np.asarray(seg)
    return (seg != -1) & ((seg & BODY_MASK) == body_id)


def link_index(seg: np.ndarray) -> np.ndarray:
    """Return the link index of each pixel (-1 for a base link; meaningless where seg is -1)."""
    seg = np.asarray(seg).astype(np.int64)
    return (seg >> 24) - 1


def frame_masks(frame: Frame, bodies: dict[str, int]) -> dict[str, np.ndarray]:
    """Return ``{name: mask}`` for each named body of ``bodies`` (name -> body id)."""
    return {name: body_mask(frame.seg, bid) for name, bid in bodies.items()}
