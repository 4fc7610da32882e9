"""Check the PDDL that Prolog writes with an off-the-shelf planner and validator.

The learned action models, the task's initial state and its goal are written by
``prolog/pddl.pl`` as ``domain.pddl`` and ``problem.pddl``.  This module is the one home
of the third-party PDDL engine: unified-planning parses the files and validates a plan
semantically (each action's preconditions in its state, the goal at the end), and its
pyperplan engine (``up-pyperplan``) solves the task, after unified-planning's
negative-conditions compiler when the domain has negative preconditions.

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
    negative-conditions remover, and the plan is mapped back to the original actions.

    Raises
    ------
    PddlError
        If the files cannot be parsed or the engine stops without an answer.
    """
    task = parse(domain, problem)
    map_back = None
    if task.kind.has_negative_conditions():
        with Compiler(
            problem_kind=task.kind,
            compilation_kind=CompilationKind.NEGATIVE_CONDITIONS_REMOVING,
        ) as compiler:
            compiled = compiler.compile(task, CompilationKind.NEGATIVE_CONDITIONS_REMOVING)
        task, map_back = compiled.problem, compiled.map_back_action_instance
    with OneshotPlanner(name=PLANNER_NAME) as planner:
        result = planner.solve(task)
    if result.status in _UNSOLVABLE:
        log.info("%s: no plan (%s)", problem, result.status.name)
        return None
    if result.status not in _SOLVED or result.plan is None:
        raise PddlError(f"{problem}: {PLANNER_NAME} stopped with {result.status.name}")
    plan = result.plan
    if map_back is not None:
        plan = plan.replace_action_instances(map_back)
    steps = [
        (ai.action.name, [p.object().name for p in ai.actual_parameters]) for ai in plan.actions
    ]
    log.info("%s: %s found %d steps", problem, PLANNER_NAME, len(steps))
    return steps
