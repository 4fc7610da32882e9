"""The same seed gives the same trial bit for bit across processes (issue: worlds)."""

import json
import subprocess
import sys

import pytest

pytestmark = pytest.mark.sim


def _trial_json(args):
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "trial", *args, "--json"],
                          capture_output=True, text=True, check=True)
    return json.loads(proc.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("args", [
    # The quick suite checks the hook's trial across processes in test_cli_trial.py
    # (test_a_trial_in_another_process_is_bit_identical: the same keys and the pose).
    pytest.param(["hook", "--tool", "hook_a2", "--location", "2", "--seed", "7"],
                 marks=pytest.mark.slow),
    ["wedge", "--object", "wedge_a2", "--seed", "7"],
])
def test_same_seed_same_trial_in_two_processes(args):
    a, b = _trial_json(args), _trial_json(args)
    for key in ("outcome", "steps", "true_final", "perceived_final"):
        assert a[key] == b[key], key
    assert a["outcome"] == "success"
