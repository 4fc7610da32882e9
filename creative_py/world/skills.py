"""Skill primitives' schemas: the motions a manifest's ``[[skill]]`` binds by name.

A skill of ``case.toml`` names a primitive of :data:`SKILLS` and may set its options
(``options = {...}``, numbers or scene expressions such as ``"tube1.mouth_x - 0.05"``,
see :mod:`creative_py.world.expressions`). A primitive that takes the pose gets
its world target from the engine's pose solution
(:attr:`creative_py.backends.pybullet.episode.Episode.pose_target`), never from case
arithmetic. This module holds what a primitive is (its options and their defaults, its
world target, its options' bounds and checks); a backend runs it (the pybullet
backend's :mod:`creative_py.backends.pybullet.primitives`):

==================== ========================= =============================================
primitive            world target              what it does
==================== ========================= =============================================
``grasp``            -                         the tool's kind grasps it where it lies
                                               (options of the kind: hook-like ``approach``
                                               ``free_speed`` ``speed`` ``lift_to``; block
                                               ``carry_z`` ``clearance`` ``gripper_yaw``)
``insert_at_pose``   ``tip(X, Y, Roll)``       carry a hook-like tool into the context's
                                               passage (a tube, the space under a shelf)
                                               and put its prong centre at (X, Y), turned to
                                               Roll; the arm's posture search is an option
``place_on_floor``   ``place(X, Y, Heading)``  put the held tool down on the context's top
                                               face, the target's holder swinging it clear
``pull_along_axis``  -                         pull the held tool back along -x until its
                                               working point passes ``until_x``, with a
                                               sideways draw of ``lateral`` m first
``push_along_axis``  -                         push the held tool along +x by ``distance``
``lower_at_pose``    ``tip(X, Y, Roll)``       carry the held tool over the table, lower it
                                               ``slide_from`` off the place and slide it in
                                               until its working point is at (X, Y,
                                               ``work_z``), turned to Roll (a pusher's head
                                               round or behind what it will push)
``sweep``            -                         move the held tool along ``direction`` (in
                                               the table's plane) until its working point
                                               reaches ``until`` along it, slowing over the
                                               last ``ramp`` metres, then wait until what
                                               it pushed is at rest
``release_joint``    -                         release the target's held joint: its closer
                                               acts for ``duration`` s (recorded for the
                                               oracle)
==================== ========================= =============================================

The primitives that move a held tool under or into something (``insert_at_pose``,
``pull_along_axis``) take a grasp-slip guard (:data:`SLIP_OPTIONS`): with
``grasp_slip_max_rad`` or ``grasp_slip_max_m`` above 0 (the default 0 turns it off),
every guarded step compares the tool's pose with the pose the grasp holds it in and
ends the motion ``blocked`` beyond either limit: a tool jammed against a static body
twists in pybullet's soft grasp constraint while the gripper follows its commands, so
the arm's tracking guard does not see it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Sequence

from creative_py.world.handlings import HANDLINGS
from creative_py.world_files import OptionError, shown


REQUIRED = None
"""An option without a default."""


@dataclass(frozen=True)
class SkillSchema:
    """A primitive's schema: its name, its options (``name -> default``), the name of
    the world target it takes (``""`` for none), the bounds of those of its options
    whose meaning is its own (``name -> (low, high, unit)``, before
    :data:`OPTION_BOUNDS`, :func:`option_bound`), and ``check(options)``, which raises
    :class:`~creative_py.world_files.OptionError` for resolved options it cannot run
    with beyond their bounds and lengths (:func:`check_options`)."""

    name: str
    options: Mapping[str, Any]
    target: str = ""
    bounds: Mapping[str, tuple[float, float, str]] = field(default_factory=dict)
    check: Callable[[Mapping[str, Any]], None] = lambda opts: None

    def needs_held_tool(self, opts: Mapping[str, Any]) -> bool:
        """Return whether the primitive moves a held tool (checked before perceiving)."""
        return bool(self.target) and not opts.get("by_hand", False)


# ------------------------------------------------------------------ grasp slip
SLIP_OPTIONS = {"grasp_slip_max_rad": 0.0, "grasp_slip_max_m": 0.0}
"""The grasp-slip guard's options (0 = no check of that limit)."""


