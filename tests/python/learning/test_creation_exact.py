"""Tool creation (Algorithm 2, :mod:`creative_py.learning.creation`), exact, without
trial physics.

Recorded real runs of the hook case (seed 0, paper strategy; ``tests/fixtures/runs/``,
see its README) share their tool-use learning: the version space it ends with is kept as
text (``hook_s0_vs.txt``, checked here against a replay of the learning). A
:class:`ToolCreator` is driven on it with a :class:`TrialRunner` that replays each
run's records through the real engine (Prolog plans every trial, sizes every tool and
names the next candidate; a replayed trial must be the one planned, and its h_s and h_g
those recorded), so that :meth:`ToolCreator.create` gives the run's own creation,
checked whole: the :class:`CreateResult`, its ``summary.json`` entry and the progress
lines. The runs cover making a tool at once (``hook_s0``), a catalogued object first
(``hook_cf_s0``), and then a tool as a demonstration (``hook_cfd_s0``), a tool too weak
for the load the physics measured, thickened (``hook_sf15_s0``) or rejected until no
literal is left (``hook_sf1000_s0``), the learned tool solving the task it is asked
(``hook_std_s0``) or failing it first where the geometry cannot tell (``wedge_s0``,
then a catalogued object in ``wedge_cf_s0``). The resumed ``hook_s0`` (the
``resumed_hook`` fixture) checks what a run folder adds: the tool's files, mass, print
and strength manifest.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.case import get_case
from creative_py.learning.creation import CreateResult, ToolCreator, exhausted_words
from creative_py.learning.phases import creation_summary
from creative_py.records.summary import print_summary
from creative_py.learning.trials import TrialRunner
from creative_py.records.folder import read_resume
from creative_py.backends.pybullet import load_world

pytestmark = pytest.mark.sim

RUNS = Path(__file__).resolve().parents[2] / "fixtures" / "runs"
LEARNED = 13
"""Trials before creation in every recorded run: 9 of tool-use learning, 4 evaluations."""

PREDICTED = ("TC predicted: hook_a2: behind(hook_a2,cube1) cannot hold within the reach "
             "of hook_a2 in the long_tube task: dx_reach = -0.011 m (deepest prong centre "
             "the held tool reaches, minus the cube centre); the trial would fail, so none "
             "is run")
MAKE_1 = "manufacturing tool 1: meshing, splitting to the build volume and slicing its pieces"
MAKE_2 = "manufacturing tool 2: meshing, splitting to the build volume and slicing its pieces"
CREATED_1 = ("created hook_new1: handle_length(A,medium) -> any_length(A) -> "
             "handle_length(A,long); handle_length 600.0 mm, handle_width 9.0 mm, "
             "hook_length 30.0 mm, hook_width 12.0 mm, hook_angle_deg 90, hook_side right")
TRY_A4 = ("TC catalogue: trying hook_a4, catalogued object admitted by any_length(_G0) "
          "(the generalised handle_length(_G0,medium)): handle_length(hook_a4,long)")


def _tc(n, tool, before=LEARNED):
    """The line of creation trial ``n``, numbered in the run (after ``before`` trials)."""
    return f"#{before + n:<3} TC   {tool:<14} loc 1  success     tested -  (replayed)"


def _evals(tool, start=2, after=1, before=LEARNED):
    """The lines of the created tool's 5 evaluation trials, after ``after`` creation
    trials."""
    locs = [(start - 1 + i) % 4 + 1 for i in range(5)]
    return [f"#{before + after + i:<3} EVAL {tool:<14} loc {loc}  success     tested -  "
            "(replayed)" for i, loc in enumerate(locs, 1)]


@pytest.fixture(scope="module")
def engine():
    return Engine.instance()


@pytest.fixture(scope="module")
def world():
    return load_world(get_case("hook"))


def _vs(engine, case):
    return engine.parse((RUNS / f"{case}_s0_vs.txt").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def vs(engine):
    return _vs(engine, "hook")


def _runner(engine, world, name, learned=LEARNED, run=None):
    """A runner replaying run ``name``, its ``learned`` trials before creation done,
    writing into ``run`` (a RunFolder or None): (runner, lines, records)."""
    records, _ = read_resume(RUNS / name)
    lines: list[str] = []
    runner = TrialRunner(engine, world, run, replay=records, progress=lines.append)
    runner.trials = list(records[:learned])
    # What creation asks of each trial (a replay reads neither the decision time nor,
    # for these, a label; the physics would: decision time 0, no label).
    runner.calls = []
    replay = runner.run

    def run(exp, phase, phase_trial, vs, task, decision, label=True):
        runner.calls.append((phase, phase_trial, decision, label))
        return replay(exp, phase, phase_trial, vs, task, decision, label=label)

    runner.run = run
    return runner, lines, records


def _recorded(name):
    """The run's ``create`` entry as a runner without a run folder makes it: no files,
    mass or print figures, and no model (the run writes that)."""
    entry = json.loads((RUNS / name / "summary.json").read_text(encoding="utf-8"))["create"]
    entry.pop("model", None)
    for tool in entry["created_tools"]:
        tool.update(files={}, mass_kg=None, print={})
    entry.update(slice_wall_time_s=0, print_wall_time_s=0)
    return entry


def _check(res, runner, vs, records, name, tmp_path, learned=LEARNED):
    assert creation_summary(res, tmp_path).to_dict() == _recorded(name)
    assert res.vs is vs
    assert res.trials == records[learned:]
    assert runner.trials == records
    assert runner.calls == [(r.phase, r.phase_trial, 0.0, False) for r in records[learned:]]
    assert all(type(c[2]) is float and c[3] is False for c in runner.calls)
    assert 0 < res.wall_time_s < 120


@pytest.mark.slow  # a replay of the tool-use learning (2 to 3 CPU s a case)
@pytest.mark.parametrize("case, learned, before, others", [
    ("hook", 9, LEARNED, ("hook_cf_s0", "hook_cfd_s0", "hook_sf15_s0", "hook_sf1000_s0",
                          "hook_std_s0")),
    ("wedge", 8, 12, ("wedge_cf_s0",))])
def test_the_stored_version_space_is_the_learned_one(engine, case, learned, before, others):
    """``<case>_s0_vs.txt`` is what replaying the run's tool-use learning gives, and the
    other runs of the case learned as it did."""
    from creative_py.learning.tool_use import LearningOptions, ToolUseLearner

    world = load_world(get_case(case))
    records, _ = read_resume(RUNS / f"{case}_s0")
    runner = TrialRunner(engine, world, None, replay=records[:learned])
    use = ToolUseLearner(runner, LearningOptions(max_trials=world.manifest.trial_budget,
                                                 consecutive=2, strategy="paper")).learn()
    assert use.vs == _vs(engine, case)
    assert len(runner.trials) == learned
    for name in others:
        other, _ = read_resume(RUNS / name)
        assert [(r.tool, r.pose, r.outcome, r.hs, r.hg, r.facts) for r in other[:before]] \
            == [(r.tool, r.pose, r.outcome, r.hs, r.hg, r.facts) for r in records[:before]]


def test_a_tool_made_at_once(engine, world, vs, tmp_path):
    runner, lines, records = _runner(engine, world, "hook_s0")
    res = ToolCreator(runner, eval_trials=5).create(vs, "long_tube")
    _check(res, runner, vs, records, "hook_s0", tmp_path)
    assert (res.variant, res.needed, res.solved_by, res.exhausted) == (
        "long_tube", True, "created", None)
    assert res.success is res.created[0]
    assert (str(res.replaced), str(res.instance)) == (
        "handle_length(_G0,medium)", "handle_length(_G0,long)")
    assert lines == [PREDICTED, MAKE_1, CREATED_1, _tc(1, "hook_new1"),
                     "hook_new1: strength pass (cantilever, 0.91 N, 4.10 MPa, "
                     "safety factor 12.21)", *_evals("hook_new1")]
    assert [r.trial for r in runner.trials] == list(range(1, 20))
    assert str(runner.world.catalogue["hook_new1"].name) == "hook_new1"


def test_no_tool_is_made_when_none_may_be(engine, world, vs, tmp_path):
    runner, lines, _ = _runner(engine, world, "hook_s0")
    res = ToolCreator(runner, max_tools=0).create(vs, "long_tube")
    predicted = _recorded("hook_s0")["predicted"]
    assert res == CreateResult("long_tube", True, [], None, vs, [], res.wall_time_s,
                               predicted=predicted)
    assert 0 < res.wall_time_s < 60
    assert lines == [PREDICTED]
    assert runner.calls == []


def test_a_catalogued_object_first(engine, world, vs, tmp_path):
    runner, lines, records = _runner(engine, world, "hook_cf_s0")
    res = ToolCreator(runner, catalogue_first=True).create(vs, "long_tube")
    _check(res, runner, vs, records, "hook_cf_s0", tmp_path)
    assert (res.created, res.success, res.exhausted) == ([], None, None)
    assert (str(res.replaced), str(res.instance)) == (
        "handle_length(_G0,medium)", "handle_length(hook_a4,long)")
    assert lines == [PREDICTED, TRY_A4, _tc(1, "hook_a4"),
                     "TC catalogue: hook_a4 solved the long_tube task; no tool is made"]


def test_a_catalogued_object_first_then_a_tool_as_a_demonstration(engine, world, vs,
                                                                   tmp_path):
    runner, lines, records = _runner(engine, world, "hook_cfd_s0")
    res = ToolCreator(runner, catalogue_first=True, demonstrate=True).create(vs, "long_tube")
    _check(res, runner, vs, records, "hook_cfd_s0", tmp_path)
    assert res.success is res.created[0]
    assert (str(res.replaced), str(res.instance)) == (
        "handle_length(_G0,medium)", "handle_length(_G0,long)")
    assert lines == [PREDICTED, TRY_A4, _tc(1, "hook_a4"),
                     "TC catalogue: hook_a4 solved the long_tube task; a tool is created "
                     "as a demonstration", MAKE_1, CREATED_1, _tc(2, "hook_new1"),
                     "hook_new1: strength pass (cantilever, 0.90 N, 4.08 MPa, "
                     "safety factor 12.26)", *_evals("hook_new1", after=2)]


def test_a_tool_too_weak_is_thickened(engine, world, vs, tmp_path):
    runner, lines, records = _runner(engine, world, "hook_sf15_s0")
    res = ToolCreator(runner, safety_factor=15.0).create(vs, "long_tube")
    _check(res, runner, vs, records, "hook_sf15_s0", tmp_path)
    assert res.success is res.created[1]
    assert lines == [PREDICTED, MAKE_1, CREATED_1, _tc(1, "hook_new1"), MAKE_2,
                     "hook_new1: safety factor 12.21 < 15 under 0.91 N; thickened into "
                     "hook_new2 {'handle_length': 0.6, 'handle_width': 0.0109, "
                     "'hook_length': 0.03, 'hook_width': 0.012, 'hook_angle_deg': 90, "
                     "'hook_side': 'right'}", _tc(2, "hook_new2"),
                     "hook_new2: strength pass (cantilever, 0.87 N, 2.22 MPa, "
                     "safety factor 22.51)", *_evals("hook_new2", after=2)]


def test_a_tool_that_cannot_be_made_strong_enough_is_rejected(engine, world, vs, tmp_path):
    runner, lines, records = _runner(engine, world, "hook_sf1000_s0")
    res = ToolCreator(runner, safety_factor=1000.0).create(vs, "long_tube")
    _check(res, runner, vs, records, "hook_sf1000_s0", tmp_path)
    exhausted = _recorded("hook_sf1000_s0")["exhausted"]
    # Prolog text, the engine's variables lettered: never the Python repr of the terms.
    assert exhausted.startswith("[handle_length(A,long)-tried,handle_length(B,short)-"
                                "infeasible([handle_length(B,short),tube_length_m(tube1,")
    # For people: in words, the candidates with one reason together, lengths in mm.
    words = ("handle_length(A, long) was made before; handle_length(A, short) cannot be "
             "sized, as handle_length(A, short) and tube_length_m(tube1, 450 mm) cannot "
             "hold together; stick(A), handle_width(A, thick), hook_angle(A, acute) and "
             "hook_angle(A, obtuse) cannot be sized, as handle_length(A, medium) and "
             "tube_length_m(tube1, 450 mm) cannot hold together")
    assert (res.exhausted, res.exhausted_words) == (exhausted, words)
    assert (res.success, res.replaced, res.instance, res.solved_by) == (None, None, None, None)
    assert lines == [PREDICTED, MAKE_1, CREATED_1, _tc(1, "hook_new1"),
                     "hook_new1: rejected: its handle would need to be at least 39.1 mm "
                     "wide for a safety factor of 1000 under 0.91 N at 549 mm, and the size "
                     "model cannot give that: min_handle_width_m(0.0391) cannot hold "
                     "together", f"no literal left to generalise: {words}"]


def test_no_literal_left_in_words_and_millimetres(engine):
    """CleanTable's exhausted answer (RoboToolBench world 0, seed 0): the floats the
    perception gave (metres, 16 digits) read as millimetres, each conflict once."""
    skipped = engine.parse(
        "[plate_width(_G0,wide)-infeasible([wing_spread(_G0,none),size(cubes,"
        "0.29331216096878054,0.4013691383600235,0.03)]),plate_width(_G1,narrow)-"
        "infeasible([wing_spread(_G1,none),size(cubes,0.29331216096878054,"
        "0.4013691383600235,0.03)]),wing_spread(_G2,flared)-tried,"
        "wing_spread(_G3,none)-tried,pole_length(_G4,long)-odd(0.5)]")
    assert exhausted_words(skipped) == (
        "plate_width(A, wide) and plate_width(A, narrow) cannot be sized, as "
        "wing_spread(A, none) and size(cubes, 293.3 mm, 401.4 mm, 30 mm) cannot hold "
        "together; wing_spread(A, flared) and wing_spread(A, none) were made before; "
        "pole_length(A, long) skipped: odd(500 mm)")
    assert exhausted_words(engine.parse("[hook(_G0)-infeasible([])]")) == (
        "hook(A) cannot be sized in this task")
    assert exhausted_words([]) == "no candidate"


class NoPoseFor:
    """The real engine, but ``plan_use`` with the tool fixed to ``tool`` answers as
    Prolog did for DislodgeCube's first created tool (a stick sized 18 mm wide, whose
    learned pose could not hold: ``no_experiment(infeasible_pose(...))``)."""

    def __init__(self, engine, tool, after=0):
        self.engine, self.tool, self.after = engine, tool, after  # real answers first

    def __getattr__(self, name):
        return getattr(self.engine, name)

    def plan_use(self, case, vs, facts, options=()):
        if [str(o) for o in options] == [f"tool({self.tool})"]:
            self.after -= 1
        if [str(o) for o in options] == [f"tool({self.tool})"] and self.after < 0:
            return self.engine.parse(f"no_experiment(infeasible_pose([behind({self.tool},"
                                     f"cube1),in_tube({self.tool},tube1)]))")
        return self.engine.plan_use(case, vs, facts, options)


NO_POSE = ("no pose of the learned model holds for it: behind({0}, cube1) and "
           "in_tube({0}, tube1) cannot hold together")
LEFT = ("handle_length(A, long) was made before; handle_length(A, short) cannot be sized, "
        "as handle_length(A, short) and tube_length_m(tube1, 450 mm) cannot hold together; "
        "stick(A), handle_width(A, thick), hook_angle(A, acute) and hook_angle(A, obtuse) "
        "cannot be sized, as handle_length(A, medium) and tube_length_m(tube1, 450 mm) "
        "cannot hold together")


def test_a_created_tool_without_a_pose_is_not_tried_and_the_next_is_made(engine, world, vs):
    """No traceback (it was RuntimeError 'no pose for the created tool'): the tool is
    recorded ``no_pose`` with why, no trial is run, and creation goes on to the next
    candidate (here none is left)."""
    runner, lines, _ = _runner(engine, world, "hook_s0")
    creator = ToolCreator(runner)
    creator.engine = NoPoseFor(engine, "hook_new1")
    res = creator.create(vs, "long_tube")
    why = NO_POSE.format("hook_new1")
    assert [(c.name, c.trial_outcome, c.reason) for c in res.created] == [
        ("hook_new1", "no_pose", why)]
    assert (res.success, res.solved_by, res.trials, runner.calls) == (None, None, [], [])
    assert res.exhausted_words == LEFT
    assert lines == [PREDICTED, MAKE_1, CREATED_1, f"hook_new1: not tried: {why}",
                     f"no literal left to generalise: {LEFT}"]
    tool = creation_summary(res, Path(".")).to_dict()["created_tools"][0]
    assert (tool["trial_outcome"], tool["reason"]) == ("no_pose", why)


def test_an_evaluation_trial_without_a_pose_is_no_plan(engine, world, vs):
    runner, lines, records = _runner(engine, world, "hook_s0")
    creator = ToolCreator(runner, eval_trials=5)
    creator.engine = NoPoseFor(engine, "hook_new1", after=1)  # its creation trial runs
    res = creator.create(vs, "long_tube")
    assert (res.success.name, res.success.eval_outcomes) == ("hook_new1", ["no_plan"] * 5)
    assert runner.calls == [("create", 1, 0.0, False)]


def test_a_thickened_tool_without_a_pose_is_rejected(engine, world, vs):
    runner, lines, records = _runner(engine, world, "hook_sf15_s0")
    creator = ToolCreator(runner, safety_factor=15.0)
    creator.engine = NoPoseFor(engine, "hook_new2")
    res = creator.create(vs, "long_tube")
    why = NO_POSE.format("hook_new2")
    assert [(c.name, c.trial_outcome, c.reason) for c in res.created] == [
        ("hook_new1", "success", ""), ("hook_new2", "no_pose", why)]
    assert res.created[1].strength["verdict"] == "rejected"
    assert (res.success, res.trials) == (None, records[LEARNED:LEARNED + 1])
    assert lines[-2:] == [f"hook_new2: rejected: hook_new2 was not tried: {why}",
                          f"no literal left to generalise: {LEFT}"]


def test_the_kind_of_a_new_tool_is_its_class_literal(engine, world):
    from creative_py.kinds import spec_classes

    creator = ToolCreator(TrialRunner(engine, world, None))
    t = engine.parse("T")
    assert creator._kind([Compound("tool", (t,)), Compound("hook_like", (t,)),
                          Compound("stick", (t,)), Compound("hook", (t,))]) == "stick"
    assert creator._kind([Compound("handle_length", (t, "long")), "hook",
                          Compound("hook", (t,))]) == "hook"
    # No class literal (any tool of the hierarchy worked): the demonstrated tool's kind.
    demo = world.item(world.manifest.demonstration.tool).spec.kind
    assert demo in spec_classes()
    assert creator._kind([Compound("tool", (t,)),
                          Compound("handle_length", (t, "long"))]) == demo


def test_the_pose_model_cannot_tell_a_force():
    """The big door needs a force, not a reach: the geometry cannot tell."""
    engine = Engine.instance()
    creator = ToolCreator(TrialRunner(engine, load_world(get_case("wedge")), None))
    use = Compound("exploit", ("wedge_a2", [], "none", [
        engine.parse(r) for r in ("near(wedge_a2,door1)", "far_from_hinge(wedge_a2,door1)",
                                  "tip_towards(wedge_a2,door1)")]))
    assert creator.predict(use, creator.runner.task("big_door")) == {
        "tool": "wedge_a2", "variant": "big_door", "location": 1, "feasible": None,
        "why": "the case's geometry sets no reach: the pose model cannot tell whether "
               "wedge_a2 works in the big_door task; the physics decides"}


def test_print_summary_keeps_the_figures_a_summary_shows():
    piece = {"name": "t_part1", "role": "part", "stl": "t_part1.stl", "gcode": "t_part1.gcode",
             "bounding_box_mm": [1.0, 2.0, 3.0], "volume_mm3": 4.5, "print_time_s": 6.0,
             "print_time": "6s", "filament_mm": 7.5, "filament_g": 0.5,
             "slice_wall_time_s": 0.25}
    entry = {"pieces": [{**piece, "layers": 12, "settings": {"layer_mm": 0.2}},
                        {"name": "t_pin1", "role": "pin", "volume_mm3": 1.0}],
             "joint": "square_dowel_pin", "clearance_mm": 0.2,
             "build_volume_mm": [250.0, 210.0, 210.0], "union_volume_error_pct": -0.19,
             "union_mismatch_pct": 0.19, "print_time_s": 14.0, "filament_mm": 21.5,
             "filament_g": 65.1, "sliced": True, "wall_time_s": 0.96,
             "printable": True, "problems": [], "pieces_dir": "pieces"}
    assert print_summary(entry) == {
        "pieces": [piece, {"name": "t_pin1", "role": "pin", "volume_mm3": 1.0}],
        "joint": "square_dowel_pin", "clearance_mm": 0.2,
        "build_volume_mm": [250.0, 210.0, 210.0], "union_volume_error_pct": -0.19,
        "union_mismatch_pct": 0.19, "print_time_s": 14.0, "filament_mm": 21.5,
        "filament_g": 65.1, "sliced": True, "wall_time_s": 0.96}
    assert list(print_summary(entry)) == [
        "pieces", "joint", "clearance_mm", "build_volume_mm", "union_volume_error_pct",
        "union_mismatch_pct", "print_time_s", "filament_mm", "filament_g", "sliced",
        "wall_time_s"]
    assert list(print_summary(entry)["pieces"][0]) == list(piece)
    assert print_summary({"sliced": False}) == {"pieces": [], "sliced": False}
    assert print_summary({}) == {"pieces": []}


WALL_TIMES = ("slice_wall_time_s", "print_wall_time_s")
"""The wall-time figures of ``summary.json``'s ``create`` (each piece's
``slice_wall_time_s`` and each print's ``wall_time_s`` too): they differ run to run."""


