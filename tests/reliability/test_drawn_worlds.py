"""Drawn worlds that work: ``--world-seed N`` never draws a world whose demonstration fails.

Before the redraw, world seeds 20, 29, 31, 36 and 38 of the hook (and 4294967296) drew
the cube onto the tube's axis (``lateral`` clipped to its ``min`` 0), where perception
error decides the side the prong is turned flat to: turned to the left, the trainer's
demonstration did not reach the goal, the run stopped with an error blaming the
shipped ``case.toml`` and a sweep recorded the run as crashed (issue 19). Now the
sampler runs the demonstration in the drawn world and draws the demonstration's
location again, deterministically, until it reaches the goal.
"""

from __future__ import annotations

import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator.randomise import apply_drawn, draw_world


@pytest.fixture(scope="module")
def hook():
    return load_world(get_case("hook"))


@pytest.fixture(scope="module")
def ranges(hook):
    """The catalogue's qualitative ranges (the engine's; no physics)."""
    from creative_py.bridge import Engine
    from creative_py.learning.checks import catalogue_ranges

    return catalogue_ranges(Engine.instance(), hook)


class FailsUntil:
    """A stand-in for the physics: the demonstration fails the first ``n`` times."""

    def __init__(self, n: int) -> None:
        self.n, self.calls, self.seen = n, 0, []

    def __call__(self, drawn) -> bool:
        self.calls += 1
        self.seen.append([dict(s) for s in drawn["locations"]])
        return self.calls > self.n


def test_a_failing_demonstration_draws_its_location_again_deterministically(hook, ranges):
    plain = draw_world(hook, 20, ranges)
    check = FailsUntil(2)
    drawn = draw_world(hook, 20, ranges, demonstrates=check)
    assert drawn["redraws"] == 2 and check.calls == 3
    assert plain["redraws"] == 0
    # the catalogue and every other location are as drawn without the check
    assert drawn["order"] == plain["order"] and drawn["objects"] == plain["objects"]
    loc = hook.manifest.demonstration.location - 1
    for i, (a, b) in enumerate(zip(plain["locations"], drawn["locations"])):
        assert (a == b) == (i != loc), i
    # each draw of the demonstration's location is a new one, within [min, max]
    tried = [seen[loc] for seen in check.seen]
    assert tried[0] == plain["locations"][loc] and len({str(t) for t in tried}) == 3
    for j in hook.manifest.location_jitter:
        assert all(j.min <= t[j.key] <= j.max for t in tried)
    # the same seed gives the same redraws
    assert draw_world(hook, 20, ranges, demonstrates=FailsUntil(2)) == drawn
    assert apply_drawn(hook, drawn).location_sets[loc] == drawn["locations"][loc]


def test_a_world_that_works_at_once_is_the_world_drawn_without_the_check(hook, ranges):
    assert draw_world(hook, 7, ranges, demonstrates=FailsUntil(0)) == draw_world(hook, 7, ranges)


def test_no_location_that_works_is_an_error_naming_the_world_seed(hook, ranges):
    check = FailsUntil(10 ** 6)
    with pytest.raises(ValueError, match=r"^world seed 31: the demonstration \(hook_a2 at "
                                         r"location 1\) failed in the physics in 4 draws"):
        draw_world(hook, 31, ranges, demonstrates=check, redraws=3)
    assert check.calls == 4


@pytest.mark.sim
def test_world_seed_20_now_draws_a_world_whose_demonstration_succeeds(hook, monkeypatch):
    """The physics: seed 20's first draw fails the demonstration (an error naming the
    world seed, not case.toml); the sampler draws the location again and the
    demonstration succeeds in the world it returns."""
    from creative_py.bridge import Engine
    from creative_py.learning import tool_use
    from creative_py.learning.drawn_world import DEMO_CHECK_SEED, draw_catalogue_world

    real, runs = tool_use.run_demonstration, []

    def spy(world, seed=0, **kw):
        try:
            demo = real(world, seed=seed, **kw)
        except tool_use.DemonstrationFailed as exc:
            runs.append((world.location_sets, seed, str(exc)))
            raise
        runs.append((world.location_sets, seed, demo.goal_reached))
        return demo

    monkeypatch.setattr(tool_use, "run_demonstration", spy)
    drawn = draw_catalogue_world(Engine.instance(), hook, 20)
    assert drawn["redraws"] == len(runs) - 1 >= 1
    first_locations, seed, error = runs[0]
    assert seed == DEMO_CHECK_SEED
    assert error.startswith("world seed 20 (drawn from ") and "did not reach the goal" in error
    assert "field 'demonstration'" not in error
    last_locations, _seed, reached = runs[-1]
    assert reached is True and list(last_locations) == drawn["locations"]
    loc = hook.manifest.demonstration.location - 1
    assert first_locations[loc] != drawn["locations"][loc]
