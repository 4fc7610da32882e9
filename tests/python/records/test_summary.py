"""The run summary (:mod:`creative_py.records.summary`), the one owner of
``summary.json``: every recorded summary reads and writes back byte for byte, a summary
built field by field is written with the keys a run writes, in their order, and a value
of the wrong type is refused naming the file and the field (or, for the reports, left
out with a warning)."""

from __future__ import annotations

import json
from dataclasses import fields
from pathlib import Path

import pytest

from creative_py.records.summary import (CreateSummary, CreatedToolSummary, Hypotheses,
                                         Outcomes, PddlCheck, PddlChecks, PrintSummary,
                                         RunSummary, TrialCounts, UsePhase, VideoEntry,
                                         WallTimes, as_summary, print_summary)
from creative_py.records.trial import TrialRecord

RUNS = Path(__file__).resolve().parents[2] / "fixtures" / "runs"
RECORDED = sorted(RUNS.glob("*/summary.json"))


def test_there_are_recorded_summaries():
    assert len(RECORDED) >= 8


@pytest.mark.parametrize("path", RECORDED, ids=lambda p: p.parent.name)
def test_a_recorded_summary_reads_and_writes_back_byte_for_byte(path, tmp_path):
    summary = RunSummary.read(path)
    assert summary.to_json() == path.read_text(encoding="utf-8")
    assert RunSummary.read(path.parent) == summary  # a run folder names its summary
    written = summary.write(tmp_path)
    assert written == tmp_path / "summary.json"
    assert written.read_bytes() == path.read_bytes()


@pytest.mark.parametrize("path", RECORDED, ids=lambda p: p.parent.name)
def test_a_summary_built_field_by_field_writes_a_run_s_keys(path):
    """Built from its parts (no keys remembered), a recorded summary gives the same JSON,
    key for key and in order: the fields' order is the order a run writes them."""
    read = RunSummary.read(path)

    def rebuilt(part):
        if isinstance(part, list):
            return [rebuilt(p) for p in part]
        if not hasattr(part, "keys") or not hasattr(part, "extra"):
            return part
        if type(part) in (PddlCheck, PrintSummary) or part.extra:
            return part  # written as the planner or the manifest gave them
        values = {f.name: rebuilt(getattr(part, f.name)) for f in fields(part)
                  if f.name not in ("keys", "extra")}
        return type(part)(**values)

    built = rebuilt(read)
    assert built.keys is None
    assert json.dumps(built.to_dict()) == json.dumps(read.to_dict())


def test_the_parts_are_typed():
    s = RunSummary.read(RUNS / "hook_cfd_s0" / "summary.json")
    assert (s.case, s.seed, s.strategy, s.budget, s.paper_trials) == (
        "hook", 0, "paper", 12, 12)
    assert s.use == UsePhase(trials=9, converged=True, trials_to_converge=7,
                             strategy="paper", stop="confirmed")
    assert s.eval == Outcomes(trials=4, successes=4, outcomes=["success"] * 4)
    assert s.create.solver == "hook_a4" and s.create.solved_by == "catalogue"
    assert [c.tool for c in s.create.catalogue] == ["hook_a4"]
    tool = s.create.created_tools[0]
    assert (tool.name, tool.print.filament_g, tool.strength.verdict) == (
        "hook_new1", 65.13, "pass")
    assert [p.role for p in tool.print.pieces] == ["part", "part", "pin"]
    assert [t for t, _ in s.pddl.tasks()] == ["use", "create"]
    assert s.wall_time_s.phases() == [("use", 16.95), ("eval", 3.12), ("create", 7.95),
                                      ("video", 0.0)]
    assert s.trials.use.trials == 9 and s.videos == []


def test_an_empty_summary_and_a_use_only_run():
    assert RunSummary().strategy is None and RunSummary().budget is None
    assert RunSummary.from_dict({}).to_dict() == {}
    built = RunSummary(case="hook", use=UsePhase(trials=1), wall_time_s=WallTimes(use=1.5))
    out = built.to_dict()
    assert "create" not in out  # left out while None: a run of phase use has none
    assert out["wall_time_s"] == {"use": 1.5}
    assert out["world_seed"] is None and out["paper_trials"] is None  # written as null


