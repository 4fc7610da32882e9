"""Exact tests of :mod:`creative_py.learning.run`, the run of a case end to end.

The recorded hook run (``tests/fixtures/runs/hook_s0/``) resumed through the real engine
(the ``resumed_hook`` session fixture) must write the recorded run again: its summary
whole (the wall times of the slicer aside), its progress lines, its model, PDDL files,
plot and report. The pure parts (the options, ``run.json``, the summaries, the checks
of a manifest and a catalogue against the ontology) are called directly with small real
inputs.
"""

from __future__ import annotations

import copy
import hashlib
import json
import shutil
import subprocess
import sys
import time
from dataclasses import asdict, fields, replace
from pathlib import Path

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.case import get_case
from creative_py.learning.clips import ClipKeeper
from creative_py.learning.strategies import STRATEGIES
from creative_py.learning.creation import CreatedTool, CreateResult
from creative_py.learning.checks import (catalogue_ranges, check_catalogue, check_manifest,
                                         require_display)
from creative_py.learning.options import (RunOptions, read_run_json, run_json,
                                          run_json_check)
from creative_py.learning.pddl_files import check_pddl, created_pddl, plan_steps
from creative_py.learning.phases import _relative, case_facts, creation_summary
from creative_py.learning.run import (_checked_world, _earlier_summary, _finish, _open_folder,
                                      _trial_runner, resume_run, run_case)
from creative_py.records.summary import Resumed, RunSummary, WallTimes
from creative_py.learning.trials import TrialRunner
from creative_py.mesh.slicer import SliceError
from creative_py.records.folder import RunFolder, read_resume, running_pid
from creative_py.report import plot_trials
from creative_py.simulator import backend_for

RECORDED = Path(__file__).resolve().parents[2] / "fixtures" / "runs" / "hook_s0"

PROGRESS = """\
resuming {run}: replaying 19 recorded trials
run folder {run}
demonstration: the trainer shows the task with hook_a2 (loc 1)
demonstration with hook_a2: new model pull_out; 16384 hypotheses
#1   TUL  hook_a1        loc 1  blocked     tested handle_length(hook_a1,medium)  \
because position_tool: gripper lagged its target by 3.0 cm at (0.978, -0.250, -0.052) m: \
something is in the way  (replayed)
#2   TUL  hook_a2        loc 1  failure     tested hook_down(hook_a2)  (replayed)
#3   TUL  hook_a2        loc 1  failure     tested behind(hook_a2,cube1)  (replayed)
#4   TUL  hook_a2        loc 1  failure     tested centred_on(hook_a2,cube1)  (replayed)
#5   TUL  hook_a3        loc 1  success     tested hook_length(hook_a3,long)  (replayed)
#6   TUL  hook_b2        loc 2  success     tested hook_width(hook_b2,wide)  (replayed)
#7   TUL  stick_a5       loc 3  failure     tested hook(stick_a5)  (replayed)
#8   TUL  hook_a2        loc 3  success     tested -  (replayed)
#9   TUL  hook_a2        loc 4  success     tested -  (replayed)
h_s: tool_pose(A,B,C) :- hook(A), hook_like(A), tool(A), \
handle_length(A,medium), handle_width(A,thin), hook_angle(A,right), hook_down(A), \
behind(A,B), centred_on(A,B), in_tube(A,C), in_tube(B,C)
h_g: tool_pose(A,B,C) :- handle_length(A,medium), hook_down(A), \
behind(A,B), centred_on(A,B), hook(A)
plan: plan([pick_up(hook_a2),position_tool(hook_a2,cube1,tube1),pull_out(hook_a2,cube1,tube1)])
pddl problem.pddl: solved by pyperplan (pick_up hook_a2) (position_tool hook_a2 cube1 tube1) \
(pull_out hook_a2 cube1 tube1) (equals Prolog's)
#10  EVAL hook_a2        loc 1  success     tested -  (replayed)
#11  EVAL hook_a2        loc 2  success     tested -  (replayed)
#12  EVAL hook_a2        loc 3  success     tested -  (replayed)
#13  EVAL hook_a2        loc 4  success     tested -  (replayed)
TC predicted: hook_a2: behind(hook_a2,cube1) cannot hold within the reach of hook_a2 in \
the long_tube task: dx_reach = -0.011 m (deepest prong centre the held tool reaches, minus \
the cube centre); the trial would fail, so none is run
manufacturing tool 1: meshing, splitting to the build volume and slicing its pieces
created hook_new1: handle_length(A,medium) -> any_length(A) -> handle_length(A,long); \
handle_length 600.0 mm, handle_width 9.0 mm, hook_length 30.0 mm, hook_width 12.0 mm, \
hook_angle_deg 90, hook_side right
#14  TC   hook_new1      loc 1  success     tested -  (replayed)
hook_new1: strength pass (cantilever, 0.91 N, 4.10 MPa, safety factor 12.21)
#15  EVAL hook_new1      loc 2  success     tested -  (replayed)
#16  EVAL hook_new1      loc 3  success     tested -  (replayed)
#17  EVAL hook_new1      loc 4  success     tested -  (replayed)
#18  EVAL hook_new1      loc 1  success     tested -  (replayed)
#19  EVAL hook_new1      loc 2  success     tested -  (replayed)
plan (long_tube, created model): \
plan([pick_up(hook_a4),position_tool(hook_a4,cube1,tube1),pull_out(hook_a4,cube1,tube1)])
pddl problem_long_tube.pddl: solved by pyperplan (pick_up hook_a4) \
(position_tool hook_a4 cube1 tube1) (pull_out hook_a4 cube1 tube1) (equals Prolog's)
done in 20.54 s: {run}
One demonstration, with hook_a2.
Tool-use learning: 9 trials of a budget of 12 (4 succeeded); stopped because the learned \
model succeeded the required times in a row; converged after 7 trials; the paper's robot \
used 12.
Evaluation of the learned model on the task it learned: 4 of 4 trials succeeded.
Tool creation on the harder task long_tube: hook_a2 was predicted to fail, so its trial \
was not run; no catalogued object tried; solved by the created hook_new1 after 1 creation \
trial; the created tool's evaluation: 5 of 5 trials succeeded.
Printing hook_new1: 3 pieces, 4 h 04 min of printing, 65.1 g of filament (21.8 m); mass \
64.3 g.
report: {run}/report.html"""