def _without_run_dependent(entry):
    """Return ``entry`` without its wall times, and them; without its slicer's print
    time estimates (PrusaSlicer's differ by a second or so from one slicing of the same
    piece to the next), and them."""
    entry = json.loads(json.dumps(entry))
    times = [entry.pop(k) for k in WALL_TIMES]
    estimates = []
    for tool in entry["created_tools"]:
        times.append(tool["print"].pop("wall_time_s"))
        estimates.append(tool["print"].pop("print_time_s"))
        for piece in tool["print"]["pieces"]:
            times.append(piece.pop("slice_wall_time_s"))
            estimates.append((piece.pop("print_time_s"), piece.pop("print_time")))
    return entry, times, estimates


def test_the_resumed_hook_run_creates_its_tool_again(request):
    """The resumed hook run sizes, writes, slices and tries hook_new1 again: its
    ``create`` entry is the recorded one but for wall times, and the lines are exact."""
    # Asked for in the call, so that the resume's time is the test's own (mutmut runs a
    # mutant's tests fastest first).
    resumed_hook = request.getfixturevalue("resumed_hook")
    path = resumed_hook.path
    now = json.loads((path / "summary.json").read_text(encoding="utf-8"))["create"]
    then = json.loads((resumed_hook.recorded / "summary.json").read_text(encoding="utf-8"))
    now, times, estimates = _without_run_dependent(now)
    expected, _, recorded = _without_run_dependent(then["create"])
    assert now == expected
    assert len(times) == 6 and all(isinstance(t, float) and 0 < t < 60 for t in times)
    assert estimates[0] == pytest.approx(recorded[0], abs=10)
    for (secs, text), (secs0, _) in zip(estimates[1:], recorded[1:]):
        assert secs == pytest.approx(secs0, abs=5)
        h, m, sec = (int(x) for x in re.fullmatch(r"(?:(\d+)h )?(\d+)m (\d+)s", text)
                     .groups(default="0"))
        assert 3600 * h + 60 * m + sec == secs
    assert len(estimates) == 4
    tool = now["created_tools"][0]
    assert tool["files"] == {k: f"tools/hook_new1/hook_new1.{ext}" for k, ext in (
        ("urdf", "urdf"), ("sdf", "sdf"), ("scad", "scad"), ("stl", "stl"), ("png", "png"),
        ("manifest", "json"))}
    assert all((path / f).is_file() for f in tool["files"].values())
    manifest = json.loads((path / tool["files"]["manifest"]).read_text(encoding="utf-8"))
    assert manifest["strength"] == tool["strength"]
    assert print_summary(manifest["print"]) == json.loads(json.dumps(
        print_summary(manifest["print"])))
    start = resumed_hook.lines.index(PREDICTED)
    assert resumed_hook.lines[start:start + 10] == [
        PREDICTED, MAKE_1, CREATED_1, _tc(1, "hook_new1"),
        "hook_new1: strength pass (cantilever, 0.91 N, 4.10 MPa, safety factor 12.21)",
        *_evals("hook_new1")]
    assert resumed_hook.lines[start - 1] == "#13  EVAL hook_a2        loc 4  success     " \
                                            "tested -  (replayed)"
    assert resumed_hook.lines[start + 10].startswith("plan (long_tube, created model): ")


