"""The pull's sideways draw (``pull_along_axis``'s ``lateral`` and ``lateral_over``).

Off by default, so every case without it pulls straight as before (the hook parity
fixtures pin that motion); set, the held tool moves across the passage's axis by
``lateral`` before the straight pull. DislodgeCube's manifest sets it from the scene:
the benchmark's cube, over the side opening, is drawn flush with the right wall; the
cube on the axis is pulled straight.
"""

import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.backends.pybullet.episode import open_episode
from creative_py.backends.pybullet.primitives import PRIMITIVES
from creative_py.world.read import resolve_options
from creative_py.world.skills import option_bound


def test_the_draw_is_off_by_default_and_bounded():
    opts = PRIMITIVES["pull_along_axis"].options
    assert (opts["lateral"], opts["lateral_over"]) == (0.0, 0.0)
    assert option_bound("pull_along_axis", "lateral") == (-0.5, 0.5, "m")
    assert option_bound("pull_along_axis", "lateral_over") == (0.0, 2.0, "m")


@pytest.mark.parametrize("variant, lateral", [("standard", 0.0), ("benchmark", 0.03)])
def test_dislodge_cube_draws_the_benchmarks_cube_flush_with_the_right_wall(variant,
                                                                           lateral):
    world = load_world(get_case("dislodge_cube"))
    ns = world.namespace(variant, 1, world.manifest.demonstration.tool)
    opts = resolve_options(world.skills["pull"].options, ns, "pull")
    # The right wall's inner face (0.2 - 0.11 / 2) plus half the cube, minus its y.
    assert opts["lateral"] == pytest.approx(lateral, abs=1e-12)
    assert opts["lateral_over"] == 0.10


def _pull(**options):
    """Pick up the hook world's demonstrated tool and pull it 5 cm back in free space;
    return how the gripper and the tool's working point moved (m)."""
    world = load_world(get_case("hook"))
    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, demo.tool, seed=0) as ep:
        assert ep.run_skill(demo.steps[0]).ok
        g0 = ep.robot.gripper_pose()[0]
        x0 = ep.kind.working_point(ep)[0]
        res = ep.run_primitive("pull_along_axis", until_x=x0 - 0.05, speed=0.10,
                               **options)
        assert res.ok, res.reason
        g1 = ep.robot.gripper_pose()[0]
        return g1[0] - g0[0], g1[1] - g0[1], ep.kind.working_point(ep)[0] - (x0 - 0.05)


@pytest.mark.sim
def test_a_lateral_draw_moves_the_held_tool_sideways_before_the_straight_pull():
    dx, dy, miss = _pull()
    assert dy == pytest.approx(0.0, abs=0.002)           # the straight pull
    assert dx == pytest.approx(-0.05, abs=0.005) and abs(miss) < 0.005
    dx, dy, miss = _pull(lateral=0.03, lateral_over=0.02)
    assert dy == pytest.approx(0.03, abs=0.003)          # drawn 3 cm to +y
    assert dx == pytest.approx(-0.05, abs=0.005) and abs(miss) < 0.005
    _, dy, _ = _pull(lateral=-0.02)
    assert dy == pytest.approx(-0.02, abs=0.003)
