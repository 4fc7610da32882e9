"""The pose model's check before tool creation's first trial (issue 11, item 3).

On the perceived scene of each harder variant (the scene is built and observed, no arm),
Prolog says whether the learned model's best tool can reach the learned pose:
the demonstrated medium hook in the long tube cannot (the cube lies deeper than its
handle reaches), so creation runs no trial with it; the big door needs a force, not a
reach, so the geometry cannot tell and the trial is run.
"""

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.case import get_case
from creative_py.learning.creation import ToolCreator
from creative_py.learning.trials import TrialRunner
from creative_py.backends.pybullet import load_world

pytestmark = pytest.mark.sim


def _creator(case):
    world = load_world(get_case(case))
    return ToolCreator(TrialRunner(Engine.instance(), world, None)), world


def _exploit(engine, tool, required):
    return Compound("exploit", (tool, [], "none", [engine.parse(r) for r in required]))


HOOK_POSE = ["in_tube(hook_a2,tube1)", "behind(hook_a2,cube1)", "hook_down(hook_a2)",
             "centred_on(hook_a2,cube1)"]


def test_the_long_tube_is_predicted_out_of_reach_at_every_location():
    creator, world = _creator("hook")
    engine = creator.engine
    for loc in world.locations:
        task = creator.runner.task("long_tube")
        task.location = loc
        p = creator.predict(_exploit(engine, "hook_a2", HOOK_POSE), task)
        assert p["feasible"] is False, p
        assert p["conflict"] == ["behind(hook_a2,cube1)"]
        assert "dx_reach" in p["why"] and "none is run" in p["why"]


def test_the_standard_tube_is_within_reach():
    creator, _ = _creator("hook")
    p = creator.predict(_exploit(creator.engine, "hook_a2", HOOK_POSE),
                        creator.runner.task("standard"))
    assert p["feasible"] is True, p


def test_the_big_door_cannot_be_told_by_the_geometry_so_the_trial_runs():
    creator, _ = _creator("wedge")
    req = ["near(wedge_a2,door1)", "far_from_hinge(wedge_a2,door1)",
           "tip_towards(wedge_a2,door1)"]
    p = creator.predict(_exploit(creator.engine, "wedge_a2", req),
                        creator.runner.task("big_door"))
    assert p["feasible"] is None, p
    assert "physics decides" in p["why"]


def test_a_longer_handle_reaches_the_long_tube():
    """The same question with the catalogue's long hook: the reach is the tool's own."""
    creator, _ = _creator("hook")
    req = [r.replace("hook_a2", "hook_a4") for r in HOOK_POSE]
    p = creator.predict(_exploit(creator.engine, "hook_a4", req),
                        creator.runner.task("long_tube"))
    assert p["feasible"] is True, p
