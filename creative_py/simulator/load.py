"""The rule every backend's tool load follows: which force, averaged how.

A backend measures the load on the tool while its tool action runs (pybullet:
:mod:`creative_py.backends.pybullet.loads`; ManiSkill:
:mod:`creative_py.backends.maniskill.loads`; over ROS 2, a wrist sensor:
:func:`creative_py.backends.ros.episode.wrench_load`), as the fields of
``ToolLoad.to_dict()``. Two things are the same in every backend and are written here:

* **the force** is the task's contact, the tool against the case's target (``[roles]
  target``: the cube a hook pulls, the door a wedge holds), not whatever else the tool
  brushes against (the table under a dragged tool, 1 mm from the grasp, is no load on
  its handle); a backend that cannot tell contacts apart (a wrist sensor) says so;
* **the robust force** the strength check uses is the :data:`ROBUST_PERCENTILE` th
  percentile of that force averaged over each :data:`LOAD_WINDOW_S` of the action
  (:func:`robust_force`). A hook pulling a cube along a tube floor in pybullet meets it
  in pulses, about 1 N for one 4 ms step in every ten and nothing between, the impulse a
  steady pull of about 0.1 N gives (a wrist sensor over ROS 2 measured that steady pull
  in the same trial, 0.08 N). A printed handle does not follow 4 ms pulses: its first
  bending period is about 0.1 s (8 Hz for the 0.6 m, 9 mm PLA hook), so it bears their
  mean. The percentile of single steps measured the pulses' height, which depends on
  the time step.

Units: newtons, seconds.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np

ROBUST_PERCENTILE = 95.0
"""The percentile of the windowed force (over the windows with contact) that a load's
``robust_force_n`` is."""

LOAD_WINDOW_S = 0.1
"""Seconds over which the task's contact force is averaged before its percentile is
taken: about a printed handle's first bending period."""


def windowed(forces: Sequence[float], per_window: int) -> list[float]:
    """Return the mean of ``forces`` (one a step or a sample, evenly spaced, N) over
    consecutive windows of ``per_window`` of them (the last window may be shorter),
    keeping the windows with contact (a positive mean)."""
    n = max(1, int(per_window))
    values = [float(f) for f in forces]
    means = [float(np.mean(values[i:i + n])) for i in range(0, len(values), n)]
    return [m for m in means if m > 0.0]


def robust_force(forces: Sequence[float], per_window: int) -> float:
    """Return the :data:`ROBUST_PERCENTILE` th percentile of the :func:`windowed`
    ``forces`` (N; 0.0 without contact).

    >>> robust_force([0, 0, 0, 4, 0, 0, 0, 4], 4)   # two windows of mean 1 N
    1.0
    """
    means = windowed(forces, per_window)
    return float(np.percentile(means, ROBUST_PERCENTILE)) if means else 0.0


def samples_per_window(rate_hz: float) -> int:
    """Return how many steps or samples at ``rate_hz`` make one :data:`LOAD_WINDOW_S`
    window (at least one)."""
    return max(1, round(LOAD_WINDOW_S * float(rate_hz)))
