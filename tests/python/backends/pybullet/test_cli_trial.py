"""The `creative trial` command: listing, errors, and a real trial in a subprocess."""

import json
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from creative_py.cli import app

from _hook_runs import hook_trial

runner = CliRunner()


def test_list_gives_tools_locations_variants_and_pose():
    res = runner.invoke(app, ["trial", "hook", "--list"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert "hook_a2" in data["objects"] and data["objects"]["hook_a2"]["set"] == "a"
    assert len(data["locations"]) == 4
    assert set(data["variants"]) == {"standard", "long_tube"}
    assert data["default_pose"] == {"dx": 0.03, "dy": 0.0, "roll": 0.0}


@pytest.mark.parametrize("args, message", [
    (["trial", "hook", "--tool", "hook_z9"], "unknown tool 'hook_z9'; available: hook_a1"),
    (["trial", "hook", "--tool", "hook_a2", "--pose", "0.1,x"], "--pose must be DX,DY,ROLL"),
    (["trial", "hook", "--tool", "hook_a2", "--location", "5"], "--location must lie in 1..4"),
    (["trial", "hook", "--tool", "hook_a2", "--variant", "huge"], "unknown variant 'huge'"),
    (["trial", "spoon", "--tool", "x"], "unknown case 'spoon'"),
    (["trial", "hook"], "--tool is required"),
])
def test_bad_arguments_give_a_clear_error(args, message):
    res = runner.invoke(app, args)
    assert res.exit_code == 2
    assert message in res.output


@pytest.mark.sim
def test_a_trial_in_another_process_is_bit_identical():
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "trial", "hook", "--tool",
                           "hook_a2", "--location", "1", "--seed", "0", "--json"],
                          capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.strip().splitlines()
    assert len(lines) == 1  # stdout carries only the JSON line
    data = json.loads(lines[0])
    here = hook_trial("hook_a2", "standard", 1).to_dict()
    assert data["outcome"] == "success"
    for key in ("outcome", "true_final", "perceived_final", "steps", "pose"):
        assert data[key] == here[key], key


def test_no_command_prints_pybullet_s_build_banner():
    proc = subprocess.run([sys.executable, "-c", "import creative_py.backends.pybullet"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0 and proc.stdout == "" and proc.stderr == ""
    listing = subprocess.run([sys.executable, "-m", "creative_py.cli", "trial", "hook",
                              "--list"], capture_output=True, text=True, timeout=60)
    assert "pybullet build time" not in listing.stderr + listing.stdout
