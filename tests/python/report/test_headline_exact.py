"""The headline of a run (:mod:`creative_py.report.headline`), exact, from summaries
written here: every sentence and figure of a full run, each part left out when its
summary key is, each way the harder task ends, and the durations' wording."""

from __future__ import annotations

from pathlib import Path

import pytest

from creative_py.report.contents import RunContents
from creative_py.report.headline import Figure, duration_text, headline


def _run(summary: dict, trials=(), budget=None, paper=None) -> RunContents:
    return RunContents(Path("r"), list(trials), summary, None, None, [], [], [], [], {},
                       budget, paper)


FULL = {
    "case": "hook", "seed": 3, "options": {"strategy": "paper"},
    "demonstration": {"tool": "hook_a2"},
    "use": {"trials": 9, "stop": "confirmed", "converged": True, "trials_to_converge": 7,
            "strategy": "random"},
    "eval": {"trials": 4, "successes": 3},
    "create": {
        "variant": "long_tube", "predicted": {"feasible": False, "tool": "hook_a2"},
        "catalogue": [{"tool": "stick", "outcome": "failure"}, "x",
                      {"tool": "rake_a1", "outcome": "blocked"}],
        "solved_by": "created", "success": "hook_new", "trials": 2,
        "eval": ["success", "failure", "success"],
        "created_tools": [
            {"name": "hook_new", "mass_kg": 0.2,
             "print": {"print_time_s": 5400, "filament_g": 12.34, "filament_mm": 12960,
                       "pieces": [{}, {}]}},
            {"name": "hook_x", "print": {"print_time_s": 30}}, "junk"]},
    "wall_time_s": {"total": 83.456, "use": 40, "create": 43.456},
}
TRIALS = [{"phase": "use", "outcome": "success"}, {"phase": "use", "outcome": "failure"},
          {"phase": "eval", "outcome": "success"}, {"phase": "use", "outcome": "success"}]


def test_every_sentence_and_figure_of_a_full_run():
    h = headline(_run(FULL, TRIALS, budget=12, paper=10))
    assert h.lines == [
        "Case hook, strategy paper, seed 3.",
        "One demonstration, with hook_a2.",
        "Tool-use learning: 9 trials of a budget of 12 (2 succeeded); stopped because the "
        "learned model succeeded the required times in a row; converged after 7 trials; "
        "the paper's robot used 10.",
        "Evaluation of the learned model on the task it learned: 3 of 4 trials succeeded.",
        "Tool creation on the harder task long_tube: hook_a2 was predicted to fail, so its "
        "trial was not run; catalogued objects tried first: stick (failure), rake_a1 "
        "(blocked); solved by the created hook_new after 2 creation trials; the created "
        "tool's evaluation: 2 of 3 trials succeeded.",
        "Printing hook_new: 2 pieces, 1 h 30 min of printing, 12.3 g of filament (13.0 m); "
        "mass 200.0 g.",
        "Wall time 83.456 s (use 40 s, create 43.456 s).",
    ]
    assert h.figures == [
        Figure("use.trials", 9, "9 of 12", "tool-use trials (of the budget); paper: 10"),
        Figure("eval.successes", 3, "3 / 4", "learned model's evaluation: successes / trials"),
        Figure("create.solved_by", "created", "created hook_new",
               "harder task (long_tube) solved by"),
        Figure("create.eval", 2, "2 / 3", "created hook_new's evaluation: successes / trials"),
        Figure("create.created_tools[hook_new].print.print_time_s", 5400, "1 h 30 min",
               "print time of hook_new"),
        Figure("create.created_tools[hook_new].print.filament_g", 12.34, "12.3 g",
               "filament for hook_new"),
        Figure("wall_time_s.total", 83.456, "83.456 s", "wall time"),
    ]


def test_an_empty_summary_has_no_headline():
    h = headline(_run({}))
    assert h.lines == [] and h.figures == []


def test_the_short_forms_when_keys_are_missing():
    h = headline(_run({"seed": 0, "use": {"trials": 3, "strategy": "random",
                                          "stop": "odd_stop", "converged": True},
                       "eval": {"trials": 2}, "wall_time_s": {"total": 5}},
                      [{"phase": "use", "outcome": "success"}]))
    assert h.lines == [
        "Strategy random, seed 0.",
        "Tool-use learning: 3 trials (1 succeeded); stopped because odd_stop.",
        "Evaluation of the learned model on the task it learned: 0 of 2 trials succeeded.",
        "Wall time 5 s.",
    ]
    assert h.figures == [
        Figure("use.trials", 3, "3", "tool-use trials (of the budget)"),
        Figure("eval.successes", 0, "0 / 2", "learned model's evaluation: successes / trials"),
        Figure("wall_time_s.total", 5, "5 s", "wall time"),
    ]
    assert headline(_run({"case": "rake", "use": {"trials": 1}})).lines == [
        "Case rake.", "Tool-use learning: 1 trials (0 succeeded)."]
    assert headline(_run({"demonstration": {}, "wall_time_s": {"use": 1}})).lines == []