MODEL = """\
%   Learned by CREATIVE-py, case hook.
%   Load: swipl prolog/creative.pl, then ?- load_model_file('{run}/model.pl').
%   learned_model(Task, Action, Precondition, Effects): Precondition is
%   the skill's own precondition, the most general hypothesis h_g, then
%   the spatial literals of h_s that h_g lacks (the pose that worked).
%   learned_hypothesis(Task, hs|hg, Clause): the version space's bounds.

:- discontiguous learned_model/4.

learned_model(hook, pull_out(A, B, C), [holding(A), in_tube(B, C), handle_length(A, medium), \
hook_down(A), behind(A, B), centred_on(A, B), hook(A), in_tube(A, C)], \
[add(out_of_tube(B, C)), del(in_tube(A, C)), del(in_tube(B, C))]).

learned_hypothesis(hook, hs, (tool_pose(A, B, C):-hook(A), hook_like(A), tool(A), \
handle_length(A, medium), handle_width(A, thin), hook_angle(A, right), hook_down(A), \
behind(A, B), centred_on(A, B), in_tube(A, C), in_tube(B, C))).
learned_hypothesis(hook, hg, (tool_pose(A, B, _):-handle_length(A, medium), hook_down(A), \
behind(A, B), centred_on(A, B), hook(A))).

%   The task variant long_tube needed a created tool.
learned_model(hook-long_tube, pull_out(A, B, C), [holding(A), in_tube(B, C), \
handle_length(A, long), hook_down(A), behind(A, B), centred_on(A, B), hook(A), \
in_tube(A, C)], [add(out_of_tube(B, C)), del(in_tube(A, C)), del(in_tube(B, C))]).
"""

PRINT_TIMES = ("wall_time_s", "print_time_s")
PIECE_TIMES = ("slice_wall_time_s", "print_time_s", "print_time")
"""What the slicer measures anew each time, of a created tool's print and of each of its
pieces (wall times, and a print time that moves by a second between slicings): left
out of the exact comparison."""


def _print_timeless(summary: dict) -> dict:
    """Return ``summary`` without the slicer's timings (:data:`PRINT_TIMES`, :data:`PIECE_TIMES`)."""
    out = copy.deepcopy(summary)
    for tool in out["create"]["created_tools"]:
        for key in PRINT_TIMES:
            tool["print"].pop(key)
        for piece in tool["print"]["pieces"]:
            for key in PIECE_TIMES:
                piece.pop(key)
    out["create"].pop("slice_wall_time_s")
    out["create"].pop("print_wall_time_s")
    return out


def test_the_resumed_hook_run_writes_the_recorded_run_again(request):
    # The fixture is asked for here, in the test's call, so that the resume's time is
    # the test's own (mutmut runs the tests of a mutant fastest first).
    resumed = request.getfixturevalue("resumed_hook")
    run = resumed.path
    assert resumed.lines == PROGRESS.format(run=run).split("\n")

    recorded = json.loads((RECORDED / "summary.json").read_text())
    summary = json.loads((run / "summary.json").read_text())
    assert _print_timeless(summary) == _print_timeless(recorded)
    # The create summary's slicer times are the sums over the pieces, as sliced now.
    pieces = [p for t in summary["create"]["created_tools"] for p in t["print"]["pieces"]]
    assert summary["create"]["slice_wall_time_s"] == round(
        sum(p["slice_wall_time_s"] for p in pieces), 2)
    assert summary["create"]["print_wall_time_s"] == round(
        sum(t["print"]["wall_time_s"] for t in summary["create"]["created_tools"]), 2)
    assert [sorted(p) for p in pieces] == [sorted(p) for t in
                                           recorded["create"]["created_tools"]
                                           for p in t["print"]["pieces"]]

    assert (run / "trials.jsonl").read_text() == (RECORDED / "trials.jsonl").read_text()
    assert (run / "run.json").read_text() == (RECORDED / "run.json").read_text()
    assert (run / "model.pl").read_text() == MODEL.format(run=run)
    heads = {name: (run / name).read_text().split("\n")[:2] for name in
             ("domain.pddl", "problem.pddl", "domain_long_tube.pddl",
              "problem_long_tube.pddl")}
    assert heads == {
        "domain.pddl": ["(define (domain creative)",
                        "  (:requirements :strips :typing)"],
        "problem.pddl": ["(define (problem task)", "  (:domain creative)"],
        "domain_long_tube.pddl": ["(define (domain creative_long_tube)",
                                  "  (:requirements :strips :typing)"],
        "problem_long_tube.pddl": ["(define (problem task_long_tube)",
                                   "  (:domain creative_long_tube)"],
    }
    trials, _ = read_resume(run)
    plot_trials(trials, run / "expected.png", title="CREATIVE-py, hook case, seed 0")
    assert (run / "trials.png").read_bytes() == (run / "expected.png").read_bytes()
    (run / "expected.png").unlink()
    assert (run / "report.html").read_text().startswith("<!DOCTYPE html>")
    assert sorted(p.name for p in (run / "tools" / "hook_new1").glob("hook_new1.*")) == [
        "hook_new1.json", "hook_new1.png", "hook_new1.scad", "hook_new1.sdf",
        "hook_new1.stl", "hook_new1.urdf"]


# ---------------------------------------------------------------- RunOptions

