"""The trial runner exact (:class:`creative_py.learning.trials.TrialRunner`): the replay
of a recorded run, the errors of a record that does not replay, and one trial in the
physics.

The recorded hook run ``tests/fixtures/runs/hook_s0`` (seed 0, paper strategy) is
replayed through the real engine and the hook world, without the demonstration: the
version space starts from :data:`EXAMPLE`, the example clause the engine learned from
that run's demonstration (``learn_from_demonstration``; the replay of trial 1 checks
it, its h_s and h_g must be the recorded ones). The experiments are Prolog's (the
learner's own ``_next`` and ``_trial``); the runner takes each outcome and observed
facts from the record, labels it and checks the bounds. One trial, trial 2 of that
run, is run again in the physics after trial 1 is replayed, as a resume does: its record
must be the recorded one but for the wall and decision times (seed ``0 * 1000 + 2``).
"""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path
from types import SimpleNamespace

import imageio.v2 as imageio
import numpy as np
import pytest

from creative_py.bridge import Compound, Engine
from creative_py.case import get_case
from creative_py.learning import trials
from creative_py.learning.clips import ClipKeeper
from creative_py.learning.strategies import strategy_named
from creative_py.learning.tool_use import ToolUseLearner
from creative_py.learning.trials import (PHASE_TAGS, TaskState, TrialRunner, pose_numbers,
                                         term_text)
from creative_py.records.folder import RunFolder, read_resume
from creative_py.records.trial import TrialRecord, measured, measured_fields
from creative_py.backends.pybullet import load_world, recorder
from creative_py.simulator import TrialResult
from creative_py.simulator import trial as simulator_trial
from creative_py.simulator.trial import task_facts
from creative_py.video import Captioner

pytestmark = pytest.mark.sim

RECORDED = Path(__file__).resolve().parents[2] / "fixtures" / "runs" / "hook_s0"

EXAMPLE = ("tool_pose(hook_a2,cube1,tube1) :- hook(hook_a2), hook_like(hook_a2), "
           "tool(hook_a2), handle_length(hook_a2,medium), handle_width(hook_a2,thin), "
           "hook_angle(hook_a2,right), hook_length(hook_a2,long), hook_side(hook_a2,right), "
           "hook_width(hook_a2,wide), hook_down(hook_a2), behind(hook_a2,cube1), "
           "centred_on(hook_a2,cube1), in_tube(hook_a2,tube1), in_tube(cube1,tube1)")
"""The example of the recorded run's demonstration (hook, seed 0)."""

EXP1 = ("experiment(hook_a1,handle_length(hook_a1,medium),[handle_length(hook_a1,medium)],"
        "hook_pose(0.0375,0.0,0.0),[hook_down(hook_a1),behind(hook_a1,cube1),"
        "centred_on(hook_a1,cube1),in_tube(hook_a1,tube1)],[])")

USE_LINES = [
    "#1   TUL  hook_a1        loc 1  blocked     tested handle_length(hook_a1,medium)  "
    "because position_tool: gripper lagged its target by 3.0 cm at (0.978, -0.250, -0.052) m: "
    "something is in the way  (replayed)",
    "#2   TUL  hook_a2        loc 1  failure     tested hook_down(hook_a2)  (replayed)",
    "#3   TUL  hook_a2        loc 1  failure     tested behind(hook_a2,cube1)  (replayed)",
    "#4   TUL  hook_a2        loc 1  failure     tested centred_on(hook_a2,cube1)  (replayed)",
    "#5   TUL  hook_a3        loc 1  success     tested hook_length(hook_a3,long)  (replayed)",
    "#6   TUL  hook_b2        loc 2  success     tested hook_width(hook_b2,wide)  (replayed)",
    "#7   TUL  stick_a5       loc 3  failure     tested hook(stick_a5)  (replayed)",
    "#8   TUL  hook_a2        loc 3  success     tested -  (replayed)",
    "#9   TUL  hook_a2        loc 4  success     tested -  (replayed)",
]

TRIAL2_LINE = ("#2   TUL  hook_a2        loc 1  failure     tested hook_down(hook_a2)  "
               "[cube1 centre x 1.1313 m, needs < 0.8500 m; moved 3.7 cm]")

