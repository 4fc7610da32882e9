"""One trial of any case: run a planned experiment in the physics, label it, record it.

The learner (Algorithm 1) and the creator (Algorithm 2) share a :class:`TrialRunner`
by composition. A trial::

    runner.task_facts(task)                 # what the robot sees of the task: catalogue,
                                            # apparatus, target (one observation per scene)
    runner.run(experiment, "use", 3, vs, task, decision_s)
        -> run_trial(world, tool, task, pose)
                                            # the manifest's skills, in order, in the
                                            # manifest's backend (pybullet by default);
                                            # the facts before the tool action are observed
                                            # (creative_py.simulator.trial)
        -> engine.label_trial(...)          # success: pos; failure or blocked: neg
        -> TrialRecord                      # one line of trials.jsonl (records.trial)

Which skills run, with which arguments and which of them takes the pose, comes from the
case manifest (``[[skill]]`` of ``worlds/<folder>/case.toml``); nothing here names a
case. The physics alone decides the outcome.

What each way of ending a trial means is decided by the physics alone, in one place
for every backend (:func:`creative_py.simulator.trial.trial_outcome`, from how the
skills ended and what the oracle measured). Outcomes ``blocked`` (the arm could
not carry out a motion before the tool action, e.g. a short handle whose gripper hits
the tube mouth before the prong is behind the cube, or a robot whose own links struck
a scene body and did not reach the goal) count as failures of the *planned*
example, so they are evidence about the tested literal only; outcomes
``unreachable`` and ``invalid`` are recorded with their reason and leave the version
space unchanged.
"""

from __future__ import annotations

import logging
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence

from creative_py.bridge import (Compound, Engine, PrologError, PrologFailed, Term, encode,
                                fact_term)
from creative_py.case import CaseManifest
from creative_py.learning import interrupts
from creative_py.learning.clips import ClipKeeper
from creative_py.learning.poses import pose_resolver
from creative_py.records.folder import RunFolder
from creative_py.records.trial import TrialRecord, measured_fields, verdict_lines
from creative_py.simulator.trial import plain_reason, task_facts
from creative_py.simulator.types import BackendLost

if TYPE_CHECKING:
    from creative_py.simulator import PoseTarget, World

log = logging.getLogger(__name__)

PHASE_TAGS = {"use": "TUL", "create": "TC", "eval": "EVAL"}
"""How the progress lines and the plot name the phases (the paper's TUL and TC)."""


@dataclass
class TaskState:
    """The current task: variant and target location (1-based)."""

    variant: str
    location: int
    locations: tuple[int, ...]

    def next_location(self) -> None:
        """Move to the next predefined location (the task changes after a success)."""
        i = self.locations.index(self.location)
        self.location = self.locations[(i + 1) % len(self.locations)]


def term_text(t: Term) -> str:
    """Return a term as Prolog text (for logs and JSON): the bridge's writer, so a
    list of terms is a Prolog list, not the Python ``repr`` of its items."""
    return encode(t, operators=True)


def pose_numbers(pose: Term) -> tuple[float, ...]:
    """Return the numbers of a ground pose term of the constraint solver."""
    if not isinstance(pose, Compound):
        raise ValueError(f"not a pose term: {pose!r}")
    return tuple(float(a) for a in pose.args)


def _trial_line(n: int, phase: str, tool: str, location: int, ex, tested: list[str]) -> str:
    """Return trial ``n``'s progress line: its number, phase, tool, location, outcome,
    tested literals and why it did not go as planned (when it did not)."""
    # One trial number everywhere (terminal, tables, plot, clips, report): the run's
    # own, n of trials.jsonl (the demonstration is 0); a phase's count repeats
    # (the created tool's evaluation starts at 1 again).
    return (f"#{n:<3} {PHASE_TAGS[phase]:<4} {tool:<14} "
            f"loc {location}  {ex.outcome:<11} tested {', '.join(tested) or '-'}"
            # how the trial did not go as planned, as the table and the clip say it
            + ("" if plain_reason(ex.reason) else f"  because {ex.reason}"))


