"""Catalogued objects before manufacturing (issue 16, item 1).

With the real engine and the hook case's own catalogue, no arm: after the short hook
failed during tool-use learning, h_g holds ``handle_length(T, medium)``; in the long tube
the generalised model (``any_length(T)``) admits the long and the short objects, the
long ones first (creation would make a long handle first), by name as the planner
orders them, and the refuted short ones last. The trials themselves are stubbed here (the whole runs measure the physics):
what is checked is the order, the reach pre-check and the stop at the first success.
"""

from types import SimpleNamespace

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.case import get_case
from creative_py.learning.creation import ToolCreator
from creative_py.learning.trials import TrialRunner
from creative_py.backends.pybullet import load_world

pytestmark = pytest.mark.sim

# h_s of a hook run, for the demonstrated hook_a2 (the world's own structural literals).
LITERALS = ["hook({t})", "hook_like({t})", "tool({t})", "handle_length({t},{length})",
            "handle_width({t},thin)", "hook_angle({t},right)", "hook_length({t},long)",
            "hook_side({t},right)", "hook_width({t},wide)", "in_tube({t},tube1)",
            "behind({t},cube1)", "centred_on({t},cube1)", "hook_down({t})",
            "in_tube(cube1,tube1)"]


def _example(engine, tool, length):
    body = ", ".join(lit.format(t=tool, length=length) for lit in LITERALS)
    return engine.parse(f"(tool_pose({tool},cube1,tube1) :- {body})")


@pytest.fixture(scope="module")
def setting():
    world = load_world(get_case("hook"))
    runner = TrialRunner(Engine.instance(), world, None)
    engine = runner.engine
    vs = engine.vs_init(_example(engine, "hook_a2", "medium"))
    # The short hook failed: h_g holds handle_length(T, medium).
    vs = engine.vs_update(vs, Compound("neg", (_example(engine, "hook_a1", "short"),)))
    return runner, vs


def _values(engine, runner, vs):
    reply = engine.catalogue_first("hook", vs, runner.task_facts(runner.task("long_tube")),
                                   ["hook_a2"])
    assert reply.name == "catalogue", reply
    replaced, general, items = reply.args
    return str(replaced), str(general), [(str(i.args[0]), str(i.args[1])) for i in items]


def test_long_objects_first_medium_and_tried_left_out(setting):
    runner, vs = setting
    replaced, general, items = _values(runner.engine, runner, vs)
    assert replaced.startswith("handle_length(") and replaced.endswith(",medium)")
    assert general.startswith("any_length(")
    names = [n for n, _ in items]
    assert "hook_a2" not in names                             # TC trial 1's tool
    assert not any(v.endswith(",medium)") for _, v in items)   # the replaced value
    lengths = [v.rsplit(",", 1)[1].rstrip(")") for _, v in items]
    assert lengths == sorted(lengths, key=["long", "short"].index), items
    # The long ones by name (the planner's tie-break: hook_a4, which the harder task's
    # plan with the created model picks, comes first), then the short ones.
    assert names == ["hook_a4", "hook_b4", "stick_b5", "hook_a1", "hook_b1"], items


def test_try_catalogue_skips_the_unreachable_and_stops_at_the_first_success(setting):
    runner, vs = setting
    creator = ToolCreator(runner, catalogue_first=True)
    _, _, items = _values(runner.engine, runner, vs)
    longs = [n for n, v in items if v.endswith(",long)")]
    assert len(longs) >= 2, items
    outcomes = {longs[0]: "failure", longs[1]: "success"}
    ran = []

    def run(use, phase, n, vs_, task, decision, label=True):
        tool = str(use.args[0])
        ran.append((tool, phase, n, label))
        return SimpleNamespace(outcome=outcomes.get(tool, "failure"), trial=len(ran),
                               reason="stub"), vs_

    runner.run = run
    try:
        out, solved, n = creator._try_catalogue(vs, runner.task("long_tube"), ["hook_a2"], 1)
    finally:
        del runner.run
    assert ran == [(longs[0], "create", 2, False), (longs[1], "create", 3, False)]
    assert n == 3
    assert solved is not None and str(solved[1]) == f"handle_length({longs[1]},long)"
    assert [e["tool"] for e in out] == longs[:2]
    assert out[0]["outcome"] == "failure" and out[1]["outcome"] == "success"
    assert all("catalogued object admitted by any_length(" in e["why"] for e in out)
    assert out[0]["predicted"]["feasible"] is True


def test_short_objects_are_predicted_out_of_reach(setting):
    runner, vs = setting
    creator = ToolCreator(runner, catalogue_first=True)

    def run(use, *a, **k):
        return SimpleNamespace(outcome="failure", trial=0, reason="stub"), vs

    runner.run = run
    try:
        out, solved, _ = creator._try_catalogue(vs, runner.task("long_tube"), ["hook_a2"], 1)
    finally:
        del runner.run
    assert solved is None
    short = [e for e in out if e["value"].endswith(",short)")]
    assert short and all(e["outcome"] == "predicted_unreachable" and e["trial"] is None
                         for e in short)


def test_catalogue_first_is_off_under_the_paper_strategy_unless_asked():
    from creative_py.learning.options import RunOptions

    assert RunOptions().tries_catalogue is True
    assert RunOptions(strategy="paper").tries_catalogue is False
    assert RunOptions(strategy="paper", catalogue_first=True).tries_catalogue is True
    assert RunOptions(catalogue_first=False).tries_catalogue is False
    assert RunOptions().demonstrate_creation is False
    with pytest.raises(ValueError, match="catalogue_first"):
        RunOptions(catalogue_first="yes")