@pytest.mark.parametrize("create, line, solved", [
    ({"variant": "v", "catalogue": [], "solved_by": "catalogue",
      "catalogue_success": "stick", "success": "x"},
     "Tool creation on the harder task v: no catalogued object tried; solved by the "
     "catalogued stick.", "catalogue stick"),
    ({"solved_by": "created", "success": "hook_new", "trials": 1},
     "Tool creation on the harder task ?: solved by the created hook_new after 1 creation "
     "trial.", "created hook_new"),
    ({"solved_by": "created", "success": "hook_new", "trials": "2"},
     "Tool creation on the harder task ?: solved by the created hook_new.",
     "created hook_new"),
    ({"solved_by": "the_learned_model"},
     "Tool creation on the harder task ?: solved by the_learned_model.", "the_learned_model"),
    ({"exhausted": "no candidate left", "predicted": {"feasible": True, "tool": "t"}},
     "Tool creation on the harder task ?: not solved: no literal left to generalise "
     "(no candidate left).", None),
    ({"exhausted": "[a(A)-infeasible([b(0.25)])]",
      "exhausted_words": "a(A) cannot be sized, as b(250 mm) cannot hold together"},
     "Tool creation on the harder task ?: not solved: no literal left to generalise "
     "(a(A) cannot be sized, as b(250 mm) cannot hold together).", None),
    ({"needed": False, "variant": "w"}, "Tool creation on the harder task w.", None),
    ({"needed": True}, "Tool creation on the harder task ?: not solved.", None),
])
def test_each_way_the_harder_task_ends(create, line, solved):
    h = headline(_run({"create": create}))
    assert h.lines == [line]
    assert [(f.key, f.raw, f.value) for f in h.figures] == (
        [("create.solved_by", create["solved_by"], solved)] if solved else [])
    if solved:
        assert h.figures[0].label == f"harder task ({create.get('variant', '?')}) solved by"


def test_print_lines_need_both_the_time_and_the_filament():
    tools = [{"name": "a", "print": {"print_time_s": 42, "filament_g": 3}},
             {"name": "b", "print": {"print_time_s": 42, "filament_g": "3"}},
             {"print": {"print_time_s": 61.0, "filament_g": 1.25, "pieces": [{}],
                        "filament_mm": "x"}, "mass_kg": "heavy"},
             {"name": "c", "print": []}, {"name": "d"}]
    h = headline(_run({"create": {"needed": False, "created_tools": tools}}))
    assert h.lines[1:] == ["Printing a: 1 piece, 42 s of printing, 3.0 g of filament.",
                           "Printing ?: 1 piece, 1 min of printing, 1.2 g of filament."]
    assert [(f.key, f.raw, f.value, f.label) for f in h.figures] == [
        ("create.created_tools[a].print.print_time_s", 42, "42 s", "print time of a"),
        ("create.created_tools[a].print.filament_g", 3, "3.0 g", "filament for a"),
        ("create.created_tools[?].print.print_time_s", 61.0, "1 min", "print time of ?"),
        ("create.created_tools[?].print.filament_g", 1.25, "1.2 g", "filament for ?")]


def test_durations_exact():
    assert [duration_text(s) for s in (0.5, 42, 59.94, 60, 89, 90, 3599, 3600, 3629, 3630,
                                       14640, 86399)] == [
        "0.5 s", "42 s", "59.9 s", "1 min", "1 min", "2 min", "60 min", "1 h 00 min",
        "1 h 00 min", "1 h 00 min", "4 h 04 min", "24 h 00 min"]


def test_a_resumed_run_says_so_with_its_trials_replayed_and_the_time_in_all():
    # Issue 25: a resumed run's report showed the resume's wall time only and never said
    # it was resumed.
    summary = {"case": "hook", "wall_time_s": {"total": 8.11},
               "resumed": {"replayed": 12, "earlier_wall_time_s": 17.5,
                           "total_wall_time_s": 25.61}}
    assert headline(_run(summary)).lines == [
        "Case hook.",
        "Resumed after an interruption: 12 trials of the interrupted run replayed from its "
        "records; the interrupted run took 17.5 s to its last recorded trial; 25.61 s in "
        "all.",
        "Wall time 8.11 s of the resumed session."]
    unknown = {"resumed": {"replayed": 1}}
    assert headline(_run(unknown)).lines == [
        "Resumed after an interruption: 1 trial of the interrupted run replayed from its "
        "records."]


def test_a_tool_made_after_a_catalogued_object_solved_the_task_is_a_demonstration():
    # Issue 25: "creation not needed" was followed by a made tool without a word.
    create = {"variant": "long_tube", "needed": False, "solved_by": "catalogue",
              "catalogue": [{"tool": "hook_a4", "outcome": "success"}],
              "catalogue_success": "hook_a4", "created_tools": [{"name": "hook_new1"}],
              "eval": ["success"]}
    assert headline(_run({"create": create})).lines == [
        "Tool creation on the harder task long_tube: catalogued objects tried first: "
        "hook_a4 (success); solved by the catalogued hook_a4; hook_new1 made all the "
        "same, as a demonstration (--demonstrate-creation); the created tool's "
        "evaluation: 1 of 1 trials succeeded."]


@pytest.mark.parametrize("options, first", [
    ({"strategy": "paper", "backend": "ros"}, "Case hook, strategy paper, seed 3, backend ros."),
    ({"backend": "ros", "robot_profile": "lab.toml"},
     "Case hook, seed 3, backend ros, robot lab.toml."),
    ({"robot": "panda"}, "Case hook, seed 3, robot panda."),
    ({"strategy": "paper"}, "Case hook, strategy paper, seed 3."),
])
def test_the_first_line_names_a_backend_the_options_chose(options, first):
    h = headline(_run({**FULL, "options": options, "use": None}))
    assert h.lines[0] == first
