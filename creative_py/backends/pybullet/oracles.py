"""Success oracles: whether the goal holds, judged from the simulated state only.

The ``[oracle]`` table of a world's ``tasks.toml`` names a kind of :data:`ORACLES` and
its options; objects are named by role (``target``, ``tool``, ``context``) or by name,
numbers may be scene expressions (:mod:`creative_py.backends.pybullet.scene`)::

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

An oracle is called as ``judge(ep, options)`` with the running
:class:`~creative_py.backends.pybullet.episode.Episode` and returns a
:class:`~creative_py.simulator.types.Verdict`: whether the goal holds, the quantity it
measured and the threshold it judged it by (the cube's centre against the mouth and how
far the cube moved; the door's angle against the held limit and how far it closed after
touching the tool). An oracle may also name a ``fact`` that the observation reports
(with the object's name) while the goal holds.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

from creative_py.simulator.types import Verdict

log = logging.getLogger(__name__)

_AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class OracleKind:
    """A registered oracle: ``judge(episode, options) -> Verdict``, its options
    (``name -> default``, None for required), the option naming the object it judges
    (``subject``) and the option holding its threshold (``threshold``)."""

    name: str
    judge: Callable[[Any, Mapping[str, Any]], Verdict]
    options: Mapping[str, Any]
    subject: str
    threshold: str = ""

    def holds(self, ep: Any, opts: Mapping[str, Any]) -> bool:
        """Return whether the goal holds (the verdict's judgement)."""
        return self.judge(ep, opts).holds


def _position(ep: Any, opts: Mapping[str, Any], relation: str) -> Verdict:
    """Judge ``object``'s centre along ``axis`` against ``limit`` (m) by ``relation``;
    measure how far it ended from the limit and how far it moved in the trial."""
    name = ep.object_name(opts["object"])
    axis, limit = opts["axis"], float(opts["limit"])
    centre = ep.true_centre(name)
    value = float(centre[_AXES[axis]])
    holds = bool(value < limit) if relation == "<" else bool(value > limit)
    start = ep.start_centres.get(name)
    moved = (None if start is None
             else math.dist(tuple(centre[:3]), tuple(start[:3])))
    beyond = (limit - value) if relation == "<" else (value - limit)
    side = "past" if beyond > 0 else "short of"
    detail = f"{abs(beyond) * 100:.1f} cm {side} the limit"
    if moved is not None:
        detail += f"; moved {moved * 100:.1f} cm in the trial"
    return Verdict(f"{name} centre {axis}", value, limit, "m", relation, holds,
                   detail=detail, note="" if moved is None else f"moved {moved * 100:.1f} cm",
                   measures={"past_limit_m": round(beyond, 6),
                             "moved_m": None if moved is None else round(moved, 6)})


def below(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge whether ``object``'s centre lies below ``limit`` (m) along ``axis``."""
    return _position(ep, opts, "<")


def above(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge whether ``object``'s centre lies above ``limit`` (m) along ``axis``."""
    return _position(ep, opts, ">")


def joint_held(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge whether the released joint of ``body`` was held by the tool.

    Held: after its release it touched the tool, moved on less than ``max_close_deg``
    after that first contact, and stands at least ``min_open_deg`` open (a door that
    closed most of the way before meeting the tool is not held open). The verdict's
    quantity is the joint's angle (its final one after the release, its present one
    before) against ``min_open_deg``; the closing after contact is a further measure.
    """
    name = ep.object_name(opts["body"])
    record = ep.records.get(name)
    max_close, min_open = float(opts["max_close_deg"]), float(opts["min_open_deg"])
    measures: dict[str, Any] = {"released": record is not None,
                                "max_close_deg": max_close}
    if record is None:
        body = ep.bodies.get(name)
        angle = getattr(body, "angle", None)
        value = math.degrees(angle(ep.sim)) if callable(angle) else None
        return Verdict(f"{name} angle", value, min_open, "deg", ">=", False,
                       detail="not released", measures=measures, note="not released")
    value = math.degrees(record.final_angle)
    closed = record.closed_after_contact_deg
    measures.update(touched=record.touched,
                    closed_after_contact_deg=None if closed is None else round(closed, 4),
                    contact_angle_deg=None if closed is None
                    else round(math.degrees(record.contact_angle), 4))
    if closed is None:
        holds, detail = False, "never touched the tool"
        note = detail
    else:
        holds = bool(closed < max_close and value >= min_open)
        detail = (f"closed {closed:.2f} deg after touching the tool at "
                  f"{math.degrees(record.contact_angle):.1f} deg (needs < {max_close:g} deg)")
        note = f"closed {closed:.1f} deg after contact, needs < {max_close:g}"
    return Verdict(f"{name} angle", value, min_open, "deg", ">=", holds, detail=detail,
                   measures=measures, note=note)


ORACLES: dict[str, OracleKind] = {o.name: o for o in (
    OracleKind("below", below, {"object": None, "axis": None, "limit": None, "fact": ""},
               "object", "limit"),
    OracleKind("above", above, {"object": None, "axis": None, "limit": None, "fact": ""},
               "object", "limit"),
    OracleKind("joint_held", joint_held,
               {"body": None, "max_close_deg": None, "min_open_deg": None, "fact": ""},
               "body", "min_open_deg"),
)}
"""The oracle kinds a world's ``[oracle]`` table may name."""


OPTION_BOUNDS: dict[str, tuple[float, float, str]] = {
    "limit": (-10.0, 10.0, "m"),
    "max_close_deg": (0.0, 180.0, "deg"),
    "min_open_deg": (0.0, 180.0, "deg"),
}
"""The bounds ``(low, high, unit)`` of the oracles' numeric options, by name (checked by
the loader in every variant and location, :func:`creative_py.backends.pybullet.world.check_values`)."""


@dataclass(frozen=True)
class OracleSpec:
    """A world's oracle: its kind and raw options (expressions resolved per episode)."""

    kind: str
    options: dict[str, Any]

    @property
    def oracle(self) -> OracleKind:
        """Return the registered kind."""
        return ORACLES[self.kind]
