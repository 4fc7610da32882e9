"""The rule every backend's tool load follows: which force, averaged how.

A backend measures the load on the tool while its tool action runs (pybullet:
:mod:`creative_py.backends.pybullet.loads`; ManiSkill:
:mod:`creative_py.backends.maniskill.loads`; over ROS 2, a wrist sensor:
:func:`creative_py.backends.ros.episode.wrench_load`), as the fields of
a :class:`ToolLoad` (this module's, every backend's record of the load; ManiSkill gives
its fields). Two things are the same in every backend and are written here:

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

from dataclasses import asdict, dataclass
from typing import Any, Optional, Sequence

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


@dataclass(frozen=True)
class ToolLoad:
    """The task's contact load on a tool during its action (the tool against the
    case's target).

    Attributes
    ----------
    max_force_n : float
        The largest sum over one physics step of the normal forces of the tool's
        contacts with the target, newtons (0.0 when the tool did not touch it).
    point : tuple of float or None
        Where it acted: the contacts' centroid weighted by normal force, tool frame,
        metres (None without contact).
    force : tuple of float or None
        The summed contact force vector of that step (normal and friction), tool frame,
        newtons.
    grasp_point : tuple of float or None
        The gripper frame's origin in the tool frame at that step, metres (None when the
        tool was not held: a placed block).
    contacts : int
        Contact points of that step.
    bodies : tuple of str
        The names of the bodies whose contacts are the load (the target; empty
        without contact).
    step : int
        The physics step (of the episode) at which it happened.
    steps : int
        The physics steps watched (the length of the tool action).
    robust_force_n : float
        The :data:`ROBUST_PERCENTILE` th percentile of the summed normal force
        averaged over each :data:`LOAD_WINDOW_S` of the action, over the windows with
        contact, newtons (0.0 without contact): the force the strength check uses,
        the peak being a contact spike.
    contact_steps : int
        The steps (or sensor samples) with contact.
    impulse_ns : float
        The summed normal force integrated over the action, newton seconds.
    other_bodies : tuple of str
        What else the tool touched during the action, not counted in the load, sorted.
    window_s : float
        The window the robust force averages over, seconds (0.0 for a load recorded
        before windows: its robust force is the per-step percentile).
    """

    max_force_n: float = 0.0
    point: Optional[tuple[float, float, float]] = None
    force: Optional[tuple[float, float, float]] = None
    grasp_point: Optional[tuple[float, float, float]] = None
    contacts: int = 0
    bodies: tuple[str, ...] = ()
    step: int = 0
    steps: int = 0
    robust_force_n: float = 0.0
    contact_steps: int = 0
    impulse_ns: float = 0.0
    other_bodies: tuple[str, ...] = ()
    window_s: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        """Return the load as JSON-ready data (tuples become lists, floats rounded)."""
        d = asdict(self)
        for k in ("point", "force", "grasp_point"):
            if d[k] is not None:
                d[k] = [round(float(v), 6) for v in d[k]]
        for k in ("max_force_n", "robust_force_n", "impulse_ns"):
            d[k] = round(float(d[k]), 6)
        d["bodies"] = list(d["bodies"])
        d["other_bodies"] = list(d["other_bodies"])
        return d

    @classmethod
    def from_dict(cls, data: Optional[dict[str, Any]]) -> "ToolLoad":
        """Return the load :meth:`to_dict` wrote (an empty load for None)."""
        if not data:
            return cls()
        def vec(v):
            return None if v is None else tuple(float(x) for x in v)
        return cls(float(data.get("max_force_n", 0.0)), vec(data.get("point")),
                   vec(data.get("force")), vec(data.get("grasp_point")),
                   int(data.get("contacts", 0)), tuple(data.get("bodies", ())),
                   int(data.get("step", 0)), int(data.get("steps", 0)),
                   float(data.get("robust_force_n", data.get("max_force_n", 0.0))),
                   int(data.get("contact_steps", 0)), float(data.get("impulse_ns", 0.0)),
                   tuple(data.get("other_bodies", ())), float(data.get("window_s", 0.0)))
