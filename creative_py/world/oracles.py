"""Success oracles: whether the goal holds, judged from the simulated state only.

The ``[oracle]`` table of a world's ``tasks.toml`` names a kind of :data:`ORACLES` and
its options; objects are named by role (``target``, ``tool``, ``context``) or by name,
numbers may be scene expressions (:mod:`creative_py.world.expressions`)::

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
episode of a backend that builds the world (the pybullet backend's
:class:`~creative_py.backends.pybullet.episode.Episode`, the ROS 2 backend's twin of it),
which measures what the judges read: ``object_name(role_or_name)``,
``true_centre(name)`` (x, y, z, yaw), ``start_centres`` (name -> the centre at the
episode's start), ``linear_velocity(name)``, ``joint_angle(name)`` (rad, or None) and
``records`` (name -> a released joint's record: ``final_angle``,
``touched``, ``closed_after_contact_deg``, ``contact_angle``). It returns a
:class:`~creative_py.simulator.types.Verdict`: whether the goal holds, the quantity it
measured and the threshold it judged it by (the cube's centre against the mouth and how
far the cube moved; the door's angle against the held limit and how far it closed after
touching the tool). An oracle may also name a ``fact`` that the observation reports
(with the object's name) while the goal holds.

The shaped-reward kinds (``goal_distance``, ``axis_progress``, ``in_box_or_distance``,
``displacement_neighbours``, ``fraction_within``; RoboToolBench's rewards, the formulas
in :mod:`creative_py.simulator.rewards`) measure a reward in [0, 1] and judge
it by ``reward > threshold`` (0.99 by default, the benchmark's ``done()``)::

    [oracle]                      # BringCube: 1 - |p - goal|_1 / |start - goal|_1
    kind = "goal_distance"
    object = "target"
    goal = [0.6, 0.0, 0.035]
    start = [1.0, 0.0, 0.035]
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

from creative_py.simulator import rewards
from creative_py.simulator.rewards import l1, terms_json
from creative_py.simulator.types import NonFiniteState, Verdict
from creative_py.world_files import OptionError, did_you_mean, shown

log = logging.getLogger(__name__)

_AXES = {"x": 0, "y": 1, "z": 2}


@dataclass(frozen=True)
class SceneNames:
    """What an oracle's options may name in one episode of a world, for the loader's
    check (:func:`check_options`): the roles (``role -> object``), every object of the
    scene (its bodies, a scatter's members, the tool) and those whose start the episode
    records (the perceived objects and the movable bodies: what a reward counting
    displacements can read)."""

    roles: Mapping[str, str]
    objects: frozenset[str]
    started: frozenset[str]

    def resolve(self, option: str, word: Any, started: bool = False) -> str:
        """Return the object ``word`` (a role or a name) denotes; raise
        :class:`OptionError` naming ``option`` if it denotes none (or, with
        ``started``, one whose start is not recorded)."""
        if not isinstance(word, str) or not word:
            raise OptionError(option, f"must name an object (a role: "
                              f"{', '.join(self.roles)}; or a body of scene.toml), got "
                              f"{word!r}")
        name = self.roles.get(word, word)
        if name not in self.objects:
            raise OptionError(option, f"{word!r} is no object of the scene"
                              + did_you_mean(word, [*self.roles, *sorted(self.objects)])
                              + f"; objects: {', '.join(sorted(self.objects))}")
        if started and name not in self.started:
            raise OptionError(option, f"{word!r}: the episode records no start of it (it "
                              "is neither perceived nor a movable body)")
        return name


@dataclass(frozen=True)
class OracleKind:
    """A registered oracle: ``judge(episode, options) -> Verdict``, its options
    (``name -> default``, None for required), the option naming the object it judges
    (``subject``), the option holding its threshold (``threshold``), the options
    that are words, not numbers (``words``: names, axes; the subject is one), and
    ``check(options, names)``, which raises :class:`OptionError` for options that
    cannot be judged (run by the loader with the options resolved,
    :func:`check_options`)."""

    name: str
    judge: Callable[[Any, Mapping[str, Any]], Verdict]
    options: Mapping[str, Any]
    subject: str
    threshold: str = ""
    words: tuple[str, ...] = ("axis", "fact")
    check: Callable[[Mapping[str, Any], SceneNames], None] = lambda opts, names: None
    velocity: Callable[[Mapping[str, Any]], bool] = lambda opts: False
    """Whether the judge reads an object's velocity with these options."""

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
        angle = ep.joint_angle(name)
        value = None if angle is None else math.degrees(angle)
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


# ------------------------------------------------------------------ shaped rewards
# RoboToolBench's rewards (creative_py/simulator/rewards.py has the formulas):
# the verdict's quantity is the reward in [0, 1], judged by ``reward > threshold`` (the
# benchmark's done(): 0.99); the formula's terms are its measures.

def _point(value: Any, option: str) -> tuple[float, ...]:
    """Return an option's point (a tuple of numbers), or raise ValueError naming it."""
    if not isinstance(value, tuple) or not value \
            or not all(isinstance(v, float) for v in value):
        raise ValueError(f"oracle option {option!r} must be a list of numbers (m), got "
                         f"{value!r}")
    return value


def _names(ep: Any, value: Any, option: str) -> list[str]:
    """Return the objects a list option names (roles or names)."""
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, (list, tuple)) or not value \
            or not all(isinstance(v, str) for v in value):
        raise ValueError(f"oracle option {option!r} must be a list of object names, got "
                         f"{value!r}")
    return [ep.object_name(v) for v in value]