def test_an_older_summary_reads_as_what_it_has():
    old = RunSummary.from_dict({"case": "hook", "options": {"max_trials": 5},
                                "use": {"trials": 3}})
    assert (old.budget, old.pose_units, old.use.stop, old.create) == (5, {}, None, None)
    assert old.to_dict() == {"case": "hook", "options": {"max_trials": 5},
                             "use": {"trials": 3}}


def test_unknown_keys_are_kept_in_their_place():
    data = {"later": 1, "case": "hook", "use": {"trials": 2, "new": [1]}, "z": None}
    s = RunSummary.from_dict(data)
    assert s.extra == {"later": 1, "z": None} and s.use.extra == {"new": [1]}
    assert json.dumps(s.to_dict()) == json.dumps(data)


def test_a_non_finite_float_reads_back_as_a_float():
    s = CreatedToolSummary.from_dict({"strength": {"safety_factor": "inf"}})
    assert s.strength.safety_factor == float("inf")
    assert json.loads(RunSummary(create=CreateSummary(created_tools=[s])).to_json())[
        "create"]["created_tools"][0]["strength"] == {"safety_factor": "inf"}


@pytest.mark.parametrize("data, message", [
    ({"seed": "0"}, "field 'seed': '0' is not of type int"),
    ({"seed": True}, "field 'seed': True is not of type int"),
    ({"use": []}, "field 'use': [] is not a JSON object"),
    ({"use": {"converged": "yes"}}, "field 'use.converged': 'yes' is not of type bool"),
    ({"wall_time_s": {"total": "1"}}, "field 'wall_time_s.total': '1' is not of type float"),
    ({"pose_units": {"dx": 1}}, "field 'pose_units.dx': 1 is not of type str"),
    ({"create": {"created_tools": [{"print": {"pieces": [{"volume_mm3": "big"}]}}]}},
     "field 'create.created_tools[0].print.pieces[0].volume_mm3': 'big' is not of type "
     "float"),
    ({"create": {"catalogue": [{"predicted": {"feasible": 1}}]}},
     "field 'create.catalogue[0].predicted.feasible': 1 is not of type bool"),
    ({"videos": [{"phase": "use"}]}, "field 'videos[0].file' is missing"),
    ({"pddl": {"use": {"plan": "a b"}}}, "field 'pddl.use.plan': 'a b' is not of type "
                                         "list[str]"),
])
def test_a_wrong_value_names_the_file_and_the_field(tmp_path, data, message):
    with pytest.raises(ValueError) as err:
        RunSummary.from_dict(data)
    assert str(err.value) == message
    path = tmp_path / "summary.json"
    path.write_text(json.dumps(data))
    with pytest.raises(ValueError) as err:
        RunSummary.read(path)
    assert str(err.value) == f"{path}: {message}"


def test_a_file_that_is_not_a_summary(tmp_path):
    path = tmp_path / "summary.json"
    path.write_text("[1]")
    with pytest.raises(ValueError, match=r"summary.json: not a JSON object, but list$"):
        RunSummary.read(path)
    path.write_text("{")
    with pytest.raises(ValueError, match=r"summary.json: not JSON \(Expecting"):
        RunSummary.read(tmp_path)
    with pytest.raises(OSError):
        RunSummary.read(tmp_path / "none.json")


def test_with_warn_a_wrong_value_is_left_out_and_said(tmp_path):
    path = tmp_path / "summary.json"
    path.write_text(json.dumps({
        "seed": "0", "case": "hook", "pose_units": {"dx": 1, "dy": "m"},
        "videos": ["a.mp4", {"file": 3}, {"file": "b.mp4", "trial": "x"}],
        "create": {"created_tools": ["t", {"name": "u", "mass_kg": "heavy"}]}}))
    said = []
    s = RunSummary.read(path, warn=said.append)
    assert (s.seed, s.case, s.pose_units) == (None, "hook", {"dy": "m"})
    assert s.videos == [VideoEntry(file="b.mp4")]
    assert [(t.name, t.mass_kg) for t in s.create.created_tools] == [("u", None)]
    assert said == [f"{path}: field {m}; not shown" for m in (
        "'seed': '0' is not of type int",
        "'pose_units.dx': 1 is not of type str",
        "'create.created_tools[0]': 't' is not a JSON object",
        "'create.created_tools[1].mass_kg': 'heavy' is not of type float",
        "'videos[0]': 'a.mp4' is not a JSON object",
        "'videos[1].file': 3 is not of type str",
        "'videos[2].trial': 'x' is not of type int")]