class TrialRunner:
    """Runs planned experiments of one case in the physics and keeps their records.

    Parameters
    ----------
    engine : Engine
        The Prolog engine (bridge).
    world : World
        The case's world (its backend's ``load_world``,
        :class:`creative_py.simulator.World`); its manifest names the case, the
        skills, the pose and the backend that runs the trials.
    run : RunFolder or None
        Where trials are logged; None logs nowhere.
    seed : int
        Seed of the run; trial ``n`` uses seed ``seed * 1000 + n`` in the physics.
    progress : callable or None
        Called with one line of text per trial.
    replay : sequence of TrialRecord
        Trials already recorded in ``trials.jsonl`` (a resumed run): the first
        ``len(replay)`` trials take their outcome and observed facts from these records
        instead of the physics, so the version space is rebuilt exactly; the decisions
        are Prolog's again and must name the recorded tool and pose, and the labels
        must give the recorded h_s and h_g.
    replay_lines : sequence of int or None
        The line of ``trials.jsonl`` of each replayed trial (for the error naming a
        record that does not replay); None: the trial numbers.
    clips : ClipKeeper or None
        Which trials become video clips (:mod:`creative_py.learning.clips`); None
        records none.
    gui : bool
        Show every trial in the simulator's window (needs a display).
    """

    def __init__(self, engine: Engine, world: World, run: Optional[RunFolder], seed: int = 0,
                 progress: Optional[Callable[[str], None]] = None,
                 replay: Sequence[TrialRecord] = (), clips: Optional[ClipKeeper] = None,
                 gui: bool = False, replay_lines: Optional[Sequence[int]] = None) -> None:
        self.engine = engine
        self.world = world
        self.run_folder = run
        self.seed = seed
        self.progress = progress or (lambda _msg: None)
        self.trials: list[TrialRecord] = []
        self.replay = list(replay)
        self.replay_lines = list(replay_lines or [r.trial for r in self.replay])
        self.physical = 0
        """Trials run in the physics (not replayed) by this runner."""
        self.clips = clips
        self.gui = gui
        self.pose_target = pose_resolver(engine, world.manifest)

    @property
    def manifest(self) -> CaseManifest:
        """Return the case manifest of the world."""
        return self.world.manifest

    @property
    def case(self) -> str:
        """Return the case id."""
        return self.world.manifest.id

    def task(self, variant: str) -> TaskState:
        """Return a task of ``variant`` at the first location."""
        locs = tuple(self.world.locations)
        return TaskState(variant, locs[0], locs)

    def task_facts(self, task: TaskState) -> list[Term]:
        """Return the primitive facts the planner needs before a trial: the catalogue
        of available objects and the task's geometry."""
        return [fact_term(f) for f in task_facts(self.world, task.variant, task.location)]

    def bounds(self, vs: Term) -> tuple[str, str]:
        """Return h_s and h_g of the version space as text."""
        hs, hg = self.engine.vs_bounds(vs)
        return term_text(hs), term_text(hg)

    def run(self, exp: Term, phase: str, phase_trial: int, vs: Term, task: TaskState,
            decision: float, label: bool = True) -> tuple[TrialRecord, Term]:
        """Execute a planned experiment, label it and update the version space.

        ``exp`` is an ``experiment/6`` or ``exploit/4`` term of the engine.
        ``label=False`` leaves the version space unchanged (evaluation trials, created
        tools). Returns the trial's record and the version space after it.
        """
        interrupts.check()  # a Ctrl-C something swallowed still ends the run here
        n = len(self.trials) + 1
        kind, tool, tested_l, violated, pose = self._planned(exp)
        replayed = n <= len(self.replay)
        if replayed:
            ex = self._replayed(self.replay[n - 1], str(tool), task, pose, phase)
            self._run_again(n, phase, phase_trial, str(tool), tested_l, task, pose, label)
        else:
            self.end_replay()  # every recorded trial was checked: the folder opens
            self.physical += 1
            ex = self._physical(n, phase, phase_trial, str(tool), tested_l, task, pose)
        td = time.perf_counter()
        if label:
            vs = self._label_trial(n, vs, exp, ex, task, replayed)
        hs, hg = self.bounds(vs)
        line = _trial_line(n, phase, str(tool), task.location, ex, tested_l)
        if replayed:
            rec = self._checked_replay(n, hs, hg)
            self.progress(line + "  (replayed)")
            return rec, vs
        decision += time.perf_counter() - td
        # The hypotheses left between h_g and h_s (version_space:vs_count/3).
        count, exact = self.engine.vs_count(vs) if label else (None, None)
        rec = TrialRecord(
            trial=n, phase=phase, phase_trial=phase_trial, variant=task.variant,
            location=task.location, tool=str(tool), kind=kind, tested=tested_l,
            violated=[term_text(v) for v in violated], pose=self._pose_dict(pose),
            outcome=ex.outcome, reason=ex.reason, hs=hs, hg=hg,
            wall_time_s=round(ex.wall_time_s, 3), sim_time_s=round(ex.sim_time_s, 3),
            decision_time_s=round(decision, 4), vs_count=count, vs_count_exact=exact,
            # What the robot observed before the tool action: a resumed run labels it again.
            facts=[[a.item() if hasattr(a, "item") else a for a in f]
                   for f in ex.facts_before],
            # The largest contact force on the tool while it acted (sim/loads.py), what
            # the strength check of a created tool reads.
            max_tool_force_n=ex.tool_load["max_force_n"] if ex.tool_load else None,
            tool_load=ex.tool_load,
            # What the physics measured against its thresholds (sim/oracles.py).
            verdict=ex.verdict,
            # The record's other measured fields, by name (records/trial.py: measured).
            **ex.measures)
        self.trials.append(rec)
        if self.run_folder:
            self.run_folder.append_trial(rec)
        measured = "; ".join(verdict_lines(ex.verdict))
        self.progress(line + (f"  [{measured}]" if measured else ""))
        return rec, vs

    def _label_trial(self, n: int, vs: Term, exp: Term, ex, task: TaskState,
                     replayed: bool) -> Term:
        """Return the version space ``vs`` after labelling trial ``n`` (its experiment
        ``exp``, its episode ``ex``); a replayed trial that does not label is a resume
        refused (ValueError naming the line of trials.jsonl)."""
        try:
            return self._label(vs, exp, ex, task)
        except (TypeError, ValueError, PrologError, PrologFailed) as exc:
            if not replayed:
                raise
            raise ValueError(f"{self._where(n)}: field 'facts' does not label "
                             f"({exc}); the run cannot be resumed") from None

    def _planned(self, exp: Term) -> tuple[str, Term, list[str], list[Term], Term]:
        """Return what an ``experiment/6`` or ``exploit/4`` term plans: its kind, the
        tool, the tested literal (as text; none for an exploit), the literals of h_s it
        violates and the pose."""
        kind = exp.name if isinstance(exp, Compound) else str(exp)
        if kind == "no_experiment":
            raise RuntimeError(f"{self.case}: no experiment is possible: {exp.args[0]}")
        if kind == "experiment":
            tool, tested, violated, pose, _req, _neg = exp.args
            return kind, tool, [term_text(tested)], violated, pose
        tool, violated, pose, _req = exp.args  # exploit
        return kind, tool, [], violated, pose

    def _checked_replay(self, n: int, hs: str, hg: str) -> TrialRecord:
        """Return replayed trial ``n``'s record as it was (its timings, clip and
        measurements stay), after checking that relabelling it gave its recorded h_s and
        h_g (an edited outcome does not)."""
        rec = self.replay[n - 1]
        for name, now in (("hs", hs), ("hg", hg)):
            if rec.get(name) is not None and rec.get(name) != now:
                raise ValueError(
                    f"{self._where(n)}: fields 'outcome' and {name!r} disagree: "
                    f"replaying the outcome {rec.outcome!r} with the line's facts "
                    f"gives another {name[0]}_{name[1]}; the record was changed, the "
                    f"run cannot be resumed")
        self.trials.append(rec)
        if self.clips is not None:
            self.clips.replayed(rec)
        return rec

    def _run_again(self, n: int, phase: str, phase_trial: int, tool: str,
                   tested: list[str], task: TaskState, pose: Term, label: bool) -> None:
        """Run replayed trial ``n`` again in the physics when its record cannot be
        checked otherwise or its clip is missing, and refuse a record the physics
        contradicts.

        A labelled trial's outcome is checked by the h_s and h_g it leads to
        (:meth:`_checked_replay`); an unlabelled one (evaluation, a created or
        catalogued tool's trial) changes no hypothesis, so the physics, which decides
        every outcome, decides it again (runs are deterministic: trial ``n`` has seed
        ``seed * 1000 + n``). A clip the interrupted run did not finish is rendered from
        this run of the trial (:meth:`ClipKeeper.missing`)."""
        rec = self.replay[n - 1]
        why = self.clips.missing(rec) if self.clips is not None else None
        if label and why is None:
            return
        from creative_py.simulator.trial import run_trial

        recorder = self.clips.recorder() if why is not None else None

        def verdict(outcome: str, reason: str, measured: dict | None) -> None:
            if outcome == rec.outcome:  # a contradicted record is refused below
                self.clips.write(recorder, why, n, phase, phase_trial, tool, tested,
                                 outcome, reason, task.location,
                                 measured=verdict_lines(measured), again=True)

        ex = run_trial(self.world, tool, task.variant, task.location, pose_numbers(pose),
                       self.seed * 1000 + n, None, gui=self.gui, record=recorder,
                       verdict=verdict if recorder is not None else None,
                       pose_target=self.pose_target)
        if ex.outcome != rec.outcome:
            raise ValueError(
                f"{self._where(n)}: field 'outcome' is {rec.outcome!r}, but the physics "
                f"gives {ex.outcome!r} for this trial (run again: {ex.reason or '-'}); "
                f"the record was changed, the run cannot be resumed")
        if why is not None:
            self.progress(f"#{n}: its clip was missing; the trial was run again and the "
                          f"clip rendered ({ClipKeeper.file_name(n, phase, tool)})")

    def end_replay(self) -> None:
        """Open the run folder and the clips again after a resume's replay (checked):
        ``trials.jsonl`` is rewritten with the replayed records, if it must be."""
        if self.run_folder is not None:
            self.run_folder.unseal()
        if self.clips is not None:
            self.clips.held = False

    def _where(self, n: int) -> str:
        """Return ``<run>/trials.jsonl: line L`` of replayed trial ``n``."""
        path = self.run_folder.trials_path if self.run_folder else "trials.jsonl"
        return f"{path}: line {self.replay_lines[n - 1]}"

    def _physical(self, n: int, phase: str, phase_trial: int, tool: str,
                  tested: list[str], task: TaskState, pose: Term) -> Any:
        """Run trial ``n`` in the physics (:func:`creative_py.simulator.trial.run_trial`
        in the manifest's backend), its snapshots in the run folder and, when the clip
        keeper wants it, its clip; return the TrialResult."""
        from creative_py.simulator.trial import run_trial

        images = self.run_folder.snapshot_dir(phase, n) if self.run_folder else None
        recorder = self.clips.recorder() if self.clips is not None else None

        def verdict(outcome: str, reason: str, measured: dict | None) -> None:
            why = self.clips.why(phase, outcome, reason)
            if why is not None:
                self.clips.write(recorder, why, n, phase, phase_trial, tool, tested,
                                 outcome, reason, task.location,
                                 measured=verdict_lines(measured))

        try:
            return run_trial(
                self.world, tool, task.variant, task.location, pose_numbers(pose),
                self.seed * 1000 + n, images, gui=self.gui, record=recorder,
                verdict=verdict if recorder is not None else None,
                pose_target=self.pose_target)
        except BackendLost as exc:
            # Not an outcome: the run stops resumably and says which trial did not go
            # as planned (stopped.json); the resume runs it again.
            exc.trial = {"trial": n, "phase": phase, "phase_trial": phase_trial,
                         "tool": tool, "variant": task.variant, "location": task.location,
                         "pose": self._pose_dict(pose)}
            raise

    def _label(self, vs: Term, exp: Term, ex: Any, task: TaskState) -> Term:
        """Return the version space after the trial's example (success: ``pos``;
        failure: ``neg`` of what was observed; blocked: ``neg`` of the planned example;
        a success in which the robot struck a scene body: ``pos`` of the planned
        example); an unreachable or invalid trial leaves it as it was."""
        lab = {"success": "pos", "failure": "neg", "blocked": "neg"}.get(ex.outcome)
        if lab is None:
            return vs
        facts = [fact_term(f) for f in ex.facts_before]
        # A blocked motion stopped before the tool acted, and a robot that struck a scene
        # body (its verdict's ``struck``: the judgement of simulator/trial.py
        # trial_outcome) moved the held tool itself: in either, what the robot observed
        # before the tool action is where the motion left or the arm pushed the tool,
        # not the pose the experiment tested, so the trial labels the planned example.
        planned = ex.outcome == "blocked" or bool((ex.verdict or {}).get("struck"))
        if planned and not facts:
            facts = self.task_facts(task)
        return self.engine.label_trial(self.case, vs, exp, facts, lab,
                                       "planned" if planned else "observed")

    def _replayed(self, record: TrialRecord, tool: str, task: TaskState, pose: Term,
                  phase: str) -> Any:
        """Return what a recorded trial did (a :class:`creative_py.simulator.TrialResult`),
        after checking it is the trial decided now."""
        from creative_py.simulator import TrialResult

        planned = (phase, tool, task.variant, task.location, self._pose_dict(pose))
        recorded = (record.phase, record.tool, record.variant, record.location, record.pose)
        if planned != recorded:
            raise ValueError(f"{self._where(record.trial)}: trial {record.trial} of the "
                             f"run being resumed was {recorded}, but the learner now plans "
                             f"{planned}: the run cannot be resumed with this code or "
                             f"these files")
        return TrialResult(
            case=self.case, object=record.tool, variant=record.variant,
            location=record.location, pose=pose_numbers(pose), outcome=record.outcome,
            reason=record.reason, perceived_final=None, true_final={},
            sim_time_s=float(record.sim_time_s), wall_time_s=float(record.wall_time_s),
            render_time_s=0.0, steps=0, max_tool_force_n=record.max_tool_force_n or 0.0,
            tool_load=record.tool_load, facts_before=tuple(tuple(f) for f in record.facts),
            verdict=record.verdict,
            measures={n: getattr(record, n) for n in measured_fields(type(record))
                      if getattr(record, n) is not None})

    def _pose_dict(self, pose: Term) -> dict[str, float]:
        m = self.manifest
        if isinstance(pose, Compound) and pose.name == m.pose_term:
            return dict(zip(m.pose_names, (round(float(a), 5) for a in pose.args)))
        return {"pose": term_text(pose)}