NOT_RESUMED = "the run cannot be resumed with this code or these files"


@pytest.fixture(scope="module")
def hook():
    engine = Engine.instance()
    records, lines = read_resume(RECORDED)
    return SimpleNamespace(engine=engine, world=load_world(get_case("hook")),
                           records=records, lines=lines,
                           vs0=engine.vs_init(engine.parse(EXAMPLE)))


def _runner(hook, replay=(), run=None, clips=None, replay_lines=None, progress=None):
    return TrialRunner(hook.engine, hook.world, run, seed=0, progress=progress,
                       replay=replay, clips=clips, replay_lines=replay_lines)


def _first(hook, runner):
    """Return trial 1's task and Prolog's experiment for it."""
    task = runner.task("standard")
    return task, hook.engine.next_experiment("hook", hook.vs0, runner.task_facts(task), [])


def _edited(hook, **changes):
    return dataclasses.replace(hook.records[0], **changes)


def _as_recorded(rec, recorded):
    """Return ``rec`` without the measured fields the recorded line lacks (a field the
    physics measures that was added after the fixture was recorded: the physics run
    again measures it, the old line has nothing to compare it with)."""
    rec = dataclasses.replace(rec, **{n: None for n in measured_fields(type(rec))
                                      if getattr(recorded, n, None) is None})
    if isinstance(rec.verdict, dict) and "struck" not in (recorded.verdict or {}):
        # The robot's strikes on the bodies the scene says it must keep clear of
        # (simulator/trial.py), measured since after the fixture was recorded.
        rec = dataclasses.replace(rec, verdict={k: v for k, v in rec.verdict.items()
                                                if k != "struck"})
    return rec


def _replay_first(hook, record, phase="use", variant="standard", run=None, lines=None,
                  label=True):
    runner = _runner(hook, [record], run=run, replay_lines=lines)
    task, exp = _first(hook, runner)
    task.variant = variant
    return runner, runner.run(exp, phase, 1, hook.vs0, task, 0.0, label=label)


def test_poses_as_numbers_and_as_records(hook):
    runner = _runner(hook)
    pose = Compound("hook_pose", (0.1234567, -2, 0.5))
    assert pose_numbers(pose) == (0.1234567, -2.0, 0.5)
    assert runner._pose_dict(pose) == {"dx": 0.12346, "dy": -2.0, "roll": 0.5}
    assert runner._pose_dict(Compound("other_pose", (1.0,))) == {"pose": "other_pose(1.0)"}
    assert runner._pose_dict("hook_pose") == {"pose": "hook_pose"}
    with pytest.raises(ValueError) as err:
        pose_numbers("hook_pose")
    assert str(err.value) == "not a pose term: 'hook_pose'"
    assert term_text(pose) == "hook_pose(0.1234567,-2,0.5)"


def test_planned_experiments_exploits_and_none(hook):
    runner = _runner(hook)
    exp = hook.engine.parse(EXP1)
    assert runner._planned(exp) == ("experiment", "hook_a1", ["handle_length(hook_a1,medium)"],
                                    exp.args[2], exp.args[3])
    exploit = Compound("exploit", ("hook_a2", ["v"], Compound("hook_pose", (1.0, 2.0, 3.0)),
                                   []))
    assert runner._planned(exploit) == ("exploit", "hook_a2", [], ["v"], exploit.args[2])
    with pytest.raises(RuntimeError) as err:
        runner._planned(Compound("no_experiment", ("nothing_left",)))
    assert str(err.value) == "hook: no experiment is possible: nothing_left"


def test_the_runner_s_case_task_and_settings(hook):
    runner = _runner(hook, hook.records[:2])
    assert (runner.case, runner.manifest, runner.world) == ("hook", hook.world.manifest,
                                                            hook.world)
    assert (runner.seed, runner.gui, runner.trials, runner.replay_lines) == (0, False, [],
                                                                              [1, 2])
    assert runner.progress("x") is None
    assert _runner(hook, hook.records[:2], replay_lines=[4, 9]).replay_lines == [4, 9]
    assert PHASE_TAGS == {"use": "TUL", "create": "TC", "eval": "EVAL"}
    task = TaskState("standard", 3, (1, 3, 4))
    task.next_location()
    assert task.location == 4
    task.next_location()
    assert task.location == 1


