"""The learning loop's stop rules and the strategies' values, exact, without the physics.

:meth:`ToolUseLearner.learn` is run against a scripted engine and runner: the engine
proposes the experiments of a script (``experiment`` terms, then ``exploit`` when
nothing is left to test) and the runner answers the outcomes of another. The checks are
the exact trial count, stop reason, convergence and ``trials_to_converge`` of each
strategy's rule (the paper's ``confirmed`` stop after exactly K successes in a row,
``certified`` and ``exhausted`` at once, the budget), and what each strategy asks
Prolog and tells it not to run again. The expected values are worked out by hand from
the scripts, not taken from the code.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import SimpleNamespace

import pytest

from creative_py.bridge.terms import Compound
from creative_py.learning.strategies import (STRATEGIES, Strategy, UnknownStrategy,
                                             strategies_help, strategy_named)
from creative_py.learning.tool_use import LearningOptions, ToolUseLearner


def _experiment(tool="t1", literal="lit", negated=()):
    return Compound("experiment", (tool, [literal], [], "pose", [], list(negated)))


EXPLOIT = Compound("exploit", ("t1", [], "pose", []))


@dataclass
class ScriptedEngine:
    """Proposes ``proposals[i - 1]`` for trial i (the last one once the script ends) and
    records what it is asked."""

    proposals: list
    asked: list = field(default_factory=list)
    calls: list = field(default_factory=list)
    exact: bool = True

    def vs_init(self, example):
        self.calls.append(("vs_init", example))
        return ("vs", 0, None)

    def vs_count(self, vs):
        self.calls.append(("vs_count", vs))
        return 16, self.exact

    def vs_bounds(self, vs):
        """h_s and h_g: the one a trial changed carries its number."""
        self.calls.append(("vs_bounds", vs))
        _, i, which = vs
        return (f"hs{i}" if which == "hs" else "hs"), (f"hg{i}" if which == "hg" else "hg")

    def next_experiment(self, case, vs, facts, skip, strategy):
        self.asked.append((list(skip), strategy))
        self.calls.append(("next_experiment", case, vs, list(facts)))
        i = len(self.asked)
        return self.proposals[min(i, len(self.proposals)) - 1]


class ScriptedRunner:
    """Answers trial i with ``outcomes[i - 1]``; a trial in ``changes`` changes h_g (or
    the bound ``changes[i]`` names, when a dict)."""

    def __init__(self, engine, outcomes, changes=None, seed=3):
        self.engine, self.outcomes, self.seed = engine, outcomes, seed
        if changes is None:
            changes = set(range(1, len(outcomes) + 1))
        self.changes = changes if isinstance(changes, dict) else dict.fromkeys(changes, "hg")
        self.case = "stub"
        self.trials = []
        self.runs = []
        self.lines = []
        self.variants = []
        self.locations = 0
        self.manifest = SimpleNamespace(demonstration=SimpleNamespace(variant="v"))

    def progress(self, text):
        self.lines.append(text)

    def task(self, variant):
        runner = self
        self.variants.append(variant)

        class Task:
            def next_location(self):
                runner.locations += 1
        self.the_task = Task()
        return self.the_task

    def task_facts(self, task):
        return [("facts_of", id(task))]

    def run(self, exp, phase, i, vs, task, decision):
        self.runs.append((phase, i, vs, task, decision))
        rec = SimpleNamespace(n=i, kind=exp.name, outcome=self.outcomes[i - 1])
        self.trials.append(rec)
        return rec, (("vs", i, self.changes[i]) if i in self.changes else vs)


MODELS = [Compound("model", ("m1",)), Compound("model", ("m2",)), "plain"]


class StubLearner(ToolUseLearner):
    models = MODELS

    def observe_demonstration(self):
        return self.models, "example", "demo_tool"


def _learn(strategy, proposals, outcomes, max_trials=12, consecutive=2, changes=None,
           exact=True):
    engine = ScriptedEngine(proposals, exact=exact)
    runner = ScriptedRunner(engine, outcomes, changes)
    use = StubLearner(runner, LearningOptions(max_trials=max_trials,
                                              consecutive=consecutive,
                                              strategy=strategy)).learn()
    return use, engine, runner


# -- the paper's strategy: confirmed after exactly K successes in a row ---------------

@pytest.mark.parametrize("k", [1, 2, 3])
def test_paper_stops_confirmed_after_exactly_k_successes(k):
    # Two experiments fail, then nothing is left to test: the model is used until K
    # successes in a row, and the loop stops at once (trial 2 + K is the last).
    use, engine, runner = _learn("paper", [_experiment(literal="a"), _experiment(literal="b"),
                                           EXPLOIT], ["failure", "failure"] + ["success"] * 6,
                                 consecutive=k)
    assert len(use.trials) == 2 + k
    assert [t.kind for t in use.trials] == ["experiment"] * 2 + ["exploit"] * k
    assert use.stop == "confirmed"
    assert use.converged is True
    assert use.trials_to_converge == 2
    assert len(engine.asked) == 3 + k          # the last ask found nothing to test
    assert runner.locations == k               # each success moves the task on


def test_paper_a_failure_while_confirming_restarts_the_count():
    use, _, runner = _learn("paper", [_experiment(), EXPLOIT],
                            ["failure", "success", "failure", "success", "success",
                             "success"], consecutive=2)
    assert len(use.trials) == 5
    assert use.stop == "confirmed" and use.converged is True
    assert use.trials_to_converge == 1
    assert runner.locations == 3


def test_paper_successful_experiments_count_towards_k():
    # The experiments themselves succeeded twice in a row: nothing left to test after
    # trial 2, and no confirmation trial is needed.
    use, engine, _ = _learn("paper", [_experiment(literal="a"), _experiment(literal="b"),
                                      EXPLOIT], ["success", "success"], consecutive=2)
    assert len(use.trials) == 2
    assert use.stop == "confirmed" and use.converged is True
    assert use.trials_to_converge == 2
    assert len(engine.asked) == 3


def test_paper_a_budget_spent_confirming_is_not_convergence():
    use, _, _ = _learn("paper", [_experiment(), EXPLOIT],
                       ["failure", "success", "failure", "success"], max_trials=4,
                       consecutive=2)
    assert len(use.trials) == 4
    assert use.stop == "budget"
    assert use.converged is False
    assert use.trials_to_converge == 1


def test_paper_last_budget_trial_completing_k_converges_but_stops_on_budget():
    use, engine, _ = _learn("paper", [_experiment(), EXPLOIT],
                            ["failure", "success", "success"], max_trials=3, consecutive=2)
    assert len(use.trials) == 3
    assert use.stop == "budget"
    assert use.converged is True
    assert use.trials_to_converge == 1
    assert len(engine.asked) == 4              # the budget's end asks once more


def test_paper_experiments_to_the_budget_never_converge():
    use, engine, _ = _learn("paper", [_experiment()], ["success"] * 3, max_trials=3)
    assert len(use.trials) == 3
    assert use.stop == "budget" and use.converged is False
    assert use.trials_to_converge is None
    assert len(engine.asked) == 4


def test_paper_budget_reached_exactly_when_nothing_is_left():
    use, _, _ = _learn("paper", [_experiment(), _experiment(), EXPLOIT],
                       ["success", "failure"], max_trials=2, consecutive=1)
    assert use.trials_to_converge == 2
    assert use.stop == "budget" and use.converged is False


# -- the strategies that stop at once --------------------------------------------------

def test_informative_stops_certified_at_once_without_confirmation():
    use, engine, _ = _learn("informative", [_experiment(literal="a"),
                                            _experiment(literal="b"), EXPLOIT],
                            ["failure", "success", "success"])
    assert len(use.trials) == 2
    assert use.stop == "certified" and use.converged is True
    assert use.trials_to_converge == 2
    assert len(engine.asked) == 3
    assert engine.asked[0][1] == "informative"     # an atom, no seed


def test_informative_nothing_left_after_the_last_budget_trial_is_certified():
    use, _, _ = _learn("informative", [_experiment(), _experiment(), EXPLOIT],
                       ["failure", "failure"], max_trials=2)
    assert len(use.trials) == 2
    assert use.stop == "certified" and use.converged is True
    assert use.trials_to_converge == 2


def test_informative_budget_with_experiments_left():
    use, _, _ = _learn("informative", [_experiment()], ["failure"] * 2, max_trials=2)
    assert use.stop == "budget" and use.converged is False
    assert use.trials_to_converge is None


def test_random_stops_exhausted_and_sends_its_seeded_term():
    use, engine, _ = _learn("random", [_experiment(literal="a"), EXPLOIT], ["failure"])
    assert len(use.trials) == 1
    assert use.stop == "exhausted" and use.converged is True
    assert use.trials_to_converge == 1
    # Seed 3 (the runner's): trial i asks random(3 * 1000 + i).
    assert [a[1] for a in engine.asked] == [Compound("random", (3001,)),
                                            Compound("random", (3002,))]


def test_the_result_carries_the_demonstration_and_the_initial_count():
    use, _, _ = _learn("informative", [EXPLOIT], [])
    assert use.trials == [] and use.trials_to_converge == 0
    assert use.stop == "certified" and use.converged is True
    assert (use.vs_count_initial, use.vs_count_initial_exact) == (16, True)
    assert use.demo_tool == "demo_tool"
    assert use.vs == ("vs", 0, None)
    assert use.models == MODELS
    assert 0 <= use.wall_time_s < 60


# -- what each strategy tells Prolog not to run again ---------------------------------

def test_skips_sent_to_prolog_after_each_trial():
    # informative: an experiment once run is skipped (with its tool; a pose test with
    # any tool). Trial 1 tests a literal with t1, trial 2 a pose with t2.
    pose = _experiment(tool="t2", literal="behind", negated=["behind"])
    _, engine, _ = _learn("informative", [_experiment(tool="t1", literal="a"), pose, EXPLOIT],
                          ["failure", "failure"])
    assert [a[0] for a in engine.asked] == [
        [],
        [Compound("skip", ("t1", ["a"]))],
        [Compound("skip", ("t1", ["a"])), Compound("skip", ("any", ["behind"]))],
    ]


def test_paper_repeats_an_experiment_that_taught_something():
    # Trial 1 changed h_g (taught): not skipped. Trial 2 left it as it was: skipped.
    _, engine, _ = _learn("paper", [_experiment(literal="a"), _experiment(literal="b"),
                                    EXPLOIT], ["failure", "failure", "success", "success"],
                          changes={1})
    assert engine.asked[1][0] == []
    assert engine.asked[2][0] == [Compound("skip", ("t1", ["b"]))]


@pytest.mark.parametrize("name,taught,idle,expected", [
    # paper repeats what taught and changed the bounds, skips the rest with its tool.
    ("paper", True, False, None),
    ("paper", True, True, ("t1", ["a"])),
    ("paper", False, False, ("t1", ["a"])),
    # informative and random never repeat.
    ("informative", True, False, ("t1", ["a"])),
    ("random", True, False, ("t1", ["a"])),
])
def test_skip_of_a_literal_test(name, taught, idle, expected):
    got = STRATEGIES[name].skip(_experiment(literal="a"), taught, idle)
    assert got == (None if expected is None else Compound("skip", expected))


@pytest.mark.parametrize("name,taught,expected_tool", [
    # A pose test the arm could not carry out (not taught): skipped with any tool.
    ("paper", False, "any"),
    ("informative", False, "any"),
    ("random", False, "any"),
    # Taught: only informative (pose_any_tool) skips it with any tool.
    ("paper", True, "t1"),
    ("informative", True, "any"),
    ("random", True, "t1"),
])
def test_skip_of_a_pose_test(name, taught, expected_tool):
    exp = _experiment(literal="behind", negated=["behind"])
    assert STRATEGIES[name].skip(exp, taught, idle=True) == Compound(
        "skip", (expected_tool, ["behind"]))


# -- the registry, field by field -----------------------------------------------------
# The shipped strategies are pinned one by one (a new entry owns its own test); what
# every entry must be is checked over the whole registry.

SHIPPED = {
    "paper": ("paper", "confirmed", True, True, False, False, False),
    "informative": ("informative", "certified", False, False, True, False, True),
    "random": ("random", "exhausted", False, False, False, True, True),
}


@pytest.mark.parametrize("name", sorted(SHIPPED))
def test_a_shipped_registry_entry_exact(name):
    s = STRATEGIES[name]
    assert (s.name, s.stop, s.confirm, s.repeat_taught, s.pose_any_tool, s.seeded,
            s.catalogue_first) == SHIPPED[name]


def test_the_paper_s_summary_exact():
    assert STRATEGIES["paper"].summary == ("Algorithm 1: one literal per trial, "
                                           "K successes to stop")


@pytest.mark.parametrize("name", list(STRATEGIES))
def test_every_registry_entry_keeps_the_contract(name):
    """What the loop and the command line need of any strategy: its key is its name,
    a one-line summary for --help, a stop the summary knows, a term that is its name
    (with the seed when seeded), and a skip rule that answers None or skip/2."""
    s = STRATEGIES[name]
    assert s.name == name and name.isidentifier()
    assert s.summary and "\n" not in s.summary and ";" not in s.summary
    assert s.stop in ("certified", "exhausted", "confirmed")
    term = s.term(7, 4)
    assert term == (Compound(name, (7004,)) if s.seeded else name)
    assert strategy_named(name) is s
    for exp in (_experiment(literal="a"), _experiment(literal="b", negated=["b"])):
        for taught in (True, False):
            for idle in (True, False):
                got = s.skip(exp, taught, idle)
                assert got is None or (isinstance(got, Compound) and got.name == "skip"
                                       and got.args[1] == exp.args[1]), got
    assert f"{name} ({s.summary})" in strategies_help().split("; ")


def test_a_strategy_s_defaults():
    s = Strategy("x", "summary", stop="s")
    assert (s.confirm, s.repeat_taught, s.pose_any_tool, s.seeded, s.catalogue_first) == (
        False, False, False, False, True)


def test_the_term_sent():
    assert STRATEGIES["paper"].term(7, 4) == "paper"
    assert STRATEGIES["random"].term(7, 4) == Compound("random", (7004,))
    assert STRATEGIES["random"].term(0, 12) == Compound("random", (12,))


def test_strategy_named_and_its_error():
    assert strategy_named("random") is STRATEGIES["random"]
    for bad in ("nope", 3, None, ["paper"]):
        with pytest.raises(UnknownStrategy) as caught:
            strategy_named(bad)
        assert caught.value.name == bad
        assert str(caught.value) == (f"unknown strategy {bad!r}; strategies: "
                                     + ", ".join(STRATEGIES))
    assert isinstance(UnknownStrategy("x"), ValueError)
    with pytest.raises(UnknownStrategy):
        LearningOptions(strategy="nope")


def test_the_help_line_exact():
    assert strategies_help().startswith(
        "paper (Algorithm 1: one literal per trial, K successes to stop); "
        "informative (largest expected reduction of the version space, certified stop); "
        "random (a seeded draw among the experiments h_g covers)")
    assert len(strategies_help().split("; ")) == len(STRATEGIES)


# -- what the loop sends to the engine and the runner ---------------------------------

def test_the_loop_passes_its_state_to_the_engine_and_the_runner():
    use, engine, runner = _learn("paper", [_experiment(literal="a"), EXPLOIT],
                                 ["failure", "success", "success"])
    assert len(use.trials) == 3
    assert engine.calls[:2] == [("vs_init", "example"), ("vs_count", ("vs", 0, None))]
    assert runner.lines[0] == "demonstration with demo_tool: new model m1, m2, plain; 16 hypotheses"
    assert runner.variants == ["v"]
    facts = [("facts_of", id(runner.the_task))]
    asked = [c for c in engine.calls if c[0] == "next_experiment"]
    # Trial i is decided on the version space after trial i - 1.
    assert asked == [("next_experiment", "stub", ("vs", i, None if i == 0 else "hg"), facts)
                     for i in range(4)]
    assert [(phase, i, vs) for phase, i, vs, _, _ in runner.runs] == [
        ("use", 1, ("vs", 0, None)), ("use", 2, ("vs", 1, "hg")), ("use", 3, ("vs", 2, "hg"))]
    for _, _, _, task, decision in runner.runs:
        assert task is runner.the_task
        assert isinstance(decision, float) and 0 <= decision < 10


def test_an_upper_bound_count_is_said_and_kept():
    use, _, runner = _learn("informative", [EXPLOIT], [], exact=False)
    assert runner.lines == ["demonstration with demo_tool: new model m1, m2, plain; "
                            "16 hypotheses at most"]
    assert (use.vs_count_initial, use.vs_count_initial_exact) == (16, False)


def test_a_model_that_is_not_a_list_is_named_whole():
    class One(StubLearner):
        models = Compound("model", ("m1",))
    engine = ScriptedEngine([EXPLOIT])
    runner = ScriptedRunner(engine, [])
    One(runner, LearningOptions(strategy="informative")).learn()
    assert runner.lines[0] == "demonstration with demo_tool: new model model(m1); 16 hypotheses"


def test_paper_a_first_success_counts_once():
    # Trial 1 succeeds and leaves nothing to test: one more success is needed (K = 2).
    use, _, _ = _learn("paper", [_experiment(), EXPLOIT], ["success"] * 4, consecutive=2)
    assert len(use.trials) == 2
    assert use.stop == "confirmed" and use.trials_to_converge == 1


def test_random_asks_the_trial_after_the_budget_with_its_number():
    _, engine, runner = _learn("random", [_experiment()], ["failure"] * 2, max_trials=2)
    assert [a[1] for a in engine.asked] == [Compound("random", (3000 + i,)) for i in (1, 2, 3)]
    # Asked on the version space after the last trial, with the task's facts.
    assert engine.calls[-1] == ("next_experiment", "stub", ("vs", 2, "hg"),
                                [("facts_of", id(runner.the_task))])


@pytest.mark.parametrize("outcome,tool", [
    ("success", "t1"), ("failure", "t1"), ("blocked", "t1"),
    # A pose the arm could not carry out taught nothing: skipped whatever the tool.
    ("unreachable", "any"), ("invalid", "any"),
])
def test_paper_which_outcomes_taught_something(outcome, tool):
    pose = _experiment(literal="behind", negated=["behind"])
    _, engine, _ = _learn("paper", [pose, EXPLOIT], [outcome, "success", "success"],
                          changes=set())
    assert engine.asked[1][0] == [Compound("skip", (tool, ["behind"]))]


def test_paper_a_trial_that_changed_h_s_only_is_run_again():
    _, engine, _ = _learn("paper", [_experiment(literal="a"), EXPLOIT],
                          ["failure", "success", "success"], changes={1: "hs"})
    assert engine.asked[1][0] == []


def test_the_bounds_are_read_only_when_the_strategy_repeats_experiments():
    # paper: h_s and h_g before and after each experiment that taught; none around an
    # exploitation trial. informative never reads them in the loop.
    _, engine, _ = _learn("paper", [_experiment(literal="a"), _experiment(literal="b"),
                                    EXPLOIT], ["failure", "unreachable", "success", "success"])
    assert sum(c[0] == "vs_bounds" for c in engine.calls) == 3
    _, engine, _ = _learn("informative", [_experiment(literal="a"), _experiment(literal="b"),
                                          EXPLOIT], ["failure", "failure"])
    assert sum(c[0] == "vs_bounds" for c in engine.calls) == 0