def _finite(values: Any, name: str, what: str) -> tuple[float, ...]:
    """Return ``values`` as floats; raise :class:`NonFiniteState` (a ValueError: the
    trial is ``invalid``) if one is not finite."""
    out = tuple(float(v) for v in values)
    if not all(math.isfinite(v) for v in out):
        raise NonFiniteState(f"non-finite {what} of {name}: {out}")
    return out


def _start(ep: Any, name: str) -> tuple[float, ...]:
    """Return where an object's centre was when the trial began (after the settling)."""
    start = ep.start_centres.get(name)
    if start is None:
        start = getattr(ep, "body_starts", {}).get(name)
    if start is None:
        raise ValueError(f"no start position recorded for {name!r}")
    return _finite(start[:3], name, "start")


def _centre(ep: Any, name: str) -> tuple[float, float, float]:
    """Return an object's true centre (m); :class:`NonFiniteState` after a blow-up."""
    return _finite(ep.true_centre(name)[:3], name, "pose")


def _speed(ep: Any, name: str) -> float:
    """Return the object's linear speed (m/s) after the last physics step.

    pybullet integrates semi-implicitly (the position moves by the new velocity times
    the step), so this is the last step's displacement over the step, the speed the
    benchmark's MoveBall env measures by differencing its positions."""
    return float(math.sqrt(sum(c * c for c in _finite(ep.linear_velocity(name), name,
                                                          "velocity"))))


def _reward_verdict(name: str, reward: float, terms: Mapping[str, Any],
                    threshold: float, words: str) -> Verdict:
    holds = bool(reward > threshold)
    return Verdict("reward", float(reward), float(threshold), "", ">", holds,
                   detail=f"{name}: {words}", measures=terms_json(terms), note=words)


