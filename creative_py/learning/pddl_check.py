"""Check the PDDL that Prolog writes with an off-the-shelf planner and validator.

The learned action models, the task's initial state and its goal are written by
``prolog/pddl.pl`` as ``domain.pddl`` and ``problem.pddl``.  This module is the one home
of the third-party PDDL engine: unified-planning parses the files and validates a plan
semantically (each action's preconditions in its state, the goal at the end), and its
pyperplan engine (``up-pyperplan``) solves the task, after unified-planning's
negative-conditions compiler when the domain has negative preconditions and its
grounder, so that the plan is deterministic and comparable with the Prolog planner's
(:func:`solve`). :func:`check_files` is what a run calls on its own files.

Plan steps are ``(action_name, [arg, ...])`` tuples of strings, e.g.
``("pull_out", ["hook_a2", "cube1", "tube1"])``.  No geometry is involved: PDDL
objects and predicates are qualitative (no units, no frames).
"""

from __future__ import annotations

import logging
from collections.abc import Sequence
from pathlib import Path
from typing import Union

from pyparsing import ParseBaseException
from unified_planning.engines import (
    CompilationKind,
    PlanGenerationResultStatus,
    ValidationResultStatus,
)
from unified_planning.exceptions import UPException
from unified_planning.io import PDDLReader
from unified_planning.model import Problem
from unified_planning.plans import ActionInstance, SequentialPlan
from unified_planning.shortcuts import Compiler, OneshotPlanner, PlanValidator, get_environment

log = logging.getLogger(__name__)

PathLike = Union[str, Path]
Step = tuple[str, list[str]]

PLANNER_NAME = "pyperplan"
"""The unified-planning engine used by solve()."""

PYPERPLAN_SEARCH = "bfs"
"""pyperplan's search: breadth-first, so a plan is a shortest one, the first in order."""

GROUNDER_NAME = "up_grounder"
"""unified-planning's grounder, which keeps the problem's object order."""

_SOLVED = (
    PlanGenerationResultStatus.SOLVED_SATISFICING,
    PlanGenerationResultStatus.SOLVED_OPTIMALLY,
)
_UNSOLVABLE = (
    PlanGenerationResultStatus.UNSOLVABLE_PROVEN,
    PlanGenerationResultStatus.UNSOLVABLE_INCOMPLETELY,
)


class PddlError(ValueError):
    """A PDDL file that cannot be read or a task the engine cannot handle."""


def _quiet_environment() -> None:
    """Stop unified-planning from printing its engine credits on stdout."""
    get_environment().credits_stream = None


def parse(domain_path: PathLike, problem_path: PathLike) -> Problem:
    """Return the unified-planning problem read from a PDDL domain and problem file.

    Raises
    ------
    PddlError
        If a file is missing or is not PDDL the reader accepts; the message names the
        files and the reader's error.
    """
    domain_path, problem_path = Path(domain_path), Path(problem_path)
    for path in (domain_path, problem_path):
        if not path.is_file():
            raise PddlError(f"{path}: no such PDDL file")
    _quiet_environment()
    try:
        return PDDLReader().parse_problem(str(domain_path), str(problem_path))
    except (UPException, ParseBaseException, SyntaxError, ValueError, KeyError) as exc:
        raise PddlError(f"{domain_path} + {problem_path}: cannot parse: {exc}") from exc


def _plan_from_steps(problem: Problem, steps: Sequence[Step]) -> SequentialPlan:
    """Return the plan of ``steps`` over ``problem``; raise PddlError naming a bad step."""
    instances = []
    for index, step in enumerate(steps, start=1):
        try:
            name, args = step
        except (TypeError, ValueError) as exc:
            raise PddlError(f"plan step {index}: {step!r} is not (action_name, [args])") from exc
        if not problem.has_action(name):
            raise PddlError(f"plan step {index}: unknown action {name!r}")
        action = problem.action(name)
        if len(args) != len(action.parameters):
            raise PddlError(
                f"plan step {index}: {name} takes {len(action.parameters)} arguments, "
                f"got {len(args)}"
            )
        objects = []
        for arg in args:
            if not problem.has_object(arg):
                raise PddlError(f"plan step {index}: unknown object {arg!r}")
            objects.append(problem.object(arg))
        try:
            instances.append(ActionInstance(action, tuple(objects)))
        except UPException as exc:
            raise PddlError(f"plan step {index}: {name}{tuple(args)}: {exc}") from exc
    return SequentialPlan(instances)


def validate_plan(
    domain: PathLike, problem: PathLike, plan_steps: Sequence[Step]
) -> tuple[bool, str]:
    """Return whether ``plan_steps`` solve the task, and why not.

    The plan is checked semantically by unified-planning's sequential validator: every
    action must be applicable in the state the previous ones produce and the goal must
    hold at the end.  A step naming an unknown action or object, or with the wrong
    number of arguments, makes the plan invalid.

    Returns
    -------
    (valid, reason)
        ``reason`` is ``"valid"`` or the validator's explanation (for example which
        precondition of which step failed).
    """
    task = parse(domain, problem)
    try:
        plan = _plan_from_steps(task, plan_steps)
    except PddlError as exc:
        return False, str(exc)
    with PlanValidator(problem_kind=task.kind, plan_kind=plan.kind) as validator:
        result = validator.validate(task, plan)
    if result.status == ValidationResultStatus.VALID:
        return True, "valid"
    messages = "; ".join(str(m) for m in (result.log_messages or []))
    reason = getattr(result, "reason", None)
    text = f"{reason.name.lower()}: {messages}" if reason is not None else messages
    return False, text or "invalid"


