"""The learning loop's Python, exercised on a short real run (Algorithm 1's first trials).

A run of the rake case limited to three tool-use trials with the paper's strategy
(Algorithm 1; ``test_strategies.py`` has the others): the demonstration, then the
experiments Prolog chooses, executed in the physics, labelled and fed back. The checks
are on the version space after each trial, not only on the outcomes: a failure (here a
blocked motion, labelled as the planned example) must make exactly the tested literal
necessary in h_g.
"""

import json

import pytest

from creative_py.learning.options import RunOptions
from creative_py.learning.run import run_case

pytestmark = pytest.mark.sim


@pytest.fixture(scope="module")
def short_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("runs")
    folder = run_case("rake", out, RunOptions(seed=0, phase="use", max_trials=3,
                                              eval_trials=0, strategy="paper"))
    trials = [json.loads(line) for line in (folder.path / "trials.jsonl").read_text()
              .splitlines()]
    summary = json.loads((folder.path / "summary.json").read_text())
    return folder.path, trials, summary


def test_the_budget_bounds_the_trials_and_each_tests_one_literal(short_run):
    _, trials, summary = short_run
    assert [t["phase"] for t in trials] == ["use"] * 3
    assert summary["use"] == {"trials": 3, "converged": False, "trials_to_converge": None,
                              "strategy": "paper", "stop": "budget"}
    assert all(len(t["tested"]) == 1 for t in trials)


def test_a_blocked_trial_makes_its_tested_literal_necessary(short_run):
    _, trials, _ = short_run
    first, second = trials[0], trials[1]
    assert (first["tool"], first["outcome"]) == ("rake_a1", "blocked")
    assert first["tested"] == ["handle_length(rake_a1,medium)"]
    assert first["hg"] == "tool_pose(_G3,_G4,_G5) :- handle_length(_G3,medium)"
    assert (second["tool"], second["outcome"]) == ("hook_a3", "blocked")
    assert second["hg"] == ("tool_pose(_G3,_G4,_G5) :- handle_length(_G3,medium), "
                            "hook_length(_G3,short)")
    # A failure specialises h_g only: h_s, the demonstration's, is unchanged.
    assert first["hs"] == second["hs"] == trials[2]["hs"]


def test_a_failed_pose_test_adds_the_spatial_literal(short_run):
    _, trials, _ = short_run
    third = trials[2]
    assert third["outcome"] == "failure"
    literal = third["tested"][0].split("(")[0]
    assert literal in third["hg"] and literal not in trials[1]["hg"]


def test_the_short_run_writes_its_model_and_plan(short_run):
    path, _, summary = short_run
    assert "learned_model(rake, pull_out(" in (path / "model.pl").read_text()
    assert summary["plan"].startswith("plan([pick_up(")
    assert (path / "domain.pddl").exists() and (path / "problem.pddl").exists()


def test_a_blocked_trial_is_labelled_with_the_planned_example():
    # The motion stopped before the tool reached its pose, so what the cameras see then
    # says nothing about the pose: the negative example is the planned one, which has
    # the pose's spatial literals (the prong behind the box, down, centred).
    from creative_py.bridge import Compound, Engine, clause_parts
    from creative_py.case import get_case
    from creative_py.learning.tool_use import LearningOptions, ToolUseLearner
    from creative_py.learning.trials import TrialRunner
    from creative_py.backends.pybullet import load_world

    engine = Engine.instance()
    runner = TrialRunner(engine, load_world(get_case("rake")), None, seed=0)
    _models, example, _tool = ToolUseLearner(runner, LearningOptions()).observe_demonstration()
    vs = engine.vs_init(example)
    task = runner.task("standard")
    exp = engine.next_experiment("rake", vs, runner.task_facts(task), [])
    rec, vs = runner.run(exp, "use", 1, vs, task, 0.0)
    assert (rec.tool, rec.outcome) == ("rake_a1", "blocked")
    _pos, neg = engine.vs_examples(vs)
    assert len(neg) == 1
    _head, body = clause_parts(neg[0])
    assert Compound("behind", ("rake_a1", "box1")) in body
    assert Compound("hook_down", ("rake_a1",)) in body


