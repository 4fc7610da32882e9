"""The PDDL that Prolog writes is solved by pyperplan and the Prolog plan validates.

Prolog (prolog/observe.pl, planner.pl, pddl.pl) runs in a subprocess on the
hand-written demonstrations of tests/prolog/fixtures/demonstrations.pl: it learns the
tool model from the demonstration, plans the task, and writes domain.pddl,
problem.pddl and its own plan.  unified-planning then solves and validates.
"""

from __future__ import annotations

import logging
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from creative_py.learning.pddl_check import (PddlError, check_files, parse, solve, step_text,
                                             validate_plan)

ROOT = Path(__file__).resolve().parents[3]
FIXTURES = ROOT / "tests" / "prolog" / "fixtures" / "demonstrations.pl"

pytestmark = pytest.mark.skipif(shutil.which("swipl") is None, reason="needs SWI-Prolog")

STEP = re.compile(r"^\((\S+)((?: \S+)*)\)$")


def read_plan(path: Path) -> list[tuple[str, list[str]]]:
    """Return the steps of a plan file with one ``(action arg ...)`` per line."""
    steps = []
    for line in path.read_text().splitlines():
        match = STEP.match(line.strip())
        assert match, f"{path}: not a plan step: {line!r}"
        steps.append((match.group(1), match.group(2).split()))
    return steps


@pytest.fixture(scope="module", params=["hook", "wedge"])
def written(request, tmp_path_factory) -> tuple[str, Path]:
    """Let Prolog write the case's domain, problem and plan; return (case, folder)."""
    case = request.param
    out = tmp_path_factory.mktemp(case)
    subprocess.run(
        ["swipl", "--on-warning=status", "-q", "-g", "fixture_write_pddl_main",
         "-t", "halt", str(FIXTURES), case, str(out)],
        check=True, cwd=ROOT, capture_output=True, text=True, timeout=60,
    )
    return case, out


LAST_ACTION = {"hook": "pull_out", "wedge": "hold_door"}


def test_pyperplan_and_prolog_agree(written):
    case, out = written
    domain, problem = out / "domain.pddl", out / "problem.pddl"
    prolog_plan = read_plan(out / "prolog_plan.txt")
    pyperplan_plan = solve(domain, problem)

    assert pyperplan_plan is not None
    assert len(pyperplan_plan) == len(prolog_plan) == 3
    assert prolog_plan[-1][0] == pyperplan_plan[-1][0] == LAST_ACTION[case]
    assert validate_plan(domain, problem, prolog_plan) == (True, "valid")
    assert validate_plan(domain, problem, pyperplan_plan) == (True, "valid")


def test_a_plan_missing_its_first_step_is_rejected(written):
    _, out = written
    domain, problem = out / "domain.pddl", out / "problem.pddl"
    plan = read_plan(out / "prolog_plan.txt")

    valid, reason = validate_plan(domain, problem, plan[1:])

    assert not valid
    assert "inapplicable" in reason and plan[1][0] in reason


def test_a_plan_that_stops_short_of_the_goal_is_rejected(written):
    _, out = written
    domain, problem = out / "domain.pddl", out / "problem.pddl"
    plan = read_plan(out / "prolog_plan.txt")

    valid, _ = validate_plan(domain, problem, plan[:-1])

    assert not valid


def test_a_step_with_an_unknown_action_or_object_is_rejected(written):
    _, out = written
    domain, problem = out / "domain.pddl", out / "problem.pddl"

    assert validate_plan(domain, problem, [("fly", [])]) == (
        False, "plan step 1: unknown action 'fly'")
    valid, reason = validate_plan(domain, problem, [("pick_up", ["no_such_tool"])])
    assert not valid and "no_such_tool" in reason


def test_a_tool_the_model_rejects_makes_the_task_unsolvable(written, tmp_path):
    """Without the demonstrated tool on the table, no object satisfies the model."""
    case, out = written
    demo_tool = read_plan(out / "prolog_plan.txt")[0][1][0]
    problem = (out / "problem.pddl").read_text()
    without = tmp_path / "problem.pddl"
    without.write_text(problem.replace(f"(on_table {demo_tool})", ""))

    assert solve(out / "domain.pddl", without) is None


NEGATIVE_DOMAIN = """(define (domain door)
  (:requirements :strips :typing :negative-preconditions)
  (:types thing)
  (:predicates (locked ?d - thing) (open ?d - thing))
  (:action unlock :parameters (?d - thing) :precondition (and (locked ?d))
    :effect (and (not (locked ?d))))
  (:action open_door :parameters (?d - thing) :precondition (and (not (locked ?d)))
    :effect (and (open ?d))))
"""
NEGATIVE_PROBLEM = """(define (problem p) (:domain door) (:objects d1 - thing)
  (:init (locked d1)) (:goal (and (open d1))))
"""


def test_negative_preconditions_are_compiled_away(tmp_path):
    domain, problem = tmp_path / "d.pddl", tmp_path / "p.pddl"
    domain.write_text(NEGATIVE_DOMAIN)
    problem.write_text(NEGATIVE_PROBLEM)

    plan = solve(domain, problem)

    assert plan == [("unlock", ["d1"]), ("open_door", ["d1"])]
    assert validate_plan(domain, problem, plan) == (True, "valid")
    assert not validate_plan(domain, problem, plan[1:])[0]


def test_bad_files_raise_an_error_naming_them(tmp_path):
    broken = tmp_path / "broken.pddl"
    broken.write_text(NEGATIVE_DOMAIN[:-3])
    problem = tmp_path / "p.pddl"
    problem.write_text(NEGATIVE_PROBLEM)

    with pytest.raises(PddlError, match="broken.pddl"):
        parse(broken, problem)
    with pytest.raises(PddlError, match="missing.pddl: no such PDDL file"):
        parse(tmp_path / "missing.pddl", problem)