def test_the_default_options():
    assert asdict(RunOptions()) == {
        "seed": 0, "phase": "all", "max_trials": None, "consecutive": 2, "eval_trials": 4,
        "create_eval_trials": 5, "video": "key", "gui": False, "strategy": "informative",
        "world_seed": None, "catalogue_first": None, "demonstrate_creation": False,
        "prior": None, "backend": None, "robot": None}


@pytest.mark.parametrize("strategy, first, tries", [
    ("paper", None, False), ("informative", None, True), ("random", None, True),
    ("paper", True, True), ("informative", False, False)])
def test_tries_catalogue_is_the_strategys_unless_set(strategy, first, tries):
    assert RunOptions(strategy=strategy, catalogue_first=first).tries_catalogue is tries


@pytest.mark.parametrize("field, least", [
    ("seed", 0), ("max_trials", 1), ("consecutive", 1), ("eval_trials", 0),
    ("create_eval_trials", 0), ("world_seed", 0)])
def test_a_whole_number_option_takes_its_least_value_and_refuses_less(field, least):
    assert getattr(RunOptions(**{field: least}), field) == least
    for bad in (least - 1, 1.0 * least, True, str(least)):
        with pytest.raises(ValueError) as err:
            RunOptions(**{field: bad})
        assert str(err.value) == (f"option {field} must be a whole number >= {least}, "
                                  f"got {bad!r}")


@pytest.mark.parametrize("field", ["seed", "consecutive", "eval_trials",
                                   "create_eval_trials"])
def test_only_max_trials_and_world_seed_may_be_none(field):
    with pytest.raises(ValueError) as err:
        RunOptions(**{field: None})
    least = 1 if field == "consecutive" else 0
    assert str(err.value) == f"option {field} must be a whole number >= {least}, got None"
    assert RunOptions(max_trials=None, world_seed=None).max_trials is None


@pytest.mark.parametrize("field, bad, message", [
    ("phase", "learn", "option phase must be one of use, create, all, got 'learn'"),
    ("video", "some", "option video must be one of all, key, none, got 'some'"),
    ("gui", 1, "option gui must be true or false, got 1"),
    ("catalogue_first", 0,
     "option catalogue_first must be true, false or unset, got 0"),
    ("demonstrate_creation", None,
     "option demonstrate_creation must be true or false, got None"),
    ("strategy", "not_a_strategy",
     "unknown strategy 'not_a_strategy'; strategies: " + ", ".join(STRATEGIES)),
])
def test_a_bad_option_is_refused_in_one_line(field, bad, message):
    with pytest.raises(ValueError) as err:
        RunOptions(**{field: bad})
    assert str(err.value) == message


@pytest.mark.parametrize("field, good", [
    ("phase", "use"), ("phase", "create"), ("video", "all"), ("video", "none"),
    ("gui", True), ("catalogue_first", True), ("catalogue_first", False),
    ("demonstrate_creation", True), ("strategy", "random")])
def test_every_good_option_value_is_taken(field, good):
    assert getattr(RunOptions(**{field: good}), field) == good


# ---------------------------------------------------------------- run.json

def _run_json(tmp_path: Path, meta, check: bool = False) -> Path:
    if check:  # as run_json writes it
        meta = {**meta, "check": run_json_check(meta)}
    (tmp_path / "run.json").write_text(meta if isinstance(meta, str) else json.dumps(meta),
                                       encoding="utf-8")
    return tmp_path / "run.json"


def test_read_run_json_reads_the_recorded_run():
    case, options, world, drawn = read_run_json(RECORDED)
    assert (case, world, drawn) == ("hook", None, None)
    assert options == RunOptions(strategy="paper", video="none")


def test_read_run_json_fills_old_runs_with_the_papers_algorithms_and_no_gui(tmp_path):
    _run_json(tmp_path, {"case": "rake", "options": {"seed": 3, "gui": True},
                         "world": "/w/rake", "drawn_world": {"hook_a1": {}}}, check=True)
    case, options, world, drawn = read_run_json(tmp_path)
    assert (case, world, drawn) == ("rake", Path("/w/rake"), {"hook_a1": {}})
    assert options == RunOptions(seed=3, strategy="paper", catalogue_first=False)
    _run_json(tmp_path, {"case": "rake", "options": {"strategy": "random",
                                                     "catalogue_first": True},
                         "world": ""}, check=True)
    assert read_run_json(tmp_path) == ("rake", RunOptions(strategy="random",
                                                          catalogue_first=True), None, None)


def test_read_run_json_without_run_json(tmp_path):
    with pytest.raises(ValueError) as err:
        read_run_json(tmp_path)
    assert str(err.value) == f"{tmp_path}: not a resumable run folder (no run.json)"
    (tmp_path / "run.json").mkdir()
    with pytest.raises(ValueError) as err:
        read_run_json(tmp_path)
    assert str(err.value) == f"{tmp_path}: not a resumable run folder (no run.json)"


@pytest.mark.parametrize("meta, message", [
    ('{"case": ', "not JSON (Expecting value)"),
    (b'{"case": "\xff"}', "not JSON ('utf-8' codec can't decode byte 0xff in position 10: "
                          "invalid start byte)"),
    ("[1, 2]", "a JSON object with keys case, options, world, drawn_world, check was "
               "expected, not a list"),
    ({"options": {}}, "field 'case' is missing"),
    ({"case": "hook"}, "field 'options' is missing"),
    ({"case": 3, "options": {}}, "field 'case' must be text, got 3"),
    ({"case": "hook", "options": [1]}, "field 'options' must be an object, got list"),
    ({"case": "hook", "options": {"seeds": 1, "zz": 2}},
     "field 'options.seeds' is not an option (backend, catalogue_first, consecutive, "
     "create_eval_trials, demonstrate_creation, eval_trials, gui, max_trials, phase, "
     "prior, robot, seed, strategy, video, world_seed)"),
    ({"case": "hook", "options": {"seed": -1}},
     "field 'options': option seed must be a whole number >= 0, got -1"),
    ({"case": "hook", "options": {}, "world": 3},
     "field 'world' must be a folder or null, got 3"),
    ({"case": "hook", "options": {}, "drawn_world": [1]},
     "field 'drawn_world' must be an object or null, got list"),
])
def test_read_run_json_refuses_a_bad_field_in_one_line(tmp_path, meta, message):
    if isinstance(meta, bytes):
        (tmp_path / "run.json").write_bytes(meta)
        path = tmp_path / "run.json"
    else:
        path = _run_json(tmp_path, meta)
    with pytest.raises(ValueError) as err:
        read_run_json(tmp_path)
    assert str(err.value) == f"{path}: {message}"