def test_the_learned_tool_fails_first_where_the_geometry_cannot_tell(engine, tmp_path):
    """Wedge: the big door needs a force, so TC trial 1 runs with the learned model's
    own tool; it fails, and a longer wedge is made."""
    vs = _vs(engine, "wedge")
    runner, lines, records = _runner(engine, load_world(get_case("wedge")), "wedge_s0", 12)
    res = ToolCreator(runner, eval_trials=5).create(vs, "big_door")
    _check(res, runner, vs, records, "wedge_s0", tmp_path, 12)
    assert res.success is res.created[0]
    assert (str(res.replaced), str(res.instance)) == (
        "block_length(_G0,medium)", "block_length(_G0,long)")
    assert lines == [
        "TC predicted: wedge_a2: the case's geometry sets no reach: the pose model cannot "
        "tell whether wedge_a2 works in the big_door task; the physics decides",
        "#13  TC   wedge_a2       loc 1  failure     tested -  (replayed)", MAKE_1,
        "created wedge_new1: block_length(A,medium) -> any_block_length(A) -> "
        "block_length(A,long); length 160.0 mm, width 85.0 mm, height 27.5 mm, "
        "tip_height 2.4 mm, shape triangular_prism",
        "#14  TC   wedge_new1     loc 1  success     tested -  (replayed)",
        "wedge_new1: strength pass (compression, 802.12 N, 0.06 MPa, safety factor 847.75)",
        *[f"#{14 + i:<3} EVAL wedge_new1     loc 1  success     tested -  (replayed)"
          for i in range(1, 6)]]


