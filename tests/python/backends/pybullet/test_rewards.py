"""RoboToolBench's rewards, re-expressed as oracle kinds: each task's reward equals the
benchmark's formula on hand-computed states, term by term (no physics).

The constants are the benchmark's (docs/robotoolbench.md; its envs' reward()): the
numbers a world's tasks.toml gives the oracle. Every expected value below is worked by
hand in its comment.
"""

from __future__ import annotations

import math

import pytest

from creative_py.simulator import rewards
from creative_py.world.oracles import ORACLES, OPTION_BOUNDS

TOL = 1e-9


# ------------------------------------------------------------------ BringCube
# reward = max(0, 1 - |p - (0.6, 0, 0.035)|_1 / |(1.0, 0, 0.035) - (0.6, 0, 0.035)|_1)
BRING_GOAL, BRING_START = (0.6, 0.0, 0.035), (1.0, 0.0, 0.035)


def test_bring_cube_reward_is_the_l1_progress_to_the_goal():
    scale = rewards.l1(BRING_START, BRING_GOAL)
    assert scale == pytest.approx(0.4, abs=TOL)
    # 0.10 + 0.02 + 0 = 0.12 m from the goal: 1 - 0.12 / 0.4 = 0.70
    r, t = rewards.goal_distance((0.70, 0.02, 0.035), BRING_GOAL, scale)
    assert r == pytest.approx(0.70, abs=TOL)
    assert t["distance_l1_m"] == pytest.approx(0.12, abs=TOL) and t["speed_penalty"] == 0.0
    # At the start: 0; farther than the start: clipped to 0.
    assert rewards.goal_distance(BRING_START, BRING_GOAL, scale)[0] == pytest.approx(0, abs=TOL)
    assert rewards.goal_distance((1.3, 0.0, 0.035), BRING_GOAL, scale)[0] == 0.0
    # 2 + 1 + 0.5 = 3.5 mm: 1 - 0.0035 / 0.4 = 0.99125 > 0.99 (done)
    r, _ = rewards.goal_distance((0.602, 0.001, 0.0355), BRING_GOAL, scale)
    assert r == pytest.approx(0.99125, abs=TOL) and r > 0.99
    # 5 mm off along x alone: 0.9875, not done (the benchmark needs under 4 mm)
    assert rewards.goal_distance((0.605, 0.0, 0.035), BRING_GOAL, scale)[0] == \
        pytest.approx(0.9875, abs=TOL)


# ------------------------------------------------------------------ MoveBall
# reward = max(0, 1 - |p - (0.6, -0.3, 0.001)|_1 / 0.679 - |v|)
BALL_GOAL, BALL_START = (0.6, -0.3, 0.001), (0.6, 0.3, 0.08)


def test_move_ball_reward_subtracts_the_speed_and_a_ball_at_rest_scores_0_884():
    scale = rewards.l1(BALL_START, BALL_GOAL)
    assert scale == pytest.approx(0.0 + 0.6 + 0.079, abs=TOL)
    # At rest on the goal mark: the centre is 0.079 m above the goal's z.
    r, t = rewards.goal_distance((0.6, -0.3, 0.08), BALL_GOAL, scale, 0.0, 1.0)
    assert r == pytest.approx(1 - 0.079 / 0.679, abs=TOL)          # 0.88365...
    assert r == pytest.approx(0.8837, abs=1e-4)
    # Rolling at 0.05 m/s there: 0.05 less.
    r2, t2 = rewards.goal_distance((0.6, -0.3, 0.08), BALL_GOAL, scale, 0.05, 1.0)
    assert r2 == pytest.approx(1 - 0.079 / 0.679 - 0.05, abs=TOL)
    assert t2["speed_m_s"] == 0.05 and t2["speed_penalty"] == pytest.approx(0.05)
    # 0.1 m short along y, at rest: 1 - (0.1 + 0.079) / 0.679
    r3, _ = rewards.goal_distance((0.6, -0.2, 0.08), BALL_GOAL, scale, 0.0, 1.0)
    assert r3 == pytest.approx(1 - 0.179 / 0.679, abs=TOL)
    # Fast enough, the penalty clips the reward to 0.
    assert rewards.goal_distance((0.6, -0.3, 0.08), BALL_GOAL, scale, 2.0, 1.0)[0] == 0.0


