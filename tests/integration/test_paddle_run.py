"""The paddle case end to end (Algorithms 1 and 2 in the physics): a tool kind no paper
case has (creative_py/kinds/paddle.py, ontology/kinds/paddle.pl) used by a case added
as data only (worlds/paddle_tube/, ontology/cases/paddle_tube.pl). Marked slow (about
a minute and a half)."""

import json

import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case
from creative_py.records.folder import read_trials

pytestmark = [pytest.mark.slow, pytest.mark.sim]


def test_paddle_case_end_to_end(tmp_path):
    # The catalogued long paddle_a4 solves the long tube first; --demonstrate-creation
    # still makes the paddle whose files and checks are tested here.
    folder = run_case("paddle_tube", tmp_path, RunOptions(seed=0, demonstrate_creation=True))
    s = json.loads((folder.path / "summary.json").read_text())
    use = [t for t in read_trials(folder.path) if t["phase"] == "use"]
    assert len(use) <= 10                     # the manifest's trial budget
    hg = s["hypotheses"]["hg"]
    for literal in ("blade_width(_G3,narrow)", "shaft_length(_G3,medium)",
                    "blade_upright(_G3)", "behind(_G3,_G4)"):
        assert literal in hg
    create = s["create"]
    assert create["solved_by"] == "catalogue" and create["success"] is not None
    tool = create["created_tools"][-1]
    assert tool["instance"] == "shaft_length(_G0,long)"
    dims = tool["dims"]
    assert dims["shaft_length"] >= 0.45 + 0.05       # the long tube plus the margin
    assert dims["blade_width"] <= 0.07 - 0.005       # upright in the tube
    assert tool["trial_outcome"] == "success"
    strength = tool["strength"]
    assert strength["model"] == "cantilever" and strength["verdict"] == "pass"
    for ext in ("urdf", "sdf", "scad", "stl"):
        assert (folder.path / "tools" / tool["name"] / f"{tool['name']}.{ext}").exists()
    printed = tool["print"]  # 0.60 m: longer than the bed, printed in pieces
    assert printed["joint"] == "square_dowel_pin" and len(printed["pieces"]) >= 3
    assert s["pddl"]["create"]["problem"] == "problem_long_tube.pddl"
    for record in s["pddl"].values():
        assert record["status"] == "solved" and record["equals_prolog"], record
