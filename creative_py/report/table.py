"""The terminal report of a run folder: every trial with every column, cut nowhere.

The width is the one asked for, else the terminal's, else (output into a pipe or a
file) the widest row's, so that every trial is one line ``grep`` finds whole
(:func:`report_width`). When the table of every column fits that width it is printed
as one rich table; when it does not (an 80-column terminal), each trial is printed as a
block: one line with its number, phase, tool, variant, location and outcome, then its
pose, tested and violated literals and reason, each on its own lines. Every cell folds
(``overflow="fold"``): a text longer than its column wraps, never ends in an ellipsis.
"""

from __future__ import annotations

from typing import Any

from rich.console import Console, Group
from rich.table import Table
from rich.text import Text

from creative_py.records.summary import Hypotheses, StrengthSummary, VideoEntry
from creative_py.report.contents import RunContents, literals_text, readable_term, why_text


def trial_table(run: RunContents) -> Table:
    """Return the table of every readable trial, with all of its columns
    (:attr:`RunContents.columns`: every field of the record with a ``column``)."""
    table = Table(title=str(run.path), title_justify="left")
    for header, _ in run.columns:
        table.add_column(header, overflow="fold",
                         justify="right" if header in ("#", "loc") else "left")
    for t in run.trials:
        table.add_row(*(cell(t) for _, cell in run.columns))
    return table


_HEAD_FIELDS = ("#", "phase", "tool", "variant", "loc", "outcome")
"""The short columns: the head line of a trial in the narrow layout; every other column
(pose, tested, violated, reason, ...) has a line of its own."""

_OUTCOME_STYLE = {"success": "bold green", "failure": "bold red", "blocked": "bold yellow",
                  "unreachable": "bold", "invalid": "bold magenta"}


def trial_blocks(run: RunContents) -> Group:
    """Return every trial as a block of lines (the narrow layout): a head line, then one
    labelled line per long column, folded to the width."""
    cells = dict(run.columns)
    blocks = []
    for t in run.trials:
        outcome = cells["outcome"](t)
        head = Text(f"{cells['#'](t):>3}  {cells['phase'](t)}  "
                    f"{cells['tool'](t)}  {cells['variant'](t)}  loc {cells['loc'](t)}  ")
        head.append(outcome, style=_OUTCOME_STYLE.get(outcome, "bold"))
        grid = Table.grid(padding=(0, 1))
        grid.add_column(no_wrap=True)
        grid.add_column(overflow="fold")
        for name, cell in run.columns:
            if name not in _HEAD_FIELDS:
                grid.add_row(Text(f"     {name:<8}"), Text(cell(t)))
        blocks += [head, grid]
    return Group(*blocks)


def summary_lines(run: RunContents) -> list[str]:
    """Return the summary's lines under the table: hypotheses, plan, PDDL planner,
    created tools (with print figures when sliced), video clips."""
    s = run.summary
    lines = []
    hyp = s.hypotheses or Hypotheses()
    for key, clause in (("hs", hyp.hs), ("hg", hyp.hg)):
        lines.append(f"{key}: {readable_term('?' if clause is None else clause)}")
    prior = s.use.prior if s.use is not None else None
    if prior is not None:
        lines.append(f"prior (case {prior.case}), predicted necessary: "
                     + (", ".join(prior.taken) or "none")
                     + "".join(f"; settled {d.literal} (trial {d.trial})"
                               for d in prior.settled)
                     + "".join(f"; confirmed {d.literal} (trial {d.trial})"
                               for d in prior.confirmed)
                     + "".join(f"; dropped {d.literal} (trial {d.trial})"
                               for d in prior.dropped))
    if s.plan is not None:
        lines.append(f"plan: {s.plan}")
    for task, answer in (s.pddl.tasks() if s.pddl is not None else []):
        lines.append(f"pddl {task}: {answer.status or '?'} "
                     f"{_plain(answer.plan or '')}".rstrip())
    for tool in run.tools:
        c = tool.created
        if c is not None:
            lines.append(f"created {tool.name}: {readable_term(str(c.replaced))} -> "
                         f"{readable_term(str(c.instance))}; {dims_text(c.dims)} "
                         f"({c.trial_outcome}{strength_note(c.strength)})")
        printed = (tool.manifest or {}).get("print")
        if isinstance(printed, dict):
            lines.append(f"print {tool.name}: {print_text(printed)}")
    for clip in run.clips:
        info = clip.info or VideoEntry()
        what = " ".join(_plain(x) for x in (info.phase, info.trial, info.tool, info.outcome)
                        if x is not None)
        if info.why:
            what += f" (kept as {why_text(info.why)})"
        lines.append(f"video {clip.file}{'' if clip.exists else ' (missing)'}"
                     f"{': ' + what if what else ''}")
    return lines