# ------------------------------------------------------------------ DislodgeCube
# r_x = clip(1 - (x - 0.9) / (1.24 - 0.9)), r_y = clip(1 - (y - 0.01) / (0.15 - 0.01)),
# reward = max(r_x, r_y); 0.9 = 1.1 - 0.4 / 2, 0.01 = 0.2 - (0.12 + 0.07).
DISLODGE = dict(start=(1.24, 0.15), near=(0.9, 0.01), axes=(0, 1))


def test_dislodge_cube_reward_is_the_better_of_the_two_ways_out():
    # Halfway to the open end: r_x = 1 - 0.17 / 0.34 = 0.5, r_y = 1 - 0.14 / 0.14 = 0
    r, t = rewards.axis_progress((1.07, 0.15, 0.05), **DISLODGE)
    assert (r, t["reward_x"], t["reward_y"]) == pytest.approx((0.5, 0.5, 0.0), abs=TOL)
    # Halfway out of the side opening: r_x = 0, r_y = 1 - 0.07 / 0.14 = 0.5
    r, t = rewards.axis_progress((1.24, 0.08, 0.05), **DISLODGE)
    assert (r, t["reward_x"], t["reward_y"]) == pytest.approx((0.5, 0.0, 0.5), abs=TOL)
    # Centre at the open end: r_x = 1; y past the start on the other side: r_y clipped 0
    r, t = rewards.axis_progress((0.90, 0.20, 0.05), **DISLODGE)
    assert (r, t["reward_x"], t["reward_y"]) == pytest.approx((1.0, 1.0, 0.0), abs=TOL)
    # Pushed deeper than it started: both clipped to 0.
    r, t = rewards.axis_progress((1.30, 0.20, 0.05), **DISLODGE)
    assert (r, t["reward_x"], t["reward_y"]) == (0.0, 0.0, 0.0)
    # done needs x < 0.9 + 0.01 * 0.34 = 0.9034: 0.905 is not, 0.903 is
    assert rewards.axis_progress((0.905, 0.15, 0.05), **DISLODGE)[0] < 0.99
    assert rewards.axis_progress((0.903, 0.15, 0.05), **DISLODGE)[0] > 0.99


# ------------------------------------------------------------------ HighObject
# The box (0.8, 0, 0.1) turned 90 degrees, 1.20 x 0.38 x 0.10, walls 0.015:
# x 0.8 -+ (0.19 - 0.015), y 0 -+ (0.60 - 0.015), z 0.1 - 0.0925 + 0.015 .. 0.1 + 0.05
BOX_MIN, BOX_MAX = (0.625, -0.585, 0.0225), (0.975, 0.585, 0.15)
HIGH_START = (1.2, 0.0, 0.925)                      # (1.3, 0, 0) + (-0.1, 0, 0.90 + 0.025)
HIGH = dict(start=HIGH_START, box_min=BOX_MIN, box_max=BOX_MAX, bonus=0.2,
            bonus_below_z=0.85)


def test_high_object_reward_is_one_in_the_box_else_l1_progress_plus_the_drop_bonus():
    centre = (0.8, 0.0, 0.08625)
    initial = 0.4 + 0.0 + (0.925 - 0.08625)                     # 1.23875
    # In the box: 1.
    r, t = rewards.in_box_or_distance((0.8, 0.1, 0.05), **HIGH)
    assert r == 1.0 and t["in_box"]
    # Still on the shelf, 0.1 m nearer: 1 - (0.3 + 0.83875) / 1.23875, no bonus (z >= 0.85)
    r, t = rewards.in_box_or_distance((1.1, 0.0, 0.925), **HIGH)
    assert r == pytest.approx(1 - 1.13875 / initial, abs=TOL) and not t["below_bonus_z"]
    assert t["initial_l1_m"] == pytest.approx(initial, abs=TOL)
    assert t["distance_l1_m"] == pytest.approx(rewards.l1((1.1, 0.0, 0.925), centre), abs=TOL)
    # Fallen to the floor beyond the box: 1 - (0.25 + 0.07125) / 1.23875 + 0.2
    r, t = rewards.in_box_or_distance((1.05, 0.0, 0.015), **HIGH)
    assert r == pytest.approx(1 - 0.32125 / initial + 0.2, abs=TOL) and t["below_bonus_z"]
    # Above the box's rim (z 0.2 > 0.15, not in it): 0.908 + 0.2 capped at 1.
    r, t = rewards.in_box_or_distance((0.8, 0.0, 0.2), **HIGH)
    assert r == 1.0 and not t["in_box"]
    # On the box's x face (0.975): in it (the benchmark's <=).
    assert rewards.in_box_or_distance((0.975, 0.0, 0.1), **HIGH)[1]["in_box"]


