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
    """Proposes ``proposals[i - 1]`` for trial i (the last one once the script ends)."""

    proposals: list
    asked: list = field(default_factory=list)

    def vs_init(self, example):
        return ("vs", 0)

    def vs_count(self, vs):
        return 16, True

    def vs_bounds(self, vs):
        return "hs", f"hg{vs[1]}"

    def next_experiment(self, case, vs, facts, skip, strategy):
        self.asked.append((list(skip), strategy))
        i = len(self.asked)
        return self.proposals[min(i, len(self.proposals)) - 1]


class ScriptedRunner:
    """Answers trial i with ``outcomes[i - 1]``; a trial in ``changes`` changes h_g."""

    def __init__(self, engine, outcomes, changes=None, seed=3):
        self.engine, self.outcomes, self.seed = engine, outcomes, seed
        self.changes = set(range(1, len(outcomes) + 1)) if changes is None else changes
        self.case = "stub"
        self.trials = []
        self.locations = 0
        self.manifest = SimpleNamespace(demonstration=SimpleNamespace(variant="v"))

    def progress(self, text):
        pass

    def task(self, variant):
        runner = self

        class Task:
            def next_location(self):
                runner.locations += 1
        return Task()

    def task_facts(self, task):
        return []

    def run(self, exp, phase, i, vs, task, decision):
        rec = SimpleNamespace(n=i, kind=exp.name, outcome=self.outcomes[i - 1])
        self.trials.append(rec)
        return rec, (("vs", i) if i in self.changes else vs)


class StubLearner(ToolUseLearner):
    def observe_demonstration(self):
        return [Compound("model", ("m",))], "example", "demo_tool"


def _learn(strategy, proposals, outcomes, max_trials=12, consecutive=2, changes=None):
    engine = ScriptedEngine(proposals)
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
    assert use.vs == ("vs", 0)


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

def test_the_registry_entries_exact():
    assert list(STRATEGIES) == ["paper", "informative", "random"]
    fields = {n: (s.name, s.stop, s.confirm, s.repeat_taught, s.pose_any_tool, s.seeded,
                  s.catalogue_first) for n, s in STRATEGIES.items()}
    assert fields == {
        "paper": ("paper", "confirmed", True, True, False, False, False),
        "informative": ("informative", "certified", False, False, True, False, True),
        "random": ("random", "exhausted", False, False, False, True, True),
    }
    assert STRATEGIES["paper"].summary == ("Algorithm 1: one literal per trial, "
                                           "K successes to stop")


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
                                     "paper, informative, random")
    assert isinstance(UnknownStrategy("x"), ValueError)
    with pytest.raises(UnknownStrategy):
        LearningOptions(strategy="nope")


def test_the_help_line_exact():
    assert strategies_help() == (
        "paper (Algorithm 1: one literal per trial, K successes to stop); "
        "informative (largest expected reduction of the version space, certified stop); "
        "random (a seeded draw among the experiments h_g covers)")
