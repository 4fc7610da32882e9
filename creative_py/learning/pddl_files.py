"""The run's own PDDL files: Prolog writes them with its plan, pyperplan solves them and
the two plans are compared (:func:`check_pddl`, :func:`created_pddl`; the solving is
:mod:`creative_py.learning.pddl_check`'s)."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, PrologError
from creative_py.learning.creation import CreateResult
from creative_py.learning.trials import TrialRunner, term_text
from creative_py.records.summary import PddlCheck

log = logging.getLogger(__name__)


def plan_steps(plan: Any) -> Optional[list[tuple[str, list[str]]]]:
    """Return the steps of the engine's ``plan(Steps)`` as (name, [args]), or None for a
    ``no_plan(Reason)``."""
    if not (isinstance(plan, Compound) and plan.name == "plan"):
        return None
    steps = []
    for step in plan.args[0]:
        if isinstance(step, Compound):
            steps.append((step.name, [str(a) for a in step.args]))
        else:
            steps.append((str(step), []))
    return steps


def check_pddl(folder: Path, domain: str, problem: str, plan: Any, variant: str,
               say: Callable[[str], None]) -> PddlCheck:
    """Solve the run's own PDDL files with pyperplan and compare with Prolog's plan
    (:func:`creative_py.learning.pddl_check.check_files`); the summary's check of one
    task (``pddl.use``, ``pddl.create``)."""
    from creative_py.learning.pddl_check import check_files

    record = check_files(folder / domain, folder / problem, plan_steps(plan))
    record["variant"] = variant
    record["prolog"] = term_text(plan)
    same = "equals Prolog's" if record["equals_prolog"] else "DIFFERS from Prolog's"
    say(f"pddl {problem}: {record['status']} by {record['planner']} "
        f"{' '.join(record['plan'])} ({same})")
    return PddlCheck.from_dict(record, "pddl")


def created_pddl(runner: TrialRunner, folder: Path, created: CreateResult,
                 models: Any, say: Callable[[str], None]) -> PddlCheck:
    """Write and check the harder task's PDDL: the created tool's model (the learned one
    with the replaced literal swapped for the created tool's value, or for the value of
    the catalogued object that solved the task) planning the harder variant, with the
    created tools in the catalogue, as ``domain_<variant>.pddl`` and
    ``problem_<variant>.pddl``.
    """
    from creative_py.learning.pddl_check import PLANNER_NAME

    task = runner.task(created.variant)
    domain, problem = f"domain_{created.variant}.pddl", f"problem_{created.variant}.pddl"
    names = [Compound("domain_name", (f"creative_{created.variant}",)),
             Compound("problem_name", (f"task_{created.variant}",))]
    try:
        plan = runner.engine.plan_models(
            runner.case, models, runner.task_facts(task),
            [Compound("pddl", (str(folder / domain), str(folder / problem))), *names])
    except PrologError as exc:
        log.warning("%s: the harder task's PDDL was not written: %s", folder, exc)
        return PddlCheck(domain=domain, problem=problem, status="error", plan=[],
                         equals_prolog=False, planner=PLANNER_NAME,
                         variant=created.variant, error=str(exc))
    say(f"plan ({created.variant}, created model): {term_text(plan)}")
    return check_pddl(folder, domain, problem, plan, created.variant, say)
