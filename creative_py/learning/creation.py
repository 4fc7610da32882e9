"""Creating a new tool: the paper's Algorithm 2.

Triggered when the task changes (the case manifest's harder variant) and the learned
model's best available tool fails in the physics (TC trial 1), or when no available
object satisfies the model. Before TC trial 1 the pose model is asked whether the held
tool can reach the learned pose in the harder task at all
(``geometry_clp:pose_reachable/5``: the tool's catalogue dimensions against the
perceived apparatus and target); when it cannot, the failure is predicted, no trial is
run and creation starts at once (:attr:`CreateResult.predicted` says why). When the
geometry cannot tell (the case sets no reach: a force decides), the trial is run.
Then, in a loop::

    create(Replaced, General, Instance, Structural, Dims) = engine.next_tool(...)
    spec  = spec_from_dict(kind + Dims)                      # sized by CLP(R)/CLP(FD)
    files = write_tool_files(spec)                           # URDF, SDF, SCAD, STL, PNG
    outcome = physics(spec at the pose the model asks for)   # TC trial
    success -> the harder task's model: the learned one with the new value; evaluate
    failure -> tried += [Instance]; next instance, next property, until none is left
    blocked, unreachable, invalid -> the same tool once more (the motion, not the design,
    failed), then as a failure

Which property is generalised first and which value is tried first is Prolog's choice
(prolog/creation.pl explains the order).
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field
from typing import Any, Optional

from creative_py.bridge import Compound, Engine, Term
from creative_py.learning.trials import TaskState, TrialRecord, TrialRunner, term_text

log = logging.getLogger(__name__)


@dataclass
class CreatedTool:
    """A tool the robot designed, sized and manufactured."""

    name: str
    replaced: str
    general: str
    instance: str
    structural: list[str]
    dims: dict[str, Any]
    files: dict[str, str]
    trial_outcome: str
    eval_outcomes: list[str] = field(default_factory=list)


@dataclass
class CreateResult:
    """What tool creation did for one harder task."""

    variant: str
    needed: bool
    created: list[CreatedTool]
    success: Optional[CreatedTool]
    vs: Term
    trials: list[TrialRecord]
    wall_time_s: float
    exhausted: Optional[str] = None
    replaced: Optional[Term] = None
    instance: Optional[Term] = None
    predicted: Optional[dict[str, Any]] = None
    """What the pose model said of the learned model's best tool in the harder task:
    ``tool``, ``feasible`` (False: unreachable, no trial run; True: reachable; None:
    the geometry cannot tell), ``why``."""


class ToolCreator:
    """Tool creation for one case (paper, Algorithm 2), on top of a learned model.

    Parameters
    ----------
    runner : TrialRunner
        Runs and records the trials; its records go on from the tool-use trials, so the
        plot shows TUL then TC trials. Created tools are added to its world.
    max_tools : int
        Stop after creating this many tools.
    eval_trials : int
        Evaluation trials of a successful created tool (paper: 5).
    """

    def __init__(self, runner: TrialRunner, max_tools: int = 6, eval_trials: int = 5) -> None:
        self.runner = runner
        self.engine: Engine = runner.engine
        self.case = runner.case
        self.max_tools = max_tools
        self.eval_trials = eval_trials

    def create(self, vs: Term, variant: str) -> CreateResult:
        """Solve the harder task ``variant``, creating a tool if the available ones fail."""
        t0 = time.perf_counter()
        runner = self.runner
        task = runner.task(variant)
        start = len(runner.trials)
        n = 0
        # TC trial 1: the learned model with the best available tool, unless the pose
        # model predicts that the tool cannot reach the learned pose in this task.
        use = self.engine.plan_use(self.case, vs, runner.task_facts(task))
        predicted = None
        if use.name == "exploit":
            predicted = self.predict(use, task)
            runner.progress(f"TC predicted: {predicted['tool']}: {predicted['why']}")
            if predicted["feasible"] is not False:
                n += 1
                rec, _ = runner.run(use, "create", n, vs, task, 0.0, label=False)
                if rec.outcome == "success":
                    return CreateResult(variant, False, [], None, vs, runner.trials[start:],
                                        time.perf_counter() - t0, predicted=predicted)
        created: list[CreatedTool] = []
        tried: list[Term] = []
        exhausted = None
        while len(created) < self.max_tools:
            reply = self.engine.next_tool(self.case, vs, tried, runner.task_facts(task))
            if reply.name == "exhausted":
                exhausted = term_text(reply.args[0])
                runner.progress(f"no literal left to generalise: {exhausted}")
                break
            replaced, general, instance, struct, dims = reply.args
            tried.append(instance)
            spec, values, files = self._manufacture(len(created) + 1, struct, dims)
            ct = CreatedTool(spec.name, term_text(replaced), term_text(general),
                             term_text(instance), [term_text(s) for s in struct],
                             dict(values), {k: str(v) for k, v in files.items()}, "")
            created.append(ct)
            runner.progress(f"created {ct.name}: {ct.replaced} -> {ct.general} -> "
                            f"{ct.instance} {ct.dims}")
            n += 1
            rec = self._trial_with(spec, n, vs, task)
            if rec.outcome in ("blocked", "unreachable", "invalid"):
                # The motion did not happen as planned: that says nothing about the
                # design, so the trial is repeated once (the paper repeats a task after
                # a failure to confirm the result).
                n += 1
                runner.progress(f"{ct.name}: {rec.outcome}, trying once more")
                rec = self._trial_with(spec, n, vs, task)
            ct.trial_outcome = rec.outcome
            if rec.outcome == "success":
                ct.eval_outcomes = self._evaluate(spec, vs, task)
                return CreateResult(variant, True, created, ct, vs, runner.trials[start:],
                                    time.perf_counter() - t0, replaced=replaced,
                                    instance=instance, predicted=predicted)
        return CreateResult(variant, True, created, None, vs, runner.trials[start:],
                            time.perf_counter() - t0, exhausted, predicted=predicted)

    def predict(self, use: Term, task: TaskState) -> dict[str, Any]:
        """Return what the pose model predicts of an ``exploit/4`` plan in ``task``.

        Prolog decides (``pose_reachable/5``): the plan's required spatial literals, the
        tool's catalogue dimensions and the perceived task. The answer is a dict with
        ``tool``, ``feasible`` (False, True, or None when the geometry cannot tell) and
        ``why`` (one sentence).
        """
        tool, _violated, _pose, required = use.args
        reply = self.engine.pose_reachable(self.case, str(tool), list(required),
                                           self.runner.task_facts(task))
        out: dict[str, Any] = {"tool": str(tool), "variant": task.variant,
                               "location": task.location}
        if isinstance(reply, Compound) and reply.name == "unreachable":
            conflict, params = reply.args
            reach = "; ".join(f"{p.args[0]} = {float(p.args[1]):.3f} m "
                              f"({str(p.args[2]).split(' (')[0]})" for p in params)
            out.update(feasible=False, conflict=[term_text(c) for c in conflict],
                       why=f"{', '.join(term_text(c) for c in conflict) or 'no pose'} "
                           f"cannot hold within the reach of {tool} in the {task.variant} "
                           f"task: {reach}; the trial would fail, so none is run")
        elif isinstance(reply, Compound) and reply.name == "reachable":
            out.update(feasible=True, pose=term_text(reply.args[0]),
                       why=f"{tool} reaches the learned pose in the {task.variant} task "
                           f"(e.g. {term_text(reply.args[0])}); the physics decides")
        else:
            out.update(feasible=None,
                       why=f"the case's geometry sets no reach: the pose model cannot "
                           f"tell whether {tool} works in the {task.variant} task; "
                           f"the physics decides")
        return out

    def _manufacture(self, k: int, struct: list, dims: Term) -> tuple[Any, dict, dict]:
        """Turn sized dimensions into a spec, write its files, add it to the world.

        The tool's kind is its class literal among the structural literals (a spec
        kind of :data:`creative_py.mesh.spec.SPEC_KINDS`, e.g. ``hook(T)``).
        """
        from creative_py.mesh.export import write_tool_files
        from creative_py.mesh.spec import SPEC_KINDS, spec_from_dict

        values = {}
        for d in dims:
            name, value = d.args
            values[str(name)] = value if not isinstance(value, str) else str(value)
        kinds = [s.name for s in struct
                 if isinstance(s, Compound) and len(s.args) == 1 and s.name in SPEC_KINDS]
        if not kinds:
            raise RuntimeError(f"{self.case}: the new tool's literals name no tool kind "
                               f"({', '.join(SPEC_KINDS)}): {term_text(struct)}")
        name = f"{self.case}_new{k}"
        spec = spec_from_dict({"kind": kinds[0], "name": name, **values},
                              source=f"created tool {name}")
        files: dict[str, Any] = {}
        run = self.runner.run_folder
        if run is not None:
            out = write_tool_files(spec, run.tools_dir(), overwrite=True)
            files = {"urdf": out.urdf, "sdf": out.sdf, "scad": out.scad, "stl": out.stl,
                     "png": out.png}
        self.runner.world = self.runner.world.with_tool(spec, files.get("urdf"))
        return spec, values, files

    def _trial_with(self, spec: Any, n: int, vs: Term, task: TaskState) -> TrialRecord:
        """Test a created tool at the pose the learned model asks for.

        The outcome is not added to the tool-use version space: the created tool differs
        from the learned model in the replaced literal by design, and the harder task is
        a different concept. A success gives the harder task's model instead
        (:func:`created_models` in ``prolog/model_file.pl``).
        """
        use = self.engine.plan_use(self.case, vs, self.runner.task_facts(task),
                                   [Compound("tool", (spec.name,))])
        if use.name != "exploit":
            raise RuntimeError(f"{self.case}: no pose for the created tool {spec.name}: "
                               f"{term_text(use)}")
        rec, _ = self.runner.run(use, "create", n, vs, task, 0.0, label=False)
        return rec

    def _evaluate(self, spec: Any, vs: Term, task: TaskState) -> list[str]:
        """Run the paper's evaluation of the new tool: fresh trials over the locations."""
        out = []
        for i in range(1, self.eval_trials + 1):
            task.next_location()
            use = self.engine.plan_use(self.case, vs, self.runner.task_facts(task),
                                       [Compound("tool", (spec.name,))])
            rec, _ = self.runner.run(use, "eval", i, vs, task, 0.0, label=False)
            out.append(rec.outcome)
        return out
