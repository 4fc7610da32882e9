"""A trial's outcome is labelled above the simulator boundary, once for every backend.

``creative_py/simulator/trial.py`` runs the trial loop and holds the outcome rules
(``trial_outcome``: what ``success``, ``failure``, ``blocked``, ``unreachable`` and
``invalid`` mean); ``creative_py/simulator/randomise.py`` draws the randomised worlds.
A backend (``creative_py/backends/<name>/``) builds scenes, runs skills, observes and
measures: a skill may report that its motion was ``blocked`` (the motion's report, a
:class:`~creative_py.simulator.SkillOutcome`), an oracle that the goal holds (a
:class:`~creative_py.simulator.Verdict`), but no backend runs a trial or says what its
outcome is. Checked on the source, so that a copy of the loop cannot creep back into
a backend (the ManiSkill backend had one):

* no backend defines a function, class or name called like the loop's own
  (``run_trial``, ``play_trial``, ``trial_outcome``, ``verdict_data``, ``Played``,
  ``draw_world``, ``apply_drawn``, ``_jittered``) or ending in ``outcome``;
* no backend writes a trial-only outcome (``"success"``, ``"failure"``) as a value: a
  literal mapping, a return, a comparison (reading a simulator's own result by that
  key, ManiSkill's ``evaluate()["success"]``, is a measure, not an outcome);
* no backend names ``TRIAL_OUTCOMES`` or ``TrialResult`` (a backend returns no trial).
"""

from __future__ import annotations

import ast
import re
from pathlib import Path

from _imports import PACKAGE, ROOT

BACKENDS = PACKAGE / "backends"
LOOP_NAMES = {"run_trial", "play_trial", "trial_outcome", "verdict_data", "Played",
              "draw_world", "apply_drawn", "_jittered"}
TRIAL_ONLY = {"success", "failure"}
ABOVE = {"TRIAL_OUTCOMES", "TrialResult"}


def _defined_names(node: ast.AST) -> list[tuple[int, str]]:
    """Return ``(line, name)`` of what a node defines: a function, a class, a name
    assigned or imported under its own name."""
    if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
        return [(node.lineno, node.name)]
    if isinstance(node, (ast.Assign, ast.AnnAssign)):
        targets = node.targets if isinstance(node, ast.Assign) else [node.target]
        return [(node.lineno, n.id) for t in targets for n in ast.walk(t)
                if isinstance(n, ast.Name)]
    if isinstance(node, ast.alias):
        return [(getattr(node, "lineno", 0), node.asname or node.name.split(".")[-1])]
    return []


def outcome_rule_errors(source: str, where: str) -> list[str]:
    """Return ``where:line: ...`` for each place of ``source`` (a backend module) that
    defines or names the trial loop's rules (see the module docstring)."""
    tree = ast.parse(source)
    keys = {id(n.slice) for n in ast.walk(tree) if isinstance(n, ast.Subscript)}
    errors = []
    for node in ast.walk(tree):
        for line, name in _defined_names(node):
            if name in LOOP_NAMES or re.search(r"(^|_)outcome$", name, re.IGNORECASE):
                errors.append(f"{where}:{line}: defines {name}: a trial is run and "
                              "labelled above the boundary (creative_py/simulator/trial.py, "
                              "randomise.py), not in a backend")
        if (isinstance(node, ast.Constant) and node.value in TRIAL_ONLY
                and id(node) not in keys):
            errors.append(f"{where}:{node.lineno}: the outcome {node.value!r} as a value: "
                          "only creative_py/simulator/trial.py labels a trial")
        if isinstance(node, (ast.Name, ast.alias, ast.Attribute)):
            name = (node.id if isinstance(node, ast.Name) else node.attr
                    if isinstance(node, ast.Attribute) else node.name.split(".")[-1])
            if name in ABOVE:
                errors.append(f"{where}:{getattr(node, 'lineno', 0)}: names {name}: a "
                              "backend returns no trial (the loop above the boundary does)")
    return errors


def test_the_checker_finds_a_copy_of_the_outcome_rules() -> None:
    copy = '''
from creative_py.simulator.types import TrialResult

def run_trial(world):
    return TrialResult()

def _outcome(status, acted, reached):
    if status.ok:
        return ("success", "goal reached") if reached else ("failure", "goal not reached")
    return status.status, status.reason

LABEL = {"ok": "success"}
'''
    errors = outcome_rule_errors(copy, "x.py")
    assert len(errors) == 7, errors
    assert sum("defines run_trial" in e for e in errors) == 1
    assert sum("defines _outcome" in e for e in errors) == 1
    assert sum("'success' as a value" in e for e in errors) == 2
    assert sum("'failure' as a value" in e for e in errors) == 1
    assert sum("names TrialResult" in e for e in errors) == 2
    # A skill's report and a simulator's own result read by its key are no outcome rule.
    fine = '''
def run_skill(self):
    if not self.held:
        return SkillOutcome("blocked", "no tool is held")
    return bool(self.u.evaluate()["success"][0])
'''
    assert outcome_rule_errors(fine, "y.py") == []


def test_no_backend_defines_the_outcome_rules() -> None:
    files = sorted(BACKENDS.rglob("*.py"))
    assert {p.parent.name for p in files} >= {"pybullet", "maniskill"}
    errors = [e for p in files
              for e in outcome_rule_errors(p.read_text(encoding="utf-8"),
                                           str(p.relative_to(ROOT)))]
    assert errors == [], "\n".join(errors)


def test_the_loop_and_the_sampler_live_above_the_boundary() -> None:
    simulator = PACKAGE / "simulator"
    tree = ast.parse((simulator / "trial.py").read_text(encoding="utf-8"))
    defined = {n.name for n in ast.walk(tree) if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    assert {"run_trial", "play_trial", "trial_outcome", "verdict_data", "Played"} <= defined
    tree = ast.parse((simulator / "randomise.py").read_text(encoding="utf-8"))
    defined = {n.name for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)}
    assert {"draw_world", "apply_drawn", "_jittered"} <= defined
    assert Path(simulator / "protocol.py").read_text(encoding="utf-8").count(
        "def run_trial") == 0