def test_the_result_of_a_replayed_trial(hook):
    runner = _runner(hook, hook.records)
    pose = Compound("hook_pose", (0.0375, 0.0, 0.9604))
    two = hook.records[1]
    task = TaskState("standard", 1, (1, 2, 3, 4))
    assert runner._replayed(two, "hook_a2", task, pose, "use") == TrialResult(
        case="hook", object="hook_a2", variant="standard", location=1,
        pose=(0.0375, 0.0, 0.9604), outcome="failure", reason="goal not reached",
        perceived_final=None, true_final={}, sim_time_s=two.sim_time_s,
        wall_time_s=two.wall_time_s, render_time_s=0.0, steps=0, seed=0,
        max_tool_force_n=0.0, tool_load=two.tool_load,
        facts_before=tuple(tuple(f) for f in two.facts), verdict=two.verdict)
    one = dataclasses.replace(hook.records[0], sim_time_s=4, wall_time_s=1)
    got = runner._replayed(one, "hook_a1", task, Compound("hook_pose", (0.0375, 0.0, 0.0)),
                           "use")
    assert (got.max_tool_force_n, got.tool_load, got.sim_time_s, got.wall_time_s) == (
        0.0, None, 4.0, 1.0)
    assert type(got.sim_time_s) is type(got.wall_time_s) is float
    assert got.facts_before[0] == ("pose", "cube1", 1.0978333768235253, -0.2619286922781563,
                                   -0.0801174103231533, 0.0)
    five = hook.records[4]   # hook_a3 pulled the cube out: the tool was loaded
    got = runner._replayed(five, "hook_a3", task, Compound("hook_pose", (0.0375, 0.0, 0.0)),
                           "use")
    assert (got.max_tool_force_n, got.tool_load) == (3.531635, five.tool_load)


def test_a_replayed_trial_is_its_record_and_its_labels(hook):
    assert str(_first(hook, _runner(hook))[1]) == EXP1
    runner, (rec, vs) = _replay_first(hook, hook.records[0])
    assert rec is hook.records[0] and runner.trials == [rec]
    assert runner.bounds(vs) == (rec.hs, rec.hg) != runner.bounds(hook.vs0)
    assert hook.engine.vs_count(vs) == (8192, True)


@pytest.mark.parametrize("change, planned, recorded", [
    ({"tool": "hook_a2"}, "'use', 'hook_a1', 'standard', 1", "'use', 'hook_a2', 'standard', 1"),
    ({"phase": "eval"}, "'use', 'hook_a1', 'standard', 1", "'eval', 'hook_a1', 'standard', 1"),
    ({"variant": "wide"}, "'use', 'hook_a1', 'standard', 1", "'use', 'hook_a1', 'wide', 1"),
    ({"location": 2}, "'use', 'hook_a1', 'standard', 1", "'use', 'hook_a1', 'standard', 2"),
])
def test_a_record_of_another_trial_does_not_replay(hook, change, planned, recorded):
    pose = "{'dx': 0.0375, 'dy': 0.0, 'roll': 0.0}"
    with pytest.raises(ValueError) as err:
        _replay_first(hook, _edited(hook, **change))
    assert str(err.value) == (
        f"trials.jsonl: line 1: trial 1 of the run being resumed was ({recorded}, {pose}), "
        f"but the learner now plans ({planned}, {pose}): {NOT_RESUMED}")


def test_the_second_record_names_its_own_line(hook):
    second = dataclasses.replace(hook.records[1], tool="hook_a3")
    runner = _runner(hook, [hook.records[0], second], replay_lines=[4, 9])
    task, exp = _first(hook, runner)
    _, vs = runner.run(exp, "use", 1, hook.vs0, task, 0.0)
    exp2 = hook.engine.next_experiment("hook", vs, runner.task_facts(task), [])
    with pytest.raises(ValueError) as err:
        runner.run(exp2, "use", 2, vs, task, 0.0)
    assert str(err.value).startswith("trials.jsonl: line 9: trial 2 of the run being "
                                     "resumed was ('use', 'hook_a3', ")