# ------------------------------------------------------------------ OneBook
# d = |book3 - start|, m = sum of the other books' |p - start|, s = sqrt(0.14^2 + 0.044^2);
# d > s: exp(-m); else d / s - (1 - exp(-m)); clipped to [0, 1].
BOOK_S = math.sqrt(0.14 ** 2 + 0.044 ** 2)            # 0.1467515...
BOOK3 = (0.6, 0.0, 0.10)


def _still(n=4):
    return [((0.6, 0.04 * i, 0.1), (0.6, 0.04 * i, 0.1)) for i in range(n)]


def test_one_book_reward_pays_the_pull_and_charges_the_neighbours_motion():
    assert BOOK_S == pytest.approx(0.1467515, abs=1e-6)
    # Out by 0.2 m, the others still: exp(0) = 1
    r, t = rewards.displacement_with_neighbours((0.4, 0.0, 0.10), BOOK3, _still(), BOOK_S)
    assert r == 1.0 and t["out"] and t["moved_m"] == pytest.approx(0.2, abs=TOL)
    # Out, two neighbours moved 1 and 2 cm: exp(-0.03)
    moved = [((0.61, -0.04, 0.1), (0.6, -0.04, 0.1)), ((0.6, 0.06, 0.1), (0.6, 0.04, 0.1))]
    r, t = rewards.displacement_with_neighbours((0.4, 0.0, 0.10), BOOK3, moved, BOOK_S)
    assert r == pytest.approx(math.exp(-0.03), abs=TOL)
    assert t["neighbours_moved_m"] == pytest.approx(0.03, abs=TOL)
    # Half way (d = s / 2), others still: 0.5; others moved 0.1 m: 0.5 - (1 - exp(-0.1))
    half = (0.6 - BOOK_S / 2, 0.0, 0.10)
    r, t = rewards.displacement_with_neighbours(half, BOOK3, _still(), BOOK_S)
    assert r == pytest.approx(0.5, abs=TOL) and not t["out"]
    one = [((0.5, 0.04, 0.1), (0.6, 0.04, 0.1))]
    r, _ = rewards.displacement_with_neighbours(half, BOOK3, one, BOOK_S)
    assert r == pytest.approx(0.5 - (1 - math.exp(-0.1)), abs=TOL)
    # Not moved, a neighbour knocked: clipped to 0.
    assert rewards.displacement_with_neighbours(BOOK3, BOOK3, one, BOOK_S)[0] == 0.0
    # The displacement is Euclidean, not L1: (0.03, 0.04) is 0.05
    r, t = rewards.displacement_with_neighbours((0.57, 0.04, 0.10), BOOK3, _still(), BOOK_S)
    assert t["moved_m"] == pytest.approx(0.05, abs=TOL)
    assert r == pytest.approx(0.05 / BOOK_S, abs=TOL)


# ------------------------------------------------------------------ CleanTable
# per cube: 1 if |p_xy - (1.1, 0)|_1 <= 0.15 + 0.01, else clip(1 - d / d0); the mean.
CIRCLE, WITHIN = (1.1, 0.0), 0.16


def test_clean_table_reward_is_the_mean_of_each_cubes_progress_into_the_circle():
    positions = [(1.0, 0.05, 0.015),    # d = 0.10 + 0.05 = 0.15 <= 0.16: 1
                 (0.8, 0.0, 0.015),     # d = 0.3, d0 = 0.5 + 0.1 = 0.6: 0.5
                 (0.7, -0.2, 0.015),    # not moved, d = d0 = 0.6: 0
                 (1.5, 0.3, 0.015)]     # d = 0.7 > d0 = 0.4: clipped 0
    starts = [(0.6, 0.1, 0.015), (0.6, 0.1, 0.015), (0.7, -0.2, 0.015), (0.9, 0.2, 0.015)]
    r, t = rewards.fraction_within(positions, starts, CIRCLE, WITHIN)
    assert r == pytest.approx((1 + 0.5 + 0 + 0) / 4, abs=TOL)
    assert t["inside"] == 1 and t["objects"] == 4
    assert t["each"] == pytest.approx([1.0, 0.5, 0.0, 0.0], abs=1e-6)
    # Just inside the L1 edge (0.1 + 0.059); z never counts. Just outside: progress.
    r, t = rewards.fraction_within([(1.0, 0.059, 0.9)], [(0.6, 0.1, 0.015)], CIRCLE, WITHIN)
    assert r == 1.0 and t["inside"] == 1
    r, t = rewards.fraction_within([(1.0, 0.061, 0.015)], [(0.6, 0.1, 0.015)], CIRCLE, WITHIN)
    assert r == pytest.approx(1 - 0.161 / 0.6, abs=TOL) and t["inside"] == 0
    # All eight in: 1.
    r, _ = rewards.fraction_within([(1.1, 0.0, 0.015)] * 8, [(0.6, 0.1, 0.015)] * 8,
                                   CIRCLE, WITHIN)
    assert r == 1.0
    # A cube that started at the centre (d0 = 0) and was pushed out: 0, the formula's
    # limit (it was a ZeroDivisionError, which ended the run), beside one inside: 0.5.
    r, t = rewards.fraction_within([(1.5, 0.0, 0.015), (1.1, 0.0, 0.015)],
                                   [(1.1, 0.0, 0.015), (0.6, 0.0, 0.015)], CIRCLE, WITHIN)
    assert (r, t["each"]) == (0.5, [0.0, 1.0])