def test_resume_run_refuses_a_folder_without_run_json(tmp_path):
    with pytest.raises(ValueError) as err:
        resume_run(tmp_path)
    assert str(err.value) == f"{tmp_path}: not a resumable run folder (no run.json)"
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- small helpers

def test_earlier_summary_is_a_finished_runs_summary_or_nothing(tmp_path):
    assert _earlier_summary(tmp_path) is None
    (tmp_path / "summary.json").write_text("{oops", encoding="utf-8")
    assert _earlier_summary(tmp_path) is None
    (tmp_path / "summary.json").write_bytes(b'{"a": "\xff"}')
    assert _earlier_summary(tmp_path) is None
    (tmp_path / "summary.json").write_text("[1]", encoding="utf-8")
    assert _earlier_summary(tmp_path) is None
    (tmp_path / "summary.json").write_text('{"wall_time_s": {"total": "x"}}', encoding="utf-8")
    assert _earlier_summary(tmp_path) is None  # not a summary's
    (tmp_path / "summary.json").write_text('{"wall_time_s": {"total": 1.5}, "é": 1}',
                                           encoding="utf-8")
    earlier = _earlier_summary(tmp_path)
    assert earlier.wall_time_s == WallTimes(total=1.5)
    assert earlier.to_dict() == {"wall_time_s": {"total": 1.5}, "é": 1}


def test_plan_steps_of_a_plan_and_of_no_plan():
    plan = Compound("plan", ([Compound("pick_up", ("hook_a2",)),
                              Compound("pull_out", ("hook_a2", "cube1", 3)), "wait"],))
    assert plan_steps(plan) == [("pick_up", ["hook_a2"]),
                                 ("pull_out", ["hook_a2", "cube1", "3"]), ("wait", [])]
    assert plan_steps(Compound("plan", ([],))) == []
    assert plan_steps(Compound("no_plan", ("no_tool",))) is None
    assert plan_steps("plan") is None


def test_relative_names_inside_the_run_folder(tmp_path):
    run = tmp_path / "run"
    assert _relative(run, str(run / "tools" / "a.stl")) == "tools/a.stl"
    assert _relative(str(run), run / "tools" / ".." / "b.urdf") == "b.urdf"
    assert _relative(run, "/elsewhere/c.stl") == "/elsewhere/c.stl"
    assert _relative(run, Path("/elsewhere/c.stl")) == "/elsewhere/c.stl"
    assert _relative(run, None) is None
    assert _relative(run, 3) == 3