def test_a_record_of_another_pose_names_its_line_in_the_folder(hook, tmp_path):
    run = RunFolder.create(tmp_path, "hook", 0, "run")
    record = _edited(hook, pose={"dx": 0.04, "dy": 0.0, "roll": 0.0})
    with pytest.raises(ValueError) as err:
        _replay_first(hook, record, run=run, lines=[7])
    assert str(err.value) == (
        f"{run.path}/trials.jsonl: line 7: trial 1 of the run being resumed was ('use', "
        f"'hook_a1', 'standard', 1, {{'dx': 0.04, 'dy': 0.0, 'roll': 0.0}}), but the "
        f"learner now plans ('use', 'hook_a1', 'standard', 1, {{'dx': 0.0375, 'dy': 0.0, "
        f"'roll': 0.0}}): {NOT_RESUMED}")


@pytest.mark.parametrize("change, field, bound", [
    ({"outcome": "success"}, "hs", "h_s"),
    ({"outcome": "failure", "facts": [["held", "hook_a1"]]}, "hg", "h_g"),
    ({"hg": "tool_pose(_G3,_G4,_G5) :- true"}, "hg", "h_g"),
])
def test_an_edited_record_does_not_replay(hook, change, field, bound):
    record = _edited(hook, **change)
    with pytest.raises(ValueError) as err:
        _replay_first(hook, record, lines=[3])
    assert str(err.value) == (
        f"trials.jsonl: line 3: fields 'outcome' and '{field}' disagree: replaying the "
        f"outcome {record.outcome!r} with the line's facts gives another {bound}; the "
        f"record was changed, the run cannot be resumed")


@pytest.mark.parametrize("facts, why", [
    ([[]], "not enough values to unpack (expected at least 1, got 0)"),
    ([["pose", None]], "argument 1 of pose/1: NoneType None is not a Prolog term (expected "
                       "str, int, float, PlString, Var, Compound or list)"),
    ("the cube's size in words",
     "label_trial: error(type_error(evaluable,'/'(a,0)),context(':'(system,'/'(is,2)),_G0))"),
])
def test_facts_that_do_not_label_do_not_replay(hook, facts, why):
    if isinstance(facts, str):  # the recorded facts, but for one
        facts = [["size", "cube1", "a", "b", "c"] if f[0] == "size" else f
                 for f in hook.records[0].facts]
    with pytest.raises(ValueError) as err:
        _replay_first(hook, _edited(hook, outcome="failure", facts=facts))
    assert str(err.value) == (f"trials.jsonl: line 1: field 'facts' does not label ({why}); "
                              f"the run cannot be resumed")


def test_a_blocked_trial_without_facts_is_labelled_with_the_task_s(hook):
    # A blocked motion that stopped before anything was observed: the planned example,
    # on the facts of the task as the robot sees it before acting.
    _, (rec, vs) = _replay_first(hook, _edited(hook, facts=[]))
    assert _runner(hook).bounds(vs) == (rec.hs, rec.hg) == (hook.records[0].hs,
                                                            hook.records[0].hg)


STRUCK = {"asked": True, "struck": {"link": "hand", "body": "tube1", "force_n": 524.0}}
"""A verdict whose robot struck a scene body (simulator/trial.py: verdict_data)."""


def test_a_success_in_which_the_robot_struck_is_labelled_with_the_planned_example(hook):
    # Trial 1's facts were observed where the arm stopped, away from the planned pose:
    # as a plain success they are the positive example, and h_s loses the spatial
    # literals they lack; the robot struck the scene, so the trial labels the planned
    # example (the tested pose), as a blocked one does, and h_s keeps them.
    runner = _runner(hook)
    task, exp = _first(hook, runner)
    observed = [trials.fact_term(f) for f in hook.records[0].facts]
    expected = {mode: runner.bounds(hook.engine.label_trial(
        "hook", hook.vs0, exp, observed, "pos", mode)) for mode in ("observed", "planned")}
    assert "centred_on(_G3,_G4)" in expected["planned"][0]
    assert "centred_on(_G3,_G4)" not in expected["observed"][0]
    for verdict, mode in ((STRUCK, "planned"), (None, "observed"),
                          ({"asked": True}, "observed")):
        hs, hg = expected[mode]  # the replay refuses a record whose bounds differ
        _, (rec, vs) = _replay_first(hook, _edited(hook, outcome="success", verdict=verdict,
                                                   hs=hs, hg=hg))
        assert (rec.outcome, _runner(hook).bounds(vs)) == ("success", expected[mode])


