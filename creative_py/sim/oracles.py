"""Success oracles: whether the goal holds, judged from the simulated state only.

The ``[oracle]`` table of a world's ``tasks.toml`` names a kind of :data:`ORACLES` and
its options; objects are named by role (``target``, ``tool``, ``context``) or by name,
numbers may be scene expressions (:mod:`creative_py.sim.scene`)::

    [oracle]                      # the cube is out: its centre in front of the mouth
    kind = "below"
    object = "target"
    axis = "x"
    limit = "tube1.mouth_x"

    [oracle]                      # the door is held by the tool
    kind = "joint_held"
    body = "target"
    max_close_deg = 2.0
    min_open_deg = 20.0
    fact = "door_held"

An oracle is called as ``holds(ep, options)`` with the running
:class:`~creative_py.sim.episode.Episode`. An oracle may also name a ``fact`` that the observation reports (with the object's
name) while the goal holds.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping


log = logging.getLogger(__name__)

_AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class OracleKind:
    """A registered oracle: ``holds(episode, options) -> bool`` and its options
    (``name -> default``, None for required)."""

    name: str
    holds: Callable[[Any, Mapping[str, Any]], bool]
    options: Mapping[str, Any]
    subject: str


def below(ep: Any, opts: Mapping[str, Any]) -> bool:
    """Return whether ``object``'s centre lies below ``limit`` (m) along ``axis``."""
    name = ep.object_name(opts["object"])
    centre = ep.true_centre(name)
    return bool(centre[_AXES[opts["axis"]]] < opts["limit"])


def above(ep: Any, opts: Mapping[str, Any]) -> bool:
    """Return whether ``object``'s centre lies above ``limit`` (m) along ``axis``."""
    name = ep.object_name(opts["object"])
    centre = ep.true_centre(name)
    return bool(centre[_AXES[opts["axis"]]] > opts["limit"])


def joint_held(ep: Any, opts: Mapping[str, Any]) -> bool:
    """Return whether the released joint of ``body`` was held by the tool.

    Held: after its release it touched the tool, moved on less than ``max_close_deg``
    after that first contact, and stands at least ``min_open_deg`` open (a door that
    closed most of the way before meeting the tool is not held open).
    """
    record = ep.records.get(ep.object_name(opts["body"]))
    if record is None or record.contact_angle is None:
        return False
    closed = record.closed_after_contact_deg
    return bool(closed < opts["max_close_deg"]
                and math.degrees(record.final_angle) >= opts["min_open_deg"])


ORACLES: dict[str, OracleKind] = {o.name: o for o in (
    OracleKind("below", below, {"object": None, "axis": None, "limit": None, "fact": ""},
               "object"),
    OracleKind("above", above, {"object": None, "axis": None, "limit": None, "fact": ""},
               "object"),
    OracleKind("joint_held", joint_held,
               {"body": None, "max_close_deg": None, "min_open_deg": None, "fact": ""},
               "body"),
)}
"""The oracle kinds a world's ``[oracle]`` table may name."""


OPTION_BOUNDS: dict[str, tuple[float, float, str]] = {
    "limit": (-10.0, 10.0, "m"),
    "max_close_deg": (0.0, 180.0, "deg"),
    "min_open_deg": (0.0, 180.0, "deg"),
}
"""The bounds ``(low, high, unit)`` of the oracles' numeric options, by name (checked by
the loader in every variant and location, :func:`creative_py.sim.world.check_values`)."""


@dataclass(frozen=True)
class OracleSpec:
    """A world's oracle: its kind and raw options (expressions resolved per episode)."""

    kind: str
    options: dict[str, Any]

    @property
    def oracle(self) -> OracleKind:
        """Return the registered kind."""
        return ORACLES[self.kind]
