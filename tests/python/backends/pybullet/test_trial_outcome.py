"""One meaning of each way a trial ends (simulator/trial.py's trial_outcome), and the
one run_trial the learner, the CLI and the benchmarks share, in the pybullet physics."""

from __future__ import annotations

from dataclasses import replace

import pytest
from _hook_runs import hook_trial, hook_world
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
    result = hook_trial("hook_a1", "standard", 1, pose=(0.0375, 0.0, 0.0))
    assert result.outcome == "blocked", result.reason
    kinds = {f[0] for f in result.facts_before}
    assert {"pose", "object_kind"} <= kinds       # the task and the catalogue
    assert result.tool_load is None and result.max_tool_force_n == 0.0   # never acted
    assert result.perceived_final is not None


@pytest.mark.sim
def test_a_finished_trial_keeps_what_the_robot_saw_before_the_tool_action():
    result = hook_trial("hook_a2", "standard", 1)
    assert result.outcome == "success" and result.reason == "goal reached"
    assert ("held", "hook_a2") in result.facts_before
    assert result.tool_load is not None and result.tool_load["max_force_n"] > 0


@pytest.mark.sim
def test_a_hand_that_strikes_the_tube_makes_the_trial_blocked_not_the_tool_s_failure():
    # On the Panda, the 0.28 m handle of hook_b3 brings the hand (20 cm across) to the
    # tube's 10 x 7 cm mouth: 2 cm to the left of the cube, the hand strikes the tube
    # without lagging its target past the tracking guard, the held hook is pushed
    # aside and the cube stays. The physics' contacts say it was the robot's hand,
    # not the tool: blocked (it was a failure when only the guard spoke).
    from creative_py.backends.pybullet import load_world
    from creative_py.case import get_case

    # What --robot panda makes of the case (hook_world() is the Baxter's, cached).
    world = load_world(replace(get_case("hook"), robot="panda"))
    assert world.scene.robot.profile.name == "panda"
    result = run_trial(world, "hook_b3", "standard", 1, pose=(0.03, 0.02, 0.0),
                       pose_target=poses(world))
    assert result.outcome == "blocked", (result.reason, result.verdict)
    assert result.reason.startswith("position_tool: the robot's panda_hand struck tube1 at ")
    struck = result.verdict["struck"]
    assert struck["quantity"] == "robot strike force" and struck["value"] > 0
    assert {"link": "panda_hand", "body": "tube1"}.items() <= struck["measures"]["struck"][0].items()
    assert all(s["link"].startswith("panda_") for s in struck["measures"]["struck"])
    assert "stop" not in result.verdict          # no guard stopped the motion
    assert result.verdict["value"] > 0.85        # the cube is still in the tube


@pytest.mark.sim
def test_the_baxter_s_trials_of_the_demonstration_pose_strike_nothing():
    # The same tool at the demonstration's pose on the Baxter: its hand stays clear.
    result = hook_trial("hook_b3", "standard", 1, pose=(0.03, 0.0, 0.0))
    assert result.outcome == "success", result.reason
    assert "struck" not in result.verdict


@pytest.mark.sim
def test_a_guard_names_the_pedestal_the_tool_lay_on():
    # A stop's touching pairs name every body: the pedestal a handle's tool lies on was
    # "body10" (CleanTable's rake_c3, stopped against it on its way out).
    from creative_py.backends.pybullet import open_episode
    from creative_py.simulator import Verdict

    world = hook_world()
    with open_episode(world, "standard", 1, "hook_a2", robot=False) as ep:
        assert set(ep.supports) == {"pedestal"}
        stop = Verdict("gripper lag", 0.04, 0.03, "m", "<=", False, measures={
            "touching_ids": [(ep.tool_body, ep.supports["pedestal"])]})
        named = ep._name_touching(stop)
    assert named.measures["touching"] == ["hook_a2 against pedestal"]
    assert named.detail == "touching: hook_a2 against pedestal"