def test_the_learned_action_s_preconditions_are_in_domain_pddl(short_run):
    # Read back by a real PDDL parser: the learned action's preconditions are exactly
    # those of the learned model in model.pl (the skill's, h_g's, h_s's pose literals).
    import re

    from unified_planning.io import PDDLReader

    path, _, _ = short_run
    problem = PDDLReader().parse_problem(str(path / "domain.pddl"),
                                         str(path / "problem.pddl"))
    pre = str(problem.action("pull_out").preconditions[0])
    pre = pre[1:-1] if pre.startswith("(") and pre.endswith(")") else pre
    in_pddl = sorted(p.strip() for p in pre.split(" and "))
    model = (path / "model.pl").read_text()
    found = re.search(r"learned_model\(rake, pull_out\(A, B, C\),\s*\[(.*?)\],", model, re.S)
    assert found, model
    names = {"A": "tool", "B": "target", "C": "site"}
    in_model = sorted(re.sub(r"\b[ABC]\b", lambda m: names[m.group(0)], lit.strip())
                      for lit in re.findall(r"\w+\([^)]*\)", found.group(1)))
    assert in_pddl == in_model
    assert len(in_model) >= 6


def test_the_run_solves_its_own_pddl_with_the_prolog_plan(short_run):
    """summary.json's pddl record: pyperplan (through unified-planning) solved the run's
    own domain.pddl/problem.pddl, with the same steps as the Prolog planner; solving the
    files again gives the same plan, and every catalogued tool is typed as a tool."""
    from creative_py.case import get_case
    from creative_py.learning.pddl_check import parse, solve, step_text
    from creative_py.backends.pybullet import load_world

    path, _, summary = short_run
    record = summary["pddl"]["use"]
    assert record["status"] == "solved" and record["planner"] == "pyperplan"
    assert record["equals_prolog"] is True and record["prolog_plan_valid"] is True
    assert (record["domain"], record["problem"]) == ("domain.pddl", "problem.pddl")
    prolog = summary["plan"][len("plan(["):-len("])")].replace("),", ") ").split(" ")
    assert record["plan"] == ["(" + s.replace("(", " ").replace(",", " ").rstrip(")") + ")"
                              for s in prolog]
    again = solve(path / "domain.pddl", path / "problem.pddl")
    assert [step_text(s) for s in again] == record["plan"]
    task = parse(path / "domain.pddl", path / "problem.pddl")
    tools = {o.name for o in task.all_objects if o.type.name == "tool_object"}
    assert tools == set(load_world(get_case("rake")).catalogue)


def test_the_short_run_keeps_its_key_trials_as_clips_that_decode(short_run):
    # The default --video key: the demonstration, and the first trial of each failure
    # reason; summary["videos"] names them (what the HTML report reads).
    import imageio.v2 as imageio

    from creative_py.learning.clips import failure_reason
    from creative_py.video import band_height

    path, trials, summary = short_run
    videos = summary["videos"]
    assert videos[0]["why"] == "demonstration" and videos[0]["trial"] == 0
    reasons, expected = set(), []
    for t in trials:
        cls = failure_reason(t["outcome"], t["reason"])
        if t["outcome"] != "success" and cls not in reasons:
            expected.append((t["trial"], t["tool"], t["tested"], t["outcome"],
                             f"failure:{cls}"))
        reasons.add(cls)
    assert [(v["trial"], v["tool"], v["tested"], v["outcome"], v["why"])
            for v in videos[1:]] == expected
    for v in videos:
        assert set(v) >= {"file", "phase", "trial", "tool", "tested", "outcome", "why"}
        assert v["file"].startswith("videos/") and v["file"].endswith(".mp4")
        with imageio.get_reader(str(path / v["file"])) as reader:
            frames = [f for f in reader]
        # The 320x240 picture with its caption in a band above it: three lines, plus
        # the measured verdict's lines for a trial the oracle judged, a long line
        # wrapped (never cut).
        bands = {band_height(n) for n in range(3, 14)}
        assert len(frames) == v["frames"] > 0 and frames[0].shape[1:] == (320, 3)
        assert frames[0].shape[0] - 240 in bands
        assert v["bytes"] == (path / v["file"]).stat().st_size
    assert sorted(p.name for p in (path / "videos").glob("*.mp4")) == sorted(
        v["file"].split("/")[1] for v in videos)


def test_the_run_folder_records_the_version_space_count(short_run):
    # 14 literals of h_s after the demonstration: 2^14 hypotheses, 14 binary trials to
    # tell them all apart in the worst case. A blocked trial labels the planned example,
    # which violates the tested literal alone: it halves the count.
    _, trials, summary = short_run
    assert summary["vs_count_initial"] == 2 ** 14 and summary["vs_count_initial_exact"]
    assert summary["info_bound_trials"] == 14
    counts = [t["vs_count"] for t in trials]
    assert all(t["vs_count_exact"] is True for t in trials)
    assert counts[:2] == [2 ** 13, 2 ** 12]
    assert counts[2] < counts[1]
    assert summary["vs_count_final"] == counts[-1]
