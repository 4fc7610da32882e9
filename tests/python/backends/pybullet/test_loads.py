"""The simulator records the largest contact force on the tool during its action."""

from __future__ import annotations

import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses
from creative_py.backends.pybullet.loads import ToolLoad

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
    assert load.bodies == ("cube1",)   # the case's target: the task's contact
    # The cube pushes back on the prong, at the handle's far end, towards +x (the tool
    # is pulled along -x).
    x, _, _ = load.point
    assert spec.handle_length - spec.hook_width - 0.01 < x < spec.handle_length + 0.005
    assert load.force[0] > 0
    # The gripper holds the handle at its grip point.
    assert load.grasp_point == pytest.approx(spec.grip_point, abs=1e-3)
    assert ToolLoad.from_dict(load.to_dict()) == ToolLoad.from_dict(result.tool_load)
    # The prong meets the cube in one-step pulses (about 1 N one step in ten): the
    # robust force is their mean over 0.1 s windows, far under the peak and above the
    # mean over the whole action (the windows without contact are left out).
    dt = world.physics["rest"].time_step
    assert load.window_s == 0.1
    assert load.impulse_ns / (load.steps * dt) < load.robust_force_n < 0.2 * load.max_force_n


def test_a_wedge_trials_load_is_the_door_on_it_not_the_floor_under_it():
    # The wedge touches the floor it stands on and the door it stops: the task's
    # contact is the door's (the case's target); the floor is named, not counted.
    world = load_world(get_case("wedge"))
    result = run_trial(world, "wedge_a3", "standard", 1, pose_target=poses(world))
    load = ToolLoad.from_dict(result.tool_load)
    assert load.bodies == ("door1",)
    assert "floor1" in load.other_bodies and "door1" not in load.other_bodies


def test_a_wedge_trial_keeps_a_robust_force_beside_the_contact_spike():
    # The door meeting the wedge gives a one-step spike; the force it then bears for
    # the rest of the release is far lower (the strength check uses that one).
    world = load_world(get_case("wedge"))
    result = run_trial(world, "wedge_a3", "standard", 1, pose_target=poses(world))
    assert result.outcome == "success", result.reason
    load = ToolLoad.from_dict(result.tool_load)
    assert 0 < load.contact_steps <= load.steps
    assert 0 < load.robust_force_n < load.max_force_n
    assert load.impulse_ns > 0
    # The percentile is of the per-step sums over the steps with contact: at most the
    # peak, and at least the mean force over the contact time (sums are mostly lower).
    dt = world.physics["rest"].time_step
    assert load.robust_force_n >= 0.5 * load.impulse_ns / (load.contact_steps * dt)
    assert ToolLoad.from_dict(load.to_dict()) == load