@pytest.mark.parametrize("outcome", ["unreachable", "invalid"])
def test_an_unreachable_or_invalid_trial_leaves_the_version_space(hook, outcome):
    hs, hg = _runner(hook).bounds(hook.vs0)
    _, (rec, vs) = _replay_first(hook, _edited(hook, outcome=outcome, hs=hs, hg=hg))
    assert vs is hook.vs0 and rec.outcome == outcome


def test_an_unlabelled_trial_leaves_the_version_space(hook):
    hs, hg = _runner(hook).bounds(hook.vs0)
    _, (rec, vs) = _replay_first(hook, _edited(hook, hs=hs, hg=hg), label=False)
    assert vs is hook.vs0


def test_end_replay_without_a_folder_or_clips(hook):
    runner = _runner(hook)
    runner.end_replay()
    assert (runner.run_folder, runner.clips, runner.physical) == (None, None, 0)


CAMERA_TOLERANCE = 1e-9
"""How far a perceived number may lie from its recorded value (m or rad): the camera
estimate's last bits differ between CPUs; a nanometre is far below what a trial sees."""


def close_facts(got, expected, tol=CAMERA_TOLERANCE):
    """Facts equal in their names, arity and order, their floats within tol."""
    if len(got) != len(expected):
        return False
    for g, e in zip(got, expected):
        if len(g) != len(e):
            return False
        for a, b in zip(g, e):
            if isinstance(b, float) and not isinstance(a, str):
                if abs(a - b) > tol:
                    return False
            elif a != b:
                return False
    return True


def test_close_facts_holds_names_exactly_and_floats_within_the_tolerance():
    fact = ("pose", "cube1", 1.0, -0.25)
    assert close_facts([fact], [("pose", "cube1", 1.0 + 4e-16, -0.25)])
    assert not close_facts([fact], [("pose", "cube1", 1.0 + 2e-9, -0.25)])
    assert not close_facts([fact], [("pose", "cube2", 1.0, -0.25)])
    assert not close_facts([fact], [("pose", "cube1", 1.0)])
    assert not close_facts([fact], [fact, fact])


def test_task_facts_are_observed_once_per_task(hook, monkeypatch):
    monkeypatch.setattr(simulator_trial, "_TASK_FACTS", {})
    one = task_facts(hook.world, "standard", 1)
    assert task_facts(hook.world, "standard", 1) is one
    two = task_facts(hook.world, "standard", 2)
    assert list(simulator_trial._TASK_FACTS) == [
        ("hook", str(hook.world.manifest.folder), "", tuple(sorted(hook.world.catalogue)),
         "standard", n) for n in (1, 2)]
    # What the robot sees before acting: the cube where the cameras see it, the tube and
    # the catalogue (trial 1 observed the same after the pick-up, and the tool held).
    # The camera estimate is numpy and pybullet arithmetic whose last bits follow the
    # CPU's vector instructions: its numbers are compared within a nanometre (and a
    # nano-radian), the names and the order exactly.
    assert close_facts(one[:2], [
        ("pose", "cube1", 1.0948933929128555, -0.24998376170532938, -0.07962856239708764,
         0.00011488096208900345),
        ("size", "cube1", 0.02983891645387815, 0.02994321503373029, 0.03)])
    assert one[2:] == [tuple(f) for f in hook.records[0].facts[2:]
                       if f[0] not in ("held", "tip_position", "tool_roll")]
    assert one[2:] == two[2:] and close_facts(two[:2], [
        ("pose", "cube1", 1.0992732274974026, -0.23058222949468382, -0.07948579540235559,
         -0.00022391494610629614),
        ("size", "cube1", 0.02693374023616757, 0.02689813153711404, 0.03)])
    assert _runner(hook).task_facts(TaskState("standard", 1, (1,))) == [
        Compound(f[0], tuple(f[1:])) if len(f) > 1 else f[0] for f in one]


