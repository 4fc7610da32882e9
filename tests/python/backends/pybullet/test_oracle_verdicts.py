"""Every oracle kind and every guard gives a measured verdict: the quantity, its value,
the threshold and the judgement, measured on real episodes of the shipped worlds."""

from __future__ import annotations

import math
from functools import lru_cache

import pytest
from _hook_runs import hook_trial, hook_world, tube
from _poses import poses

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world, open_episode
from creative_py.simulator.trial import run_trial
from creative_py.world.oracles import ORACLES
from creative_py.simulator.types import Verdict


# ------------------------------------------------------------------ the value type
def test_a_verdict_says_its_value_and_threshold_in_words_and_data():
    v = Verdict("door1 angle", 12.34, 20.0, "deg", ">=", False,
                threshold_name="min_open_deg", detail="closed 5 deg after contact")
    assert not v.met()
    assert v.text() == ("door1 angle 12.3 deg (needs >= 20.0 deg, min_open_deg); "
                        "closed 5 deg after contact")
    d = v.to_dict()
    assert (d["quantity"], d["value"], d["threshold"], d["unit"], d["relation"],
            d["holds"]) == ("door1 angle", 12.34, 20.0, "deg", ">=", False)
    assert d["text"] == v.text()
    assert Verdict("x", -1e-9, 0.5, "m", "<", True).text().startswith("x 0.0000 m ")
    assert Verdict("x", None, 0.5, "m", "<", False).text() == "x unmeasured (needs < 0.5000 m)"


# ------------------------------------------------------- what every oracle kind must do
# A new kind (one ORACLES entry) is checked by these; no line of them changes.

def _world_judged_by(kind: str):
    """Return a shipped pybullet world whose [oracle] is of ``kind`` (None: no world)."""
    from creative_py.case import load_cases

    for _, manifest in sorted(load_cases().items()):
        if manifest.backend == "pybullet":
            world = load_world(manifest)
            if world.oracle.oracle.name == kind:
                return world
    return None


@pytest.mark.parametrize("name", list(ORACLES))
def test_every_oracle_kind_names_its_subject_and_threshold_options(name):
    kind = ORACLES[name]
    assert kind.name == name and callable(kind.judge)
    assert kind.threshold in kind.options and kind.subject in kind.options, name


@pytest.mark.sim
@pytest.mark.parametrize("name", list(ORACLES))
def test_every_oracle_kind_measures_a_verdict_in_a_shipped_world(name):
    """Each kind judges the scene of a world that names it, before the robot acts: a
    Verdict with its quantity, unit, relation and threshold, and the judgement it
    states (the goal does not hold before anything acted)."""
    world = _world_judged_by(name)
    if world is None:       # a kind no world uses yet (above) has its own test below
        pytest.skip(f"no shipped world's tasks.toml names the oracle {name!r}")
    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, demo.tool, robot=False) as ep:
        v = ep.verdict()
    assert isinstance(v, Verdict) and v.quantity
    assert isinstance(v.unit, str)     # empty for a dimensionless quantity (a reward)
    assert v.relation in ("<", "<=", ">", ">=") and v.threshold_name
    assert isinstance(v.threshold, float) and math.isfinite(v.threshold)
    assert v.holds is False            # nothing has acted yet: the goal does not hold


# ------------------------------------------------------------------ below / above
@pytest.mark.sim
def test_a_pulled_out_cube_is_measured_past_the_mouth_and_how_far_it_moved():
    r = hook_trial("hook_a2", "standard", 1)
    assert r.outcome == "success", r.reason
    v = r.verdict
    mouth = tube(hook_world()).mouth_x
    assert v["quantity"] == "cube1 centre x" and v["unit"] == "m" and v["relation"] == "<"
    assert v["threshold"] == pytest.approx(mouth) and v["threshold_name"] == "tube1.mouth_x"
    assert v["value"] == pytest.approx(r.true_final["cube1"][0], abs=1e-5)
    assert v["value"] < v["threshold"] and v["holds"] and v["asked"]
    assert v["measures"]["past_limit_m"] == pytest.approx(mouth - v["value"], abs=1e-5)
    assert v["measures"]["moved_m"] > 0.05           # it was pulled out of the tube
    assert "past the limit" in v["text"] and "moved" in v["text"]


@pytest.mark.sim
def test_a_short_handle_leaves_the_cube_short_of_the_mouth():
    r = hook_trial("hook_a1", "standard", 3)
    assert r.outcome in ("blocked", "failure"), r.reason
    v = r.verdict
    assert not v["holds"] and v["value"] >= v["threshold"]
    assert "short of the limit" in v["text"]
    # How far it moved is measured from where it settled before the trial.
    assert isinstance(v["measures"]["moved_m"], float) and v["measures"]["moved_m"] >= 0.0
    assert v["measures"]["past_limit_m"] == pytest.approx(
        v["threshold"] - v["value"], abs=1e-5) and v["measures"]["past_limit_m"] < 0


