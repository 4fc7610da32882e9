"""Shaped rewards in [0, 1]: pure functions of positions and speeds.

The formulas of RoboToolBench (Gao et al., "VLMgineer: Vision Language Models as
Robotic Toolsmiths", arXiv 2507.12644; its environments' ``reward()`` methods, MIT),
written generically and term by term, so that a world's ``tasks.toml`` sets every
constant (:mod:`creative_py.world.oracles` registers them as oracle kinds;
docs/robotoolbench.md says which task uses which). Each function returns the reward and
its terms by name (JSON-ready numbers), the terms a report shows and a test checks.

Positions are in metres in the world frame, speeds in m/s. No physics here: the oracle
reads the positions from the episode and hands them over. The formulas sit above the
backend boundary, beside the tool load's rule (:mod:`creative_py.simulator.load`), so
that every backend's oracle scores a task alike.
"""

from __future__ import annotations

import math
from typing import Mapping, Sequence

Point = Sequence[float]


def l1(a: Point, b: Point) -> float:
    """Return the L1 distance between two points of the same dimension (m)."""
    if len(a) != len(b):
        raise ValueError(f"points of different dimensions: {tuple(a)} and {tuple(b)}")
    return float(sum(abs(float(x) - float(y)) for x, y in zip(a, b)))


def clip01(v: float) -> float:
    """Return ``v`` clipped to [0, 1]."""
    return float(min(1.0, max(0.0, v)))


def goal_distance(position: Point, goal: Point, scale: float,
                  speed: float = 0.0, speed_weight: float = 0.0) -> tuple[float, dict]:
    """Return ``max(0, 1 - |p - g|_1 / scale - speed_weight * speed)``.

    The L1 distance of ``position`` to ``goal`` normalised by ``scale`` (the start's
    distance: 0 at the start, 1 at the goal), less a penalty on the object's speed
    (m/s); never below 0 (BringCube: no penalty; MoveBall: weight 1).
    """
    if scale <= 0:
        raise ValueError(f"scale must be positive, got {scale}")
    distance = l1(position, goal)
    penalty = speed_weight * speed
    reward = max(0.0, 1.0 - distance / scale - penalty)
    return float(reward), {"distance_l1_m": distance, "scale_m": float(scale),
                           "speed_m_s": float(speed), "speed_penalty": float(penalty)}


def axis_progress(position: Point, start: Point, near: Point,
                  axes: Sequence[int]) -> tuple[float, dict]:
    """Return the largest over ``axes`` of ``clip(1 - (p_a - near_a) / (start_a - near_a))``.

    Each axis' term is 0 with the object at its start and 1 once it reaches ``near_a``
    (the apparatus' near boundary along that axis); ``start`` and ``near`` give one
    number per axis of ``axes`` (indices into ``position``). DislodgeCube: x towards the
    pipe's open end, y out of its side opening.
    """
    if not (len(start) == len(near) == len(axes)) or not axes:
        raise ValueError("start, near and axes must have the same, non-zero length")
    terms = {}
    for a, s, n in zip(axes, start, near):
        span = float(s) - float(n)
        if span == 0:
            raise ValueError(f"axis {a}: the start lies on the near boundary")
        terms["xyz"[a]] = clip01(1.0 - (float(position[a]) - float(n)) / span)
    return max(terms.values()), {f"reward_{k}": v for k, v in terms.items()}


def inside(position: Point, box_min: Point, box_max: Point) -> bool:
    """Return whether ``position`` lies in the axis-aligned box (faces included)."""
    return all(lo <= p <= hi for p, lo, hi in zip(position, box_min, box_max))


def in_box_or_distance(position: Point, start: Point, box_min: Point, box_max: Point,
                       bonus: float, bonus_below_z: float) -> tuple[float, dict]:
    """Return 1 inside the box, else ``max(0, 1 - |p - c|_1 / |s - c|_1)`` plus ``bonus``
    (capped at 1) while ``p_z < bonus_below_z``.

    ``c`` is the box's centre, ``s`` the object's start (HighObject: the cube off the
    shelf's top gets 0.2, in the box 1).
    """
    centre = [(lo + hi) / 2 for lo, hi in zip(box_min, box_max)]
    in_box = inside(position, box_min, box_max)
    distance, initial = l1(position, centre), l1(start, centre)
    below = float(position[2]) < bonus_below_z
    if in_box:
        reward = 1.0
    else:
        reward = max(0.0, 1.0 - distance / initial)
        if below:
            reward = min(1.0, reward + bonus)
    return float(reward), {"in_box": in_box, "distance_l1_m": distance,
                           "initial_l1_m": initial, "below_bonus_z": below}


def displacement_with_neighbours(position: Point, start: Point,
                                 neighbours: Sequence[tuple[Point, Point]],
                                 success_distance: float) -> tuple[float, dict]:
    """Return the displacement reward with a penalty on the neighbours' motion.

    ``d`` is how far the object moved (Euclidean, m), ``m`` the sum of how far each
    neighbour moved (``(position, start)`` pairs). Past ``success_distance``:
    ``exp(-m)``; before it: ``d / success_distance - (1 - exp(-m))``; clipped to [0, 1]
    (OneBook: book 3 out, books 1, 2, 4, 5 still).
    """
    moved = math.dist(tuple(map(float, position)), tuple(map(float, start)))
    others = float(sum(math.dist(tuple(map(float, p)), tuple(map(float, s)))
                       for p, s in neighbours))
    out = moved > success_distance
    raw = math.exp(-others) if out else moved / success_distance - (1.0 - math.exp(-others))
    return clip01(raw), {"moved_m": moved, "neighbours_moved_m": others, "out": out,
                         "success_distance_m": float(success_distance)}


def fraction_within(positions: Sequence[Point], starts: Sequence[Point], centre: Point,
                    within: float) -> tuple[float, dict]:
    """Return the mean over objects of 1 within ``within`` (L1 in the plane of
    ``centre``) of ``centre``, else ``clip(1 - d / d0)``, ``d0`` its start's distance.

    Only the first ``len(centre)`` coordinates count (CleanTable: x, y, within 0.16 of
    the goal circle's centre). An object that started at the centre and left the goal
    scores 0 (the limit of the formula as ``d0`` goes to 0).
    """
    if not positions or len(positions) != len(starts):
        raise ValueError("one start per object is needed, and at least one object")
    k = len(centre)
    each, inside_count = [], 0
    for p, s in zip(positions, starts):
        d, d0 = l1(p[:k], centre), l1(s[:k], centre)
        if d <= within:
            each.append(1.0)
            inside_count += 1
        elif d0 == 0:  # it started at the centre and left: 1 - d / d0 tends to -inf
            each.append(0.0)
        else:
            each.append(clip01(1.0 - d / d0))
    return float(sum(each) / len(each)), {"inside": inside_count, "objects": len(each),
                                          "each": [round(v, 6) for v in each]}


def terms_json(terms: Mapping[str, object]) -> dict:
    """Return ``terms`` with floats rounded to 6 decimals (a verdict's measures)."""
    return {k: (round(v, 6) if isinstance(v, float) else v) for k, v in terms.items()}
