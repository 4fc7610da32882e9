"""One run of a case end to end: demonstration, tool-use learning, tool creation.

:func:`run_case` is what ``creative run hook`` and ``make hook`` call. It writes the run
folder described in :mod:`creative_py.learning.run_folder` as it goes, so an interrupted
run leaves a readable ``trials.jsonl`` of the finished trials.
"""

from __future__ import annotations

import logging
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, Engine
from creative_py.learning.creation import CreateResult, ToolCreator
from creative_py.learning.run_folder import RunFolder
from creative_py.learning.tool_use import (
    LearningOptions, TaskState, ToolUseLearner, UseResult, term_text,
)
from creative_py.report import plot_trials, summarise_trials

log = logging.getLogger(__name__)

HARDER_VARIANT = {"hook": "long_tube", "wedge": "big_door"}
"""The task variant that needs a new tool in each case."""

DEFAULT_TRIALS = {"hook": 12, "wedge": 9}
"""The paper's tool-use trial budget per case (Figures 5 and 6): N of Algorithm 1."""

PHASES = ("use", "create", "all")


@dataclass(frozen=True)
class RunOptions:
    """Options of one run.

    Parameters
    ----------
    seed : int
        Seed of the physics and sensor noise.
    phase : {"use", "create", "all"}
        ``use``: demonstration and tool-use learning only; ``create`` and ``all``: then
        tool creation on the harder variant.
    max_trials : int or None
        N of Algorithm 1 (default: the paper's budget, 12 for the hook, 9 for the wedge).
    consecutive : int
        K of Algorithm 1: consecutive successes needed once nothing is left to test.
    eval_trials : int
        Evaluation trials of the learned model after tool-use learning (planner's own
        tool and pose choice), over the predefined locations.
    create_eval_trials : int
        Evaluation trials of a successful created tool (paper: 5).
    """

    seed: int = 0
    phase: str = "all"
    max_trials: Optional[int] = None
    consecutive: int = 2
    eval_trials: int = 4
    create_eval_trials: int = 5