def test_the_use_phase_replays_its_records_and_lines(hook, tmp_path):
    # A resume: the folder sealed with the use trials, the clip keeper held.
    run = RunFolder.create(tmp_path, "hook", 0, "run")
    (run.path / "trials.jsonl").write_text((RECORDED / "trials.jsonl").read_text())
    use = hook.records[:9]
    run.seal(use)
    # The interrupted run wrote its clips (a missing one would be rendered again by
    # running its trial in the physics: test_replay.py).
    for rec in use:
        clip = run.path / ClipKeeper.file_name(rec.trial, rec.phase, rec.tool)
        clip.parent.mkdir(exist_ok=True)
        clip.write_bytes(b"mp4")
    clips = ClipKeeper("key", run.path, hook.world.video, background=False,
                       new_recorder=recorder)
    clips.held = True
    lines = []
    runner = _runner(hook, use, run=run, clips=clips, progress=lines.append)
    learner, strategy = ToolUseLearner(runner), strategy_named("paper")
    task, vs, skip = runner.task("standard"), hook.vs0, []
    assert (task.variant, task.location, task.locations) == ("standard", 1, (1, 2, 3, 4))
    for i in range(1, 10):
        exp = learner._next(strategy, vs, task, skip, i)
        rec, vs = learner._trial(strategy, exp, i, vs, task, 0.0, skip)
        assert rec is use[i - 1]
        if rec.outcome == "success":
            task.next_location()
    assert lines == USE_LINES
    assert all(a is b for a, b in zip(runner.trials, use)) and len(runner.trials) == 9
    assert runner.bounds(vs) == (use[-1].hs, use[-1].hg)
    assert runner.physical == 0
    # Nothing was written while replaying; the clip keeper saw every trial.
    assert run.sealed and clips.held
    assert sorted(p.name for p in run.path.rglob("*") if p.suffix != ".mp4") == [
        ".lock", "snapshots", "trials.jsonl", "videos"]
    assert [e["file"] for e in clips.entries] == [
        ClipKeeper.file_name(r.trial, r.phase, r.tool) for r in use
        if r.trial in (1, 2, 5)] and clips.succeeded
    assert clips.seen == {
        "blocked: position_tool: gripper lagged its target by N cm at (N, N, N) m: "
        "something is in the way", "failure: goal not reached"}
    runner.end_replay()
    assert not run.sealed and not clips.held
    # The folder holds the replayed trials again, as they were recorded.
    assert (run.path / "trials.jsonl").read_text().splitlines() == (
        (RECORDED / "trials.jsonl").read_text().splitlines()[:9])