def natural_width(table: Table) -> int:
    """Return the width at which no cell of ``table`` wraps."""
    return Console(width=100_000).measure(table).maximum


def report_width(console: Console, table: Table, width: int | None) -> int:
    """Return the width to print at: ``width`` when given, the terminal's when the output
    is one, else the table's natural width (no row wraps)."""
    if width is not None:
        return width
    if console.is_terminal:
        return console.width
    return max(80, natural_width(table))


def print_report(run: RunContents, console: Console, width: int | None = None) -> None:
    """Print the run's headline (:func:`creative_py.report.headline.headline`), then the
    trials (a table when it fits the width, else blocks) and the summary lines of a run
    on ``console``."""
    from creative_py.report.headline import headline

    table = trial_table(run)
    console.width = report_width(console, table, width)
    from creative_py.report.contents import state_text

    lines = [x for x in (state_text(run),) if x] + headline(run).lines
    for line in lines:
        console.print(line, markup=False, highlight=False)
    if lines:
        console.print()
    if natural_width(table) <= console.width:
        console.print(table)
    else:
        console.print(Text(str(run.path), style="italic"), soft_wrap=True)
        console.print(trial_blocks(run))
    for line in summary_lines(run):
        console.print(line, markup=False, highlight=False)


def dims_text(dims: Any) -> str:
    """Return a created tool's dimensions (metres, degrees) as ``handle_length 600 mm,
    hook_angle_deg 90, ...``."""
    if not isinstance(dims, dict):
        return str(dims)
    return ", ".join(f"{k} {v * 1000:.1f} mm" if isinstance(v, float) else f"{k} {v}"
                     for k, v in dims.items())


def print_text(printed: dict[str, Any]) -> str:
    """Return a tool's print figures (its JSON's ``print``) on one line: pieces, print
    time, filament, and each piece's size, time and filament."""
    from creative_py.report.headline import duration_text

    pieces = [p for p in printed.get("pieces") or [] if isinstance(p, dict)]
    bits = [f"{len(pieces)} piece{'s' if len(pieces) != 1 else ''}"]
    if isinstance(printed.get("print_time_s"), (int, float)):
        bits.append(duration_text(printed["print_time_s"]))
    if isinstance(printed.get("filament_g"), (int, float)):
        bits.append(f"{printed['filament_g']:.1f} g of filament")
    for p in pieces:
        box = p.get("bounding_box_mm")
        size = " x ".join(f"{v:.0f}" for v in box) + " mm" if isinstance(box, list) else "?"
        seconds, grams = p.get("print_time_s"), p.get("filament_g")
        bits.append(f"{p.get('name', '?')} {size}"
                    + (f" {duration_text(seconds)}" if isinstance(seconds, (int, float)) else "")
                    + (f" {grams:.1f} g" if isinstance(grams, (int, float)) else ""))
    return "; ".join(bits)


def _plain(value: Any) -> str:
    """A JSON value on one line: lists joined by commas, mappings as ``k=v``."""
    if isinstance(value, dict):
        return ", ".join(f"{k}={_plain(v)}" for k, v in value.items())
    if isinstance(value, list):
        if all(isinstance(v, dict) for v in value):
            return "; ".join(f"[{_plain(v)}]" for v in value)
        return literals_text(value)
    return str(value)


def strength_note(strength: StrengthSummary | dict | None) -> str:
    """Return ``"; strength pass, 13.8 MPa, safety factor 3.61"`` for a created tool's
    strength check (empty when it has none; a dict is read as the summary's
    ``strength``)."""
    if isinstance(strength, dict):
        strength = StrengthSummary.from_dict(strength, "strength")
    if strength is None or not strength.to_dict():
        return ""
    sf = strength.safety_factor
    stress = strength.stress_mpa if strength.stress_mpa is not None else 0
    text = (f"; strength {strength.verdict}, {stress:.1f} MPa, "
            f"safety factor {'-' if sf is None else f'{sf:.2f}'}")
    if strength.thickened_into:
        text += f", thickened into {strength.thickened_into}"
    if strength.reason:
        text += f": {strength.reason}"
    if strength.caveat:
        text += f" ({strength.caveat})"
    return text
