"""The learning loop (:class:`ToolUseLearner`) with each experiment strategy, in the physics.

Short real runs of the rake case (about a second a trial): ``informative`` to its
certified stop and ``random`` for a few trials (``test_learning_loop.py`` runs
``paper``). The checks are on what the
loop does with Prolog's choices: when it stops, what it records (the version space's
count after every trial), and that ``random`` only draws experiments h_g covers.

Strategies are values (:mod:`creative_py.learning.strategies`): the tests at the end
add strategies of their own, each one registry entry and one Prolog clause group
written here, and run them through the real engine and loop.
"""

import re

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.case import get_case
from creative_py.learning.options import RunOptions
from creative_py.learning.strategies import STRATEGIES, Strategy, UnknownStrategy
from creative_py.learning.tool_use import LearningOptions, ToolUseLearner
from creative_py.learning.trials import TrialRunner
from creative_py.backends.pybullet import load_world

pytestmark = pytest.mark.sim


def _learn(strategy, max_trials, seed=0, consecutive=2):
    runner = TrialRunner(Engine.instance(), load_world(get_case("rake")), None, seed=seed)
    return ToolUseLearner(runner, LearningOptions(max_trials=max_trials,
                                                  consecutive=consecutive,
                                                  strategy=strategy)).learn()


def _names(clause_text):
    body = clause_text.split(":-", 1)[1] if ":-" in clause_text else ""
    return set(re.findall(r"(\w+)\(", body))


@pytest.fixture(scope="module")
def informative():
    return _learn("informative", 10)


def test_informative_stops_certified_without_confirmation_trials(informative):
    use = informative
    assert use.stop == "certified" and use.converged
    # Every trial tested something: no exploit (confirmation) trial was run.
    assert [t.kind for t in use.trials] == ["experiment"] * len(use.trials)
    assert use.trials_to_converge == len(use.trials)
    # The paper's strategy takes 7 here (6 tests, then a confirmation).
    assert len(use.trials) <= 6
    hg = use.trials[-1].hg
    for literal in ("handle_length(_G3,medium)", "hook_length(_G3,short)", "hook_down(_G3)",
                    "behind(_G3,_G4)", "centred_on(_G3,_G4)"):
        assert literal in hg


def test_informative_records_the_count_after_every_trial(informative):
    use = informative
    counts = [t.vs_count for t in use.trials]
    assert all(t.vs_count_exact is True for t in use.trials)
    # The demonstration leaves 2^14 hypotheses (14 literals of h_s); no trial adds one,
    # and every trial the strategy chose removed some.
    assert use.vs_count_initial == 2 ** 14
    steps = [use.vs_count_initial] + counts
    assert all(b < a for a, b in zip(steps, steps[1:])), steps
    assert counts[-1] >= 1


def test_random_draws_experiments_that_hg_covers():
    use = _learn("random", 3, seed=1)
    assert len(use.trials) == 3 and use.stop == "budget"
    assert len({(t.tool, tuple(t.violated)) for t in use.trials}) == 3    # no repeat
    before = "tool_pose(_G3,_G4,_G5)"
    for t in use.trials:
        assert t.kind == "experiment"
        # h_g before the trial covered the planned example: it violates no literal
        # of h_g (the literals' names suffice in this case: each appears once).
        assert not _names(before) & {v.split("(")[0] for v in t.violated}, (before, t)
        before = t.hg


def test_the_run_options_name_the_strategies():
    assert RunOptions().strategy == "informative"
    names = ", ".join(STRATEGIES)       # the registry's, whatever it holds
    assert names.startswith("paper, informative, random")
    for options in (RunOptions, LearningOptions):
        with pytest.raises(UnknownStrategy, match=re.escape(
                f"unknown strategy 'not_a_strategy'; strategies: {names}")):
            options(strategy="not_a_strategy")
        for name in STRATEGIES:
            assert options(strategy=name).strategy == name


def test_the_shipped_strategies_are_declared_in_prolog():
    declared = Engine.instance().experiment_strategies()
    for shipped in ("paper", "informative", Compound("random", ("integer",))):
        assert shipped in declared
    assert STRATEGIES["random"].term(3, 4) == Compound("random", (3004,))


@pytest.mark.parametrize("name", list(STRATEGIES))
def test_every_registered_strategy_s_term_is_one_prolog_declares(name):
    """The contract of a registry entry with Prolog: the term it sends has the shape
    of an ``experiment:experiment_strategy/1`` declaration (its clause group)."""
    declared = Engine.instance().experiment_strategies()
    shapes = {d if isinstance(d, str) else (d.name, len(d.args)) for d in declared}
    term = STRATEGIES[name].term(3, 4)
    assert (term if isinstance(term, str) else (term.name, len(term.args))) in shapes