def solve(domain: PathLike, problem: PathLike) -> list[Step] | None:
    """Return a plan for the task found by pyperplan, or None if it has none.

    A domain with negative preconditions is first compiled by unified-planning's
    negative-conditions remover. The task is then grounded by unified-planning's own
    grounder (``up_grounder``: every action instance, objects in the problem's order)
    and solved by pyperplan's breadth-first search (:data:`PYPERPLAN_SEARCH`), and the
    plan is mapped back to the original actions. So the plan is a shortest one and,
    among those, the first in the domain's action order and the problem's object order
    (the objects are written sorted by name): the tie-break of the Prolog planner
    (``prolog/planner.pl``: tools in the standard order of their names), which makes
    the two plans comparable step for step. Left to its own grounding, pyperplan
    orders the objects by Python's string hashes, so its choice among equally good
    tools changes from process to process.

    Raises
    ------
    PddlError
        If the files cannot be parsed or the engine stops without an answer.
    """
    task = parse(domain, problem)
    map_backs = []
    compilations = [CompilationKind.GROUNDING]
    if task.kind.has_negative_conditions():
        compilations.insert(0, CompilationKind.NEGATIVE_CONDITIONS_REMOVING)
    for kind in compilations:
        if kind == CompilationKind.GROUNDING:
            # Without static-fluent pruning: unified-planning 1.3's pruning raises
            # "list.remove(x): x not in list" when two static preconditions rule out
            # the same object; pyperplan's own relevance analysis prunes instead.
            options = {"name": GROUNDER_NAME, "params": {"prune_actions": False}}
        else:
            options = {}
        with Compiler(**options, problem_kind=task.kind, compilation_kind=kind) as compiler:
            compiled = compiler.compile(task, kind)
        task = compiled.problem
        map_backs.append(compiled.map_back_action_instance)
    with OneshotPlanner(name=PLANNER_NAME, params={"search": PYPERPLAN_SEARCH}) as planner:
        result = planner.solve(task)
    if result.status in _UNSOLVABLE:
        log.info("%s: no plan (%s)", problem, result.status.name)
        return None
    if result.status not in _SOLVED or result.plan is None:
        raise PddlError(f"{problem}: {PLANNER_NAME} stopped with {result.status.name}")
    plan = result.plan
    for map_back in reversed(map_backs):
        plan = plan.replace_action_instances(map_back)
    steps = [
        (ai.action.name, [p.object().name for p in ai.actual_parameters]) for ai in plan.actions
    ]
    log.info("%s: %s found %d steps", problem, PLANNER_NAME, len(steps))
    return steps


def step_text(step: Step) -> str:
    """Return a plan step in the plan-file form ``(name arg ...)``."""
    name, args = step
    return "(" + " ".join([name, *args]) + ")"


def check_files(domain: PathLike, problem: PathLike,
                prolog_plan: Sequence[Step] | None) -> dict:
    """Solve a run's own PDDL files with pyperplan and compare with the Prolog plan.

    Never raises for a PDDL problem: an unsolvable task, a planner error or a plan that
    differs from Prolog's is logged as a warning and recorded.

    Parameters
    ----------
    domain, problem : path
        The files Prolog wrote (``prolog/pddl.pl``).
    prolog_plan : list of steps or None
        The Prolog planner's plan of the same task (None: Prolog found none).

    Returns
    -------
    dict
        ``{"domain": file name, "problem": file name, "status": "solved" | "unsolvable"
        | "error", "plan": [step text, ...], "equals_prolog": bool, "planner":
        "pyperplan"}``; ``equals_prolog`` is true when both planners give the same
        steps (action names and arguments, in order) or both find no plan.  Also
        ``prolog_plan`` (step texts), ``prolog_plan_valid`` (whether unified-planning's
        validator accepts the Prolog plan in the PDDL task) and, on an error, ``error``.
    """
    domain, problem = Path(domain), Path(problem)
    record: dict = {"domain": domain.name, "problem": problem.name, "status": "error",
                    "plan": [], "equals_prolog": False, "planner": PLANNER_NAME,
                    "prolog_plan": ([step_text(s) for s in prolog_plan]
                                    if prolog_plan is not None else None)}
    try:
        steps = solve(domain, problem)
        if prolog_plan is not None:
            record["prolog_plan_valid"] = validate_plan(domain, problem, prolog_plan)[0]
    except (PddlError, UPException) as exc:
        record["error"] = str(exc)
        log.warning("%s: %s could not solve its own PDDL: %s", problem, PLANNER_NAME, exc)
        return record
    if steps is None:
        record["status"] = "unsolvable"
        record["equals_prolog"] = prolog_plan is None
        log.warning("%s: %s finds no plan for the run's own PDDL", problem, PLANNER_NAME)
        return record
    record["status"] = "solved"
    record["plan"] = [step_text(s) for s in steps]
    record["equals_prolog"] = prolog_plan is not None and [
        (n, list(a)) for n, a in prolog_plan] == steps
    if not record["equals_prolog"]:
        log.warning("%s: %s's plan %s differs from Prolog's %s", problem, PLANNER_NAME,
                    " ".join(record["plan"]), record["prolog_plan"])
    return record
