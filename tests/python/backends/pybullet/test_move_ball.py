"""RoboToolBench's MoveBall on the Panda: what the physics decides at the demonstration's
pose (worlds/move_ball/).

The verdict is the benchmark's reward, 1 - |p - g|_1 / 0.679 - |v|, with the goal's z at
0.001: a ball at rest on the table, its centre 0.08 up, scores 1 - 0.079 / 0.679 = 0.884
at most, so no trial reaches the benchmark's done() (reward > 0.99). The trainer's cage,
whose walls close round the ball and catch it when the sweep slows, leaves it at rest
within a few centimetres of the goal; a head too narrow for the ball lands on it, a
straight blade leaves the arm nowhere to reach.
"""

import subprocess
import sys
from functools import lru_cache

import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses

pytestmark = pytest.mark.sim

BEST = 1 - (0.08 - 0.001) / 0.679
"""The formula's reward of a ball at rest on the goal (its centre 0.08 above the table)."""


@lru_cache(maxsize=None)
def _world():
    return load_world(get_case("move_ball"))


@pytest.mark.parametrize("variant", ["standard", "benchmark"])
def test_the_cage_leaves_the_ball_at_rest_near_the_goal_below_done(variant):
    result = run_trial(_world(), "cage_a1", variant, 1, pose_target=poses(_world()))
    verdict = result.verdict
    assert result.outcome == "failure", result.reason
    assert verdict["quantity"] == "reward" and verdict["threshold"] == 0.99
    assert 0.84 < verdict["value"] <= BEST + 1e-6
    assert verdict["measures"]["speed_m_s"] < 0.01
    assert verdict["measures"]["distance_l1_m"] < 0.079 + 0.03


@pytest.mark.parametrize("tool, outcome, why", [
    ("cage_a3", "blocked", "ball1"),             # the U narrower than the ball lands on it
    ("blade_a2", "unreachable", "position_tool"),
])
def test_the_physics_discriminates_the_heads(tool, outcome, why):
    result = run_trial(_world(), tool, "standard", 1, pose_target=poses(_world()))
    assert result.outcome == outcome, result.reason
    assert why in result.reason + str(result.verdict)


def test_a_run_stops_at_the_failed_demonstration_with_exit_2_and_one_line(tmp_path):
    """``creative run move_ball``: the demonstration cannot pass done(), so nothing is
    learned; the run ends as docs/new-case.md says (exit 2, one line naming the
    demonstration) and leaves no run folder. (The options would make a run that went
    on past the demonstration end after one trial, with exit 0.)"""
    proc = subprocess.run(
        [sys.executable, "-m", "creative_py.cli", "run", "move_ball", "--phase", "use",
         "--max-trials", "1", "--eval-trials", "0", "--video", "none",
         "--out", str(tmp_path)], capture_output=True, text=True, timeout=300)
    errors = [line for line in proc.stderr.splitlines() if line.startswith("error: ")]
    assert (proc.returncode, len(errors)) == (2, 1), proc.stderr
    assert errors[0].endswith("worlds/move_ball/case.toml: field 'demonstration': cage_a1 "
                              "at location 1 did not reach the goal in the physics: "
                              "nothing to learn from")
    assert "Traceback" not in proc.stderr
    assert list(tmp_path.iterdir()) == []
