"""The phases of a run, each giving its part of the summary
(:class:`~creative_py.records.summary.RunSummary`): the demonstration and tool-use
learning (:func:`learn_to_use`), the learned model's plan and evaluation
(:func:`plan_and_evaluate`), tool creation on the harder variant (:func:`create`)."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound
from creative_py.learning.creation import CreateResult, ToolCreator
from creative_py.learning.options import RunOptions
from creative_py.learning.prior import load_prior
from creative_py.learning.pddl_files import check_pddl, created_pddl
from creative_py.learning.tool_use import LearningOptions, ToolUseLearner, UseResult
from creative_py.learning.trials import TrialRunner, term_text
from creative_py.records.summary import (CatalogueEntry, CreatedToolSummary, CreateSummary,
                                         Demonstration, Hypotheses, Outcomes, PddlCheck,
                                         PddlChecks, Prediction, PrintSummary,
                                         StrengthSummary, UsePhase, UsePrior,
                                         PriorDrop)
from creative_py.robots import load_profile

Say = Callable[[str], None]


def case_facts(manifest: Any, options: RunOptions) -> dict[str, Any]:
    """What the reports need of the case, written into ``summary.json`` so that they read
    the run folder alone: the unit of each pose number (``pose_units``), N of Algorithm 1
    as this run used it (``trial_budget``) and the paper's count of tool-use trials
    (``paper_trials``, None when the paper has no such case) and, where ``--robot``
    gave a profile by its ``.toml`` path, the profile's name (``robot_name``); fields of
    :class:`~creative_py.records.summary.RunSummary`."""
    facts = {"pose_units": {p.name: p.unit for p in manifest.pose_params},
             "trial_budget": options.max_trials or manifest.trial_budget,
             "paper_trials": manifest.paper_trials}
    if options.robot is not None:
        name = load_profile(options.robot).name
        if name != options.robot:
            facts["robot_name"] = name
    return facts


def learn_to_use(runner: TrialRunner, options: RunOptions, wall: dict[str, float],
                 say: Say) -> tuple[UseResult, dict[str, Any]]:
    """The demonstration and tool-use learning (Algorithm 1); write ``model.pl``; return
    the learner's result and the phase's fields of the summary (its wall time in
    ``wall``)."""
    engine, run = runner.engine, runner.run_folder
    lopts = LearningOptions(max_trials=options.max_trials or runner.manifest.trial_budget,
                            consecutive=options.consecutive, strategy=options.strategy)
    t0 = time.perf_counter()
    prior = load_prior(engine, runner.case, options.prior) if options.prior else None
    use = ToolUseLearner(runner, lopts, prior).learn()
    wall["use"] = round(time.perf_counter() - t0, 2)
    engine.write_model_file(run.path / "model.pl", runner.case, use.models, use.vs)
    hs, hg = runner.bounds(use.vs)
    say(f"h_s: {hs}")
    say(f"h_g: {hg}")
    return use, {
        "demonstration": Demonstration(tool=use.demo_tool),
        "use": UsePhase(trials=len(use.trials), converged=use.converged,
                        trials_to_converge=use.trials_to_converge,
                        strategy=options.strategy, stop=use.stop,
                        prior=(UsePrior(source=str(use.prior.source), case=use.prior.case,
                                        taken=list(use.prior_taken),
                                        dropped=[PriorDrop(literal=lit, trial=i)
                                                 for lit, i in use.prior_dropped],
                                        settled=[PriorDrop(literal=lit, trial=i)
                                                 for lit, i in use.prior_settled],
                                        confirmed=[PriorDrop(literal=lit, trial=i)
                                                   for lit, i in use.prior_confirmed])
                               if use.prior is not None else None)),
        # The version space after the demonstration, and the information-theoretic
        # bound: with binary outcomes, telling N0 hypotheses apart in the worst case
        # takes ceil(log2 N0) trials.
        "vs_count_initial": use.vs_count_initial,
        "vs_count_initial_exact": use.vs_count_initial_exact,
        "info_bound_trials": (use.vs_count_initial - 1).bit_length(),
        "vs_count_final": (use.trials[-1].vs_count if use.trials
                           else use.vs_count_initial),
        "hypotheses": Hypotheses(hs=hs, hg=hg),
    }


def plan_and_evaluate(runner: TrialRunner, use: UseResult, options: RunOptions,
                      wall: dict[str, float], say: Say) -> dict[str, Any]:
    """Plan the task with the learned model (``domain.pddl``/``problem.pddl``, solved by
    pyperplan and compared), then evaluate the model on fresh trials; return the
    summary's ``plan``, ``pddl`` and ``eval``."""
    engine, path = runner.engine, runner.run_folder.path
    # Tool-use learning runs every trial on the demonstration's variant.
    task = runner.task(runner.manifest.demonstration.variant)
    plan = engine.plan_task(runner.case, use.models, use.vs, runner.task_facts(task),
                            [Compound("pddl", (str(path / "domain.pddl"),
                                               str(path / "problem.pddl")))])
    say(f"plan: {term_text(plan)}")
    pddl = PddlChecks(use=check_pddl(path, "domain.pddl", "problem.pddl", plan,
                                     task.variant, say))
    # Evaluation of the learned model: the planner's own tool and pose choice.
    t0 = time.perf_counter()
    evaluation = _evaluate(runner, use, options.eval_trials)
    wall["eval"] = round(time.perf_counter() - t0, 2)
    return {"plan": term_text(plan), "pddl": pddl, "eval": evaluation}


