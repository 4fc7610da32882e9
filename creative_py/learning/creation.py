"""Creating a new tool: the paper's Algorithm 2.

Triggered when the task changes (the long tube, the bigger door) and the learned model's
best available tool fails in the physics (TC trial 1), or when no available object
satisfies the model. Then, in a loop::

    create(Replaced, General, Instance, Structural, Dims) = prolog.next_tool(vs, tried)
    spec  = HookSpec/BlockSpec(**Dims)                       # sized by CLP(R)/CLP(FD)
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

import dataclasses
import logging
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, Engine, Term
from creative_py.learning.run_folder import RunFolder
from creative_py.learning.tool_use import (
    LearningOptions, TaskState, ToolUseLearner, TrialRecord, fact_term, term_text,
)

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


class ToolCreator(ToolUseLearner):
    """Tool creation for one case (paper, Algorithm 2), on top of a learned model.

    Shares the trial execution and logging of :class:`ToolUseLearner`; ``trials`` goes
    on counting from the tool-use trials so the plot shows TUL then TC trials.
    """

    def __init__(self, engine: Engine, case: str, world: Any, run: Optional[RunFolder],
                 options: LearningOptions = LearningOptions(),
                 progress: Optional[Callable[[str], None]] = None,
                 previous: Optional[list[TrialRecord]] = None,
                 max_tools: int = 6, eval_trials: int = 5) -> None:
        super().__init__(engine, case, world, run, options, progress)
        self.trials = list(previous or [])
        self.max_tools = max_tools
        self.eval_trials = eval_trials

    def create(self, vs: Term, variant: str) -> CreateResult:
        """Solve the harder task ``variant``, creating a tool if the available ones fail."""
        t0 = time.perf_counter()
        task = TaskState(variant, *self._locations())
        start = len(self.trials)
        n = 0
        # TC trial 1: the learned model with the best available tool.
        use = self.engine.call("plan_use", self.case, vs, self.task_facts(task), [])
        if use.name == "exploit":
            n += 1
            rec, _ = self._run_experiment(len(self.trials) + 1, "create", n, use, vs, task,
                                          0.0, label=False)
            if rec.outcome == "success":
                return CreateResult(variant, False, [], None, vs, self.trials[start:],
                                    time.perf_counter() - t0)
        created: list[CreatedTool] = []
        tried: list[Term] = []
        exhausted = None
        while len(created) < self.max_tools:
            facts = self.task_facts(task)
            reply = self.engine.call("next_tool", self.case, vs, tried, facts)
            if reply.name == "exhausted":
                exhausted = term_text(reply.args[0])
                self.progress(f"no literal left to generalise: {exhausted}")
                break
            replaced, general, instance, struct, dims = reply.args
            tried.append(instance)
            tool = self._manufacture(len(created) + 1, dims)
            ct = CreatedTool(tool.spec.name, term_text(replaced), term_text(general),
                             term_text(instance), [term_text(s) for s in struct],
                             dict(tool.dims), {k: str(v) for k, v in tool.files.items()},
                             "")
            created.append(ct)
            self.progress(f"created {ct.name}: {ct.replaced} -> {ct.general} -> "
                          f"{ct.instance} {ct.dims}")
            n += 1
            rec, _ = self._trial_with(tool.spec, n, vs, task)
            if rec.outcome in ("blocked", "unreachable", "invalid"):
                # The motion did not happen as planned: that says nothing about the
                # design, so the trial is repeated once (the paper repeats a task after
                # a failure to confirm the result).
                n += 1
                self.progress(f"{ct.name}: {rec.outcome}, trying once more")
                rec, _ = self._trial_with(tool.spec, n, vs, task)
            ct.trial_outcome = rec.outcome
            if rec.outcome == "success":
                ct.eval_outcomes = self._evaluate(tool.spec, vs, task)
                return CreateResult(variant, True, created, ct, vs, self.trials[start:],
                                    time.perf_counter() - t0, replaced=replaced,
                                    instance=instance)
        return CreateResult(variant, True, created, None, vs, self.trials[start:],
                            time.perf_counter() - t0, exhausted)

    # -- steps ---------------------------------------------------------------------------

    def _manufacture(self, k: int, dims: Term) -> "_Made":
        """Turn sized dimensions into a spec, write its files, add it to the world."""
        from creative_py.mesh.export import write_tool_files
        from creative_py.mesh.spec import spec_from_dict

        values = {}
        for d in dims:
            name, value = d.args
            values[str(name)] = value if not isinstance(value, str) else str(value)
        name = f"{self.case}_new{k}"
        if self.case == "hook":
            kind = "stick" if values.get("hook_side") == "none" else "hook"
            data = {"kind": kind, "name": name, **values}
            if kind == "stick":
                data.pop("hook_side", None)
                data["hook_length"] = 0.0
        else:
            data = {"kind": "block", "name": name, **values}
        spec = spec_from_dict(data, source=f"created tool {name}")
        files = {}
        if self.run is not None:
            out = write_tool_files(spec, self.run.tools_dir(), overwrite=True)
            files = {"urdf": out.urdf, "sdf": out.sdf, "scad": out.scad, "stl": out.stl,
                     "png": out.png}
        self.world = _with_tool(self.world, spec, files.get("urdf"))
        return _Made(spec, values, files)

    def _trial_with(self, spec: Any, n: int, vs: Term,
                    task: TaskState) -> tuple[TrialRecord, Term]:
        """Test a created tool at the pose the learned model asks for.

        The outcome is not added to the tool-use version space: the created tool differs
        from the learned model in the replaced literal by design, and the harder task is
        a different concept. A success gives the harder task's model instead
        (:func:`created_models` in ``prolog/model_file.pl``).
        """
        use = self.engine.call("plan_use", self.case, vs, self.task_facts(task),
                               [Compound("tool", (spec.name,))])
        if use.name != "exploit":
            raise RuntimeError(f"{self.case}: no pose for the created tool {spec.name}: "
                               f"{term_text(use)}")
        return self._run_experiment(len(self.trials) + 1, "create", n, use, vs, task, 0.0,
                                    label=False)

    def _evaluate(self, spec: Any, vs: Term, task: TaskState) -> list[str]:
        """Run the paper's evaluation of the new tool: fresh trials over the locations."""
        out = []
        for i in range(1, self.eval_trials + 1):
            task.next_location()
            use = self.engine.call("plan_use", self.case, vs, self.task_facts(task),
                                   [Compound("tool", (spec.name,))])
            rec, _ = self._run_experiment(len(self.trials) + 1, "eval", i, use, vs, task,
                                          0.0, label=False)
            out.append(rec.outcome)
        return out


@dataclass
class _Made:
    spec: Any
    dims: dict[str, Any]
    files: dict[str, Any]


def _with_tool(world: Any, spec: Any, urdf: Any) -> Any:
    """Return the world with one more available tool (spawned from its URDF if given)."""
    fields = {f.name for f in dataclasses.fields(world)}
    changes: dict[str, Any] = {}
    if "tools" in fields:
        changes["tools"] = {**world.tools, spec.name: spec}
    elif "objects" in fields:
        # The wedge world keeps each object with its set and friction: a created object
        # takes the friction of the existing ones (the same printed material).
        template = next(iter(world.objects.values()))
        if hasattr(template, "spec"):
            extra = {"urdf": urdf} if hasattr(template, "urdf") else {}
            item = dataclasses.replace(template, spec=spec, set="created", **extra)
        else:
            item = spec
        changes["objects"] = {**world.objects, spec.name: item}
    else:
        raise TypeError(f"cannot add a tool to a {type(world).__name__}")
    if urdf is not None and "tool_urdfs" in fields:
        changes["tool_urdfs"] = {**world.tool_urdfs, spec.name: urdf}
    return dataclasses.replace(world, **changes)