# ------------------------------------------------------------------------ checks
def _grasp_options() -> dict[str, Any]:
    """Return the ``grasp`` primitive's options: every handling's, in their order."""
    out: dict[str, Any] = {}
    for h in HANDLINGS.values():
        out.update(h.grasp_options)
    return out


MIN_INSERT_CLEARANCE_M = -0.05
"""The lowest ``clearance`` of ``insert_at_pose`` (m): the handle's underside at most
5 cm below the target's top. A target a tool is inserted over lies in a passage (the
tube's 7 cm, the shelf's 4 cm of room) and is lower than that, so a lower value would
put the handle under the target, which is nonsense."""


FLAT_ROLLS = (-math.pi / 2, 0.0, math.pi / 2)
"""The values of ``insert_at_pose``'s ``flat_roll`` (rad): the prong flat towards -y or
+y, or 0, chosen by the room (a roll between would carry it neither flat nor down)."""

FLAT_ROLL_TOLERANCE = 1e-6
"""How far (rad) a ``flat_roll`` may lie from one of :data:`FLAT_ROLLS` (the digits of
pi / 2 a file writes)."""


def _check_insert(opts: Mapping[str, Any]) -> None:
    roll = opts["flat_roll"]
    if not any(abs(roll - r) <= FLAT_ROLL_TOLERANCE for r in FLAT_ROLLS):
        raise OptionError("flat_roll", f"must be -pi/2, 0 (chosen by the room) or pi/2 "
                          f"(the prong carried flat), got {roll:g} rad")


def _check_sweep(opts: Mapping[str, Any]) -> None:
    if math.hypot(*opts["direction"]) < 1e-9:
        raise OptionError("direction", f"must not be zero, got {shown(opts['direction'])}")


# ------------------------------------------------------------------------ registry
SKILLS: dict[str, SkillSchema] = {p.name: p for p in (
    SkillSchema("grasp", _grasp_options()),
    SkillSchema("insert_at_pose",
                {"travel_z": REQUIRED, "pull_to_x": REQUIRED, "clearance": 0.008,
                 "free_speed": 0.35, "speed": 0.20, "posture_search": True, "perceive": True,
                 "flat_roll": 0.0, "from_above": False, "keep_roll": False,
                 **SLIP_OPTIONS},
                target="tip",
                bounds={"clearance": (MIN_INSERT_CLEARANCE_M, 1.0, "m")}, check=_check_insert),
    SkillSchema("place_on_floor",
                {"hold_angle": REQUIRED, "carry_height": 0.10, "release_height": 0.003,
                 "lower_speed": 0.10, "gripper_yaw": 0.0, "retreat": REQUIRED,
                 "settle_time": 0.25, "by_hand": False, "perceive": False}, target="place"),
    SkillSchema("pull_along_axis",
                {"until_x": REQUIRED, "speed": 0.20, "settle_steps": 60, "lateral": 0.0,
                 "lateral_over": 0.0, **SLIP_OPTIONS},
                bounds={"lateral": (-0.5, 0.5, "m"), "lateral_over": (0.0, 2.0, "m")}),
    SkillSchema("push_along_axis",
                {"distance": REQUIRED, "speed": 0.10, "settle_steps": 60}),
    SkillSchema("lower_at_pose",
                {"travel_z": REQUIRED, "work_z": REQUIRED, "slide_from": None,
                 "via": None, "carry_z": None, "free_speed": 0.35, "speed": 0.10,
                 "posture_search": False,
                 "perceive": True}, target="tip"),
    SkillSchema("sweep",
                {"direction": REQUIRED, "until": REQUIRED, "speed": 0.10, "ramp": 0.0,
                 "ramp_pieces": 4, "end_speed": 0.02, "settle_steps": 60, "rest_speed": 0.0,
                 "settle_time": 2.0, "lift": 0.0}, check=_check_sweep),
    SkillSchema("release_joint",
                {"duration": 4.0, "contact_distance": 0.0005, "park_robot": True}),
)}
"""The skill primitives a manifest may bind, by name."""


_POSITION = (-10.0, 10.0, "m")
_SPEED = (1e-3, 2.0, "m/s")
_ANGLE = (-2 * math.pi, 2 * math.pi, "rad")