def test_an_unlabelled_trial_in_the_physics_without_a_folder_or_clips(hook):
    # Trial 1 of the recorded run again (its seed, 0 * 1000 + 1), as an evaluation
    # trial: recorded as it was, the version space left as it was.
    lines = []
    runner = _runner(hook, progress=lines.append)
    task, exp = _first(hook, runner)
    rec, vs = runner.run(exp, "eval", 1, hook.vs0, task, 0.0, label=False)
    one = hook.records[0]
    hs, hg = runner.bounds(hook.vs0)
    assert vs is hook.vs0 and runner.trials == [rec] and runner.physical == 1
    # The gripper met the riser and the tube's mouth before the guard stopped it: the
    # physics now also says which robot links struck them (the record of 2026-12-02
    # predates it); the outcome and its reason stay the guard's.
    struck = rec.verdict["struck"]["measures"]["struck"]
    assert {s["body"] for s in struck} <= {"riser1", "tube1"} and struck
    # The strike's force is the contact solver's (its last bits the CPU's): said, not pinned.
    force = f"{rec.verdict['struck']['value']:.0f}"
    assert all(s["force_n"] > 0 for s in struck)
    # The limit names the bodies the scene says the robot must keep clear of; the
    # strike's words count the other contacts as its short line does (more_strikes).
    assert rec.verdict["struck"]["threshold_name"] == "robot links strike none of tube1, riser1"
    head, _, tail = rec.verdict["struck"]["text"].partition(" at (")
    assert head == (f"robot strike force {rec.verdict['struck']['value']:.1f} N (needs <= "
                    "0.0 N, robot links strike none of tube1, riser1); the robot's "
                    "right_gripper_base_link struck tube1")
    assert tail.endswith(f") m with {force} N (3 more link-body contacts): the arm, not the "
                         "tool, met the scene")
    assert dataclasses.replace(_as_recorded(rec, one), decision_time_s=0.0,
                               wall_time_s=0.0) == (
        dataclasses.replace(one, phase="eval", hs=hs, hg=hg, vs_count=None,
                            vs_count_exact=None, decision_time_s=0.0, wall_time_s=0.0))
    assert [line.replace(f"with {force} N", "with F N") for line in lines] == [
        "#1   EVAL hook_a1        loc 1  blocked     tested handle_length(hook_a1,medium)  "
        "because position_tool: gripper lagged its target by 3.0 cm at (0.978, -0.250, "
        "-0.052) m: something is in the way  [stopped: gripper lag 0.0301 m, needs <= "
        "0.0300 m; touching hook_a1 against cube1, hook_a1 against tube1, robot against "
        "riser1, robot against tube1; struck: right_gripper_base_link against tube1 with "
        "F N (3 more link-body contacts); cube1 centre x 1.0985 m, needs < 0.8500 m; moved "
        "1.1 cm]"]


def test_a_trial_in_the_physics_after_a_replayed_one(hook, tmp_path):
    # A resume of trial 1: trial 2 runs in the physics, is labelled, recorded, filmed.
    run = RunFolder.create(tmp_path, "hook", 0, "run")
    one, two = hook.records[:2]
    (run.path / "trials.jsonl").write_text(one.to_json() + "\n")
    (run.path / "videos").mkdir()
    (run.path / "videos" / "001-use-hook_a1.mp4").write_bytes(b"mp4")  # written before
    run.seal([one])
    camera = dataclasses.replace(hook.world.video.camera, width=320, height=60)
    clips = ClipKeeper("key", run.path, dataclasses.replace(hook.world.video, camera=camera),
                       background=False, new_recorder=recorder)
    clips.held = True
    lines = []
    runner = _runner(hook, [one], run=run, clips=clips, replay_lines=[1],
                     progress=lines.append)
    task, exp = _first(hook, runner)
    rec1, vs = runner.run(exp, "use", 1, hook.vs0, task, 0.0)
    exp2 = hook.engine.next_experiment("hook", vs, runner.task_facts(task), [])
    rec2, vs = runner.run(exp2, "use", 2, vs, task, 100.0)
    assert rec1 is one and runner.trials == [one, rec2] and runner.physical == 1
    assert lines == [USE_LINES[0], TRIAL2_LINE]
    assert 100.0 <= rec2.decision_time_s < 101.0 and 0 < rec2.wall_time_s < 60
    assert (rec2.decision_time_s, rec2.wall_time_s) == (round(rec2.decision_time_s, 4),
                                                        round(rec2.wall_time_s, 3))
    assert type(rec2.decision_time_s) is type(rec2.wall_time_s) is float
    assert {type(a) for f in rec2.facts for a in f} == {str, float}
    # The physics ran the recorded trial again: the same record, its camera facts within
    # the camera's tolerance (the CPU's last bits), its load with the fields a load has
    # gained since the recording (the contacts with other bodies than the target, the
    # averaging window) and the recorded ones equal.
    assert close_facts(rec2.facts, [tuple(f) for f in two.facts])
    assert {k: v for k, v in rec2.tool_load.items() if k in two.tool_load} == two.tool_load
    assert (rec2.tool_load["other_bodies"], rec2.tool_load["window_s"]) == ([], 0.1)
    assert dataclasses.replace(_as_recorded(rec2, two), decision_time_s=0.0, wall_time_s=0.0,
                               facts=two.facts, tool_load=two.tool_load) == (
        dataclasses.replace(two, decision_time_s=0.0, wall_time_s=0.0))
    assert _as_recorded(rec2, two).to_dict().keys() == two.to_dict().keys()
    assert runner.bounds(vs) == (two.hs, two.hg)
    assert (run.path / "trials.jsonl").read_text() == one.to_json() + "\n" + rec2.to_json() + "\n"
    assert sorted(p.name for p in (run.path / "snapshots" / "use-002").iterdir()) == [
        "00_after_pick_up_top.png", "01_after_position_tool_top.png",
        "02_after_pull_top.png"]
    assert not run.sealed and not clips.held
    replayed, *entries = clips.finish()
    assert replayed["file"] == "videos/001-use-hook_a1.mp4"  # the earlier run's file
    size = (run.path / "videos" / "002-use-hook_a2.mp4").stat().st_size
    assert entries == [{
        "file": "videos/002-use-hook_a2.mp4", "phase": "use", "trial": 2, "tool": "hook_a2",
        "tested": ["hook_down(hook_a2)"], "outcome": "failure", "reason": "goal not reached",
        "verdict": "cube1 centre x 1.1313 m, needs < 0.8500 m; moved 3.7 cm",
        "why": "failure:failure: goal not reached", "frames": 42,
        "duration_s": 8.4, "bytes": size}]
    assert json.loads((run.path / "videos" / "clips.jsonl").read_text()) == {
        k: v for k, v in entries[0].items() if k != "bytes"}
    # The caption above the picture, the first frame's simulated time at its right.
    with imageio.get_reader(str(run.path / entries[0]["file"])) as reader:
        first = np.asarray(reader.get_data(0)).astype(int).mean(axis=2)
    draw = Captioner(320, 60, ["#2 TUL  hook_a2  loc 1", "tested hook_down(hook_a2)",
                                "failure: goal not reached", "cube1 centre x 1.1313 m, "
                                "needs < 0.8500 m", "moved 3.7 cm"])
    band = draw(np.zeros((60, 320, 3), np.uint8), "t = 0.0 s")[:draw.band]
    assert first.shape == (60 + draw.band, 320)
    assert int((np.abs(band.astype(int).mean(axis=2) - first[:draw.band]) > 100).sum()) == 0



