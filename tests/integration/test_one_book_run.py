"""RoboToolBench's OneBook end to end on the Panda (Algorithms 1 and 2 in the physics,
scored by the benchmark's reward), added as data and generic plug-ins:
worlds/one_book/, ontology/cases/one_book.pl. Marked slow (a few minutes)."""

import json

import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case
from creative_py.records.folder import read_trials

pytestmark = [pytest.mark.slow, pytest.mark.sim]


def test_one_book_is_learned_and_solved_by_a_created_tool(tmp_path):
    folder = run_case("one_book", tmp_path, RunOptions(seed=0))
    s = json.loads((folder.path / "summary.json").read_text())
    trials = read_trials(folder.path)
    assert len([t for t in trials if t["phase"] == "use"]) <= 10
    assert s["eval"]["outcomes"] == ["success"] * 4
    create = s["create"]
    # No catalogued object reaches reward 0.99 in the benchmark's row: the 0.30 m hook
    # moves the neighbours, longer ones find no arm posture.
    assert create["solved_by"] == "created"
    for entry in create["catalogue"]:
        assert entry["outcome"] != "success"
    tool = create["created_tools"][-1]
    dims = tool["dims"]
    assert 0.34 <= dims["handle_length"] <= 0.35 and dims["handle_width"] <= 0.012
    used = [t for t in trials if t["phase"] == "create" and t["tool"] == tool["name"]]
    assert used[0]["outcome"] == "success" and used[0]["verdict"]["value"] > 0.99
    assert create["eval"] == ["success"] * 5