def test_relative_resolves_a_relative_run_folder(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert _relative("run", "run/tools/../a.stl") == "a.stl"
    assert _relative(Path("run"), str(tmp_path / "run" / "b.stl")) == "b.stl"


def _created(run: Path, name: str, print_: dict) -> CreatedTool:
    return CreatedTool(name=name, replaced="r", general="g", instance="i", structural=[],
                       dims={}, files={"stl": str(run / "tools" / f"{name}.stl"),
                                       "gone": None},
                       trial_outcome="failure", print=print_)


def _tried(tool: CreatedTool) -> dict:
    """A tried tool's summary entry: no ``reason`` (only a tool not tried has one)."""
    return {k: v for k, v in asdict(tool).items() if k != "reason"}


def test_creation_summary_of_a_catalogue_object_that_solved_the_task(tmp_path):
    """The summary's sums and counts: trials of the create phase only, the failed ones,
    the catalogued objects tried and the one that succeeded."""
    trials, _ = read_resume(RECORDED)
    a = _created(tmp_path, "hook_new1", {"pieces": [{"slice_wall_time_s": 0.1141},
                                                    {"slice_wall_time_s": 0.2212}, {}],
                                         "wall_time_s": 1.004})
    b = _created(tmp_path, "hook_new2", {"pieces": [{"slice_wall_time_s": 1.0}]})
    c = replace(_created(tmp_path, "hook_new3", {}), files=None, trial_outcome="no_pose",
                reason="no pose of the learned model holds for it")
    catalogue = [{"tool": "hook_a4", "trial": None, "outcome": "predicted_unreachable"},
                 {"tool": "hook_b4", "trial": 11, "outcome": "failure"},
                 {"tool": "stick_b5", "trial": 12, "outcome": "success"},
                 {"tool": "hook_b1", "trial": 13, "outcome": "success"}]
    res = CreateResult(variant="long_tube", needed=True, created=[a, b, c], success=None,
                       vs=None, trials=trials[12:16], wall_time_s=3.0,
                       exhausted="no tool left", predicted={"feasible": None},
                       catalogue=catalogue, solved_by="catalogue")
    assert [(t.phase, t.outcome) for t in res.trials] == [
        ("eval", "success"), ("create", "success"), ("eval", "success"),
        ("eval", "success")]
    got = creation_summary(res, tmp_path).to_dict()
    assert got == {
        "variant": "long_tube", "needed": True, "predicted": {"feasible": None},
        "predicted_failure_skipped": False, "trials": 1, "failed_trials": 0,
        "created_tools": [
            {**_tried(a), "files": {"stl": "tools/hook_new1.stl", "gone": None}},
            {**_tried(b), "files": {"stl": "tools/hook_new2.stl", "gone": None}},
            asdict(c)],
        "slice_wall_time_s": 1.34, "print_wall_time_s": 1.0,
        "success": None, "eval": [], "exhausted": "no tool left", "solved_by": "catalogue",
        "catalogue": catalogue, "catalogue_trials": 3, "catalogue_success": "stick_b5"}
    assert a.files["stl"] == str(tmp_path / "tools" / "hook_new1.stl")  # not changed


def test_creation_summary_counts_failed_creation_trials(tmp_path):
    trials, _ = read_resume(RECORDED)
    failed = [replace(t, phase="create") for t in trials[:4]]  # blocked, 3 failures
    success = replace(_created(tmp_path, "hook_new1", {}), eval_outcomes=["success"])
    res = CreateResult(variant="long_tube", needed=True, created=[], success=success,
                       vs=None, trials=failed + trials[4:5], wall_time_s=0.0,
                       predicted={"feasible": False}, catalogue=[
                           {"tool": "hook_a4", "trial": None, "outcome": "no_pose"}])
    got = creation_summary(res, tmp_path).to_dict()
    assert {k: got[k] for k in ("predicted_failure_skipped", "trials", "failed_trials",
                                "slice_wall_time_s", "print_wall_time_s", "success",
                                "eval", "catalogue_trials", "catalogue_success")} == {
        "predicted_failure_skipped": True, "trials": 4, "failed_trials": 4,
        "slice_wall_time_s": 0, "print_wall_time_s": 0, "success": "hook_new1",
        "eval": ["success"], "catalogue_trials": 0, "catalogue_success": None}
    res.predicted = None
    assert creation_summary(res, tmp_path).predicted_failure_skipped is False


# ---------------------------------------------------------------- the case's checks

@pytest.fixture(scope="module")
def hook_world():
    """The engine and the hook case's world as its files say."""
    manifest = get_case("hook")
    return Engine.instance(), backend_for(manifest).load_world(manifest)


def test_case_facts_of_the_hook_case(hook_world):
    manifest = hook_world[1].manifest
    assert case_facts(manifest, RunOptions()) == {
        "pose_units": {"dx": "m", "dy": "m", "roll": "rad"}, "trial_budget": 12,
        "paper_trials": 12}
    assert case_facts(manifest, RunOptions(max_trials=3))["trial_budget"] == 3


def test_catalogue_ranges_of_the_hook_world(hook_world):
    ranges = catalogue_ranges(*hook_world)
    assert list(ranges) == list(hook_world[1].catalogue)
    assert sorted(ranges) == ["hook_a1", "hook_a2", "hook_a3", "hook_a4", "hook_b1",
                              "hook_b2", "hook_b3", "hook_b4", "stick_a5", "stick_b5"]
    assert ranges["hook_a4"] == {
        "handle_length_m": (0.45, 0.7, "closed_closed", "long"),
        "handle_width_m": (0.012, 0.03, "closed_closed", "thick"),
        "hook_angle_deg": (75.0, 105.0, "closed_closed", "right"),
        "hook_length_m": (0.025, 0.05, "closed_closed", "long"),
        "hook_width_m": (0.008, 0.02, "closed_closed", "wide")}
    assert ranges["stick_a5"] == {
        "handle_length_m": (0.25, 0.45, "closed_open", "medium"),
        "handle_width_m": (0.006, 0.012, "closed_open", "thin")}
    assert all(type(v) is tuple and [type(x) for x in v] == [float, float, str, str]
               for obj in ranges.values() for v in obj.values())


def test_check_manifest_names_the_field_that_differs(hook_world):
    engine, world = hook_world
    manifest = world.manifest
    where = manifest.folder / "case.toml"
    check_manifest(engine, manifest)
    skills = manifest.skills
    cases = [
        (replace(manifest, skills=skills[:2]),
         f"{where}: field 'skill': ['pick_up', 'position_tool'] differs from the "
         f"ontology's ['pick_up', 'position_tool', 'pull'] (ontology/cases/hook.pl)"),
        (replace(manifest, goal=("out_of_tube(cube1, tube2)",)),
         f"{where}: field 'goal': ['out_of_tube(cube1,tube2)'] differs from the "
         f"ontology's ['out_of_tube(cube1,tube1)'] (ontology/cases/hook.pl)"),
        (replace(manifest, target="cube2"),
         f"{where}: field 'roles.target': cube2 differs from the ontology's cube1 "
         f"(ontology/cases/hook.pl)"),
        (replace(manifest, context="tube2"),
         f"{where}: field 'roles.context': tube2 differs from the ontology's tube1 "
         f"(ontology/cases/hook.pl)"),
        (replace(manifest, pose_term="rake_pose"),
         f"{where}: field 'pose.term': rake_pose differs from the ontology's hook_pose "
         f"(ontology/cases/hook.pl)"),
    ]
    for broken, message in cases:
        with pytest.raises(ValueError) as err:
            check_manifest(engine, broken)
        assert str(err.value) == message


def test_check_manifest_of_a_case_the_ontology_does_not_know(hook_world, tmp_path):
    engine, world = hook_world
    broken = replace(world.manifest, id="nocase", ontology="nocase", folder=tmp_path)
    with pytest.raises(ValueError) as err:
        check_manifest(engine, broken)
    assert str(err.value).startswith(
        f"{tmp_path}/case.toml: field 'id': the ontology does not know case 'nocase' "
        f"(add ontology/cases/nocase.pl): ")
    assert "\n" not in str(err.value)


def test_check_catalogue_refuses_a_number_outside_every_range(hook_world):
    engine, world = hook_world
    check_catalogue(engine, world)
    where = world.manifest.folder / "objects.toml"
    spec = world.catalogue["hook_a2"]
    long_ = world.with_spec("hook_a2", replace(spec, handle_length=0.9))
    with pytest.raises(ValueError) as err:
        check_catalogue(engine, long_)
    assert str(err.value) == (
        f"{where}: hook_a2: handle_length outside every qualitative range of the ontology "
        f"(ontology/ranges.pl); the learner could not tell its value (write "
        f"outside_ranges = true in its table if that is meant)")
    both = world.with_spec("hook_a2", replace(spec, handle_length=0.9, hook_width=0.5))
    with pytest.raises(ValueError) as err:
        check_catalogue(engine, both)
    assert str(err.value).startswith(f"{where}: hook_a2: handle_length, hook_width outside")
    meant = replace(long_, items={**long_.items, "hook_a2": replace(
        long_.items["hook_a2"], outside_ranges=True)})
    check_catalogue(engine, meant)


def test_check_catalogue_refuses_a_fact_outside_the_vocabulary(hook_world):
    engine, world = hook_world
    where = world.manifest.folder / "objects.toml"
    spec = world.catalogue["hook_a2"]

    class Odd(type(spec)):  # a hook with one fact the ontology does not know
        def catalogue_facts(self):
            return [*super().catalogue_facts(), ("colour_of", self.name, "red")]

    odd = world.with_spec("hook_a2", Odd(**{f.name: getattr(spec, f.name)
                                            for f in fields(spec) if f.init}))
    with pytest.raises(ValueError) as err:
        check_catalogue(engine, odd)
    known = str(err.value).split("(")[-1]
    assert str(err.value) == (
        f"{where}: hook_a2: the catalogue fact colour_of/2 is not in the ontology's "
        f"vocabulary of the case's tools ({known}")
    assert known.startswith("handle_length_m/2, handle_width_m/2, ")


def test_checked_world_refuses_a_world_folder_of_another_case(hook_world):
    folder = hook_world[1].manifest.folder
    with pytest.raises(ValueError) as err:
        _checked_world("rake", RunOptions(phase="use"), folder, None)
    assert str(err.value) == f"{folder}/case.toml: declares case 'hook', not 'rake'"


def test_require_display_without_a_display(monkeypatch, hook_world):
    monkeypatch.delenv("DISPLAY", raising=False)
    message = ("--gui: no display to open pybullet's GUI on (DISPLAY is not set); run "
               "without --gui, or under a display (e.g. xvfb-run)")
    for manifest in (None, hook_world[1].manifest):
        with pytest.raises(ValueError) as err:
            require_display(manifest)
        assert str(err.value) == message


def test_a_run_stopped_before_its_first_trial_leaves_no_folder(tmp_path):
    """A new run writes its ``run.json`` first, and a run stopped before it learned
    anything leaves no folder behind."""
    options = RunOptions(phase="use", video="none", world_seed=None)
    seen = []

    def stop(line: str) -> None:
        seen.append(line)
        if line.startswith("demonstration"):
            folder = Path(seen[0][len("run folder "):])
            seen.append(json.loads((folder / "run.json").read_text()))
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        run_case("hook", tmp_path, options, progress=stop, run_name="stopped")
    assert seen == [f"run folder {tmp_path / 'stopped'}",
                    "demonstration: the trainer shows the task with hook_a2 (loc 1)",
                    run_json("hook", replace(options, robot="baxter"), None, None),
                    "interrupted before the first trial: nothing was kept"]
    assert list(tmp_path.iterdir()) == []


def test_resume_run_warns_of_a_torn_line_and_releases_the_folder(tmp_path, caplog,
                                                                   hook_world):
    """The torn last line of a killed run is dropped with a warning; a resume refused
    after that (here: the world folder declares another case) leaves the folder free."""
    folder = tmp_path / "run"
    folder.mkdir()
    world = hook_world[1].manifest.folder
    _run_json(folder, {"case": "rake", "options": {"phase": "use"}, "world": str(world)},
              check=True)
    (folder / "trials.jsonl").write_text('{"trial": 1, "pha', encoding="utf-8")
    with pytest.raises(ValueError) as err:
        resume_run(folder)
    assert str(err.value) == f"{world}/case.toml: declares case 'hook', not 'rake'"
    assert [(r.name, r.levelname, r.getMessage()) for r in caplog.records] == [
        ("creative_py.learning.run", "WARNING",
         f"{folder / 'trials.jsonl'}: line 1 is not a JSON object (Unterminated string "
         f"starting at): the torn last line of a killed run; dropped")]
    assert sorted(p.name for p in folder.iterdir()) == [".lock", "run.json", "trials.jsonl"]
    with pytest.raises(ValueError, match="declares case 'hook'"):
        resume_run(folder)  # not "in use": the first resume released the folder


def test_a_created_model_the_planner_refuses_is_an_error_record(hook_world, tmp_path,
                                                                 caplog):
    engine, world = hook_world
    runner = TrialRunner(engine, world, None)
    created = CreateResult(variant="long_tube", needed=True, created=[], success=None,
                           vs=None, trials=[], wall_time_s=0.0)
    lines = []
    record = created_pddl(runner, tmp_path, created, "oops", lines.append).to_dict()
    error = "plan_models: error(type_error(action_model,o),_G0)"
    assert record == {"domain": "domain_long_tube.pddl",
                      "problem": "problem_long_tube.pddl", "status": "error", "plan": [],
                      "equals_prolog": False, "planner": "pyperplan",
                      "variant": "long_tube", "error": error}
    assert lines == []
    assert [(r.name, r.levelname, r.getMessage()) for r in caplog.records] == [
        ("creative_py.learning.pddl_files", "WARNING",
         f"{tmp_path}: the harder task's PDDL was not written: {error}")]
    assert list(tmp_path.iterdir()) == []


def test_a_created_model_with_no_plan_is_checked_against_pyperplan(hook_world, tmp_path):
    """No model: Prolog has no plan, and the PDDL files it wrote (named after the
    variant) have none either; a plan Prolog would give differs from pyperplan's."""
    engine, world = hook_world
    runner = TrialRunner(engine, world, None)
    created = CreateResult(variant="long_tube", needed=True, created=[], success=None,
                           vs=None, trials=[], wall_time_s=0.0)
    lines = []
    record = created_pddl(runner, tmp_path, created, [], lines.append).to_dict()
    no_plan = "no_plan(no_model_achieves([out_of_tube(cube1,tube1)]))"
    assert record == {"domain": "domain_long_tube.pddl",
                      "problem": "problem_long_tube.pddl", "status": "unsolvable",
                      "plan": [], "equals_prolog": True, "planner": "pyperplan",
                      "prolog_plan": None, "variant": "long_tube", "prolog": no_plan}
    assert lines == [f"plan (long_tube, created model): {no_plan}",
                     "pddl problem_long_tube.pddl: unsolvable by pyperplan  (equals "
                     "Prolog's)"]
    assert [(tmp_path / n).read_text().split("\n")[:2] for n in
            ("domain_long_tube.pddl", "problem_long_tube.pddl")] == [
        ["(define (domain creative_long_tube)", "  (:requirements :strips :typing)"],
        ["(define (problem task_long_tube)", "  (:domain creative_long_tube)"]]
    plan = Compound("plan", ([Compound("pick_up", ("hook_a2",))],))
    record = check_pddl(tmp_path, "domain_long_tube.pddl", "problem_long_tube.pddl",
                        plan, "standard", lines.append)
    assert (record.variant, record.prolog, record.equals_prolog) == (
        "standard", "plan([pick_up(hook_a2)])", False)
    assert lines[2:] == ["pddl problem_long_tube.pddl: unsolvable by pyperplan  "
                         "(DIFFERS from Prolog's)"]


def test_checked_world_refuses_a_create_phase_without_the_slicer(monkeypatch):
    monkeypatch.setenv("PATH", "")
    with pytest.raises(SliceError):
        _checked_world("hook", RunOptions(phase="create"), None, None)
    with pytest.raises(SliceError):
        _checked_world("hook", RunOptions(phase="all"), None, None)
    with pytest.raises(KeyError):  # no slicer needed: the case comes next
        _checked_world("nocase", RunOptions(phase="use"), None, None)


def test_checked_world_reads_back_a_drawn_world(hook_world, tmp_path):
    world = hook_world[1]
    order = list(reversed(world.catalogue))
    drawn = {"seed": 4, "order": order, "objects": {},
             "locations": [dict(s) for s in world.location_sets]}
    options = RunOptions(phase="use", world_seed=4)
    engine, new, back = _checked_world("hook", options, None, drawn)
    assert (engine, back, list(new.catalogue), new.variation) == (
        hook_world[0], drawn, order, "world seed 4")
    with pytest.raises(ValueError) as err:
        _checked_world("hook", options, None, {**drawn, "order": order[1:]},
                       tmp_path / "run.json")
    assert str(err.value) == (
        f"{tmp_path / 'run.json'}: field 'drawn_world' is not a drawn world of this case "
        f"(ValueError: world seed 4: the drawn catalogue {sorted(order[1:])} is not the "
        f"world's {sorted(order)})")
    with pytest.raises(ValueError) as err:
        _checked_world("hook", options, None, {"seed": 4})
    assert str(err.value) == ("run.json: field 'drawn_world' is not a drawn world of this "
                              "case (KeyError: 'order')")
    for bad in ({"order": 3}, {"order": order, "objects": 3}, {"order": order, "objects": {
            "hook_a1": {"colour": 1}}}):
        with pytest.raises(ValueError, match="^run.json: field 'drawn_world' is not"):
            _checked_world("hook", options, None, bad)


def test_checked_world_asks_for_a_display_under_gui(monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    with pytest.raises(ValueError, match="^--gui: no display"):
        _checked_world("hook", RunOptions(phase="use", gui=True), None, None)


# ---------------------------------------------------------------- the run's steps

def test_a_new_run_names_the_interrupted_run_of_its_case_and_seed(tmp_path, hook_world):
    # Issue 25: running again without --resume started a new folder and said nothing
    # of the interrupted one.
    for name, finished in (("hook-20260101-000000-s3", False),
                           ("hook-20260102-000000-s3", True),
                           ("hook-20260103-000000-s4", False)):
        (tmp_path / name).mkdir()
        (tmp_path / name / "run.json").write_text("{}")
        if finished:
            (tmp_path / name / "summary.json").write_text("{}")
    said = []
    run = _open_folder(tmp_path, "hook", RunOptions(seed=3), None, None, "new", None,
                       said.append)[0]
    run.release()
    old = tmp_path / "hook-20260101-000000-s3"
    assert said == [f"run folder {tmp_path / 'new'}",
                    f"a new run; the interrupted run {old} of this case and seed can go "
                    f"on with: creative run hook --resume {old}"]


def test_a_new_run_beside_a_live_one_does_not_call_it_interrupted(tmp_path, hook_world):
    # Issue 32: a run started beside one still going called the live run "interrupted"
    # and offered to resume it.
    live = tmp_path / "hook-20260101-000000-s3"
    live.mkdir()
    (live / "run.json").write_text("{}")
    holder = subprocess.Popen(
        [sys.executable, "-c", "import fcntl, os, sys, time; "
         f"fd = os.open({str(live / '.lock')!r}, os.O_RDWR | os.O_CREAT); "
         "fcntl.flock(fd, fcntl.LOCK_EX); print('locked', flush=True); time.sleep(60)"],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline() == "locked\n"
        assert running_pid(live) == str(holder.pid)
        said = []
        run = _open_folder(tmp_path, "hook", RunOptions(seed=3), None, None, "new", None,
                           said.append)[0]
        run.release()
        assert said == [f"run folder {tmp_path / 'new'}"]
    finally:
        holder.kill()
        holder.wait()
    assert running_pid(live) == ""  # the lock died with its process: now interrupted


def test_open_folder_of_a_resume_seals_it_and_reads_its_summary(tmp_path):
    folder = tmp_path / "hook_s0"
    shutil.copytree(RECORDED, folder)
    trials, lines = read_resume(folder)
    run = RunFolder.open(folder)
    try:
        said = []
        got = _open_folder(tmp_path, "hook", RunOptions(), None, None, None,
                           (run, trials, lines), said.append)
        earlier = round((folder / "trials.jsonl").stat().st_mtime
                        - (folder / "run.json").stat().st_mtime, 2)
        assert got == (run, trials, lines, RunSummary.read(RECORDED / "summary.json"),
                       Resumed(replayed=19, earlier_wall_time_s=max(0.0, earlier)))
        assert (run.sealed, run.trials) == (True, trials)
        assert said == [f"resuming {folder}: replaying 19 recorded trials",
                        f"run folder {folder}"]
        (folder / "summary.json").unlink()
        assert _open_folder(tmp_path, "hook", RunOptions(), None, None, None,
                            (run, [], []), said.append)[:4] == (run, [], [], None)
        assert (run.sealed, run.trials) == (False, [])
        assert said[2:] == [f"resuming {folder}: replaying 0 recorded trials",
                            f"run folder {folder}"]
    finally:
        run.release()


def test_open_folder_of_a_new_run_writes_run_json(tmp_path, hook_world):
    options = RunOptions(seed=3, world_seed=2)
    drawn = {"seed": 2}
    said = []
    run, replay, lines, before, resumed = _open_folder(tmp_path, "hook", options,
                                                       hook_world[1].manifest.folder,
                                                       drawn, "new", None, said.append)
    assert resumed is None
    try:
        assert (run.path, replay, lines, before, run.sealed) == (
            tmp_path / "new", [], [], None, False)
        assert said == [f"run folder {tmp_path / 'new'}"]
        meta = {"case": "hook", "options": options.recorded(),
                "world": str(hook_world[1].manifest.folder), "drawn_world": drawn}
        assert json.loads((run.path / "run.json").read_text()) == {
            **meta, "check": hashlib.sha256(json.dumps(meta, sort_keys=True).encode()
                                            ).hexdigest()}
    finally:
        run.release()


def test_trial_runner_of_a_run(tmp_path, hook_world):
    engine, world = hook_world
    run = RunFolder.create(tmp_path, "hook", 0, "r")
    trials, lines = read_resume(RECORDED)
    run.seal(trials)
    said = []
    try:
        runner = _trial_runner(engine, world, run, RunOptions(seed=5, video="all"),
                               said.append, trials, [n + 10 for n in lines])
        runner.progress("hello")
        clips = runner.clips
        assert (runner.engine, runner.world, runner.run_folder, runner.seed, runner.gui,
                runner.replay, runner.replay_lines, said) == (
            engine, world, run, 5, False, trials, list(range(11, 30)), ["hello"])
        assert (clips.mode, clips.run_dir, clips.spec, clips.background, clips.held,
                clips.new_recorder) == ("all", run.path, world.video, True, True,
                                        backend_for(world.manifest).recorder)
        gui = _trial_runner(engine, world, run, RunOptions(gui=True, video="none"),
                            said.append, [], [])
        assert (gui.gui, gui.clips.background, gui.clips.mode, gui.seed) == (
            True, False, "none", 0)
    finally:
        run.release()


@pytest.mark.filterwarnings("ignore:No artists with labels found")
def test_finish_writes_the_summary_plot_and_report(tmp_path, hook_world):
    """A new run's wall times are measured; a finished run resumed again (``before``)
    keeps its own."""
    engine, world = hook_world
    run = RunFolder.create(tmp_path, "hook", 0, "r")
    (run.path / "trials.jsonl").write_text("", encoding="utf-8")  # no trial: a quick plot
    try:
        runner = TrialRunner(engine, world, run)
        clips = ClipKeeper("none", run.path, world.video)
        parts = {"case": "hook", "seed": 7}
        said = []
        summary = _finish(runner, clips, parts, {"use": 1.25}, time.perf_counter() - 2.5,
                          said.append, None)
        total = summary.wall_time_s.total
        assert 2.5 <= total < 3.5 and total == round(total, 2)
        empty = {"trials": 0, "successes": 0, "outcomes": []}
        written = json.loads((run.path / "summary.json").read_text())
        assert written == {**RunSummary().to_dict(), "case": "hook", "seed": 7,
                           "wall_time_s": {"use": 1.25, "video": 0.0, "total": total},
                           "trials": {"use": empty, "create": empty, "eval": empty},
                           "videos": []}
        assert list(written) == list(RunSummary().to_dict())  # every key, in order
        assert summary == RunSummary.read(run.path)
        # Issue 25: the run ends with its headline and the report's path (before: the
        # "done in" line alone).
        assert said == [f"done in {total} s: {run.path}", f"report: {run.path}/report.html"]
        assert (run.path / "report.html").read_text().startswith("<!DOCTYPE html>")
        plot_trials([], tmp_path / "expected.png",
                    title="CREATIVE-py, hook case, seed 7")
        assert (run.path / "trials.png").read_bytes() == (
            tmp_path / "expected.png").read_bytes()
        before = RunSummary.from_dict({"wall_time_s": {"use": 1.0, "total": 9.99},
                                       "case": "x"})
        again = _finish(runner, clips, {}, {}, 0.0, said.append, before)
        assert again.wall_time_s.to_dict() == {"use": 1.0, "total": 9.99}
        assert said[2:] == [f"done in 9.99 s: {run.path}", f"report: {run.path}/report.html"]
    finally:
        run.release()
