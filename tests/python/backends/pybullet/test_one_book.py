"""RoboToolBench's OneBook on the Panda: what the physics decides, scored by the
benchmark's reward (worlds/one_book/, docs/robotoolbench.md).

The physics is the oracle: a few real trials check the discrimination the learner and
the creator rely on (objects.toml). The books stand still until touched (the reward
counts every millimetre a neighbour moves). In the trainer's paperback row the
demonstrated 0.30 m hook pulls book 3 out alone; a stick passes over it. In the
benchmark's row the same hook pulls book 3 out but its hand moves the neighbours
(reward below 0.99), and a 0.345 m hook with a thin handle, the size the creator makes,
pulls it out alone.
"""

from functools import lru_cache

import pytest

from creative_py.case import get_case
from creative_py.kinds.hook_like import HookSpec
from creative_py.backends.pybullet import load_world
from creative_py.backends.pybullet.episode import open_episode
from creative_py.simulator.trial import run_trial

from _poses import poses

pytestmark = pytest.mark.sim

BOOKS = ("book1", "book2", "book3", "book4", "book5")


@lru_cache(maxsize=None)
def _world():
    world = load_world(get_case("one_book"))
    created = HookSpec(name="hook_new", handle_length=0.345, handle_width=0.009,
                       hook_length=0.030, hook_width=0.006, hook_side="right", mass=None)
    return world.with_tool(created)


def test_the_books_stand_where_the_benchmark_puts_them_and_stay():
    world = _world()
    with open_episode(world, "benchmark", 1, "hook_a1", pose_target=poses(world)) as ep:
        ep.run(1.0)
        centres = {b: ep.true_centre(b) for b in BOOKS}
        starts = dict(ep.body_starts)
    for i, book in enumerate(BOOKS):
        x, y, z = centres[book][:3]
        # The env's side face at y = -0.08 + 0.04 i, its centre 0.02 further; books 1-3
        # centred at z = 0.10, books 4-5 at 0.18.
        assert (x, y) == (pytest.approx(0.6, abs=1e-3), pytest.approx(-0.06 + 0.04 * i, abs=1e-3))
        assert z == pytest.approx(0.10 if i < 3 else 0.18, abs=1e-3)
        assert starts[book][:3] == pytest.approx(centres[book][:3], abs=1e-4)


@pytest.mark.parametrize("tool, variant, pose, outcome, low, high", [
    ("hook_a1", "standard", (0.118, 0.0, 0.0), "success", 0.99, 1.0),
    ("stick_a4", "standard", (0.118, 0.0, 0.0), "failure", 0.0, 0.01),
    ("hook_a1", "benchmark", (0.159, 0.0, 0.0), "failure", 0.90, 0.99),
    ("hook_new", "benchmark", (0.159, 0.0, 0.0), "success", 0.99, 1.0),
])
def test_the_physics_discriminates_the_tools_by_the_benchmarks_reward(
        tool, variant, pose, outcome, low, high):
    result = run_trial(_world(), tool, variant, 1, pose=pose, pose_target=poses(_world()))
    assert result.outcome == outcome, result.reason
    verdict = result.verdict
    assert verdict["quantity"] == "reward"
    assert low <= verdict["value"] <= high
    if tool == "hook_a1" and variant == "benchmark":
        # Book 3 is out; the hand among the books moved its neighbours.
        assert verdict["measures"]["out"] is True
        assert verdict["measures"]["neighbours_moved_m"] > 0.01