def goal_distance(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge ``max(0, 1 - |p - goal|_1 / scale - speed_weight * |v|)`` of ``object``.

    ``scale`` 0 (the default) is the L1 distance from ``start`` to ``goal``, as the
    benchmark's envs normalise it."""
    name = ep.object_name(opts["object"])
    goal, start = _point(opts["goal"], "goal"), _point(opts["start"], "start")
    scale = float(opts["scale"]) or l1(start, goal)
    weight = float(opts["speed_weight"])
    speed = _speed(ep, name) if weight else 0.0
    p = _centre(ep, name)[:len(goal)]
    reward, terms = rewards.goal_distance(p, goal, scale, speed, weight)
    words = f"{terms['distance_l1_m'] * 1000:.1f} mm (L1) from the goal"
    if weight:
        words += f", moving at {speed:.3f} m/s"
    return _reward_verdict(name, reward, terms, opts["threshold"], words)


def axis_progress(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge the best over ``axes`` of ``clip(1 - (p - near) / (start - near))``."""
    name = ep.object_name(opts["object"])
    axes = opts["axes"]
    if isinstance(axes, str):
        axes = [axes]
    if not isinstance(axes, (list, tuple)) or not all(a in _AXES for a in axes):
        raise ValueError(f"oracle option 'axes' must list x, y or z, got {axes!r}")
    reward, terms = rewards.axis_progress(_centre(ep, name), _point(opts["start"], "start"),
                                          _point(opts["near"], "near"),
                                          [_AXES[a] for a in axes])
    words = ", ".join(f"{k[-1]} {v:.3f}" for k, v in terms.items())
    return _reward_verdict(name, reward, terms, opts["threshold"], words)


def in_box_or_distance(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge 1 inside the box ``box_min``-``box_max``, else the L1 progress to its
    centre from ``start`` plus ``bonus`` below ``bonus_below_z``."""
    name = ep.object_name(opts["object"])
    reward, terms = rewards.in_box_or_distance(
        _centre(ep, name), _point(opts["start"], "start"), _point(opts["box_min"], "box_min"),
        _point(opts["box_max"], "box_max"), float(opts["bonus"]),
        float(opts["bonus_below_z"]))
    words = ("in the box" if terms["in_box"] else
             f"{terms['distance_l1_m'] * 100:.1f} cm (L1) from the box's centre"
             + (", below the bonus height" if terms["below_bonus_z"] else ""))
    return _reward_verdict(name, reward, terms, opts["threshold"], words)


def displacement_neighbours(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge ``object``'s displacement against ``success_distance`` with the penalty
    ``exp(-sum of the neighbours' displacements)``."""
    name = ep.object_name(opts["object"])
    others = _names(ep, opts["neighbours"], "neighbours")
    reward, terms = rewards.displacement_with_neighbours(
        _centre(ep, name), _start(ep, name),
        [(_centre(ep, n), _start(ep, n)) for n in others], float(opts["success_distance"]))
    words = (f"moved {terms['moved_m'] * 100:.1f} cm, the others "
             f"{terms['neighbours_moved_m'] * 100:.1f} cm")
    return _reward_verdict(name, reward, terms, opts["threshold"], words)


def fraction_within(ep: Any, opts: Mapping[str, Any]) -> Verdict:
    """Judge the mean over ``objects`` of 1 within ``within`` (L1) of ``centre``, else
    their L1 progress towards it from where each started."""
    names = _names(ep, opts["objects"], "objects")
    centre = _point(opts["centre"], "centre")
    reward, terms = rewards.fraction_within([_centre(ep, n) for n in names],
                                            [_start(ep, n) for n in names], centre,
                                            float(opts["within"]))
    words = f"{terms['inside']} of {terms['objects']} in the goal"
    return _reward_verdict("objects", reward, terms, opts["threshold"], words)


# ------------------------------------------------------------------ load-time checks
# Each kind's check of its resolved options against the scene (the loader runs it for
# every variant and location, :func:`creative_py.world.read.check_values`):
# what its judge would otherwise fail on mid-run, or measure without meaning.

def _vector(opts: Mapping[str, Any], option: str, lengths: tuple[int, ...],
            why: str = "") -> tuple:
    """Return the option's numbers; raise unless it has one of ``lengths`` numbers."""
    value = opts[option]
    if not isinstance(value, tuple) or len(value) not in lengths \
            or not all(isinstance(v, float) for v in value):
        want = " or ".join(str(n) for n in lengths)
        raise OptionError(option, f"must be a list of {want} numbers (m){why}, got "
                          f"{shown(value)}")
    return value


def _scalars(opts: Mapping[str, Any], names: tuple[str, ...]) -> None:
    for option in names:
        if isinstance(opts.get(option), tuple):
            raise OptionError(option, f"must be a number, got a list {shown(opts[option])}")


def _axis(option: str, word: Any) -> int:
    if word not in _AXES:
        raise OptionError(option, f"must be x, y or z, got {word!r}")
    return _AXES[word]


def _check_position(opts: Mapping[str, Any], names: SceneNames) -> None:
    names.resolve("object", opts["object"])
    _axis("axis", opts["axis"])
    _scalars(opts, ("limit",))


def _check_joint_held(opts: Mapping[str, Any], names: SceneNames) -> None:
    names.resolve("body", opts["body"])
    _scalars(opts, ("max_close_deg", "min_open_deg"))


def _check_goal_distance(opts: Mapping[str, Any], names: SceneNames) -> None:
    names.resolve("object", opts["object"])
    _scalars(opts, ("scale", "speed_weight", "threshold"))
    goal = _vector(opts, "goal", (1, 2, 3))
    start = _vector(opts, "start", (len(goal),), ", as many as 'goal'")
    if not opts["scale"] and l1(start, goal) == 0:
        raise OptionError("start", "equals 'goal', so the reward's scale |start - goal|_1 "
                          "is 0 (move them apart or set 'scale')")


def _check_axis_progress(opts: Mapping[str, Any], names: SceneNames) -> None:
    names.resolve("object", opts["object"])
    _scalars(opts, ("threshold",))
    axes = opts["axes"]
    if isinstance(axes, str):
        axes = [axes]
    if not isinstance(axes, (list, tuple)) or not axes:
        raise OptionError("axes", f"must list x, y or z, got {axes!r}")
    for a in axes:
        _axis("axes", a)
    if len(set(axes)) != len(axes):
        raise OptionError("axes", f"names an axis twice: {list(axes)}")
    start = _vector(opts, "start", (len(axes),), ", one per axis of 'axes'")
    near = _vector(opts, "near", (len(axes),), ", one per axis of 'axes'")
    for a, s, n in zip(axes, start, near):
        if s == n:
            raise OptionError("near", f"along {a} equals 'start' ({s:g}), so that axis' "
                              "progress has no scale")


def _check_in_box(opts: Mapping[str, Any], names: SceneNames) -> None:
    names.resolve("object", opts["object"])
    _scalars(opts, ("bonus", "bonus_below_z", "threshold"))
    lo, hi = _vector(opts, "box_min", (3,)), _vector(opts, "box_max", (3,))
    for axis, a, b in zip("xyz", lo, hi):
        if not a < b:
            raise OptionError("box_min", f"along {axis} ({a:g}) must lie below "
                              f"'box_max' ({b:g})")
    start = _vector(opts, "start", (3,))
    centre = [(a + b) / 2 for a, b in zip(lo, hi)]
    if l1(start, centre) == 0:
        raise OptionError("start", "lies at the box's centre, so the reward's scale "
                          "|start - centre|_1 is 0")


def _check_displacement(opts: Mapping[str, Any], names: SceneNames) -> None:
    subject = names.resolve("object", opts["object"], started=True)
    _scalars(opts, ("success_distance", "threshold"))
    others = _name_list(opts, "neighbours", names)
    if subject in others:
        raise OptionError("neighbours", f"names the object itself ({subject!r})")


def _check_fraction_within(opts: Mapping[str, Any], names: SceneNames) -> None:
    _name_list(opts, "objects", names)
    _scalars(opts, ("within", "threshold"))
    _vector(opts, "centre", (1, 2, 3))


def _name_list(opts: Mapping[str, Any], option: str, names: SceneNames) -> list[str]:
    """Return the objects a list option names, each resolved once, with a start."""
    value = opts[option]
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, (list, tuple)) or not value:
        raise OptionError(option, f"must be a list of object names, got {value!r}")
    out = [names.resolve(option, v, started=True) for v in value]
    if len(set(out)) != len(out):
        raise OptionError(option, f"names an object twice: {shown(value)}")
    return out


def check_options(kind: str, opts: Mapping[str, Any], names: SceneNames) -> None:
    """Raise :class:`OptionError` unless the oracle ``kind``'s resolved options can be
    judged in a scene of ``names`` (vector lengths, axes, box order, non-zero scales,
    names that resolve)."""
    ORACLES[kind].check(opts, names)


def objects_read(kind: str, opts: Mapping[str, Any], names: SceneNames) -> list[str]:
    """Return the objects the oracle ``kind`` reads with the resolved ``opts`` in a
    scene of ``names``, in order: those its check resolves (a backend that follows only
    some objects' poses refuses the others, :mod:`creative_py.backends.ros`)."""
    seen: list[str] = []

    class _Seen(SceneNames):
        def resolve(self, option: str, word: Any, started: bool = False) -> str:
            name = SceneNames.resolve(self, option, word, started)
            seen.append(name)
            return name

    ORACLES[kind].check(opts, _Seen(names.roles, names.objects, names.started))
    return list(dict.fromkeys(seen))


ORACLES: dict[str, OracleKind] = {o.name: o for o in (
    OracleKind("below", below, {"object": None, "axis": None, "limit": None, "fact": ""},
               "object", "limit", check=_check_position),
    OracleKind("above", above, {"object": None, "axis": None, "limit": None, "fact": ""},
               "object", "limit", check=_check_position),
    OracleKind("joint_held", joint_held,
               {"body": None, "max_close_deg": None, "min_open_deg": None, "fact": ""},
               "body", "min_open_deg", check=_check_joint_held),
    OracleKind("goal_distance", goal_distance,
               {"object": None, "goal": None, "start": None, "scale": 0.0,
                "speed_weight": 0.0, "threshold": 0.99, "fact": ""},
               "object", "threshold", check=_check_goal_distance,
               velocity=lambda opts: float(opts["speed_weight"]) > 0.0),
    OracleKind("axis_progress", axis_progress,
               {"object": None, "axes": None, "start": None, "near": None,
                "threshold": 0.99, "fact": ""},
               "object", "threshold", words=("axes", "fact"), check=_check_axis_progress),
    OracleKind("in_box_or_distance", in_box_or_distance,
               {"object": None, "box_min": None, "box_max": None, "start": None,
                "bonus": 0.0, "bonus_below_z": -10.0, "threshold": 0.99, "fact": ""},
               "object", "threshold", check=_check_in_box),
    OracleKind("displacement_neighbours", displacement_neighbours,
               {"object": None, "neighbours": None, "success_distance": None,
                "threshold": 0.99, "fact": ""},
               "object", "threshold", words=("neighbours", "fact"),
               check=_check_displacement),
    OracleKind("fraction_within", fraction_within,
               {"objects": None, "centre": None, "within": None, "threshold": 0.99},
               "objects", "threshold", words=(), check=_check_fraction_within),
)}
"""The oracle kinds a world's ``[oracle]`` table may name."""


OPTION_BOUNDS: dict[str, tuple[float, float, str]] = {
    "limit": (-10.0, 10.0, "m"),
    "goal": (-10.0, 10.0, "m"),
    "start": (-10.0, 10.0, "m"),
    "near": (-10.0, 10.0, "m"),
    "box_min": (-10.0, 10.0, "m"),
    "box_max": (-10.0, 10.0, "m"),
    "centre": (-10.0, 10.0, "m"),
    "scale": (0.0, 10.0, "m"),
    "within": (0.0, 10.0, "m"),
    "success_distance": (0.0001, 10.0, "m"),
    "bonus_below_z": (-10.0, 10.0, "m"),
    "bonus": (0.0, 1.0, "(a reward)"),
    "speed_weight": (0.0, 100.0, "s/m"),
    "threshold": (0.0, 1.0, "(a reward)"),
    "max_close_deg": (0.0, 180.0, "deg"),
    "min_open_deg": (0.0, 180.0, "deg"),
}
"""The bounds ``(low, high, unit)`` of the oracles' numeric options, by name (checked by
the loader in every variant and location, :func:`creative_py.world.read.check_values`)."""


@dataclass(frozen=True)
class OracleSpec:
    """A world's oracle: its kind and raw options (expressions resolved per episode)."""

    kind: str
    options: dict[str, Any]

    @property
    def oracle(self) -> OracleKind:
        """Return the registered kind."""
        return ORACLES[self.kind]
