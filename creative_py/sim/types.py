"""The simulator's value types: what a skill, an observation and a trial give back.

A leaf of the simulator (it imports only the outcome vocabulary of
:mod:`creative_py.records.trial`, the bottom layer), so the episode, the primitives,
the robot and the learning loop can all share one ``SkillOutcome`` without an import
cycle.

Outcomes of a trial (:data:`TRIAL_OUTCOMES`, decided in one place,
:func:`creative_py.sim.episode.trial_outcome`): ``success`` / ``failure`` (every skill
ran, or the tool was stopped while acting; the goal was or was not reached),
``blocked`` (a move before the tool action was stopped by a collision: the
tracking-error guard), ``unreachable`` (no arm posture reaches a waypoint),
``invalid`` (the physics blew up: NaN, an object thrown out of the scene).
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field
from typing import Any, Literal

from creative_py.records.trial import TRIAL_OUTCOMES  # noqa: F401 - the simulator's vocabulary too

SkillStatus = Literal["ok", "blocked", "unreachable", "invalid"]
TrialOutcome = Literal["success", "failure", "blocked", "unreachable", "invalid"]
SKILL_STATUSES: tuple[str, ...] = ("ok", "blocked", "unreachable", "invalid")

Fact = tuple[Any, ...]
"""A primitive fact as a tuple: predicate name then arguments, e.g. ``("held", "t1")``."""


@dataclass(frozen=True)
class SkillOutcome:
    """How a skill or a single arm motion ended: ``status`` and why.

    Attributes
    ----------
    status : str
        One of :data:`SKILL_STATUSES`: ``ok``, ``blocked`` (the tracking guard stopped a
        motion), ``unreachable`` (no arm posture), ``invalid`` (a physics blow-up or a
        skill that cannot run in this state).
    reason : str
        Why, in words (empty for a plain ``ok``).
    """

    status: SkillStatus
    reason: str = ""

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
    """What the physics did in one trial (:func:`creative_py.sim.episode.run_trial`).

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
        step of the tool action, newtons (:mod:`creative_py.sim.loads`).
    tool_load : dict or None
        Where and how that force acted (``ToolLoad.to_dict``: point and force in the
        tool frame, the grasp point, the bodies touched); None when the tool action did
        not start.
    facts_before : tuple of Fact
        What the robot observed just before the tool action, or where a blocked motion
        stopped (empty when a skill before the action ended unreachable or invalid).
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

    def to_dict(self) -> dict[str, Any]:
        """Return the result as plain JSON-ready data (tuples become lists)."""
        return json.loads(json.dumps(asdict(self)))

    def to_json(self) -> str:
        """Return the result as one line of JSON."""
        return json.dumps(asdict(self), sort_keys=True)