def test_catalogued_objects_out_of_reach_are_not_tried(engine, world, vs):
    """With the long objects left out, the short ones the generalised model admits are
    all predicted out of reach: none is tried."""
    runner, lines, _ = _runner(engine, world, "hook_s0")
    creator = ToolCreator(runner, catalogue_first=True)
    out, solved, n = creator._try_catalogue(vs, runner.task("long_tube"),
                                            ["hook_a2", "hook_a4", "hook_b4", "stick_b5"], 3)

    def entry(tool, reach):
        why = (f"behind({tool},cube1) cannot hold within the reach of {tool} in the "
               f"long_tube task: dx_reach = {reach} m (deepest prong centre the held tool "
               f"reaches, minus the cube centre); the trial would fail, so none is run")
        return {"tool": tool, "value": f"handle_length({tool},short)",
                "why": f"catalogued object admitted by any_length(_G0) (the generalised "
                       f"handle_length(_G0,medium)): handle_length({tool},short)",
                "predicted": {"tool": tool, "variant": "long_tube", "location": 1,
                              "feasible": False, "conflict": [f"behind({tool},cube1)"],
                              "why": why},
                "trial": None, "outcome": "predicted_unreachable"}, why

    (a1, why1), (b1, why2) = entry("hook_a1", "-0.161"), entry("hook_b1", "-0.178")
    assert (out, solved, n) == ([a1, b1], None, 3)
    assert lines == [f"TC catalogue: hook_a1 not tried: {why1}",
                     f"TC catalogue: hook_b1 not tried: {why2}"]
    assert runner.trials == _runner(engine, world, "hook_s0")[0].trials
    assert runner.calls == []