OPTION_BOUNDS: dict[str, tuple[float, float, str]] = {
    # where things are: coordinates in the world frame (a list: each of its numbers)
    "travel_z": _POSITION, "pull_to_x": _POSITION, "until_x": _POSITION,
    "lift_to": _POSITION, "carry_z": _POSITION, "retreat": _POSITION,
    "work_z": _POSITION, "direction": (-1.0, 1.0, "(a unit vector)"),
    "slide_from": (-2.0, 2.0, "m"), "via": (-2.0, 2.0, "m"), "until": _POSITION,
    # how far
    "approach": (0.0, 1.0, "m"), "clearance": (0.0, 1.0, "m"),
    "carry_height": (0.0, 1.0, "m"), "release_height": (0.0, 1.0, "m"),
    "distance": (-2.0, 2.0, "m"), "contact_distance": (-0.1, 0.1, "m"),
    "ramp": (0.0, 2.0, "m"), "lift": (0.0, 1.0, "m"), "ramp_pieces": (1, 100, "steps"),
    # how fast
    "free_speed": _SPEED, "speed": _SPEED, "lower_speed": _SPEED, "end_speed": _SPEED,
    "rest_speed": (0.0, 1.0, "m/s"),
    # angles
    "gripper_yaw": _ANGLE, "hold_angle": _ANGLE, "flat_roll": _ANGLE,
    # how long: what a hang would come from
    "settle_time": (0.0, 10.0, "s"), "duration": (0.0, 60.0, "s"),
    "settle_steps": (0, 10000, "steps"),
    # the grasp-slip guard
    "grasp_slip_max_rad": (0.0, math.pi, "rad"), "grasp_slip_max_m": (0.0, 1.0, "m"),
}
"""The bounds ``(low, high, unit)`` of every numeric option of the primitives and of
the tool kinds' grasps, by option name, unless the primitive bounds it itself
(:attr:`SkillSchema.bounds`, :func:`option_bound`: ``insert_at_pose``'s ``clearance``
may be negative, a grasp's may not); a ``steps`` option must be a whole number, an
option whose default is true or false (``posture_search``, ``perceive``, ``by_hand``,
``park_robot``) must be true or false. The loader checks every skill's options in
every variant and location (:func:`creative_py.world.read.check_values`), so that no
number of ``case.toml`` makes a motion or a wait run without end."""


VECTOR_OPTIONS: dict[str, int] = {"direction": 2, "via": 2, "slide_from": 2, "retreat": 3}
"""The options that are lists of numbers, by name, and how many numbers each holds
(``direction``, ``via``, ``slide_from``: x, y in the table's plane; ``retreat``: a
point x, y, z); every other numeric option is one number."""


def check_options(primitive_name: str, opts: Mapping[str, Any]) -> None:
    """Raise :class:`~creative_py.world_files.OptionError` unless the resolved options
    of the primitive named ``primitive_name`` have their shapes (a list of
    :data:`VECTOR_OPTIONS`'s length, else one number; an unset optional list is None)
    and pass its own check (:attr:`SkillSchema.check`). Bounds are checked apart
    (:func:`option_bound`)."""
    p = SKILLS[primitive_name]
    flags = option_flags()
    for k, v in opts.items():
        if k in flags or v is None:  # None: an optional option left unset
            continue
        n = VECTOR_OPTIONS.get(k)
        if n is not None and not (isinstance(v, tuple) and len(v) == n):
            raise OptionError(k, f"must be a list of {n} numbers, got {shown(v)}")
        if n is None and isinstance(v, tuple):
            raise OptionError(k, f"must be a number, got a list {shown(v)}")
    p.check(opts)


def option_bound(primitive_name: str, option: str) -> tuple[float, float, str] | None:
    """Return the bound ``(low, high, unit)`` of ``option`` of the primitive named
    ``primitive_name``: its own (:attr:`SkillSchema.bounds`), else
    :data:`OPTION_BOUNDS`'s, else None (an option without a numeric bound)."""
    p = SKILLS.get(primitive_name)
    if p is not None and option in p.bounds:
        return p.bounds[option]
    return OPTION_BOUNDS.get(option)


def option_flags() -> frozenset[str]:
    """Return the options that are true or false (their default is a bool)."""
    return frozenset(n for p in SKILLS.values() for n, d in p.options.items()
                     if isinstance(d, bool))


def option_names(p: SkillSchema) -> Sequence[str]:
    """Return the option names of primitive ``p``."""
    return tuple(p.options)