def create(runner: TrialRunner, use: UseResult, options: RunOptions,
           wall: dict[str, float], say: Say) -> tuple[CreateSummary, Optional[PddlCheck]]:
    """Tool creation (Algorithm 2) on the harder variant; the harder task's model in
    ``model.pl`` and its PDDL when a tool (catalogued or made) solved it. Return the
    summary's ``create`` and ``pddl.create`` (None when nothing solved the task)."""
    engine, path = runner.engine, runner.run_folder.path
    t0 = time.perf_counter()
    creator = ToolCreator(runner, eval_trials=options.create_eval_trials,
                          catalogue_first=options.tries_catalogue,
                          demonstrate=options.demonstrate_creation)
    created = creator.create(use.vs, runner.manifest.harder_variant)
    wall["create"] = round(time.perf_counter() - t0, 2)
    if created.instance is None:
        return creation_summary(created, path), None
    models = engine.created_models(use.models, use.vs, created.replaced, created.instance)
    engine.write_model_file(path / "model.pl", runner.case, use.models, use.vs,
                            [Compound("created", (created.variant, models))])
    summary = creation_summary(created, path, [term_text(m) for m in models])
    return summary, created_pddl(runner, path, created, models, say)


def _evaluate(runner: TrialRunner, use: UseResult, n: int) -> Outcomes:
    """Run ``n`` trials of the learned model over the locations, no learning."""
    outcomes = []
    task = runner.task(runner.manifest.demonstration.variant)
    for i in range(1, n + 1):
        plan = runner.engine.plan_use(runner.case, use.vs, runner.task_facts(task))
        if not isinstance(plan, Compound) or plan.name != "exploit":
            outcomes.append("no_plan")
            continue
        rec, _ = runner.run(plan, "eval", i, use.vs, task, 0.0, label=False)
        outcomes.append(rec.outcome)
        task.next_location()
    return Outcomes.of(outcomes, trials=n)


def creation_summary(res: CreateResult, run_dir: Path,
                     model: Optional[list[str]] = None) -> CreateSummary:
    """The summary's ``create``, with the harder task's ``model`` when a tool solved it;
    the created tools' file names relative to the run folder (the folder can be
    moved)."""
    return CreateSummary(
        variant=res.variant,
        needed=res.needed,
        predicted=(None if res.predicted is None
                   else Prediction.from_dict(res.predicted, "create.predicted")),
        # The learned model's best tool was not tried: the geometry predicted its failure.
        predicted_failure_skipped=bool(res.predicted and res.predicted["feasible"] is False),
        trials=len([t for t in res.trials if t.phase == "create"]),
        failed_trials=len([t for t in res.trials
                           if t.phase == "create" and t.outcome != "success"]),
        created_tools=[_created_tool(c, run_dir) for c in res.created],
        slice_wall_time_s=round(sum(p.get("slice_wall_time_s", 0.0)
                                    for c in res.created
                                    for p in c.print.get("pieces", [])), 2),
        print_wall_time_s=round(sum(c.print.get("wall_time_s", 0.0)
                                    for c in res.created), 2),
        success=res.success.name if res.success else None,
        eval=res.success.eval_outcomes if res.success else [],
        exhausted=res.exhausted,
        exhausted_words=res.exhausted_words,
        # What solved the harder task: learned (TC trial 1), catalogue (an available
        # object the generalised model admits, tried before manufacturing), created or
        # None; the catalogued objects tried (or skipped), best first, with why.
        solved_by=res.solved_by,
        catalogue=[CatalogueEntry.from_dict(c, f"create.catalogue[{i}]")
                   for i, c in enumerate(res.catalogue)],
        catalogue_trials=len([c for c in res.catalogue if c["trial"] is not None]),
        catalogue_success=next((c["tool"] for c in res.catalogue
                                if c["outcome"] == "success"), None),
        model=model,
    )


def _created_tool(c: Any, run_dir: Path) -> CreatedToolSummary:
    """A created tool (:class:`~creative_py.learning.creation.CreatedTool`) as the
    summary records it."""
    where = f"create.created_tools[{c.name}]"
    return CreatedToolSummary(
        name=c.name, replaced=c.replaced, general=c.general, instance=c.instance,
        structural=list(c.structural), dims=dict(c.dims),
        files=({k: _relative(run_dir, v) for k, v in c.files.items()}
               if isinstance(c.files, dict) else c.files),
        trial_outcome=c.trial_outcome, eval_outcomes=list(c.eval_outcomes),
        mass_kg=c.mass_kg, print=PrintSummary.from_dict(c.print, f"{where}.print"),
        strength=StrengthSummary.from_dict(c.strength, f"{where}.strength"),
        reason=c.reason or None)


def _relative(run_dir: Path, name: Any) -> Any:
    """A file name as a POSIX path relative to the run folder when it is inside it; any
    other value as it is."""
    if not isinstance(name, (str, Path)):
        return name
    path = Path(name)
    try:
        return path.resolve().relative_to(Path(run_dir).resolve()).as_posix()
    except ValueError:
        return str(name)