def test_no_catalogued_object_when_nothing_can_be_generalised(engine, world):
    """A model whose h_s has no literal to generalise admits no catalogued object."""
    runner = TrialRunner(engine, world, None)
    lone = engine.vs_init(engine.parse("(tool_pose(hook_a2,cube1,tube1) :- "
                                       "in_tube(hook_a2,tube1))"))
    creator = ToolCreator(runner, catalogue_first=True)
    assert creator._try_catalogue(lone, runner.task("long_tube"), [], 4) == ([], None, 4)


def test_a_tool_is_manufactured_into_the_run_folder(engine, world, vs, tmp_path):
    """With a run folder, hook_s0's hook_new1 is sized, written, split, sliced, added to
    the world and tried again (no evaluation asked), and its strength check goes into
    its manifest."""
    from creative_py.records.folder import RunFolder

    run = RunFolder.create(tmp_path, "hook", 0, "run")
    try:
        runner, lines, records = _runner(engine, world, "hook_s0", run=run)
        # A resumed run may have made it before: the tool's folder is replaced.
        (run.tools_dir() / "hook_new1").mkdir(parents=True)
        (run.tools_dir() / "hook_new1" / "stale.txt").write_text("before", encoding="utf-8")
        res = ToolCreator(runner, eval_trials=0).create(vs, "long_tube")
    finally:
        run.release()
    folder = run.path / "tools" / "hook_new1"
    recorded = json.loads((RUNS / "hook_s0" / "summary.json").read_text(encoding="utf-8"))
    tool = recorded["create"]["created_tools"][0]
    made = creation_summary(res, run.path).to_dict()["created_tools"][0]
    assert made["files"] == tool["files"]
    assert {k: str(folder / Path(v).name) for k, v in tool["files"].items()} \
        == res.success.files
    assert not (folder / "stale.txt").exists()
    made, _, _ = _without_run_dependent({"created_tools": [made],
                                         **dict.fromkeys(WALL_TIMES, 0)})
    expected, _, _ = _without_run_dependent({"created_tools": [{**tool, "eval_outcomes": []}],
                                             **dict.fromkeys(WALL_TIMES, 0)})
    assert made == expected
    manifest = json.loads((folder / "hook_new1.json").read_text(encoding="utf-8"))
    assert res.success.print == print_summary(manifest["print"])
    assert manifest["strength"] == tool["strength"]
    assert runner.world.items["hook_new1"].urdf == folder / "hook_new1.urdf"
    assert runner.world.items["hook_new1"].set == "created"
    assert res.trials == records[LEARNED:LEARNED + 1]
    assert lines == [PREDICTED, MAKE_1, CREATED_1, _tc(1, "hook_new1"),
                     "hook_new1: strength pass (cantilever, 0.91 N, 4.10 MPa, "
                     "safety factor 12.21)"]