@dataclasses.dataclass(kw_only=True)
class _WithLift(trials.TrialRecord):
    """The trial record with one more field the physics measures, added as a maintainer
    would: one typed line."""

    lift_m: "float | None" = dataclasses.field(default=None, metadata=measured())


def test_a_measured_field_reaches_the_file_and_comes_back_on_a_replay(hook, tmp_path,
                                                                      monkeypatch):
    """A field marked measured goes from the trial loop (TrialResult.measures) to the
    record and the line of trials.jsonl, and a replay gives it back, with no line of the
    learning loop naming it."""
    real = simulator_trial.run_trial

    def measuring(*args, **kwargs):         # the code that measures it
        return dataclasses.replace(real(*args, **kwargs), measures={"lift_m": 0.0125})

    monkeypatch.setattr(simulator_trial, "run_trial", measuring)
    monkeypatch.setattr(trials, "TrialRecord", _WithLift)
    run = RunFolder.create(tmp_path, "hook", 0, "run")
    runner = _runner(hook, run=run)
    task, exp = _first(hook, runner)
    rec, _vs = runner.run(exp, "eval", 1, hook.vs0, task, 0.0, label=False)
    assert isinstance(rec, _WithLift) and rec.lift_m == 0.0125
    line = json.loads((run.path / "trials.jsonl").read_text().splitlines()[0])
    assert line["lift_m"] == 0.0125
    back = _WithLift.from_dict(line)
    got = runner._replayed(back, "hook_a1", task, exp.args[3], "eval")
    assert got.measures == {"lift_m": 0.0125}
    # A measure the record has no field for is refused, naming it.
    monkeypatch.setattr(trials, "TrialRecord", TrialRecord)
    with pytest.raises(TypeError, match="lift_m"):
        _runner(hook).run(exp, "eval", 1, hook.vs0, task, 0.0, label=False)
