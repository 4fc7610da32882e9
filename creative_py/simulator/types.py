"""The simulator's value types: what a skill, an observation and a trial give back.

Every backend (:mod:`creative_py.simulator`) returns these, so the learning loop reads
one ``SkillOutcome``, ``Observation`` and ``TrialResult`` whatever the physics. A leaf
of the boundary (it imports only the outcome vocabulary of
:mod:`creative_py.records.trial`, the bottom layer), so a backend's episode, primitives
and robot and the learning loop can all share them without an import cycle.

Outcomes of a trial (:data:`TRIAL_OUTCOMES`, decided in one place for every backend,
above the boundary: :func:`creative_py.simulator.trial.trial_outcome`): ``success`` /
``failure`` (every skill
ran, or the tool was stopped while acting; the goal was or was not reached),
``blocked`` (a move before the tool action was stopped by a collision: the
tracking-error guard; or the trial's step or time budget ran out before the goal was
reached, wherever it ran out), ``unreachable`` (no arm posture reaches a waypoint),
``invalid`` (the physics blew up: NaN, an object thrown out of the scene).
"""

from __future__ import annotations

import json
import math
from dataclasses import asdict, dataclass, field
from typing import Any, Callable, Literal, Optional, Sequence

from creative_py.records.trial import TRIAL_OUTCOMES  # noqa: F401 - the simulator's vocabulary too

SkillStatus = Literal["ok", "blocked", "out_of_time", "unreachable", "invalid"]
TrialOutcome = Literal["success", "failure", "blocked", "unreachable", "invalid"]
SKILL_STATUSES: tuple[str, ...] = ("ok", "blocked", "out_of_time", "unreachable", "invalid")

Fact = tuple[Any, ...]
"""A primitive fact as a tuple: predicate name then arguments, e.g. ``("held", "t1")``."""

PoseTarget = Callable[[list[Fact], str, tuple[float, ...]], tuple]
"""``(facts, tool, pose) -> world target`` of a pose, e.g. ``("tip", x, y, roll)``, or
``()`` if the perceived state lacks what it needs. The caller gives it to the episode
(the learning layer builds it from the engine's pose solution,
:func:`creative_py.learning.poses.pose_resolver`); a backend asks no one."""


_RELATIONS = {"<": lambda a, b: a < b, "<=": lambda a, b: a <= b,
              ">": lambda a, b: a > b, ">=": lambda a, b: a >= b}


@dataclass(frozen=True)
class Verdict:
    """A measured verdict: what the physics measured and the threshold it was judged by.

    Every oracle (the world files' kinds: :mod:`creative_py.world.oracles`) and every
    guard that stops a motion gives one, so a failure says how far it was from success,
    in the world's units.

    Attributes
    ----------
    quantity : str
        What was measured, in words (``cube1 centre x``, ``door1 angle``,
        ``gripper lag``).
    value : float or None
        The measured value (None when there was nothing to measure).
    threshold : float or None
        The limit it is judged against.
    unit : str
        The unit of both (``m``, ``deg``, ``rad``).
    relation : str
        What passing needs: ``value relation threshold`` with one of ``<``, ``<=``,
        ``>``, ``>=`` (for a guard: what lets the motion go on).
    holds : bool
        Whether the judgement passed (the goal holds; the motion was not stopped).
    threshold_name : str
        Where the threshold comes from (a scene expression or an option's name).
    detail : str
        The other measures behind the judgement, in words (empty when none).
    measures : dict
        The other measures by name (numbers, names), JSON-ready.
    note : str
        The measure beside the main one that the judgement also rests on, in a few
        words (``closed 0.3 deg after contact, needs < 2``), for short lines. Left
        empty while the judgement disagrees with the main measure, the short lines
        say so (:meth:`short_note`), so that no line reads as a pass that failed.
    """

    quantity: str
    value: float | None
    threshold: float | None
    unit: str
    relation: str
    holds: bool
    threshold_name: str = ""
    detail: str = ""
    measures: dict[str, Any] = field(default_factory=dict)
    note: str = ""

    def met(self) -> bool:
        """Return whether ``value relation threshold`` (False without a value)."""
        if self.value is None or self.threshold is None:
            return False
        return bool(_RELATIONS[self.relation](self.value, self.threshold))

    def short_note(self) -> str:
        """Return :attr:`note`, or, when there is none and the judgement is not what
        the main measure against its threshold says, what judged it (``judged not met
        by ManiSkill PokeCube-v1 evaluate()``); empty otherwise."""
        if self.note or self.value is None or self.threshold is None \
                or self.met() == bool(self.holds):
            return self.note
        return (f"judged {'met' if self.holds else 'not met'} by "
                f"{self.threshold_name or 'the oracle'}")

    def text(self) -> str:
        """Return the verdict in words, e.g. ``door1 angle 12.5 deg (needs >= 20 deg);
        closed 0.3 deg after touching the tool (needs < 2 deg)``."""
        unit = f" {self.unit}" if self.unit else ""  # a reward has none
        value = ("unmeasured" if self.value is None
                 else f"{_num(self.value, self.unit)}{unit}")
        limit = ("" if self.threshold is None
                 else f"{_num(self.threshold, self.unit)}{unit}")
        src = f", {self.threshold_name}" if self.threshold_name else ""
        text = f"{self.quantity} {value} (needs {self.relation} {limit}{src})"
        return f"{text}; {self.detail}" if self.detail else text

    def brief(self) -> str:
        """Return the main measure on one short line (a clip caption's), e.g.
        ``door1 angle 12.3 deg, needs >= 20.0``."""
        unit = f" {self.unit}" if self.unit else ""
        value = ("unmeasured" if self.value is None
                 else f"{_num(self.value, self.unit)}{unit}")
        limit = "" if self.threshold is None else _num(self.threshold, self.unit)
        return f"{self.quantity} {value}, needs {self.relation} {limit}"

    def to_dict(self) -> dict[str, Any]:
        """Return the verdict as JSON-ready data with its :meth:`text`."""
        def r(v):
            return None if v is None else float(f"{float(v):.6g}")
        return {"quantity": self.quantity, "value": r(self.value),
                "threshold": r(self.threshold), "unit": self.unit,
                "relation": self.relation, "holds": bool(self.holds),
                "threshold_name": self.threshold_name,
                "measures": json.loads(json.dumps(self.measures, default=str)),
                "text": self.text(), "brief": self.brief(), "note": self.short_note()}