def test_the_registry_s_skip_rules():
    """What each strategy does not run again: the paper repeats a taught experiment
    unless it was idle; the others never repeat one; a pose the arm could not carry
    out is left out with every tool, and informative leaves out every pose test it
    ran with every tool."""
    pose = Compound("experiment", ("t1", "behind(t1,c)", [], "p", [], ["behind(t1,c)"]))
    obj = Compound("experiment", ("t2", "hook(t2)", [], "p", [], []))
    paper, informative, random = (STRATEGIES[n] for n in ("paper", "informative", "random"))
    assert paper.skip(obj, taught=True, idle=False) is None
    assert paper.skip(obj, taught=True, idle=True) == Compound("skip", ("t2", "hook(t2)"))
    assert paper.skip(pose, taught=False, idle=False) == Compound("skip", ("any",
                                                                           "behind(t1,c)"))
    assert random.skip(obj, taught=True, idle=False) == Compound("skip", ("t2", "hook(t2)"))
    assert random.skip(pose, taught=True, idle=False) == Compound("skip", ("t1",
                                                                           "behind(t1,c)"))
    assert informative.skip(pose, taught=True, idle=False) == Compound("skip", (
        "any", "behind(t1,c)"))


def test_paper_does_not_repeat_an_experiment_that_left_the_space_as_it_was():
    """Algorithm 1 repeats the task after a failure, but an experiment whose trial left
    h_s and h_g unchanged (what the robot observed was already excluded: in a drawn
    hook world a stick seen outside the tube) would give the same answer until the
    budget is spent. Here every trial is made to leave the version space as it was."""
    runner = TrialRunner(Engine.instance(), load_world(get_case("rake")), None, seed=0)
    real_run = runner.run
    chosen = []

    def idle_run(exp, phase, i, vs, task, decision):
        rec, _new_vs = real_run(exp, phase, i, vs, task, decision)
        chosen.append((str(exp.args[0]), str(exp.args[1])))
        return rec, vs                      # the trial taught nothing

    runner.run = idle_run
    use = ToolUseLearner(runner, LearningOptions(max_trials=4, strategy="paper")).learn()
    assert len(use.trials) == 4
    assert len(set(chosen)) == len(chosen), chosen


# Strategies defined here, as a new one is added: one Prolog clause group (consulted into
# the engine) and one registry entry. ``reversed`` takes the paper's candidates in
# reverse order; ``idle`` never proposes an experiment (it has no choice clause).
TEST_STRATEGIES_PL = """
experiment:experiment_strategy(reversed).
experiment:strategy_experiment(reversed, Problem, Experiment) :-
    experiment:paper_candidates(Problem, Cands0),
    reverse(Cands0, Cands),
    experiment:feasible_experiment(Problem, Cands, Experiment).

experiment:experiment_strategy(idle).
"""


@pytest.fixture(scope="module")
def test_strategies(tmp_path_factory):
    path = tmp_path_factory.mktemp("strategies") / "test_strategies.pl"
    path.write_text(TEST_STRATEGIES_PL)
    Engine.instance(load=[path])
    with pytest.MonkeyPatch.context() as mp:
        mp.setitem(STRATEGIES, "reversed",
                   Strategy("reversed", "the paper's order reversed", stop="exhausted"))
        mp.setitem(STRATEGIES, "idle", Strategy("idle", "no experiment", stop="exhausted"))
        yield


def test_a_strategy_defined_by_a_test_runs_through_the_engine_and_the_loop(test_strategies):
    assert RunOptions(strategy="reversed").strategy == "reversed"
    assert "reversed" in Engine.instance().experiment_strategies()
    use = _learn("reversed", 3)
    chosen = [(t.tool, tuple(t.tested)) for t in use.trials]
    assert len(chosen) == 3 and use.stop == "budget"
    assert len(set(chosen)) == 3                           # the registry's skip rule
    # The paper's first experiment (test_learning_loop.py) is rake_a1's handle alone;
    # its last candidates violate the most literals of h_s, so reversed starts there.
    assert chosen[0] != ("rake_a1", ("handle_length(rake_a1,medium)",))
    assert len(use.trials[0].violated) > 1


def test_the_registry_s_stop_rule_applies_to_a_test_strategy(test_strategies):
    """No experiment proposed: a strategy that does not confirm stops at once with its
    stop word; one that confirms uses the learned model until K successes."""
    use = _learn("idle", 3)
    assert (use.trials, use.stop, use.converged, use.trials_to_converge) == (
        [], "exhausted", True, 0)
    STRATEGIES["idle"] = Strategy("idle", "no experiment", stop="confirmed", confirm=True)
    use = _learn("idle", 3, consecutive=1)
    assert [(t.kind, t.outcome) for t in use.trials] == [("exploit", "success")]
    assert (use.stop, use.converged, use.trials_to_converge) == ("confirmed", True, 0)
