"""Creating a new tool: the paper's Algorithm 2.

Triggered when the task changes (the case manifest's harder variant) and the learned
model's best available tool fails in the physics (TC trial 1), or when no available
object satisfies the model. Before TC trial 1 the pose model is asked whether the held
tool can reach the learned pose in the harder task at all
(``geometry_clp:pose_reachable/5``: the tool's catalogue dimensions against the
perceived apparatus and target); when it cannot, the failure is predicted, no trial is
run and creation starts at once (:attr:`CreateResult.predicted` says why). When the
geometry cannot tell (the case sets no reach: a force decides), the trial is run.
With catalogued objects first (``catalogue_first``, the default except under the
paper's strategy) the available objects that the *generalised* model admits are then
tried in the physics before anything is made (``creation:catalogue_first/5``: h_g
with the literal creation would replace swapped for its general one, e.g.
``any_length(T)`` for ``handle_length(T, medium)``; objects with an alternative value,
in the order creation would make them, best first); a tool is manufactured only when
none succeeds, or, with ``demonstrate``, afterwards as a demonstration of Algorithm 2
(:attr:`CreateResult.solved_by` says which solved the task). Then, in a loop::

    create(Replaced, General, Instance, Structural, Dims) = engine.next_tool(...)
    spec  = spec_from_dict(kind + Dims)                      # sized by CLP(R)/CLP(FD)
    files = write_tool_files(spec)                           # URDF, SDF, SCAD, STL, PNG
    outcome = physics(spec at the pose the model asks for)   # TC trial
    success -> the harder task's model: the learned one with the new value; evaluate
    failure -> tried += [Instance]; next instance, next property, until none is left
    blocked, unreachable, invalid -> the same tool once more (the motion, not the design,
    failed), then as a failure
    no pose (the learned model's pose cannot hold for it) -> no trial (``no_pose``),
    as a failure

Which property is generalised first and which value is tried first is Prolog's choice
(prolog/creation.pl explains the order).
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable, Optional

from creative_py.bridge import Compound, Engine, Term, lettered, readable
from creative_py.learning.trials import TaskState, TrialRecord, TrialRunner, term_text
from creative_py.records.summary import print_summary
from creative_py.report.contents import readable_term
from creative_py.report.table import dims_text

log = logging.getLogger(__name__)

NOT_AS_PLANNED = ("blocked", "unreachable", "invalid")
"""Outcomes of a trial whose motion did not happen as planned: a creation trial that
ends so is run once more (:meth:`ToolCreator._once_more`)."""


def exhausted_words(skipped: Term) -> str:
    """Return why no candidate of ``creation:next_tool/6``'s ``exhausted(Skipped)`` was
    made, in words: the candidates with the same reason together, each reason once.

    ``Skipped`` lists ``Instance-Reason``: ``tried`` (made before) or
    ``infeasible(Conflict)``, the size model's minimal conflict of spec literals and
    task facts. Each candidate's tool is ``A``; the facts the size model reads are
    lengths and positions, so their numbers (metres) are written in millimetres::

        plate_width(A, wide) and plate_width(A, narrow) cannot be sized, as
        wing_spread(A, none) and size(cubes, 293.3 mm, 401.4 mm, 30 mm) cannot hold
        together; wing_spread(A, flared) was made before
    """
    if not skipped:
        return "no candidate"
    reasons: dict[str, list[str]] = {}
    for item in skipped:
        if not (isinstance(item, Compound) and item.name == "-" and len(item.args) == 2):
            reasons.setdefault(readable(item), [])
            continue
        instance, reason = lettered(item).args
        if reason == "tried":
            why = "made before"
        elif (isinstance(reason, Compound) and reason.name == "infeasible"
              and isinstance(reason.args[0], list)):
            conflict = [_words(c) for c in reason.args[0]]
            why = ("cannot be sized, as " + _and(conflict) + " cannot hold together"
                   if conflict else "cannot be sized in this task")
        else:
            why = "skipped: " + _words(reason)
        reasons.setdefault(why, []).append(_words(instance))
    out = []
    for why, names in reasons.items():
        if why == "made before":
            why = ("was " if len(names) == 1 else "were ") + why
        out.append(f"{_and(names)} {why}" if names else why)
    return "; ".join(out)


def _words(term: Term) -> str:
    """A lettered literal for people: its floats (metres) in mm."""
    if isinstance(term, float):
        return f"{term * 1000:.1f}".rstrip("0").rstrip(".") + " mm"
    if isinstance(term, Compound):
        return f"{term.name}({', '.join(_words(a) for a in term.args)})"
    if isinstance(term, list):
        return "[" + ", ".join(_words(a) for a in term) + "]"
    return readable(term)


def _and(items: list[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def no_pose_words(plan: Term) -> str:
    """Return why ``plan_use`` gave a created tool no pose, in words: its answer
    ``no_experiment(infeasible_pose(Conflict))`` (the learned model's spatial literals
    that cannot hold together for the tool in the task) or another reason term."""
    reason = plan.args[0] if isinstance(plan, Compound) and plan.args else plan
    if (isinstance(reason, Compound) and reason.name == "infeasible_pose"
            and isinstance(reason.args[0], list) and reason.args[0]):
        return (f"no pose of the learned model holds for it: "
                f"{_and([_words(c) for c in lettered(reason.args[0])])} cannot hold together")
    return f"the learned model gives it no pose: {readable(plan)}"


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
    mass_kg: Optional[float] = None
    print: dict[str, Any] = field(default_factory=dict)
    """The printed pieces (the tool manifest's ``"print"`` entry, in short): per piece
    its STL, G-code, bounding box (mm), volume, print time and filament; the joint; the
    union's volume check; totals."""
    strength: dict[str, Any] = field(default_factory=dict)
    """The strength check of its successful trial (:mod:`creative_py.fabrication.strength`)."""
    reason: str = ""
    """Why it was not tried (its ``trial_outcome`` ``no_pose``: the learned model's pose
    cannot hold for it in the task), in words; empty when it was."""


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
    """Why no literal was left to generalise: ``creation:next_tool/6``'s skipped
    candidates as Prolog text (:func:`~creative_py.bridge.readable`)."""
    exhausted_words: Optional[str] = None
    """The same in words and millimetres (:func:`exhausted_words`), for people."""
    replaced: Optional[Term] = None
    instance: Optional[Term] = None
    predicted: Optional[dict[str, Any]] = None
    """What the pose model said of the learned model's best tool in the harder task:
    ``tool``, ``feasible`` (False: unreachable, no trial run; True: reachable; None:
    the geometry cannot tell), ``why``."""
    catalogue: list[dict[str, Any]] = field(default_factory=list)
    """The catalogued objects the generalised model admitted, best first: per object
    ``tool``, ``value`` (its value of the generalised property), ``why`` it was
    chosen, ``predicted`` (the pose model's answer, as :attr:`predicted`), ``trial``
    (its trial number, None if not run) and ``outcome`` (the physics' outcome, or
    ``predicted_unreachable`` / ``no_pose`` when no trial was run)."""
    solved_by: Optional[str] = None
    """What solved the harder task: ``learned`` (TC trial 1, the learned model's own
    best tool), ``catalogue`` (a catalogued object the generalised model admits),
    ``created`` (a made tool) or None."""


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
    safety_factor : float or None
        The least safety factor of the strength check (None: the default,
        :data:`creative_py.mesh.spec.MIN_SAFETY_FACTOR`).
    catalogue_first : bool
        Try the catalogued objects the generalised model admits before manufacturing
        (False: the paper's Algorithm 2, which makes a tool at once).
    demonstrate : bool
        When a catalogued object solved the harder task, still create a tool afterwards
        as a demonstration of Algorithm 2.
    """

    def __init__(self, runner: TrialRunner, max_tools: int = 6, eval_trials: int = 5,
                 safety_factor: Optional[float] = None, catalogue_first: bool = False,
                 demonstrate: bool = False) -> None:
        from creative_py.mesh.spec import MIN_SAFETY_FACTOR

        self.safety_factor = MIN_SAFETY_FACTOR if safety_factor is None else safety_factor
        self.runner = runner
        self.engine: Engine = runner.engine
        self.case = runner.case
        self.max_tools = max_tools
        self.eval_trials = eval_trials
        self.catalogue_first = catalogue_first
        self.demonstrate = demonstrate

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
                                        time.perf_counter() - t0, predicted=predicted,
                                        solved_by="learned")
        catalogue: list[dict[str, Any]] = []
        solved = None
        if self.catalogue_first:
            tried_first = [str(use.args[0])] if use.name == "exploit" else []
            catalogue, solved, n = self._try_catalogue(vs, task, tried_first, n)
            if solved is not None and not self.demonstrate:
                # The harder task's model: the learned one with the object's value.
                return CreateResult(variant, False, [], None, vs, runner.trials[start:],
                                    time.perf_counter() - t0, replaced=solved[0],
                                    instance=solved[1], predicted=predicted,
                                    catalogue=catalogue, solved_by="catalogue")
        by_catalogue = solved is not None
        solved_by = "catalogue" if by_catalogue else None
        created: list[CreatedTool] = []
        tried: list[Term] = []
        exhausted = words = None
        while len(created) < self.max_tools:
            reply = self.engine.next_tool(self.case, vs, tried, runner.task_facts(task))
            if reply.name == "exhausted":
                exhausted, words = readable(reply.args[0]), exhausted_words(reply.args[0])
                runner.progress(f"no literal left to generalise: {words}")
                break
            replaced, _general, instance, _struct, _dims = reply.args
            tried.append(instance)
            spec, ct, n = self._make_and_try(reply, created, n, vs, task)
            if (ct.trial_outcome == "success"
                    and ct.strength.get("verdict") in ("pass", "unmeasured")):
                ct.eval_outcomes = self._evaluate(spec, vs, task)
                return CreateResult(variant, not by_catalogue, created, ct, vs,
                                    runner.trials[start:], time.perf_counter() - t0,
                                    replaced=replaced, instance=instance,
                                    predicted=predicted, catalogue=catalogue,
                                    solved_by=solved_by or "created")
        return CreateResult(variant, not by_catalogue, created, None, vs,
                            runner.trials[start:], time.perf_counter() - t0, exhausted,
                            exhausted_words=words, predicted=predicted, catalogue=catalogue,
                            solved_by=solved_by)

    def _make_and_try(self, reply: Compound, created: list[CreatedTool], n: int,
                      vs: Term, task: TaskState) -> tuple[Any, CreatedTool, int]:
        """Manufacture the candidate ``reply`` (``create/5`` of ``next_tool``), try it in
        the physics (once more when the motion, not the design, failed; not at all when
        the learned pose cannot hold for it: ``no_pose``) and, after a success, check it
        against the load the physics measured; return its spec, its record (appended to
        ``created``) and the creation trials so far."""
        runner = self.runner
        replaced, general, instance, struct, dims = reply.args
        spec, values, files, mass, printed = self._manufacture(len(created) + 1, struct, dims)
        ct = CreatedTool(spec.name, term_text(replaced), term_text(general),
                         term_text(instance), [term_text(s) for s in struct],
                         dict(values), {k: str(v) for k, v in files.items()}, "",
                         mass_kg=mass, print=printed)
        created.append(ct)
        runner.progress(f"created {ct.name}: " + " -> ".join(
            readable_term(x) for x in (ct.replaced, ct.general, ct.instance))
            + f"; {dims_text(ct.dims)}")
        use = self._use_of(spec, vs, task)
        if use.name != "exploit":
            # Sized, but the learned model's pose cannot hold for it here: no trial; the
            # next candidate is made (its instance is in ``tried``).
            ct.trial_outcome, ct.reason = "no_pose", no_pose_words(use)
            runner.progress(f"{ct.name}: not tried: {ct.reason}")
            return spec, ct, n
        rec, n = self._once_more(lambda k: self._trial_with(use, k, vs, task), n, ct.name)
        ct.trial_outcome = rec.outcome
        if rec.outcome == "success":
            # The physics measured the load; a tool too weak for it is thickened (tried
            # again) or rejected, and then the next candidate is created.
            spec, ct, n = self._strengthen(spec, ct, struct, rec, n, vs, task, created)
        return spec, ct, n

    def _once_more(self, trial: Callable[[int], TrialRecord], n: int,
                   tool: Optional[str] = None) -> tuple[TrialRecord, int]:
        """Run ``trial`` as creation trial ``n + 1`` and, when its motion did not happen
        as planned (:data:`NOT_AS_PLANNED`), once more: that says nothing about the tool,
        so the trial is repeated (the paper repeats a task after a failure to confirm
        the result), saying so for ``tool`` when given. Return the last trial's record
        and the creation trials so far."""
        rec = trial(n + 1)
        if rec.outcome not in NOT_AS_PLANNED:
            return rec, n + 1
        if tool is not None:
            self.runner.progress(f"{tool}: {rec.outcome}, trying once more")
        return trial(n + 2), n + 2

    def _try_catalogue(self, vs: Term, task: TaskState, exclude: list[str], n: int,
                       ) -> tuple[list[dict[str, Any]], Optional[tuple[Term, Term]], int]:
        """Try the catalogued objects the generalised model admits, best first.

        Prolog chooses and orders them (``creation:catalogue_first/5``) and gives each
        its pose; objects in ``exclude`` (TC trial 1's) are left out. An object the
        pose model predicts cannot reach the pose is not tried (as for TC trial 1);
        every other is run in the physics as a creation trial (phase ``create``), once
        more if the motion did not happen as planned, until one succeeds. Returns the
        record of each object (:attr:`CreateResult.catalogue`), the replaced literal
        and the successful object's value (None if none succeeded), and the trial
        count.
        """
        runner = self.runner
        reply = self.engine.catalogue_first(self.case, vs, runner.task_facts(task), exclude)
        if not (isinstance(reply, Compound) and reply.name == "catalogue"):
            return [], None, n
        replaced, general, items = reply.args
        out: list[dict[str, Any]] = []
        for item in items:
            obj, value, use = item.args
            entry: dict[str, Any] = {
                "tool": str(obj), "value": term_text(value),
                "why": f"catalogued object admitted by {term_text(general)} (the "
                       f"generalised {term_text(replaced)}): {term_text(value)}",
                "predicted": None, "trial": None, "outcome": None}
            out.append(entry)
            if not (isinstance(use, Compound) and use.name == "exploit"):
                entry.update(outcome="no_pose", reason=term_text(use))
                continue
            entry["predicted"] = self.predict(use, task)
            if entry["predicted"]["feasible"] is False:
                entry["outcome"] = "predicted_unreachable"
                runner.progress(f"TC catalogue: {obj} not tried: "
                                f"{entry['predicted']['why']}")
                continue
            runner.progress(f"TC catalogue: trying {obj}, {entry['why']}")
            rec, n = self._once_more(
                lambda k: runner.run(use, "create", k, vs, task, 0.0, label=False)[0], n,
                str(obj))
            entry.update(trial=rec.trial, outcome=rec.outcome, reason=rec.reason)
            if rec.outcome == "success":
                runner.progress(f"TC catalogue: {obj} solved the {task.variant} task"
                                + ("; a tool is created as a demonstration"
                                   if self.demonstrate else "; no tool is made"))
                return out, (replaced, value), n
        return out, None, n

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

    def _strengthen(self, spec: Any, ct: CreatedTool, struct: list, rec: TrialRecord, n: int,
                    vs: Term, task: TaskState, created: list[CreatedTool],
                    ) -> tuple[Any, CreatedTool, int]:
        """Check a created tool's strength from its successful trial; thicken it if needed.

        The check (:mod:`creative_py.fabrication.strength`) uses the largest contact force
        the physics recorded on the tool in ``rec``. A tool that fails it is sized again
        with a wider handle (a ``min_handle_width_m`` fact for the CLP size model),
        written, added to ``created`` and tried in the physics; a tool the size model
        cannot thicken is rejected. The figures go into each tool's ``strength`` and
        its JSON manifest. Returns the tool to evaluate (its ``trial_outcome`` and
        ``strength["verdict"]`` say whether it may be) and the trial count.
        """
        from creative_py.fabrication.strength import (MAX_THICKENINGS, check_strength,
                                                   rejected, thicker_dims)

        sf = self.safety_factor
        check = check_strength(spec, rec.tool_load, trial=rec.trial,
                               safety_factor=sf)
        for _ in range(MAX_THICKENINGS):
            if check.verdict != "fail" or check.model != "cantilever":
                break
            reply = thicker_dims(self.engine, self.case, self._kind(struct), struct,
                                 self.runner.task_facts(task), check)
            if reply.name == "infeasible":
                check = rejected(check, reply.args[0])
                break
            thick, values, files, mass, printed = self._manufacture(len(created) + 1, struct,
                                                                    reply.args[0])
            self._record_strength(ct, replace(check, thickened_into=thick.name))
            ct2 = CreatedTool(thick.name, ct.replaced, ct.general, ct.instance,
                              list(ct.structural), dict(values),
                              {k: str(v) for k, v in files.items()}, "",
                              mass_kg=mass, print=printed)
            created.append(ct2)
            self.runner.progress(
                f"{ct.name}: safety factor {check.safety_factor:.2f} < "
                f"{check.required_safety_factor:g} under {check.force_n:.2f} N; thickened "
                f"into {thick.name} {ct2.dims}")
            use = self._use_of(thick, vs, task)
            spec, ct = thick, ct2
            if use.name != "exploit":
                ct2.trial_outcome, ct2.reason = "no_pose", no_pose_words(use)
                check = replace(check, verdict="rejected",
                                reason=f"{thick.name} was not tried: {ct2.reason}")
                break
            rec, n = self._once_more(lambda k: self._trial_with(use, k, vs, task), n)
            ct2.trial_outcome = rec.outcome
            check = check_strength(thick, rec.tool_load, trial=rec.trial,
                                   safety_factor=sf, thickened_from=check.tool)
            if rec.outcome != "success":
                check = replace(check, reason=f"the thickened tool's trial ended {rec.outcome}")
                break
        self._final_strength(ct, check, MAX_THICKENINGS)
        return spec, ct, n

    def _final_strength(self, ct: CreatedTool, check: Any, thickenings: int) -> None:
        """Record the last strength check of ``ct`` (a failing one is a rejection: no
        more thickening helps) and say it."""
        if check.verdict == "fail":
            check = replace(check, verdict="rejected", reason=(
                f"still too weak after {thickenings} thickenings"
                if check.model == "cantilever" else
                f"a {check.model} check is not met by thickening a handle"))
        self._record_strength(ct, check)
        if check.verdict == "rejected":
            self.runner.progress(f"{ct.name}: rejected: {check.reason}")
        else:
            got = "-" if check.safety_factor is None else f"{check.safety_factor:.2f}"
            self.runner.progress(f"{ct.name}: strength {check.verdict} ({check.model}, "
                                 f"{check.force_n:.2f} N, {check.stress_pa / 1e6:.2f} MPa, "
                                 f"safety factor {got})")

    def _record_strength(self, ct: CreatedTool, check: Any) -> None:
        """Put a strength check into the created tool and its JSON manifest."""
        from creative_py.fabrication.strength import write_strength

        ct.strength = check.to_dict()
        urdf = ct.files.get("urdf")
        if urdf:
            write_strength(Path(urdf).with_suffix(".json"), check)

    def _kind(self, struct: list) -> str:
        """Return the spec kind of a new tool: its class literal among ``struct``; when
        the learned model names none (any tool of the hierarchy worked), the kind of the
        demonstration's tool."""
        from creative_py.kinds import spec_classes

        kinds = [s.name for s in struct
                 if isinstance(s, Compound) and len(s.args) == 1 and s.name in spec_classes()]
        if kinds:
            return kinds[0]
        world = self.runner.world
        demo = world.manifest.demonstration.tool
        kind = getattr(world.item(demo).spec, "kind", None) if demo in world.items else None
        if kind not in spec_classes():
            raise RuntimeError(f"{self.case}: the new tool's literals name no tool kind "
                               f"({', '.join(spec_classes())}): {term_text(struct)}")
        return kind

    def _manufacture(self, k: int, struct: list, dims: Term,
                     ) -> tuple[Any, dict, dict, Optional[float], dict]:
        """Turn sized dimensions into a spec, write its files, add it to the world.

        The tool's kind is its class literal among the structural literals (a spec
        class of a tool kind, :func:`creative_py.kinds.spec_classes`, e.g. ``hook(T)``).
        """
        from creative_py.mesh.export import write_tool_files
        from creative_py.kinds import spec_from_dict

        self.runner.progress(f"manufacturing tool {k}: meshing, splitting to the build "
                             "volume and slicing its pieces")
        values = {}
        for d in dims:
            name, value = d.args
            values[str(name)] = value if not isinstance(value, str) else str(value)
        kind = self._kind(struct)
        name = f"{self.case}_new{k}"
        # A created tool is printed: its mass is PLA density times its volume
        # (mass None, :func:`creative_py.mesh.spec.spec_mass`), in the URDF it is
        # spawned from and so in the physics.
        spec = spec_from_dict({"kind": kind, "name": name, **values, "mass": None},
                              source=f"created tool {name}")
        files: dict[str, Any] = {}
        mass: Optional[float] = None
        printed: dict[str, Any] = {}
        run = self.runner.run_folder
        if run is not None:
            # Written, split to fit the printer and sliced: a piece the slicer rejects
            # stops the run (SliceError).
            out = write_tool_files(spec, run.tools_dir(), overwrite=True, gcode=True)
            files = {"urdf": out.urdf, "sdf": out.sdf, "scad": out.scad, "stl": out.stl,
                     "png": out.png, "manifest": out.manifest}
            mass = out.mass.mass
            printed = print_summary(out.assembly)
        self.runner.world = self.runner.world.with_tool(spec, files.get("urdf"))
        return spec, values, files, mass, printed

    def _use_of(self, spec: Any, vs: Term, task: TaskState) -> Compound:
        """Return the learned model's plan for a created tool in ``task``: ``exploit/4``
        (its pose) or ``no_experiment(Why)`` when the pose cannot hold for it
        (``plan_use`` with the tool fixed)."""
        return self.engine.plan_use(self.case, vs, self.runner.task_facts(task),
                                    [Compound("tool", (spec.name,))])

    def _trial_with(self, use: Compound, n: int, vs: Term, task: TaskState) -> TrialRecord:
        """Test a created tool at the pose the learned model asks for (``use``, an
        ``exploit/4`` plan of :meth:`_use_of`) as creation trial ``n``.

        The outcome is not added to the tool-use version space: the created tool differs
        from the learned model in the replaced literal by design, and the harder task is
        a different concept. A success gives the harder task's model instead
        (:func:`created_models` in ``prolog/model_file.pl``).
        """
        rec, _ = self.runner.run(use, "create", n, vs, task, 0.0, label=False)
        return rec

    def _evaluate(self, spec: Any, vs: Term, task: TaskState) -> list[str]:
        """Run the paper's evaluation of the new tool: fresh trials over the locations."""
        out = []
        for i in range(1, self.eval_trials + 1):
            task.next_location()
            use = self._use_of(spec, vs, task)
            if use.name != "exploit":  # no pose at this location: as the learned model's
                out.append("no_plan")  # evaluation records it (phases._evaluate)
                continue
            rec, _ = self.runner.run(use, "eval", i, vs, task, 0.0, label=False)
            out.append(rec.outcome)
        return out
