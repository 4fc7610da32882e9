"""What ``creative run`` shows while a run goes on: its progress lines, and on a terminal
a live status line under them.

:class:`RunProgress` is the ``progress`` callback of
:func:`creative_py.learning.run.run_case`. Each line it receives is printed whole
(``soft_wrap``: a line written into a log file is never folded inside a Prolog term).
On a terminal, a status line stays under the printed lines and is redrawn several times
a second: the phase, trial k of the budget (in tool-use learning), the elapsed time and
the last trial's outcome, or what the run is doing between trials (the demonstration,
manufacturing and slicing a tool, encoding the clips). When the output is not a
terminal (a pipe, a log file) there is no status line, only the lines.
"""

from __future__ import annotations

import re
import time
from typing import Any, Optional

from rich.console import Console
from rich.live import Live
from rich.text import Text

PHASE_NAMES = {"DEMO": "demonstration", "TUL": "tool-use learning", "EVAL": "evaluation",
               "TC": "tool creation"}
"""The progress lines' phase tags (:data:`creative_py.learning.trials.PHASE_TAGS`), in
words."""

_TRIAL = re.compile(r"^#(\d+)\s+(DEMO|TUL|TC|EVAL)\s+(\S+)\s+loc\s+(\S+)\s+(\w+)")
"""A trial's progress line: its number in the run, tag, tool, location, outcome."""

_DOING = (("demonstration", "demonstration"), ("manufacturing", "tool creation"),
          ("TC catalogue", "tool creation"), ("TC predicted", "tool creation"),
          ("encoding", "video"), ("pddl", "planning"), ("plan", "planning"))
"""Progress lines that start a long step: their start, and the phase they belong to."""


def elapsed_text(seconds: float) -> str:
    """Return ``1:05`` (minutes and seconds) or ``1:02:05``."""
    s = int(seconds)
    return f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}" if s >= 3600 else \
        f"{s // 60}:{s % 60:02d}"


class RunProgress:
    """The progress callback of a run on a Rich console.

    Parameters
    ----------
    console : rich.console.Console
        Where the lines go (``creative run`` uses standard error).
    budget : int or None
        The tool-use trial budget (N of Algorithm 1), shown as "trial k of N".
    live : bool or None
        Whether to show the status line; None: when the console is a terminal.

    Use it as a context manager around the run::

        with RunProgress(console, budget=12) as progress:
            run_case(case, out, options, progress=progress)
    """

    def __init__(self, console: Console, budget: Optional[int] = None,
                 live: Optional[bool] = None) -> None:
        self.console = console
        self.budget = budget
        self.start = time.monotonic()
        self.phase = "starting"
        self.trial: Optional[int] = None
        self.last = ""
        self.doing = ""
        show = console.is_terminal if live is None else live
        self._live = (Live(self, console=console, refresh_per_second=4, transient=True)
                      if show else None)

    def __enter__(self) -> "RunProgress":
        self.start = time.monotonic()
        if self._live is not None:
            self._live.start()
        return self

    def __exit__(self, *exc: Any) -> None:
        if self._live is not None:
            self._live.stop()

    def __call__(self, message: str) -> None:
        """Update the status line from one progress line and print the line whole."""
        match = _TRIAL.match(message)
        if match:
            k, tag, tool, _, outcome = match.groups()
            self.phase, self.trial = PHASE_NAMES[tag], int(k)
            self.last, self.doing = f"{tool} {outcome}", ""
        else:
            for start, phase in _DOING:
                if message.startswith(start):
                    self.phase, self.trial, self.doing = phase, None, message
                    break
        self.console.print(message, markup=False, highlight=False, soft_wrap=True)

    def status(self) -> str:
        """Return the status line's text."""
        parts = [self.phase]
        if self.trial is not None:
            of = f" of {self.budget}" if self.budget and self.phase == "tool-use learning" \
                else ""
            parts.append(f"trial {self.trial}{of}")
        parts.append(f"{elapsed_text(time.monotonic() - self.start)} elapsed")
        if self.doing:
            parts.append(self.doing)
        elif self.last:
            parts.append(f"last: {self.last}")
        return " · ".join(parts)

    def __rich__(self) -> Text:
        width = max(20, self.console.width - 1)
        text = self.status()
        return Text(text if len(text) <= width else text[:width - 1] + "…", style="bold")
