"""The learning loop (:class:`ToolUseLearner`) with each experiment strategy, in the physics.

Short real runs of the rake case (about a second a trial): ``informative`` to its
certified stop and ``random`` for a few trials (``test_learning_loop.py`` runs
``paper``). The checks are on what the
loop does with Prolog's choices: when it stops, what it records (the version space's
count after every trial), and that ``random`` only draws experiments h_g covers.
"""

import re

import pytest

from creative_py.bridge import Engine
from creative_py.case import get_case
from creative_py.learning.run import RunOptions
from creative_py.learning.tool_use import STRATEGIES, LearningOptions, ToolUseLearner
from creative_py.learning.trials import TrialRunner
from creative_py.sim import load_world

pytestmark = pytest.mark.sim


def _learn(strategy, max_trials, seed=0):
    runner = TrialRunner(Engine.instance(), load_world(get_case("rake")), None, seed=seed)
    return ToolUseLearner(runner, LearningOptions(max_trials=max_trials,
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
    assert STRATEGIES == ("paper", "informative", "random")
    assert RunOptions().strategy == "informative"
    with pytest.raises(ValueError, match="strategy"):
        RunOptions(strategy="clever")
    with pytest.raises(ValueError, match="strategy"):
        LearningOptions(strategy="clever")


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
