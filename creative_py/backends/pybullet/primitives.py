"""Skill primitives run in pybullet: the motions :mod:`creative_py.world.skills` defines.

Each primitive of :data:`creative_py.world.skills.SKILLS` (its options, their defaults
and bounds, its world target: what a manifest's ``[[skill]]`` may bind) has its run
function here; :data:`PRIMITIVES` pairs each schema with it, by the same names.

The grasp-slip guard of the primitives that move a held tool under or into something
(``insert_at_pose``, ``pull_along_axis``; :func:`slip_guard`) compares, at every
guarded step, the tool's pose with the pose the grasp holds it in
(:func:`~creative_py.backends.pybullet.tools.grasp_slip`).

A primitive is called as ``run(ep, options, target)`` with the running
:class:`~creative_py.backends.pybullet.episode.Episode` (typed ``Any`` here: this module must not
import the episode, which imports it). Each returns a
:class:`~creative_py.simulator.types.SkillOutcome`; a motion stopped by the tracking guard is
``blocked``, an arm that cannot follow ``unreachable``, a physics blow-up ``invalid``.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass
from typing import Any, Callable, Mapping

import numpy as np
import pybullet as pb

from creative_py.backends.pybullet.bodies import frame_pose, set_frame_pose
from creative_py.backends.pybullet.core import Pose
from creative_py.simulator.types import SkillOutcome, Verdict
from creative_py.backends.pybullet.tools import (HandleHeld, grasp_slip, prong_centre, prong_reach,
                                   roll_of, tool_orientation)
from creative_py.world.skills import SKILLS, SkillSchema


log = logging.getLogger(__name__)

@dataclass(frozen=True)
class Primitive:
    """A registered primitive: its schema (:class:`~creative_py.world.skills.SkillSchema`:
    its name, options, world target, bounds and check) and its function ``run``."""

    schema: SkillSchema
    run: Callable[[Any, Mapping[str, Any], tuple], SkillOutcome]

    @property
    def name(self) -> str:
        """Return the primitive's name."""
        return self.schema.name

    @property
    def options(self) -> Mapping[str, Any]:
        """Return its options (``name -> default``)."""
        return self.schema.options

    @property
    def target(self) -> str:
        """Return the name of the world target it takes (``""`` for none)."""
        return self.schema.target

    @property
    def bounds(self) -> Mapping[str, tuple[float, float, str]]:
        """Return the bounds of the options whose meaning is its own."""
        return self.schema.bounds

    @property
    def check(self) -> Callable[[Mapping[str, Any]], None]:
        """Return its check of resolved options."""
        return self.schema.check

    def needs_held_tool(self, opts: Mapping[str, Any]) -> bool:
        """Return whether the primitive moves a held tool (checked before perceiving)."""
        return self.schema.needs_held_tool(opts)


# -------------------------------------------------------------------------- grasp
FELL_M = 0.02
"""How far (m) below where it was spawned a tool may lie at a grasp: further, it is
falling off its stand or the table (a tool at rest settles by under a millimetre), and
the trial is ``invalid``."""