def test_as_summary_takes_a_summary_or_its_json():
    s = RunSummary(case="hook")
    assert as_summary(s) is s
    assert as_summary({"case": "hook"}) == s
    assert as_summary({"seed": "x"}, warn=lambda _m: None) == RunSummary()


def test_trial_counts_of_the_records():
    records = [TrialRecord(trial=1, phase="use", variant="v", location=1, tool="t",
                           outcome="failure"),
               {"trial": 2, "phase": "eval", "variant": "v", "location": 1, "tool": "t",
                "outcome": "success"}]
    assert TrialCounts.of(records).to_dict() == {
        "use": {"trials": 1, "successes": 0, "outcomes": ["failure"]},
        "create": {"trials": 0, "successes": 0, "outcomes": []},
        "eval": {"trials": 1, "successes": 1, "outcomes": ["success"]}}
    assert Outcomes.of(["no_plan", "success"], trials=2) == Outcomes(
        trials=2, successes=1, outcomes=["no_plan", "success"])


def test_the_print_figures_a_summary_keeps():
    entry = {"pieces": [{"name": "p", "stl": "p.stl", "placement": [[1]], "volume_mm3": 2}],
             "joint": None, "print_time_s": 60.0, "profile": "PLA", "sliced": True}
    assert print_summary(entry) == {
        "pieces": [{"name": "p", "stl": "p.stl", "volume_mm3": 2}], "joint": None,
        "print_time_s": 60.0, "sliced": True}
    printed = PrintSummary.of_manifest(entry)
    assert printed.to_dict() == print_summary(entry)
    assert PrintSummary.from_dict({}).to_dict() == {}  # a tool made without a folder


def test_pddl_checks_and_hypotheses():
    error = PddlCheck(domain="d", problem="p", status="error", plan=[], equals_prolog=False,
                      planner="pyperplan", variant="v", error="e")
    assert list(error.to_dict()) == ["domain", "problem", "status", "plan", "equals_prolog",
                                     "planner", "variant", "error"]
    checks = PddlChecks(use=error)
    assert checks.tasks() == [("use", error)] and "create" not in checks.to_dict()
    assert Hypotheses(hs="a").to_dict() == {"hs": "a", "hg": None}


def test_resumed_is_one_typed_field_absent_from_runs_never_resumed():
    # Issue 25: a resumed run's summary says so; an older summary (and a run never
    # resumed) has no such key and loads as before.
    from creative_py.records.summary import Resumed

    old = RunSummary.from_dict({"case": "hook"})
    assert old.resumed is None and "resumed" not in old.to_dict()
    assert "resumed" not in RunSummary(case="hook").to_dict()
    data = {"case": "hook", "resumed": {"replayed": 12, "earlier_wall_time_s": 8.65,
                                        "total_wall_time_s": 25.63}}
    new = RunSummary.from_dict(data)
    assert new.resumed == Resumed(replayed=12, earlier_wall_time_s=8.65,
                                  total_wall_time_s=25.63)
    assert new.to_dict() == data
    with pytest.raises(ValueError, match="field 'resumed.replayed': 'x' is not of type int"):
        RunSummary.from_dict({"resumed": {"replayed": "x"}})


@pytest.mark.parametrize("counts, wrong", [
    ({"trials": 4, "successes": 9}, "9 successes of 4 trials"),
    ({"trials": -1}, "-1 trials"),
    ({"successes": -2}, "-2 successes"),
    ({"trials": 1, "outcomes": ["success", "failure"]}, "1 trials but 2 outcomes"),
    ({"trials": 2, "successes": 2, "outcomes": ["success", "failure"]},
     "2 successes but 1 success outcomes"),
])
def test_counts_that_contradict_each_other_are_refused(counts, wrong):
    """An edited summary.json made the report say "9 of 4 trials succeeded"."""
    with pytest.raises(ValueError) as info:
        RunSummary.from_dict({"eval": counts})
    assert str(info.value) == f"field 'eval': {wrong}: the counts contradict each other"
    warned = []
    assert RunSummary.from_dict({"eval": counts}, warn=warned.append).eval is None
    assert warned == [f"field 'eval': {wrong}: the counts contradict each other; not shown"]
    # an evaluation stopped early lists fewer outcomes than its trials: consistent
    assert RunSummary.from_dict({"eval": {"trials": 4, "successes": 1,
                                          "outcomes": ["success"]}}).eval.successes == 1
