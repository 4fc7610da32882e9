"""The simulator records the largest contact force on the tool during its action."""

from __future__ import annotations

import pytest

from creative_py.case import get_case
from creative_py.sim import load_world, run_trial

from _poses import poses
from creative_py.sim.loads import ToolLoad

pytestmark = pytest.mark.sim


def test_a_hook_trial_records_a_positive_force_where_the_prong_pulls_the_cube():
    world = load_world(get_case("hook"))
    spec = world.item("hook_a2").spec
    result = run_trial(world, "hook_a2", "standard", 1, pose_target=poses(world))
    assert result.outcome == "success"
    assert result.max_tool_force_n > 0
    load = ToolLoad.from_dict(result.tool_load)
    assert load.max_force_n == pytest.approx(result.max_tool_force_n, rel=1e-5)
    assert load.steps > 0 and 0 < load.step <= result.steps and load.contacts > 0
    assert "cube1" in load.bodies
    # The cube pushes back on the prong, at the handle's far end, towards +x (the tool
    # is pulled along -x).
    x, _, _ = load.point
    assert spec.handle_length - spec.hook_width - 0.01 < x < spec.handle_length + 0.005
    assert load.force[0] > 0
    # The gripper holds the handle at its grip point.
    assert load.grasp_point == pytest.approx(spec.grip_point, abs=1e-3)
    assert ToolLoad.from_dict(load.to_dict()) == ToolLoad.from_dict(result.tool_load)