@pytest.mark.sim
def test_above_is_the_mirror_of_below_on_a_real_episode():
    world = hook_world()
    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, demo.tool, robot=False) as ep:
        opts = {"object": "target", "axis": "x", "limit": tube(world).mouth_x}
        below = ORACLES["below"].judge(ep, opts)
        above = ORACLES["above"].judge(ep, opts)
        assert below.value == above.value                      # the cube's centre x
        assert not below.holds and above.holds                 # it starts in the tube
        assert above.met() and not below.met()
        assert below.measures["moved_m"] == pytest.approx(0.0, abs=1e-3)


# ------------------------------------------------------------------ joint_held
@lru_cache(maxsize=None)
def _wedge_world():
    return load_world(get_case("wedge"))


@lru_cache(maxsize=None)
def _wedge_trial(tool: str, variant: str = "standard"):
    w = _wedge_world()
    return run_trial(w, tool, variant, 1, pose_target=poses(w))


@pytest.mark.sim
def test_a_held_door_is_measured_open_past_the_limit_with_its_closing_after_contact():
    r = _wedge_trial("wedge_a3")
    assert r.outcome == "success", r.reason
    v = r.verdict
    assert v["quantity"] == "door1 angle" and v["unit"] == "deg" and v["relation"] == ">="
    assert v["threshold"] == 20.0 and v["threshold_name"] == "min_open_deg"
    assert v["holds"] and v["value"] >= 20.0 and v["asked"]
    m = v["measures"]
    assert m["released"] and m["touched"] and m["max_close_deg"] == 2.0
    assert 0.0 <= m["closed_after_contact_deg"] < 2.0
    assert m["contact_angle_deg"] - m["closed_after_contact_deg"] == pytest.approx(
        v["value"], abs=1e-3)


@pytest.mark.sim
def test_a_short_wedge_is_measured_with_the_door_shut_below_the_limit():
    r = _wedge_trial("wedge_a1")
    assert r.outcome == "failure", r.reason
    v = r.verdict
    assert not v["holds"] and v["value"] < v["threshold"] == 20.0
    assert v["measures"]["closed_after_contact_deg"] > 2.0
    assert "door1 angle" in v["text"] and "needs >= 20.0 deg" in v["text"]


@pytest.mark.sim
def test_a_door_not_yet_released_is_measured_at_its_open_angle():
    w = _wedge_world()
    demo = w.manifest.demonstration
    with open_episode(w, demo.variant, demo.location, demo.tool, robot=False) as ep:
        v = ep.verdict()
        assert not v.holds and v.detail == "not released"
        assert v.value == pytest.approx(math.degrees(0.7), abs=0.5)   # open_angle
        assert ep.verdict().holds is False


# ------------------------------------------------------------------ guards
@lru_cache(maxsize=None)
def _rake_world():
    return load_world(get_case("rake"))


@pytest.mark.sim
def test_a_blocked_motion_names_the_guards_measure_and_what_it_ran_into():
    w = _rake_world()
    r = run_trial(w, "rake_a1", "standard", 1, pose_target=poses(w))
    assert r.outcome == "blocked", r.reason
    stop = r.verdict["stop"]
    assert stop["quantity"] == "gripper lag" and stop["unit"] == "m"
    assert stop["value"] > stop["threshold"] and not stop["holds"]
    assert stop["threshold_name"] == "max_tracking_error"
    assert stop["measures"]["touching"], stop                 # something was hit
    # The robot or the tool it holds first, then what it ran into.
    pairs = [pair.split(" against ") for pair in stop["measures"]["touching"]]
    assert all(len(p) == 2 and p[0] in ("robot", "rake_a1") for p in pairs), pairs
    assert "touching" in stop["text"]
    # The oracle is measured too, though the outcome does not rest on it.
    assert r.verdict["asked"] is False and r.verdict["quantity"] == "box1 centre x"


@pytest.mark.sim
def test_a_jammed_tool_is_stopped_by_its_grasp_slip_against_the_limit():
    w = _rake_world()
    r = run_trial(w, "hook_a3", "standard", 1, pose_target=poses(w))
    assert r.outcome == "blocked", r.reason
    stop = r.verdict["stop"]
    assert stop["quantity"] == "grasp slip"
    assert stop["value"] > stop["threshold"] > 0
    assert stop["threshold_name"].startswith("grasp_slip_max_")


# ------------------------------------------------------------------ a blow-up
@pytest.mark.sim
def test_a_blown_up_body_only_the_oracle_reads_makes_the_trial_invalid():
    """CleanTable perceives nothing (no motion watches its cubes): one cube thrown to
    NaN gave the mean of the other seven's rewards, a failure the learner labels."""
    import pybullet as pb

    from creative_py.simulator.trial import judge
    from creative_py.simulator.types import SkillOutcome

    world = load_world(get_case("clean_table"))
    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, demo.tool, robot=False) as ep:
        assert ep.watch == [] and ep.verdict().value < 0.99
        cube = ep.bodies["cubes3"].id
        pb.resetBasePositionAndOrientation(cube, (math.nan, 0.0, 0.015), (0, 0, 0, 1),
                                           physicsClientId=ep.sim.client)
        outcome, reason, oracle, asked = judge(ep, SkillOutcome("ok"), acted=True)
    assert (outcome, oracle, asked) == ("invalid", None, True)
    assert reason.startswith("non-finite pose of cubes3: (nan, "), reason