_DECIMALS = {"m": 4, "deg": 1, "rad": 4, "N": 1}


def pose_numbers(skill: str, pose: Optional[Sequence[float]],
                 names: Sequence[str]) -> tuple[float, ...]:
    """Return the pose numbers a pose skill is given, as floats; what every backend's
    ``run_skill`` checks before it moves.

    Raises
    ------
    ValueError
        ``pose`` is None (the message names the skill and the pose's ``names``) or a
        number is not finite.
    """
    if pose is None:
        raise ValueError(f"skill {skill} needs the pose numbers ({', '.join(names)})")
    numbers = tuple(float(v) for v in pose)
    if not all(math.isfinite(v) for v in numbers):
        raise ValueError(f"pose numbers must be finite, got {numbers}")
    return numbers


def _num(v: float, unit: str = "") -> str:
    """A measured number as the reports show it: tenths of millimetres in metres, tenths of
    degrees (a guard's lag of 0.0302 m against 0.03 shows), four significant digits
    otherwise (no ``-0``)."""
    d = _DECIMALS.get(unit)
    text = f"{v:.4g}" if d is None else f"{v:.{d}f}"
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text


class BackendLost(RuntimeError):
    """The world behind the boundary went away during a run: a robot's arm stopped
    answering or publishing (its joint states or its clock went silent), a simulator's
    process died.

    Not an outcome of the trial: nothing was learned about the tool, so the trial must
    not be recorded as a failure. An episode raises it (from ``run_skill``,
    ``observe`` or ``verdict``) and the learning loop stops the run resumably, as on a
    Ctrl-C: the trials recorded so far stay, and the run folder says how to go on
    (:func:`creative_py.learning.run.run_case`). The message names what went silent.

    Attributes
    ----------
    skill : str or None
        The skill that was running when the backend went away (set by the trial loop,
        :func:`creative_py.simulator.trial.run_trial`; None outside a skill, e.g.
        while a trainer set up the scene).
    trial : dict or None
        The trial that was running (set by the learning loop: its number, phase, tool,
        variant, location and pose): ``stopped.json`` records it as a trial that did
        not go as planned, and the resume runs it again.
    """

    skill: Optional[str] = None
    trial: Optional[dict] = None


class NonFiniteState(ValueError):
    """A measure met a non-finite number in the simulated state (a physics blow-up: a
    body thrown to NaN or infinity). An episode's ``verdict`` raises it; the trial is
    then ``invalid`` (:func:`creative_py.simulator.trial.judge`), not a failure the
    learner would label. The message names the object (``non-finite pose of cubes3``)."""


