"""The case facts the reports show come from the run folder, not from the case's manifest.

A run writes the unit of each pose number, its trial budget and the paper's count into
``summary.json`` (``learning/run.py``); :func:`read_run` reads them from there. A folder
written before these fields (no ``pose_units``, ``trial_budget``, ``paper_trials``) is
still read: its poses are the bare numbers, its budget the run's ``--max-trials`` when
given, the paper's count not shown. The case named in the summary is never looked up:
a folder of a case unknown here shows its facts all the same.
"""

from __future__ import annotations

import json
from pathlib import Path

from creative_py.learning.options import RunOptions
from creative_py.learning.phases import case_facts
from creative_py.report.contents import read_run
from creative_py.report.headline import headline

TRIAL = {"trial": 1, "phase": "use", "phase_trial": 1, "variant": "standard",
         "location": 2, "tool": "hook_a2", "kind": "experiment", "tested": [],
         "violated": [], "pose": {"dx": 0.0375, "dy": 0.0, "roll": 0.5},
         "outcome": "success"}


def _folder(root: Path, summary: dict) -> Path:
    run = root / "run"
    run.mkdir()
    (run / "trials.jsonl").write_text(json.dumps(TRIAL) + "\n")
    (run / "summary.json").write_text(json.dumps(summary))
    return run


def _pose_cell(contents) -> str:
    cell = dict(contents.columns)["pose"]
    return cell(contents.trials[0])


def test_the_facts_written_by_the_run_are_read_from_the_summary(tmp_path):
    run = _folder(tmp_path, {
        "case": "no_such_case", "use": {"trials": 1},
        "pose_units": {"dx": "m", "dy": "m", "roll": "rad"},
        "trial_budget": 7, "paper_trials": 12})
    c = read_run(run)
    assert (c.pose_units, c.budget, c.paper_trials) == (
        {"dx": "m", "dy": "m", "roll": "rad"}, 7, 12)
    assert _pose_cell(c) == "dx 37.5 mm, dy 0 mm, roll 28.6 deg"
    assert ("Tool-use learning: 1 trials of a budget of 7 (1 succeeded); "
            "the paper's robot used 12.") in headline(c).lines


def test_an_old_folder_without_the_fields_is_read_without_units_or_paper_count(tmp_path):
    run = _folder(tmp_path, {"case": "hook", "use": {"trials": 1}})
    c = read_run(run)
    assert (c.pose_units, c.budget, c.paper_trials) == ({}, None, None)
    assert _pose_cell(c) == "dx 0.0375, dy 0, roll 0.5"
    assert "Tool-use learning: 1 trials (1 succeeded)." in headline(c).lines
    assert c.warnings == []


def test_an_old_folder_s_budget_is_its_max_trials_when_given(tmp_path):
    run = _folder(tmp_path, {"case": "hook", "options": {"max_trials": 5}})
    assert read_run(run).budget == 5


def test_odd_values_are_dropped_not_shown(tmp_path):
    run = _folder(tmp_path, {"pose_units": {"dx": 3, "dy": "m"}, "trial_budget": True,
                             "paper_trials": "12"})
    c = read_run(run)
    assert (c.pose_units, c.budget, c.paper_trials) == ({"dy": "m"}, None, None)


def test_the_run_writes_the_manifest_s_facts():
    from creative_py.case import get_case

    hook = get_case("hook")
    facts = case_facts(hook, RunOptions())
    assert facts == {"pose_units": {p.name: p.unit for p in hook.pose_params},
                     "trial_budget": hook.trial_budget, "paper_trials": hook.paper_trials}
    assert facts["trial_budget"] == 12 and facts["paper_trials"] == 12
    assert set(facts["pose_units"].values()) <= {"m", "rad"}
    assert case_facts(hook, RunOptions(max_trials=3))["trial_budget"] == 3


def test_a_robot_given_by_its_toml_path_is_named_by_the_profile_in_the_headline(tmp_path):
    # --robot PATH.toml showed the whole path in the headline; --robot panda its name.
    from creative_py.case import get_case
    from creative_py.robots import ROBOTS_ROOT

    profile = tmp_path / "lab_arm.toml"            # the file's stem is not the name
    profile.write_text((ROBOTS_ROOT / "panda.toml").read_text())
    hook = get_case("hook")
    options = RunOptions(robot=str(profile))
    facts = case_facts(hook, options)
    assert facts["robot_name"] == "panda"
    assert "robot_name" not in case_facts(hook, RunOptions(robot="panda"))
    run = _folder(tmp_path, {"case": "hook", "seed": 0, "options": options.recorded(),
                             **facts})
    c = read_run(run)
    assert c.summary.options["robot"] == str(profile)   # a resume loads the path again
    assert headline(c).lines[0] == "Case hook, strategy informative, seed 0, robot panda."