def grasp(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Grasp the episode's tool the way its kind is grasped, and lift it.

    A tool that fell from where it lay (off its stand, off the table), before the grasp
    or while the arm reached for it, cannot be picked up as the skill assumes: the
    trial is ``invalid``, with that reason.
    """
    ep.need_robot("grasp")
    res = _fell(ep)
    if res is None:
        res = ep.kind.grasp(ep, opts)
        if not res.ok:
            res = _fell(ep) or res
    return res


def _fell(ep: Any) -> SkillOutcome | None:
    drop = ep.tool_spawn_z - frame_pose(ep.sim, ep.tool_body)[0][2]
    if drop > FELL_M:
        return SkillOutcome("invalid", f"the tool fell {drop:.2f} m from where it lay "
                                       "(off its stand or the table)")
    return None


# ------------------------------------------------------------------ grasp slip
def slip_guard(ep: Any, opts: Mapping[str, Any]) -> Callable[[], SkillOutcome | None] | None:
    """Return the grasp-slip check of ``opts`` for the held tool, or None if it is off."""
    max_rad = float(opts.get("grasp_slip_max_rad", 0.0) or 0.0)
    max_m = float(opts.get("grasp_slip_max_m", 0.0) or 0.0)
    if max_rad <= 0.0 and max_m <= 0.0:
        return None

    def check() -> SkillOutcome | None:
        if not ep.held:
            return None
        angle, offset = grasp_slip(ep)
        if (max_rad > 0.0 and angle > max_rad) or (max_m > 0.0 and offset > max_m):
            by_angle = max_rad > 0.0 and angle > max_rad
            stop = Verdict("grasp slip", angle if by_angle else offset,
                           max_rad if by_angle else max_m, "rad" if by_angle else "m",
                           "<=", False,
                           threshold_name="grasp_slip_max_rad" if by_angle
                           else "grasp_slip_max_m",
                           measures={"slip_rad": round(angle, 6), "slip_m": round(offset, 6),
                                     "touching_ids": ep.robot.touching()})
            return SkillOutcome("blocked", f"the tool slipped in the grasp by "
                                f"{angle:.3f} rad, {offset * 1000:.1f} mm: it is jammed", stop)
        return None

    return check


# ------------------------------------------------------------------ insert at pose
def insert_at_pose(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Insert the held hook-like tool into the context's passage, prong centre at (X, Y).

    The context is a body with a passage along +x (a ``tube``, the space under a
    ``shelf``, the room above a ``standing_shelf`` or between ``bookends``: its
    ``mouth_x``, ``axis_y``, ``passage_floor_z``, ``inner_width`` and
    ``inner_height``). The gripper carries the tool above it to in front of its mouth
    and turns it so the prong is flat: at the requested roll if that is flat, otherwise
    towards the side of the handle with more room, or at ``flat_roll`` (rad, +pi/2 or
    -pi/2; 0, the default, chooses by the room;
    :data:`~creative_py.world.skills.FLAT_ROLLS`, nothing else) if the
    manifest sets one: an arm whose
    wrist turns only one way from the pose's roll (a 7-joint arm's last joint at the
    height of a tall shelf) carries the prong flat on that side. With ``from_above`` (a passage
    open at the top: the room above a shelf's top or a row of books) the tool is
    lowered at the goal's x instead of in front of the mouth, so that an arm of short
    reach need not hold the whole tool in front of the passage. With ``keep_roll`` the
    tool is carried and lowered at the pose's roll, not turned flat first (a prong
    lowered from above behind the target needs no flat phase, and the wrist no turn).
    With ``posture_search`` it first tries the rest of the motion (insertion, turning,
    the pull back to ``pull_to_x``) in the kinematics client and, if the arm would meet
    a joint limit, re-shapes it in free space. It then lowers the tool to
    ``clearance`` above the target (its perceived top), inserts it along +x until the
    prong is at X, raises the handle if needed so that the lowered prong clears the
    passage's floor, and turns the tool to Roll.

    ``clearance`` is the height of the handle's underside above the target's perceived
    top during the insertion (m). A negative value puts the underside that far below
    the top, so that a tool without a prong (a plain stick) meets the target's side and
    pushes or pulls it; it may not go below
    :data:`~creative_py.world.skills.MIN_INSERT_CLEARANCE_M` (its bound in
    :data:`~creative_py.world.skills.SKILLS`). The handle never goes below the passage's floor.
    """
    if not isinstance(ep.kind, HandleHeld):
        raise TypeError(f"insert_at_pose moves handled tools, not {ep.spec.kind}")
    _, x_goal, y_goal, roll = target
    top = ep.perceived_top(ep.target_name)
    if top is None:
        return SkillOutcome("unreachable", f"the camera does not see {ep.target_name}")
    flat = _flat_roll(ep, opts, y_goal, roll)
    steps = _insertion_steps(ep, opts, top, (x_goal, y_goal), flat, roll)
    pull_dx = min(0.0, opts["pull_to_x"] - x_goal)
    guard = slip_guard(ep, opts)
    kind = ep.kind
    for i, (origin, r, speed) in enumerate(steps):
        res = kind.move(ep, kind.gripper_for_tool(ep, origin, r), r, speed, guard)
        if not res.ok:
            return res
        if i == 0 and opts["posture_search"]:
            res = _choose_posture(ep, steps[1:], pull_dx, opts["free_speed"])
            if not res.ok:
                return res
    ep.state["attitude"] = roll
    log.info("insert_at_pose %s at %s: ok", ep.spec.name, target)
    return SkillOutcome("ok")


def _flat_roll(ep: Any, opts: Mapping[str, Any], y_goal: float, roll: float) -> float:
    """Return the roll (rad) at which :func:`insert_at_pose` carries and inserts the
    tool: the requested ``roll`` if it is flat, the tool has no head or ``keep_roll``
    is set; else the manifest's ``flat_roll``; else the flat roll towards the side of
    the passage with more room beside ``y_goal`` (m)."""
    if abs(roll) >= math.pi / 4 or not ep.spec.has_head or opts["keep_roll"]:
        return roll
    if opts["flat_roll"]:
        return opts["flat_roll"]
    tb = ep.context_body
    room_left = tb.axis_y + tb.inner_width / 2 - y_goal
    room_right = y_goal - (tb.axis_y - tb.inner_width / 2)
    return math.pi / 2 if room_left > room_right else -math.pi / 2


def _insertion_steps(ep: Any, opts: Mapping[str, Any], top: float,
                     goal: tuple[float, float], flat: float, roll: float) -> list[tuple]:
    """Return the tool-origin moves ``(origin, roll, speed)`` of :func:`insert_at_pose`
    (m, rad, m/s): over the passage at travel height, turned ``flat``, lowered to the
    insertion height above the target's perceived ``top``, in along +x until the prong
    is at ``goal`` = (X, Y), down so the prong clears the passage's floor, turned to
    ``roll``."""
    tb = ep.context_body
    spec = ep.spec
    x_goal, y_goal = goal
    travel = opts["travel_z"]
    half_t = spec.handle_width / 2
    z_insert = top + half_t + opts["clearance"]
    tip_local = prong_centre(spec)
    q_flat = tool_orientation(spec, flat)
    tip_off = pb.multiplyTransforms((0, 0, 0), q_flat, tip_local, (0, 0, 0, 1))[0]
    goal_origin_x = x_goal - tip_off[0]
    far_x = max(spec.handle_length, tip_local[0] + spec.head_width)
    # Lowered into the passage in front of its mouth, or, with from_above (a passage
    # open at the top), straight down at the goal.
    pre_origin_x = goal_origin_x if opts["from_above"] else tb.mouth_x - 0.03 - far_x
    carried = ep.kind.attitude(ep)
    steps = [((pre_origin_x, y_goal, travel), carried, opts["free_speed"]),
             ((pre_origin_x, y_goal, travel), flat, opts["free_speed"]),
             ((pre_origin_x, y_goal, z_insert), flat, opts["free_speed"]),
             ((goal_origin_x, y_goal, z_insert), flat, opts["speed"])]
    floor = tb.passage_floor_z
    z_down = min(max(z_insert, floor + prong_reach(spec) + 0.004),
                 floor + tb.inner_height - half_t - 0.002)
    steps.append(((goal_origin_x, y_goal, z_down), flat, opts["speed"]))
    steps.append(((goal_origin_x, y_goal, z_down), roll, opts["speed"]))
    return steps


def _gripper_path(ep: Any, steps, pull_dx: float) -> list[Pose]:
    """Return the gripper poses of ``steps`` then the pull, rolls split as in the move."""
    from creative_py.backends.pybullet.arm import gripper_forward

    kind = ep.kind
    pos, quat = ep.robot.gripper_pose()
    roll = roll_of(ep.spec, pb.multiplyTransforms(pos, quat, *ep.grasp)[1])
    path: list[Pose] = []
    for origin, new_roll, _ in steps:
        goal = kind.gripper_for_tool(ep, origin, new_roll)
        n = max(1, math.ceil(abs(new_roll - roll) / math.radians(70)))
        for i in range(1, n + 1):
            t = i / n
            p = tuple(a + t * (b - a) for a, b in zip(pos, goal))
            path.append((p, gripper_forward(roll + t * (new_roll - roll))))
        pos, roll = goal, new_roll
    path.append(((pos[0] + pull_dx, pos[1], pos[2]), gripper_forward(roll)))
    return path


def _start_candidates(ep: Any, here: Pose, path: list[Pose]):
    """Yield start postures at ``here`` for following ``path``.

    Direct IK solutions at ``here`` first; then, for key poses of the path (where the
    tool turns flat, the deepest point, the last turn), IK solutions there walked back
    along the path to ``here`` in the kinematics client.
    """
    rb = ep.robot
    yield from rb.ik_candidates(here, keep=4)
    turned = path[:-1]
    deep = max(range(len(turned)), key=lambda i: turned[i][0][0])
    for key in sorted({0, deep, len(turned) - 1}):
        for cand in rb.ik_candidates(turned[key], keep=4):
            q = rb.dry_run(cand, [*reversed(turned[:key]), here])
            if q is not None:
                yield q


def _choose_posture(ep: Any, steps, pull_dx: float, speed: float) -> SkillOutcome:
    """Make sure the arm can follow the insertion and the pull; re-shape it if not.

    The path is tried in the kinematics client from the current posture. If IK would
    lose it, other postures at the current gripper pose are tried; the first that
    carries the whole path is reached by lifting the tool clear, moving in joint
    space, and coming back down.
    """
    return _posture_for_path(ep, _gripper_path(ep, steps, pull_dx), speed,
                             "the insertion and the pull")


def _posture_for_path(ep: Any, path: list[Pose], speed: float, what: str) -> SkillOutcome:
    """Make sure the arm can follow the gripper poses ``path``; re-shape it if not (as
    :func:`_choose_posture` says)."""
    rb = ep.robot
    if rb.dry_run(rb.arm_q(), path) is not None:
        return SkillOutcome("ok")
    here = rb.gripper_pose()
    for cand in _start_candidates(ep, here, path):
        if rb.dry_run(cand, path) is None:
            continue
        for lift in (0.30, 0.22, 0.15, 0.10, 0.05):
            high = ((here[0][0], here[0][1], here[0][2] + lift), here[1])
            q_high = rb.dry_run(cand, [high])
            if q_high is not None:
                break
        else:
            continue
        for res in (rb.move_to(high, speed=speed, watch=ep.watch),
                    rb.move_joints(q_high, watch=ep.watch),
                    rb.move_to(here, speed=speed, watch=ep.watch)):
            if not res.ok:
                return res
        return SkillOutcome("ok")
    return SkillOutcome("unreachable", f"no arm posture can carry the tool along {what} "
                        "(joint limits)")


# ----------------------------------------------------------------- place on floor
def place_on_floor(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Put the held tool on the context's top face at (X, Y) heading ``Heading``.

    The target body's holder (a door) swings it to ``hold_angle`` while the arm
    works: the arm lowers the tool until its base is ``release_height`` above the
    floor, lets go, waits ``settle_time`` and retreats to ``retreat``; then the holder
    swings the target back. With ``by_hand`` the trainer puts the tool there instead
    (no arm: the demonstration's placing, or a quick test of the physics alone).
    """
    _, x, y, heading = target
    top = ep.context_body.top
    holder = ep.bodies.get(ep.target_name)
    if opts["by_hand"]:
        if ep.held:
            ep.robot.release()
            ep.held = False
        _swing(ep, holder, None)
        set_frame_pose(ep.sim, ep.tool_body,
                       ((x, y, top + opts["release_height"]),
                        tuple(pb.getQuaternionFromEuler((0, 0, heading)))))
        ep.use_physics("rest")
        ep.run(opts["settle_time"])
        why = ep.sim.blow_up(ep.tool_body)
        return SkillOutcome("invalid", why) if why else SkillOutcome("ok")
    ep.need_robot("place_on_floor")
    _swing(ep, holder, opts["hold_angle"])
    above = ep.gripper_for_tool_at(x, y, top + opts["carry_height"], heading)
    down = ep.gripper_for_tool_at(x, y, top + opts["release_height"], heading)
    for goal, speed in ((above, None), (down, opts["lower_speed"])):
        res = ep.robot.move_to(goal, speed=speed, watch=ep.watch)
        if not res.ok:
            return res
    ep.use_physics("rest")
    ep.robot.release()
    ep.held = False
    ep.run(opts["settle_time"])
    why = ep.sim.blow_up(ep.tool_body)
    if why:
        return SkillOutcome("invalid", why)
    ep.use_physics("arm")
    g = ep.robot.gripper_pose()[0]
    for goal in ((g[0], g[1], g[2] + 0.08), tuple(opts["retreat"])):
        res = ep.kind.move(ep, goal, opts["gripper_yaw"], None)
        if not res.ok:
            return SkillOutcome(res.status, f"retreat: {res.reason}", res.stop)
    _swing(ep, holder, None)
    why = ep.sim.blow_up(ep.tool_body)
    return SkillOutcome("invalid", why) if why else SkillOutcome("ok")


def _swing(ep: Any, holder, angle: float | None) -> None:
    """Swing a holder-carrying body to ``angle`` (None: back to its open angle)."""
    if holder is not None and hasattr(holder, "swing"):
        holder.swing(ep.sim, holder.open_angle if angle is None else angle, ep.run)


# ------------------------------------------------------------ pull / push on an axis
def pull_along_axis(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Pull the held tool back along -x until its working point is at ``until_x``.

    The tool keeps the attitude the pose skill gave it; afterwards the physics runs
    ``settle_steps`` more steps so that what was pulled comes to rest.

    With ``lateral`` (m, default 0: a straight pull) the pull starts with a sideways
    draw across the passage's axis: the tool moves by ``lateral`` along +y (negative:
    -y) while it moves back ``lateral_over`` metres along -x (0: sideways only; at most
    the whole pull), and then straight back along -x to ``until_x``. It draws what the
    tool holds past an obstacle in front of it (a wall's end) before pulling it out.
    """
    if not ep.held:
        return SkillOutcome("blocked", "no tool is held")
    g_pos, _ = ep.robot.gripper_pose()
    dx = opts["until_x"] - ep.kind.working_point(ep)[0]
    attitude = ep.state.get("attitude", None)
    if attitude is None:
        attitude = ep.kind.attitude(ep)
    guard = slip_guard(ep, opts)
    lateral = opts["lateral"]
    if lateral:
        over = max(min(dx, 0.0), -opts["lateral_over"])
        res = ep.kind.move(ep, (g_pos[0] + over, g_pos[1] + lateral, g_pos[2]), attitude,
                           opts["speed"], guard)
        if not res.ok:
            return res
        g_pos = (g_pos[0], g_pos[1] + lateral, g_pos[2])
    res = ep.kind.move(ep, (g_pos[0] + min(dx, 0.0), g_pos[1], g_pos[2]), attitude,
                       opts["speed"], guard)
    if not res.ok:
        return res
    ep.sim.step(int(opts["settle_steps"]))
    for body in ep.watch:
        why = ep.sim.blow_up(body)
        if why:
            return SkillOutcome("invalid", why)
    return SkillOutcome("ok")


def push_along_axis(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Push the held tool straight along +x by ``distance`` metres, keeping its attitude."""
    if not ep.held:
        return SkillOutcome("blocked", "no tool is held")
    g_pos, _ = ep.robot.gripper_pose()
    attitude = ep.state.get("attitude", None)
    if attitude is None:
        attitude = ep.kind.attitude(ep)
    res = ep.kind.move(ep, (g_pos[0] + opts["distance"], g_pos[1], g_pos[2]), attitude,
                       opts["speed"])
    if not res.ok:
        return res
    ep.sim.step(int(opts["settle_steps"]))
    return SkillOutcome("ok")


# ------------------------------------------------------- lower a tool onto the table
def lower_at_pose(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Lower the held tool onto the table with its working point at (X, Y, ``work_z``).

    The tool's frame is carried at height ``travel_z``, first along x, then along y,
    to where its working point is ``slide_from`` = (dx, dy) m off the place; there it is
    turned to Roll, lowered straight down at ``speed`` and slid in at that height to
    the place (without it, straight down onto it). With ``via``
    = (dx, dy) it first goes at height ``carry_z`` (default ``travel_z``), along x,
    then along y, to that offset from the place, and is raised to ``travel_z`` there.
    A pusher's head comes down round a ball or behind a row of cubes; what it meets is
    the physics' business. The via point, the slide and the order of the legs let
    a world route the tool round what it must not touch and through where the arm
    reaches. With ``posture_search`` (a handled tool's) the arm's posture for the whole
    path is checked first and, if it would lose it, re-shaped as ``insert_at_pose``
    does (:func:`_choose_posture`).
    """
    _, x, y, roll = target
    spec, kind = ep.spec, ep.kind
    q = tool_orientation(spec, roll)
    off = pb.multiplyTransforms((0, 0, 0), q, prong_centre(spec), (0, 0, 0, 1))[0]
    low = (x - off[0], y - off[1], opts["work_z"] - off[2])
    ax, ay = (float(v) for v in (opts.get("slide_from") or (0.0, 0.0)))
    side = (low[0] + ax, low[1] + ay)
    high = opts["travel_z"]
    carried = kind.attitude(ep)
    here = ep.tool_pose()[0]
    fast = opts["free_speed"]
    legs: list[tuple[float, float, float]] = []
    if opts.get("via") is not None:
        vx, vy = (float(v) for v in opts["via"])
        carry = high if opts.get("carry_z") is None else opts["carry_z"]
        via = (low[0] + vx, low[1] + vy)
        legs += [(here[0], here[1], carry), (via[0], here[1], carry),
                 (via[0], via[1], carry)]
        here = (via[0], via[1], carry)
    legs += [(here[0], here[1], high), (side[0], here[1], high), (side[0], side[1], high)]
    steps = [(p, carried, fast) for p in legs]
    steps += [((side[0], side[1], high), roll, fast),
              ((side[0], side[1], low[2]), roll, opts["speed"]),
              (low, roll, opts["speed"])]
    if opts["posture_search"]:
        from creative_py.backends.pybullet.arm import gripper_forward

        path = [(kind.gripper_for_tool(ep, origin, r), gripper_forward(r))
                for origin, r, _ in steps]
        res = _posture_for_path(ep, path, fast, "the carrying and the lowering")
        if not res.ok:
            return res
    for origin, r, speed in steps:
        res = kind.move(ep, kind.gripper_for_tool(ep, origin, r), r, speed)
        if not res.ok:
            return res
    ep.state["attitude"] = roll
    return SkillOutcome("ok")


# ------------------------------------------------------------ sweep across the table
def sweep(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Move the held tool along ``direction`` until its working point reaches ``until``.

    ``direction`` is a unit vector (x, y) in the table's plane; ``until`` is where the
    working point stops, measured along it (the dot product of its (x, y) with the
    direction, m). The tool keeps its height and attitude and moves at ``speed``, the
    last ``ramp`` metres in ``ramp_pieces`` moves whose speeds fall evenly to
    ``end_speed`` (a ball pushed ahead rolls on at the speed it was pushed: slowing
    down lets the tool's walls take it back). Then the physics runs ``settle_steps``
    steps and, with ``rest_speed`` above 0, further steps until every dynamic body of
    the scene moves slower than ``rest_speed`` m/s, for at most ``settle_time`` s. With
    ``lift`` above 0 the tool is then raised straight up by that much.
    """
    if not ep.held:
        return SkillOutcome("blocked", "no tool is held")
    dx, dy = (float(v) for v in opts["direction"])
    norm = math.hypot(dx, dy)
    if norm < 1e-9:
        return SkillOutcome("invalid", "the sweep's direction is zero")
    dx, dy = dx / norm, dy / norm
    wp = ep.kind.working_point(ep)
    travel = float(opts["until"]) - (wp[0] * dx + wp[1] * dy)
    attitude = ep.state.get("attitude", None)
    if attitude is None:
        attitude = ep.kind.attitude(ep)
    g, _ = ep.robot.gripper_pose()
    ramp = min(max(float(opts["ramp"]), 0.0), max(travel, 0.0))
    pieces = max(1, int(opts["ramp_pieces"])) if ramp > 0 else 0
    plan = [(travel - ramp, float(opts["speed"]))]
    for i in range(1, pieces + 1):
        t = i / pieces
        speed = opts["speed"] + t * (opts["end_speed"] - opts["speed"])
        plan.append((travel - ramp + t * ramp, max(float(speed), 1e-3)))
    for dist, speed in plan:
        if dist <= 0:
            continue
        goal = (g[0] + dx * dist, g[1] + dy * dist, g[2])
        res = ep.kind.move(ep, goal, attitude, speed)
        if not res.ok:
            return res
    ep.sim.step(int(opts["settle_steps"]))
    if opts["rest_speed"] > 0:
        moving = _moving_bodies(ep)
        n = int(round(opts["settle_time"] / ep.sim.physics.time_step))
        for _ in range(max(n, 0)):
            if all(_speed_of(ep, b) < opts["rest_speed"] for b in moving):
                break
            ep.sim.step()
    for body in ep.watch:
        why = ep.sim.blow_up(body)
        if why:
            return SkillOutcome("invalid", why)
    if opts["lift"] > 0:
        g, _ = ep.robot.gripper_pose()
        res = ep.kind.move(ep, (g[0], g[1], g[2] + opts["lift"]), attitude,
                           opts["speed"])
        if not res.ok:
            return res
    return SkillOutcome("ok")


def _moving_bodies(ep: Any) -> list[int]:
    """Return the scene's dynamic bodies (what a push can set moving)."""
    return [b.id for b in ep.bodies.values() if getattr(b, "dynamic", False) and b.id >= 0]


def _speed_of(ep: Any, body: int) -> float:
    """Return a body's linear speed, m/s."""
    v, _ = pb.getBaseVelocity(body, physicsClientId=ep.sim.client)
    return math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2)


# ------------------------------------------------------------------ release a joint
@dataclass(frozen=True)
class JointRelease:
    """What a released joint did (radians; None where it never touched the tool)."""

    body: str
    contact_angle: float | None
    final_angle: float

    @property
    def touched(self) -> bool:
        """Return whether the body touched the tool after its release."""
        return self.contact_angle is not None

    @property
    def closed_after_contact_deg(self) -> float | None:
        """Return how far (deg) it moved on after the first contact."""
        if self.contact_angle is None:
            return None
        return math.degrees(self.contact_angle - self.final_angle)


def release_joint(ep: Any, opts: Mapping[str, Any], target: tuple) -> SkillOutcome:
    """Release the target's held joint: its closer pushes it for ``duration`` seconds.

    The holder first brings it back to its open angle; a robot link in the sweep from
    there to closed makes the skill ``blocked``. The idle robot is then taken out of
    the physics (``park_robot``: it stands outside the sweep, so nothing changes but
    the cost of a step). The first contact with the tool (a contact point closer than
    ``contact_distance`` m) and the final angle are recorded for the oracle.
    """
    door = ep.bodies[ep.target_name]
    if door.released:
        return SkillOutcome("blocked", "the joint was already released")
    c = ep.sim.client
    if ep.robot is not None and not ep.robot_parked:
        in_sweep = _robot_in_sweep(ep, door)
        if in_sweep:
            return SkillOutcome("blocked", f"the robot's {in_sweep} is in the door's sweep")
    _swing(ep, door, None)
    if opts["park_robot"]:
        ep.park_robot()
    ep.use_physics("rest")
    door.released = True
    pb.setJointMotorControl2(door.id, 0, pb.VELOCITY_CONTROL, force=0.0, physicsClientId=c)
    n = int(round(opts["duration"] / ep.sim.physics.time_step))
    contact = None
    for i in range(n):
        pb.setJointMotorControl2(door.id, 0, pb.TORQUE_CONTROL, force=-door.closing_torque,
                                 physicsClientId=c)
        ep.sim.step()
        if contact is None and any(
                cp[8] <= opts["contact_distance"]
                for cp in pb.getContactPoints(door.id, ep.tool_body, physicsClientId=c)):
            contact = door.angle(ep.sim)
        if i % 32 == 31:
            why = ep.sim.blow_up(ep.tool_body)
            if why:
                return SkillOutcome("invalid", why)
    final = door.angle(ep.sim)
    if not math.isfinite(final):
        return SkillOutcome("invalid", "the joint's angle is not finite")
    ep.records[door.name] = JointRelease(door.name, contact, final)
    return SkillOutcome("ok")


def _robot_in_sweep(ep: Any, door) -> str:
    """Return the name of a robot link that the closing door would touch, or "".

    The door is put at angles from its current one down to 0 (closed) and the robot's
    links are tested against it (1 cm margin); the state is restored.
    """
    c, robot = ep.sim.client, ep.robot.body
    a0 = door.angle(ep.sim)
    with ep.sim.saved():
        for a in np.linspace(a0, 0.0, 9):
            pb.resetJointState(door.id, 0, float(a), 0.0, physicsClientId=c)
            pb.performCollisionDetection(physicsClientId=c)
            near = pb.getClosestPoints(door.id, robot, 0.01, physicsClientId=c)
            if near:
                link = near[0][4]
                return (pb.getJointInfo(robot, link, physicsClientId=c)[12].decode()
                        if link >= 0 else "base")
    return ""


# ------------------------------------------------------------------------ registry
_RUNS: dict[str, Callable[[Any, Mapping[str, Any], tuple], SkillOutcome]] = {
    "grasp": grasp, "insert_at_pose": insert_at_pose, "place_on_floor": place_on_floor,
    "pull_along_axis": pull_along_axis, "push_along_axis": push_along_axis,
    "lower_at_pose": lower_at_pose, "sweep": sweep, "release_joint": release_joint,
}

PRIMITIVES: dict[str, Primitive] = {name: Primitive(schema, _RUNS[name])
                                    for name, schema in SKILLS.items()}
"""The skill primitives a manifest may bind, by name: each schema of
:data:`creative_py.world.skills.SKILLS` with its run function."""


def primitive(name: str) -> Primitive:
    """Return the primitive ``name``; raise listing the registered ones."""
    if name not in PRIMITIVES:
        raise KeyError(f"unknown primitive {name!r}; primitives: {', '.join(PRIMITIVES)}")
    return PRIMITIVES[name]