@dataclass(frozen=True)
class SkillOutcome:
    """How a skill or a single arm motion ended: ``status`` and why.

    Attributes
    ----------
    status : str
        One of :data:`SKILL_STATUSES`: ``ok``, ``blocked`` (the tracking guard stopped a
        motion), ``out_of_time`` (the motion's step or time budget ran out before it
        ended: a ManiSkill episode's control steps, a ROS goal's time; what that means
        for the trial is decided above the boundary,
        :func:`creative_py.simulator.trial.trial_outcome`), ``unreachable`` (no arm
        posture), ``invalid`` (a physics blow-up or a skill that cannot run in this
        state).
    reason : str
        Why, in words (empty for a plain ``ok``).
    stop : Verdict or None
        For a motion a guard stopped: what the guard measured against its limit (the
        gripper's lag, its twist, the grasp's slip) and which bodies the robot and
        the held tool touched then (``measures["touching"]``); for a motion out of
        time: what it needed against the budget (control steps, seconds).
    struck : Verdict or None
        Set when the robot itself (one of its links, not the tool it holds) struck a
        scene body during the skill's motion, as the backend measured it (the
        pybullet backend: from the physics' contacts): the largest normal force, and
        in ``measures["struck"]`` each link and body with its force and where. What
        that means for the trial is decided above the boundary
        (:func:`creative_py.simulator.trial.trial_outcome`: ``blocked``). A backend
        that cannot tell (an arm over ROS 2, ManiSkill) leaves it None.
    """

    status: SkillStatus
    reason: str = ""
    stop: "Verdict | None" = None
    struck: "Verdict | None" = None

    @property
    def ok(self) -> bool:
        """Return whether the skill or motion completed."""
        return self.status == "ok"


@dataclass(frozen=True)
class Observation:
    """What the robot perceives at one instant, plus ground truth for error reports.

    Attributes
    ----------
    facts : tuple of Fact
        Primitive facts: perceived poses/sizes (cameras), proprioception (held tool,
        tip position, roll), the scene's fixed facts and the catalogue of every
        available object. World frame, metres, radians.
    frames : tuple
        The camera frames (:class:`creative_py.perception.frame.Frame`) behind the
        perceived facts.
    truth : dict
        Ground-truth ``name -> (x, y, z, yaw)`` from the simulator, for measuring
        perception error only; never used to decide anything.
    """

    facts: tuple[Fact, ...]
    frames: tuple = ()
    truth: dict[str, tuple[float, float, float, float]] = field(default_factory=dict)

    def perceived_poses(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ``name -> (x, y, z, yaw)`` from the perceived ``pose`` facts."""
        return {f[1]: tuple(float(v) for v in f[2:6]) for f in self.facts if f[0] == "pose"}


@dataclass(frozen=True)
class TrialResult:
    """What the physics did in one trial (:func:`creative_py.simulator.trial.run_trial`,
    in the case's backend).

    The learning loop turns it into a :class:`creative_py.records.trial.TrialRecord`,
    the line of ``trials.jsonl``.

    Attributes
    ----------
    case, object, variant : str
        What was tried: case id, object (tool) name, task variant.
    location : int
        Index of the predefined target location (1-based).
    pose : tuple of float
        The pose numbers tried, in the order of the manifest's ``[[pose.param]]``.
    outcome : str
        One of :data:`TRIAL_OUTCOMES`.
    reason : str
        Why, in words (empty for a plain success).
    perceived_final : dict or None
        ``name -> (x, y, z, yaw)`` perceived by the cameras after the trial; None when
        no camera frame was taken.
    true_final : dict
        ``name -> (x, y, z, yaw)`` ground truth after the trial.
    sim_time_s, wall_time_s, render_time_s : float
        Simulated time, wall time of the whole trial, and the part spent rendering.
    steps : int
        Physics steps taken.
    seed : int
        The seed of the trial.
    max_tool_force_n : float
        The largest sum of the normal forces of the tool's contacts over one physics
        step of the tool action, newtons (pybullet: :mod:`creative_py.backends.pybullet.loads`).
    tool_load : dict or None
        Where and how that force acted (``ToolLoad.to_dict``: point and force in the
        tool frame, the grasp point, the bodies touched); None when the tool action did
        not start.
    facts_before : tuple of Fact
        What the robot observed just before the tool action, or where a blocked motion
        stopped (empty when a skill before the action ended unreachable or invalid).
    verdict : dict or None
        What the physics measured against its thresholds
        (:func:`creative_py.simulator.trial.verdict_data`): the oracle's quantity, value,
        threshold, unit, relation and judgement (measured in every trial, ``asked``
        when the outcome rests on it) and, for a motion a guard stopped, ``stop``.
    measures : dict
        Further measures of the trial, each by the name of the trial record's field
        that keeps it (a field marked ``measured`` in
        :mod:`creative_py.records.trial`): the record takes them as they are (checked
        by its type) and a replayed trial gives them back.
    """

    case: str
    object: str
    variant: str
    location: int
    pose: tuple[float, ...]
    outcome: str
    reason: str
    perceived_final: dict[str, tuple[float, ...]] | None
    true_final: dict[str, tuple[float, ...]]
    sim_time_s: float
    wall_time_s: float
    render_time_s: float
    steps: int
    seed: int = 0
    max_tool_force_n: float = 0.0
    tool_load: dict[str, Any] | None = None
    facts_before: tuple[Fact, ...] = ()
    verdict: dict[str, Any] | None = None
    measures: dict[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict[str, Any]:
        """Return the result as plain JSON-ready data (tuples become lists)."""
        return json.loads(json.dumps(asdict(self)))

    def to_json(self) -> str:
        """Return the result as one line of JSON."""
        return json.dumps(asdict(self), sort_keys=True)
