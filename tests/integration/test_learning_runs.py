"""Whole learning runs in the physics (Algorithms 1 and 2), one per case.

These run many pybullet trials (a wedge run takes about two minutes, a hook run more), so
they are marked ``slow`` and run by ``make test-all``; ``make test`` leaves them out.
What they check is what a user of ``make hook`` / ``make wedge`` would notice: the trial
budget of the paper, the learned model, the created tool and its files.
"""

import json

import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case
from creative_py.records.folder import read_trials

pytestmark = [pytest.mark.slow, pytest.mark.sim]


def _run(case, tmp_path, **kw):
    # As make hook / make wedge run it: catalogued objects first, and a tool created
    # even when one of them solved the harder task.
    folder = run_case(case, tmp_path, RunOptions(seed=0, demonstrate_creation=True, **kw))
    return folder.path, json.loads((folder.path / "summary.json").read_text())


def assert_pddl_solved(path, s):
    """Both tasks' own PDDL files (the tool-use task, the harder one with the created
    tool's model) solved by pyperplan with the Prolog planner's plan."""
    variant = s["create"]["variant"]
    assert set(s["pddl"]) == {"use", "create"}
    assert s["pddl"]["create"]["domain"] == f"domain_{variant}.pddl"
    for record in s["pddl"].values():
        assert record["status"] == "solved", record
        assert record["equals_prolog"] and record["prolog_plan_valid"], record
        assert (path / record["domain"]).exists() and (path / record["problem"]).exists()


def test_wedge_case_end_to_end(tmp_path):
    path, s = _run("wedge", tmp_path)
    trials = read_trials(path)
    use = [t for t in trials if t["phase"] == "use"]
    assert len(use) <= 9                      # the paper's budget (Figure 6)
    hg = s["hypotheses"]["hg"]
    for literal in ("shape(_G3,triangular_prism)", "far_from_hinge(", "tip_towards("):
        assert literal in hg
    assert s["eval"]["successes"] >= s["eval"]["trials"] - 1
    create = s["create"]
    assert create["success"] is not None
    assert create["solved_by"] in ("catalogue", "created")
    tool = create["created_tools"][-1]
    assert tool["instance"].startswith("block_length(") and "long" in tool["instance"]
    assert sum(o == "success" for o in create["eval"]) >= 4      # paper: 5 of 5
    assert tool["dims"]["tip_height"] >= 0.0008                # blunted: it prints
    assert tool["strength"]["model"] == "compression"          # not a beam
    assert tool["strength"]["verdict"] == "pass"
    for ext in ("urdf", "sdf", "scad", "stl"):
        assert (path / "tools" / tool["name"] / f"{tool['name']}.{ext}").exists()
    model = (path / "model.pl").read_text()
    assert "learned_model(wedge-big_door" in model and "block_length(A, long)" in model
    for f in ("domain.pddl", "problem.pddl", "trials.png"):
        assert (path / f).exists()
    assert_pddl_solved(path, s)


def test_hook_case_end_to_end(tmp_path):
    path, s = _run("hook", tmp_path)
    use = [t for t in read_trials(path) if t["phase"] == "use"]
    assert len(use) <= 12                     # the paper's budget (Figure 5)
    assert "behind(" in s["hypotheses"]["hg"]
    create = s["create"]
    assert create["success"] is not None
    assert create["solved_by"] in ("catalogue", "created")
    tool = create["created_tools"][-1]
    assert tool["instance"].startswith("handle_length(") and "long" in tool["instance"]
    assert sum(o == "success" for o in create["eval"]) >= 4      # paper: 5 of 5
    assert_pddl_solved(path, s)
    # Printed PLA, in parts that fit the bed, each sliced.
    assert tool["mass_kg"] < 0.1
    printed = tool["print"]
    assert printed["joint"] == "square_dowel_pin" and len(printed["pieces"]) >= 3
    assert all(p["print_time_s"] > 0 and p["filament_g"] > 0 for p in printed["pieces"])
    strength = tool["strength"]                 # the beam check of its handle
    assert strength["verdict"] == "pass" and strength["safety_factor"] >= 2.0
    assert strength["model"] == "cantilever" and strength["force_n"] > 0