def run_case(case: str, out: Path = Path("runs"), options: RunOptions = RunOptions(),
             progress: Optional[Callable[[str], None]] = None,
             world_dir: Optional[Path] = None, run_name: Optional[str] = None) -> RunFolder:
    """Run one case end to end and return its run folder.

    Parameters
    ----------
    case : {"hook", "wedge"}
    out : Path
        Parent folder of the run folder.
    options : RunOptions
    progress : callable or None
        Receives one line of text per step (the CLI shows it).
    world_dir : Path or None
        A world folder other than the shipped ``worlds/<case>``.
    """
    from creative_py.sim.trial import load_case_world

    if case not in HARDER_VARIANT:
        raise ValueError(f"unknown case {case!r}; cases: {', '.join(HARDER_VARIANT)}")
    if options.phase not in PHASES:
        raise ValueError(f"unknown phase {options.phase!r}; phases: {', '.join(PHASES)}")
    say = progress or (lambda _m: None)
    t_start = time.perf_counter()
    world = load_case_world(case, world_dir)
    run = RunFolder.create(Path(out), case, options.seed, run_name)
    say(f"run folder {run.path}")
    engine = Engine.instance()
    lopts = LearningOptions(max_trials=options.max_trials or DEFAULT_TRIALS[case],
                            consecutive=options.consecutive, seed=options.seed)
    summary: dict[str, Any] = {"case": case, "seed": options.seed, "phase": options.phase,
                               "options": asdict(options), "wall_time_s": {}}

    # Demonstration and tool-use learning (Algorithm 1).
    t0 = time.perf_counter()
    learner = ToolUseLearner(engine, case, world, run, lopts, say)
    use = learner.learn()
    summary["wall_time_s"]["use"] = round(time.perf_counter() - t0, 2)
    summary["demonstration"] = {"tool": use.demo_tool}
    summary["use"] = {"trials": len(use.trials), "converged": use.converged,
                      "trials_to_converge": use.trials_to_converge}
    _write_model(engine, run, case, use)
    hs, hg = learner._bounds(use.vs)
    summary["hypotheses"] = {"hs": hs, "hg": hg}
    say(f"h_s: {hs}")
    say(f"h_g: {hg}")

    # The learned model planning the standard task (PDDL written for every run).
    task = TaskState(use.trials[-1].variant if use.trials else "standard",
                     *learner._locations())
    facts = learner.task_facts(task)
    plan = engine.call("plan_task", case, use.models, use.vs, facts,
                       [Compound("pddl", (str(run.path / "domain.pddl"),
                                          str(run.path / "problem.pddl")))])
    summary["plan"] = term_text(plan)
    say(f"plan: {term_text(plan)}")

    # Evaluation of the learned model: the planner's own tool and pose choice.
    t0 = time.perf_counter()
    summary["eval"] = _evaluate(learner, use, options.eval_trials)
    summary["wall_time_s"]["eval"] = round(time.perf_counter() - t0, 2)

    # Tool creation (Algorithm 2) on the harder variant.
    vs = use.vs
    if options.phase in ("create", "all"):
        t0 = time.perf_counter()
        creator = ToolCreator(engine, case, learner.world, run, lopts, say,
                              previous=learner.trials,
                              eval_trials=options.create_eval_trials)
        created = creator.create(use.vs, HARDER_VARIANT[case])
        vs = created.vs
        summary["wall_time_s"]["create"] = round(time.perf_counter() - t0, 2)
        summary["create"] = _creation_summary(created)
        if created.success is not None:
            models = engine.call("created_models", use.models, use.vs, created.replaced,
                                 created.instance)
            engine.call("write_model_file", str(run.path / "model.pl"), case, use.models,
                        use.vs, [Compound("created", (created.variant, models))])
            summary["create"]["model"] = [term_text(m) for m in models]
        trials = creator.trials
    else:
        trials = learner.trials
    summary["trials"] = summarise_trials([t.as_dict() for t in trials])
    summary["wall_time_s"]["total"] = round(time.perf_counter() - t_start, 2)
    plot_trials([t.as_dict() for t in trials], run.path / "trials.png",
                title=f"CREATIVE-py, {case} case, seed {options.seed}")
    run.write_json("summary.json", summary)
    say(f"done in {summary['wall_time_s']['total']} s: {run.path}")
    return run


def _write_model(engine: Engine, run: RunFolder, case: str, use: UseResult) -> None:
    engine.call("write_model_file", str(run.path / "model.pl"), case, use.models, use.vs)


def _evaluate(learner: ToolUseLearner, use: UseResult, n: int) -> dict[str, Any]:
    """Run ``n`` trials of the learned model over the locations, no learning."""
    outcomes = []
    task = TaskState("standard", *learner._locations())
    for i in range(1, n + 1):
        plan = learner.engine.call("plan_use", learner.case, use.vs,
                                   learner.task_facts(task), [])
        if not isinstance(plan, Compound) or plan.name != "exploit":
            outcomes.append("no_plan")
            continue
        rec, _ = learner._run_experiment(len(learner.trials) + 1, "eval", i, plan, use.vs,
                                         task, 0.0, label=False)
        outcomes.append(rec.outcome)
        task.next_location()
    return {"trials": n, "successes": outcomes.count("success"), "outcomes": outcomes}


def _creation_summary(res: CreateResult) -> dict[str, Any]:
    return {
        "variant": res.variant,
        "needed": res.needed,
        "trials": len([t for t in res.trials if t.phase == "create"]),
        "failed_trials": len([t for t in res.trials
                              if t.phase == "create" and t.outcome != "success"]),
        "created_tools": [asdict(c) for c in res.created],
        "success": res.success.name if res.success else None,
        "eval": res.success.eval_outcomes if res.success else [],
        "exhausted": res.exhausted,
    }