@pytest.fixture
def door(tmp_path) -> tuple[Path, Path]:
    domain, problem = tmp_path / "d.pddl", tmp_path / "p.pddl"
    domain.write_text(NEGATIVE_DOMAIN)
    problem.write_text(NEGATIVE_PROBLEM)
    return domain, problem


def test_check_files_records_a_plan_equal_to_prolog_s(door, caplog):
    plan = [("unlock", ["d1"]), ("open_door", ["d1"])]
    assert check_files(*door, plan) == {
        "domain": "d.pddl", "problem": "p.pddl", "status": "solved",
        "plan": ["(unlock d1)", "(open_door d1)"], "equals_prolog": True,
        "planner": "pyperplan", "prolog_plan": ["(unlock d1)", "(open_door d1)"],
        "prolog_plan_valid": True}
    assert [r.getMessage() for r in caplog.records if r.levelname == "WARNING"] == []


def test_check_files_records_a_prolog_plan_that_differs_or_is_missing(door, caplog):
    domain, problem = door
    record = check_files(domain, problem, [("open_door", ["d1"])])
    assert record == {
        "domain": "d.pddl", "problem": "p.pddl", "status": "solved",
        "plan": ["(unlock d1)", "(open_door d1)"], "equals_prolog": False,
        "planner": "pyperplan", "prolog_plan": ["(open_door d1)"],
        "prolog_plan_valid": False}
    assert [r.getMessage() for r in caplog.records if r.levelname == "WARNING"] == [
        f"{problem}: pyperplan's plan (unlock d1) (open_door d1) differs from Prolog's "
        "['(open_door d1)']"]
    assert check_files(domain, problem, None) == {
        "domain": "d.pddl", "problem": "p.pddl", "status": "solved",
        "plan": ["(unlock d1)", "(open_door d1)"], "equals_prolog": False,
        "planner": "pyperplan", "prolog_plan": None}


def test_check_files_records_an_unsolvable_task(door, caplog):
    domain, problem = door
    problem.write_text(NEGATIVE_PROBLEM.replace("(:goal (and (open d1)))",
                                                "(:goal (and (open d1) (locked d1)))"))
    assert check_files(domain, problem, None) == {
        "domain": "d.pddl", "problem": "p.pddl", "status": "unsolvable", "plan": [],
        "equals_prolog": True, "planner": "pyperplan", "prolog_plan": None}
    record = check_files(domain, problem, [("unlock", ["d1"])])
    assert (record["status"], record["equals_prolog"], record["prolog_plan_valid"]) == (
        "unsolvable", False, False)
    assert [r.getMessage() for r in caplog.records if r.levelname == "WARNING"] == [
        f"{problem}: pyperplan finds no plan for the run's own PDDL"] * 2


def test_check_files_records_an_error_and_never_raises(door, caplog):
    domain, problem = door
    domain.write_text(NEGATIVE_DOMAIN[:-3])
    record = check_files(domain, problem, [("unlock", ["d1"])])
    error = record.pop("error")
    assert record == {"domain": "d.pddl", "problem": "p.pddl", "status": "error",
                      "plan": [], "equals_prolog": False, "planner": "pyperplan",
                      "prolog_plan": ["(unlock d1)"]}
    assert error.startswith(f"{domain} + {problem}: cannot parse: ")
    assert [r.getMessage() for r in caplog.records if r.levelname == "WARNING"] == [
        f"{problem}: pyperplan could not solve its own PDDL: {error}"]
    assert step_text(("pull_out", ["hook_a2", "cube1", "tube1"])) == \
        "(pull_out hook_a2 cube1 tube1)"
    assert step_text(("stop", [])) == "(stop)"


def _infos(caplog) -> list[str]:
    return [r.getMessage() for r in caplog.records
            if r.name == "creative_py.learning.pddl_check" and r.levelname == "INFO"]


def test_solve_logs_its_answer_and_validate_plan_says_why_not(door, caplog):
    caplog.set_level(logging.INFO, logger="creative_py.learning.pddl_check")
    domain, problem = door
    assert solve(domain, problem) == [("unlock", ["d1"]), ("open_door", ["d1"])]
    assert _infos(caplog) == [f"{problem}: pyperplan found 2 steps"]
    assert validate_plan(domain, problem, [("open_door", ["d1"])]) == (
        False, "inapplicable_action: [INFO] Preconditions [(not locked(d1))] of 1-th action "
               "instance open_door(d1) are not satisfied.")
    assert validate_plan(domain, problem, [("unlock", ["d1"])]) == (
        False, "unsatisfied_goals: [INFO] Goals [open(d1)] are not satisfied by the plan.")
    assert validate_plan(domain, problem, ["x"]) == (
        False, "plan step 1: 'x' is not (action_name, [args])")
    assert validate_plan(domain, problem, [("unlock", ["d1"]), ("unlock", ["d1", "d1"])]) == (
        False, "plan step 2: unlock takes 1 arguments, got 2")
    assert validate_plan(domain, problem, [("nope", ["d1"])]) == (
        False, "plan step 1: unknown action 'nope'")
    assert validate_plan(domain, problem, [("unlock", ["zz"])]) == (
        False, "plan step 1: unknown object 'zz'")
    problem.write_text(NEGATIVE_PROBLEM.replace("(:goal (and (open d1)))",
                                                "(:goal (and (open d1) (locked d1)))"))
    caplog.clear()
    assert solve(domain, problem) is None
    assert _infos(caplog) == [f"{problem}: no plan (UNSOLVABLE_INCOMPLETELY)"]