# ------------------------------------------------------------------ as oracle kinds
class _Episode:
    """What an oracle reads of an episode: names, true centres, starts, velocities."""

    def __init__(self, centres, starts, velocity=(0.0, 0.0, 0.0), tracked=()):
        self.centres = centres
        self.start_centres = {n: s for n, s in starts.items() if n in tracked}
        self.body_starts = {n: s for n, s in starts.items() if n not in tracked}
        self.velocity = velocity

    def object_name(self, name):
        return {"target": "cube1"}.get(name, name)

    def true_centre(self, name):
        return (*self.centres[name], 0.0)

    def linear_velocity(self, name):
        return self.velocity


def _opts(kind, **given):
    """The options as the loader gives them: defaults, then the file's (numbers as
    floats and lists as tuples, as scene expressions resolve them)."""
    opts = {k: v for k, v in ORACLES[kind].options.items() if v is not None}
    for k, v in given.items():
        numbers = isinstance(v, list) and not isinstance(v[0], str)
        opts[k] = tuple(float(x) for x in v) if numbers else v
    return opts


def test_goal_distance_oracle_judges_reward_above_0_99_with_the_speed_penalty():
    ep = _Episode({"cube1": (0.6, -0.3, 0.08)}, {}, velocity=(0.03, 0.0, 0.04))
    v = ORACLES["goal_distance"].judge(ep, _opts(
        "goal_distance", object="target", goal=list(BALL_GOAL), start=list(BALL_START),
        speed_weight=1.0))
    assert v.quantity == "reward" and v.threshold == 0.99 and v.relation == ">"
    assert v.value == pytest.approx(1 - 0.079 / 0.679 - 0.05, abs=TOL)   # |v| = 0.05
    assert not v.holds and v.measures["speed_m_s"] == pytest.approx(0.05)
    ep = _Episode({"cube1": (0.602, 0.001, 0.0355)}, {})
    v = ORACLES["goal_distance"].judge(ep, _opts(
        "goal_distance", object="target", goal=list(BRING_GOAL), start=list(BRING_START)))
    assert v.value == pytest.approx(0.99125, abs=TOL) and v.holds and v.met()
    assert v.text().startswith("reward 0.9912 (needs > 0.99)")
    # A scale given overrides the start's distance.
    v = ORACLES["goal_distance"].judge(ep, _opts(
        "goal_distance", object="target", goal=list(BRING_GOAL), start=list(BRING_START),
        scale=0.035))
    assert v.value == pytest.approx(0.9, abs=TOL)


def test_axis_progress_and_in_box_oracles_read_their_options():
    ep = _Episode({"cube1": (1.24, 0.08, 0.05)}, {})
    v = ORACLES["axis_progress"].judge(ep, _opts(
        "axis_progress", object="target", axes=["x", "y"], start=[1.24, 0.15],
        near=[0.9, 0.01]))
    assert v.value == pytest.approx(0.5, abs=TOL) and not v.holds
    assert v.measures == {"reward_x": 0.0, "reward_y": 0.5}
    ep = _Episode({"cube1": (0.8, 0.1, 0.05)}, {})
    v = ORACLES["in_box_or_distance"].judge(ep, _opts(
        "in_box_or_distance", object="target", box_min=list(BOX_MIN), box_max=list(BOX_MAX),
        start=list(HIGH_START), bonus=0.2, bonus_below_z=0.85))
    assert v.value == 1.0 and v.holds and v.measures["in_box"] is True


