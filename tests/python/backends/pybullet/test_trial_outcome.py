"""One meaning of each way a trial ends (simulator/trial.py's trial_outcome), and the
one run_trial the learner, the CLI and the benchmarks share, in the pybullet physics."""

from __future__ import annotations

import pytest
from _hook_runs import hook_world
from _poses import poses

from creative_py.simulator import TRIAL_OUTCOMES, SkillOutcome
from creative_py.simulator.trial import run_trial, trial_outcome


@pytest.mark.parametrize("status, acted, reached, want", [
    (SkillOutcome("ok"), True, True, ("success", "goal reached")),
    (SkillOutcome("ok"), True, False, ("failure", "goal not reached")),
    # Blocked before the tool action: the arm could not carry out the planned motion.
    (SkillOutcome("blocked", "position_tool: gripper lagged"), False, False,
     ("blocked", "position_tool: gripper lagged")),
    # Blocked while the tool acted: the goal says.
    (SkillOutcome("blocked", "pull: slipped"), True, True, ("success", "pull: slipped")),
    (SkillOutcome("blocked", "pull: slipped"), True, False, ("failure", "pull: slipped")),
    (SkillOutcome("unreachable", "pick_up: no posture"), False, False,
     ("unreachable", "pick_up: no posture")),
    (SkillOutcome("invalid", "pull: NaN"), True, False, ("invalid", "pull: NaN")),
])
def test_each_ending_has_one_outcome(status, acted, reached, want):
    got = trial_outcome(status, acted, reached)
    assert got == want and got[0] in TRIAL_OUTCOMES


@pytest.mark.sim
def test_a_blocked_trial_keeps_what_the_robot_saw_where_it_stopped():
    # The short handle at the pose the learning runs test it with (dx 0.0375 m): its
    # wrist jams at the mouth past the tracking guard whatever the robot model (at the
    # demonstration's dx 0.03 the lag straddles the guard).
    world = hook_world()
    result = run_trial(world, "hook_a1", "standard", 1, pose=(0.0375, 0.0, 0.0),
                       pose_target=poses(world))
    assert result.outcome == "blocked", result.reason
    kinds = {f[0] for f in result.facts_before}
    assert {"pose", "object_kind"} <= kinds       # the task and the catalogue
    assert result.tool_load is None and result.max_tool_force_n == 0.0   # never acted
    assert result.perceived_final is not None


@pytest.mark.sim
def test_a_finished_trial_keeps_what_the_robot_saw_before_the_tool_action():
    world = hook_world()
    result = run_trial(world, "hook_a2", "standard", 1, pose_target=poses(world))
    assert result.outcome == "success" and result.reason == "goal reached"
    assert ("held", "hook_a2") in result.facts_before
    assert result.tool_load is not None and result.tool_load["max_force_n"] > 0
