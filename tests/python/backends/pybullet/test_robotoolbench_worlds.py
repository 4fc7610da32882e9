"""RoboToolBench's BringCube and DislodgeCube as worlds: the benchmark's layout and what
the physics decides at the demonstration's pose, scored by the benchmark's reward.

The physics is the oracle: a few real trials on the Panda check the discrimination the
learner relies on (worlds/bring_cube/objects.toml, worlds/dislodge_cube/objects.toml)
and that the verdict is the benchmark's reward judged by its done() (reward > 0.99).
"""

from functools import lru_cache

import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses

pytestmark = pytest.mark.sim


@lru_cache(maxsize=None)
def _world(case):
    return load_world(get_case(case))


@pytest.mark.parametrize("case", ["bring_cube", "dislodge_cube"])
def test_the_panda_and_the_table_stand_where_the_benchmark_puts_them(case):
    world = _world(case)
    assert world.manifest.robot == "panda"
    assert (world.manifest.benchmark, world.manifest.benchmark_task) == (
        "robotoolbench", {"bring_cube": "BringCube", "dislodge_cube": "DislodgeCube"}[case])
    base = world.scene.robot.base
    assert tuple(base[0]) == (0.0, 0.0, 0.0) and tuple(base[1]) == (0.0, 0.0, 0.0)
    table = next(b for b in world.scene.bodies if b.name == "table1")
    size, pos = table.fields["size"], table.fields["position"]
    assert pos[2] + size[2] / 2 == pytest.approx(0.0, abs=1e-12)     # the top at z = 0
    assert (size, pos[:2], table.fields["friction"]) == ([1.5, 1.0, 0.05], [0.6, 0.0], 1.0)


@pytest.mark.parametrize("case, tool, variant, outcome, reward", [
    # BringCube: the demonstrated 0.30 m hook brings the cube within 4 mm of the goal
    # from the benchmark's x = 1.0; a 2 cm prong passes over the cube (reward 0).
    ("bring_cube", "hook_a1", "benchmark", "success", (0.99, 1.0)),
    ("bring_cube", "rake_a2", "benchmark", "failure", (0.0, 0.01)),
    # DislodgeCube: with the cube on the pipe's axis the 0.50 m hook pulls it out; at
    # the benchmark's y = 0.15 the pull's sideways draw takes it past the side
    # opening's corner but the prong loses it (0.21; docs/robotoolbench.md).
    ("dislodge_cube", "hook_a1", "standard", "success", (0.99, 1.0)),
    ("dislodge_cube", "hook_a1", "benchmark", "failure", (0.1, 0.3)),
])
def test_the_physics_scores_the_tools_with_the_benchmarks_reward(case, tool, variant,
                                                                 outcome, reward):
    world = _world(case)
    result = run_trial(world, tool, variant, 1, pose_target=poses(world))
    assert result.outcome == outcome, result.reason
    v = result.verdict
    assert (v["quantity"], v["relation"], v["threshold"]) == ("reward", ">", 0.99)
    assert reward[0] <= v["value"] <= reward[1], v["text"]
    assert v["holds"] == (v["value"] > 0.99)