def test_displacement_and_fraction_oracles_read_where_every_body_started():
    starts = {"book3": BOOK3, "book2": (0.6, -0.04, 0.1), "book4": (0.6, 0.04, 0.18)}
    ep = _Episode({"book3": (0.4, 0.0, 0.1), "book2": (0.61, -0.04, 0.1),
                   "book4": (0.6, 0.04, 0.18)}, starts, tracked=("book3",))
    v = ORACLES["displacement_neighbours"].judge(ep, _opts(
        "displacement_neighbours", object="book3", neighbours=["book2", "book4"],
        success_distance=BOOK_S))
    # Out, book 2 knocked 1 cm: exp(-0.01) = 0.99005, still done.
    assert v.value == pytest.approx(math.exp(-0.01), abs=TOL) and v.holds is True
    starts = {"c1": (0.6, 0.1, 0.015), "c2": (0.6, 0.1, 0.015)}
    ep = _Episode({"c1": (1.0, 0.05, 0.015), "c2": (0.8, 0.0, 0.015)}, starts)
    v = ORACLES["fraction_within"].judge(ep, _opts(
        "fraction_within", objects=["c1", "c2"], centre=list(CIRCLE), within=WITHIN))
    assert v.value == pytest.approx(0.75, abs=TOL) and v.measures["inside"] == 1


def test_every_reward_option_with_a_number_has_bounds():
    for kind in ("goal_distance", "axis_progress", "in_box_or_distance",
                 "displacement_neighbours", "fraction_within"):
        o = ORACLES[kind]
        for name in o.options:
            if name not in o.words and name != o.subject:
                assert name in OPTION_BOUNDS, (kind, name)


# ------------------------------------------------------------------ a blow-up
NAN = float("nan")


@pytest.mark.parametrize("kind, ep, given", [
    # one cube thrown to NaN: the mean of the others' rewards was 0.5, a learned failure
    ("fraction_within", _Episode({"c1": (NAN, 0.0, 0.015), "c2": (1.1, 0.0, 0.015)},
                                 {"c1": (0.6, 0.0, 0.015), "c2": (0.6, 0.0, 0.015)}),
     {"objects": ["c1", "c2"], "centre": list(CIRCLE), "within": WITHIN}),
    # a neighbour at NaN: the reward was 0.0
    ("displacement_neighbours",
     _Episode({"book3": (0.4, 0.0, 0.1), "book2": (0.6, NAN, 0.1)},
              {"book3": BOOK3, "book2": (0.6, -0.04, 0.1)}, tracked=("book3",)),
     {"object": "book3", "neighbours": ["book2"], "success_distance": BOOK_S}),
    # a start that was already not finite
    ("displacement_neighbours",
     _Episode({"book3": (0.4, 0.0, 0.1), "book2": (0.6, -0.04, 0.1)},
              {"book3": BOOK3, "book2": (0.6, math.inf, 0.1)}, tracked=("book3",)),
     {"object": "book3", "neighbours": ["book2"], "success_distance": BOOK_S}),
    ("goal_distance", _Episode({"cube1": (NAN, 0.0, 0.035)}, {}),
     {"object": "target", "goal": list(BRING_GOAL), "start": list(BRING_START)}),
    # the speed penalty's velocity
    ("goal_distance", _Episode({"cube1": (0.6, -0.3, 0.08)}, {}, velocity=(NAN, 0.0, 0.0)),
     {"object": "target", "goal": list(BALL_GOAL), "start": list(BALL_START),
      "speed_weight": 1.0}),
    ("axis_progress", _Episode({"cube1": (1.24, NAN, 0.05)}, {}),
     {"object": "target", "axes": ["x", "y"], "start": [1.24, 0.15], "near": [0.9, 0.01]}),
    ("in_box_or_distance", _Episode({"cube1": (0.8, 0.1, NAN)}, {}),
     {"object": "target", "box_min": list(BOX_MIN), "box_max": list(BOX_MAX),
      "start": list(HIGH_START), "bonus": 0.2, "bonus_below_z": 0.85}),
], ids=["fraction_within", "neighbour", "start", "goal_distance", "velocity",
        "axis_progress", "in_box"])
def test_a_non_finite_state_is_no_reward_but_a_blow_up(kind, ep, given):
    """The protocol's rule: a state with nothing finite to measure raises (the trial is
    invalid), never a finite reward the learner would take for a failure."""
    from creative_py.simulator.types import NonFiniteState

    with pytest.raises(NonFiniteState, match="non-finite (pose|start|velocity) of "):
        ORACLES[kind].judge(ep, _opts(kind, **given))
    assert issubclass(NonFiniteState, ValueError)
