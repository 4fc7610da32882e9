"""The hook and wedge cases behave as they did before a case became data.

The fixtures (``tests/fixtures/trial_sequences/``) were recorded from whole runs of
seeds 0, 1 and 2 on ``main`` before the refactoring: per trial the phase, tool,
variant, location, tested literal and outcome, and the created tools' dimensions.
Each test runs the same seed again, with the paper's experiment strategy (Algorithm 1,
which the fixtures recorded), and compares (``parity.py`` says how).
"""

import json
from pathlib import Path

import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case

from parity import FIXTURES, differences, sequence

pytestmark = [pytest.mark.slow, pytest.mark.sim]

CASES = sorted(p.stem for p in FIXTURES.glob("*.json"))


@pytest.mark.parametrize("fixture", CASES)
def test_run_reproduces_the_recorded_trial_sequence(fixture, tmp_path):
    want = json.loads((FIXTURES / f"{fixture}.json").read_text())
    folder = run_case(want["case"], tmp_path, RunOptions(seed=want["seed"], strategy="paper"))
    assert differences(sequence(folder.path), want) == []


def test_the_fixtures_cover_both_paper_cases_and_three_seeds():
    assert CASES == [f"{c}_s{s}" for c in ("hook", "wedge") for s in range(3)]
