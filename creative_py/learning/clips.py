"""Which trials of a run become video clips, and the list of clips of ``summary.json``.

``--video key`` (the default) keeps the demonstration, the first success, every
tool-creation trial and the first trial of each distinct failure (its outcome and
reason, numbers left out: two ``blocked`` trials whose gripper lagged by 3.1 and 3.4 cm
are one reason); ``--video all`` keeps every trial; ``--video none`` records nothing.

Every trial's poses are kept while it runs (cheap: the backend's recorder,
:class:`creative_py.simulator.ClipRecorder`); once the physics has given the outcome,
:meth:`ClipKeeper.why` says whether the trial is kept, and only a kept trial is
rendered and written, as ``videos/<trial>-<phase>-<tool>.mp4`` (the demonstration is trial 0). Each entry of
:attr:`ClipKeeper.entries` (``summary["videos"]``) is::

    {"file": "videos/002-use-hook_a2.mp4", "phase": "use", "trial": 2,
     "tool": "hook_a2", "tested": ["hook_down(hook_a2)"], "outcome": "failure",
     "reason": "goal not reached", "why": "failure:failure: goal not reached",
     "frames": 42, "duration_s": 8.4, "bytes": 32873}

``why`` is ``demonstration``, ``creation``, ``first_success``, ``failure:<reason>``
or, with ``all``, ``trial`` for a trial kept only because every trial is.

Each entry is also appended to ``videos/clips.jsonl`` when its clip is started, so a
resumed run keeps the entries (frames, duration) of the clips the interrupted run made.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path
from typing import Any, Callable, Optional, Sequence

from creative_py.records.trial import TrialRecord

VIDEO_MODES = ("all", "key", "none")
"""The values of ``--video`` (``RunOptions.video``)."""

CLIP_NICE = 10
"""How much lower than the run's the scheduling priority of a clip process is: it
renders and encodes on the CPU the run leaves idle."""

CLIPS_FILE = "videos/clips.jsonl"
"""The entries of the clips started so far, one JSON object a line."""

PHASE_TAGS = {"demo": "DEMO", "use": "TUL", "create": "TC", "eval": "EVAL"}


def failure_reason(outcome: str, reason: str) -> str:
    """Return the failure class of a trial: its outcome and reason, each number (not a
    name's digits: ``cube1`` stays) written N."""
    text = re.sub(r"(?<![\w.])[-+]?\d+(?:\.\d+)?(?![\w.])", "N", reason or "")
    return f"{outcome}: {' '.join(text.split())}" if text else outcome


class ClipError(RuntimeError):
    """A clip could not be written; the message names its file and trial and the
    cause."""


class ClipKeeper:
    """Decides which trials become clips and writes them into ``<run>/videos/``.

    Parameters
    ----------
    mode : {"all", "key", "none"}
    run_dir : Path
        The run folder.
    spec : ClipCamera or None
        The world's clip camera (``world.video``, :class:`creative_py.simulator.
        ClipCamera`); None records nothing.
    background : bool
        Render and encode each clip in a child process (forked inside the trial's
        episode, after the verdict, at :data:`CLIP_NICE` lower priority) while the run
        goes on; :meth:`finish` waits for them. Off: in this process, at once.
    max_children : int
        Most clip processes running at once (one more waits for the oldest).
    new_recorder : callable or None
        ``new_recorder(spec)`` returns an empty recorder of one trial (the world's
        backend's ``recorder``, :meth:`creative_py.simulator.Backend.recorder`); needed
        unless nothing is recorded.
    """

    def __init__(self, mode: str, run_dir: Path, spec: Any, background: bool = True,
                 max_children: int = 2,
                 new_recorder: Optional[Callable[[Any], Any]] = None) -> None:
        if mode not in VIDEO_MODES:
            raise ValueError(f"option video must be one of {', '.join(VIDEO_MODES)}, "
                             f"got {mode!r}")
        self.mode = mode if spec is not None else "none"
        if self.mode != "none" and new_recorder is None:
            raise ValueError("a clip keeper that records needs the backend's recorder "
                             "(new_recorder)")
        self.new_recorder = new_recorder
        self.run_dir = Path(run_dir)
        self.spec = spec
        self.entries: list[dict[str, Any]] = []
        self.seen: set[str] = set()
        self.succeeded = False
        self.wall_time_s = 0.0
        """Wall time the run spent on clips: rendering and encoding them, or, in the
        background, starting them and waiting for them (the snapshots aside)."""
        self.background = background
        self.max_children = max_children
        self.children: dict[int, str] = {}
        self.held = False
        """True while a resumed run replays its recorded trials: nothing is written,
        and a clip the interrupted run made is kept with its entry."""
        self.earlier = self._earlier_entries()
        if self.mode != "none":
            from creative_py.video import prepare

            prepare()

    def recorder(self):
        """Return a new recorder for one trial, or None when nothing is recorded."""
        if self.mode == "none":
            return None
        return self.new_recorder(self.spec)

    def why(self, phase: str, outcome: str, reason: str) -> Optional[str]:
        """Return why the trial that just ended is kept, or None; note what it showed.

        Call it once per trial, in order (replayed trials of a resumed run included),
        so that "first" means first in the run.
        """
        return self._decide(phase, outcome, reason, note=True)

    def peek(self, phase: str, outcome: str, reason: str) -> Optional[str]:
        """Return what :meth:`why` would return for the next trial, noting nothing."""
        return self._decide(phase, outcome, reason, note=False)

    def _decide(self, phase: str, outcome: str, reason: str, note: bool) -> Optional[str]:
        why = None
        if phase == "demo":
            why = "demonstration"
        elif phase == "create":
            why = "creation"
        if phase == "demo":
            pass  # the trainer's, not a trial: the first success is the robot's own
        elif outcome == "success":
            if not self.succeeded:
                why = why or "first_success"
            self.succeeded = self.succeeded or note
        else:
            cls = failure_reason(outcome, reason)
            if cls not in self.seen:
                why = why or f"failure:{cls}"
            if note:
                self.seen.add(cls)
        if self.mode == "all":
            return why or "trial"
        return why if self.mode == "key" else None

    @staticmethod
    def file_name(trial: int, phase: str, tool: str) -> str:
        """Return the clip's path relative to the run folder."""
        return f"videos/{trial:03d}-{phase}-{tool}.mp4"

    def write(self, recorder: Any, why: str, trial: int, phase: str, phase_trial: int,
              tool: str, tested: Sequence[str], outcome: str, reason: str,
              location: Any = None, measured: Sequence[str] = (),
              again: bool = False) -> dict[str, Any]:
        """Render a trial's recorder and encode its frames with their caption, in a
        child process when :attr:`background` (call it inside the trial's episode);
        add and return the clip's entry (its ``bytes`` once :meth:`finish` ran).
        ``measured`` is the trial's measured verdict in short lines
        (:func:`creative_py.records.trial.verdict_lines`: caption lines, and the
        entry's ``verdict``). ``again``: a resume's replayed trial whose clip is missing
        (the interrupted run never finished it) was run again in the physics to render
        it."""
        import time

        from creative_py.video import write_clip

        from creative_py.learning import interrupts

        t0 = time.perf_counter()
        name = self.file_name(trial, phase, tool)
        if self.held and not again:  # a resume's replay: the clip was made before
            entry = self._kept(name, why)
            if entry is not None:
                self.entries.append(entry)
            return entry
        head = (f"#{trial} {PHASE_TAGS.get(phase, phase)}  {tool}"
                + (f"  loc {location}" if location is not None else ""))
        lines = [head, f"tested {', '.join(tested) or '-'}",
                 f"{outcome}" + (f": {reason}" if reason else "")]
        lines += list(measured)
        path, fps = self.run_dir / name, self.spec.fps

        def use(frames, times) -> None:
            try:
                write_clip(path, frames, fps, lines, times)
            except BaseException as exc:  # name the clip: the child's warning says it
                raise ClipError(f"{name} (trial {trial}): {type(exc).__name__}"
                                + (f": {exc}" if str(exc) else "")) from exc

        if self.background:
            self._wait(self.max_children - 1)
        # A Ctrl-C while the clip is started is held back until it is: the clip process
        # forked here ignores it and writes the clip of this ended trial.
        with interrupts.deferred():
            pid = recorder.render_then(use, background=self.background, nice=CLIP_NICE)
        if pid is not None:
            self.children[pid] = name
        n = len(recorder.snapshots)
        entry = {"file": name, "phase": phase, "trial": trial, "tool": tool,
                 "tested": list(tested), "outcome": outcome, "reason": reason,
                 "verdict": "; ".join(measured), "why": why,
                 "frames": n, "duration_s": round(n / fps, 2), "bytes": None}
        self.entries.append(entry)
        self._note(entry)
        self.wall_time_s += time.perf_counter() - t0
        return entry

    def _wait(self, most: int) -> None:
        """Wait for clip processes until at most ``most`` are still running."""
        import logging

        while len(self.children) > most:
            pid = next(iter(self.children))  # the oldest; never another process's child
            name = self.children.pop(pid)
            _, status = os.waitpid(pid, 0)
            code = os.waitstatus_to_exitcode(status)
            if code != 0:
                cause = (f"its process was ended by signal {-code}" if code < 0
                         else "its process failed (the line above says why)")
                logging.getLogger(__name__).warning("%s: the clip was not written: %s",
                                                    name, cause)

    def finish(self) -> list[dict[str, Any]]:
        """Wait for every clip being written; drop the entries of clips that failed,
        fill in the others' sizes; return :attr:`entries`."""
        import time

        t0 = time.perf_counter()
        self._wait(0)
        kept = []
        for e in self.entries:
            f = self.run_dir / e["file"]
            if f.is_file():
                e["bytes"] = f.stat().st_size
                kept.append(e)
        self.entries = kept
        self.wall_time_s += time.perf_counter() - t0
        return kept

    def replayed(self, record: TrialRecord) -> None:
        """Account for a trial of a resumed run (no physics): note its outcome and keep
        the entry of its clip, as the interrupted run recorded it, if it wrote one."""
        why = self.why(record.phase, record.outcome, record.reason)
        name = self.file_name(record.trial, record.phase, record.tool)
        if any(e["file"] == name for e in self.entries):
            return  # rendered again during the replay (:meth:`missing`)
        if why is not None:
            entry = self._kept(name, why)
            if entry is None and (self.run_dir / name).is_file():
                entry = {"file": name, "phase": record.phase, "trial": record.trial,
                         "tool": record.tool, "tested": list(record.tested),
                         "outcome": record.outcome, "reason": record.reason, "why": why,
                         "frames": None, "duration_s": None, "bytes": None}
            if entry is not None:
                self.entries.append(entry)

    def missing(self, record: TrialRecord) -> Optional[str]:
        """Return why a replayed trial would be kept when its clip file is missing (a
        run killed or interrupted before the clip was written), else None: the trial
        is then run again in the physics to render it."""
        if self.mode == "none":
            return None
        why = self.peek(record.phase, record.outcome, record.reason)
        name = self.file_name(record.trial, record.phase, record.tool)
        return why if why is not None and not (self.run_dir / name).is_file() else None

    def _kept(self, name: str, why: str) -> Optional[dict[str, Any]]:
        """Return the recorded entry of an existing clip ``name`` (its ``why`` as
        decided now), or None."""
        if not (self.run_dir / name).is_file() or name not in self.earlier:
            return None
        return {**self.earlier[name], "why": why, "bytes": None}

    def _note(self, entry: dict[str, Any]) -> None:
        """Append a clip's entry to :data:`CLIPS_FILE`."""
        path = self.run_dir / CLIPS_FILE
        path.parent.mkdir(parents=True, exist_ok=True)
        with open(path, "a", encoding="utf-8") as fh:
            fh.write(json.dumps({k: v for k, v in entry.items() if k != "bytes"}) + "\n")

    def _earlier_entries(self) -> dict[str, dict[str, Any]]:
        """Return the entries :data:`CLIPS_FILE` holds, by file (the last of each)."""
        out: dict[str, dict[str, Any]] = {}
        try:
            text = (self.run_dir / CLIPS_FILE).read_text(encoding="utf-8")
        except OSError:
            return out
        for line in text.splitlines():
            try:
                entry = json.loads(line)
            except ValueError:
                continue  # a torn last line of a killed run
            if isinstance(entry, dict) and isinstance(entry.get("file"), str):
                out[entry["file"]] = entry
        return out