def test_the_learned_tool_solves_a_task_within_its_reach(engine, world, vs, tmp_path):
    """Creation asked for the standard task: TC trial 1 with the learned model's tool
    succeeds, and nothing is made."""
    runner, lines, records = _runner(engine, world, "hook_std_s0")
    res = ToolCreator(runner).create(vs, "standard")
    _check(res, runner, vs, records, "hook_std_s0", tmp_path)
    assert res == CreateResult("standard", False, [], None, vs, records[LEARNED:],
                               res.wall_time_s, predicted=_recorded("hook_std_s0")["predicted"],
                               solved_by="learned")
    assert lines == ["TC predicted: hook_a2: hook_a2 reaches the learned pose in the standard "
                     "task (e.g. hook_pose(0.0375,0.0,0.0)); the physics decides",
                     _tc(1, "hook_a2")]


def test_a_catalogued_object_after_the_learned_tool_failed(engine, tmp_path):
    """Wedge with catalogued objects first: TC trial 1 fails, then the long wedge_a3
    the generalised model admits solves the big door."""
    vs = _vs(engine, "wedge")
    runner, lines, records = _runner(engine, load_world(get_case("wedge")), "wedge_cf_s0", 12)
    res = ToolCreator(runner, catalogue_first=True).create(vs, "big_door")
    _check(res, runner, vs, records, "wedge_cf_s0", tmp_path, 12)
    assert (res.created, res.success, str(res.replaced), str(res.instance)) == (
        [], None, "block_length(_G0,medium)", "block_length(wedge_a3,long)")
    assert lines == [
        "TC predicted: wedge_a2: the case's geometry sets no reach: the pose model cannot "
        "tell whether wedge_a2 works in the big_door task; the physics decides",
        "#13  TC   wedge_a2       loc 1  failure     tested -  (replayed)",
        "TC catalogue: trying wedge_a3, catalogued object admitted by any_block_length(_G0) "
        "(the generalised block_length(_G0,medium)): block_length(wedge_a3,long)",
        "#14  TC   wedge_a3       loc 1  success     tested -  (replayed)",
        "TC catalogue: wedge_a3 solved the big_door task; no tool is made"]
