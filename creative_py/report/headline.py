"""The headline of a run: what a person wants to know first, in a few sentences and
figures, for the page (:mod:`creative_py.report.page`) and the terminal report
(:mod:`creative_py.report.table`) alike.

The sentences say the case and strategy, the trials of each phase with the stop reason
and the paper's figure, what solved the harder task (the learned model's tool, a
catalogued object or a created tool) and which catalogued objects were tried, the
learned model's evaluation apart from the created tool's, the print time and filament,
and the wall time. Each :class:`Figure` names the ``summary.json`` key its number
comes from, so a test can compare the two.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from creative_py.report.contents import RunContents, number_text

STOP_TEXT = {"confirmed": "the learned model succeeded the required times in a row",
             "certified": "no experiment left that could change the model",
             "exhausted": "no experiment left to draw",
             "budget": "the trial budget was used up"}
"""What each stop reason of ``summary.json``'s ``use.stop`` means."""


@dataclass
class Figure:
    """One number of the headline.

    Attributes
    ----------
    key : str
        Where it is in ``summary.json`` (dotted: ``use.trials``).
    raw : Any
        Its value there.
    value : str
        As shown (``9 of 12``, ``4 h 04 min``).
    label : str
        What it is.
    """

    key: str
    raw: Any
    value: str
    label: str


@dataclass
class Headline:
    """The headline's sentences and figures."""

    lines: list[str] = field(default_factory=list)
    figures: list[Figure] = field(default_factory=list)


def duration_text(seconds: float) -> str:
    """Return a duration as ``4 h 04 min``, ``12 min`` or ``42 s``."""
    if seconds >= 3600:
        minutes = round(seconds / 60)
        return f"{minutes // 60} h {minutes % 60:02d} min"
    if seconds >= 60:
        return f"{round(seconds / 60)} min"
    return f"{seconds:.3g} s"


def _dict(value: Any) -> dict[str, Any]:
    return value if isinstance(value, dict) else {}


def _successes(outcomes: Any) -> tuple[int, int]:
    outcomes = outcomes if isinstance(outcomes, list) else []
    return sum(o == "success" for o in outcomes), len(outcomes)


def headline(run: RunContents) -> Headline:
    """Return the headline of a run folder's contents (empty parts are left out)."""
    s = run.summary
    out = Headline()
    options = _dict(s.get("options"))
    use, create, ev = _dict(s.get("use")), _dict(s.get("create")), _dict(s.get("eval"))
    strategy = options.get("strategy") or use.get("strategy")
    first = [f"case {s['case']}" if "case" in s else "",
             f"strategy {strategy}" if strategy else "",
             f"seed {s['seed']}" if "seed" in s else ""]
    if any(first):
        out.lines.append(", ".join(x for x in first if x).capitalize() + ".")
    demo = _dict(s.get("demonstration"))
    if demo.get("tool"):
        out.lines.append(f"One demonstration, with {demo['tool']}.")
    if "trials" in use:
        n = use["trials"]
        ok = sum(1 for t in run.trials if t.get("phase") == "use"
                 and t.get("outcome") == "success")
        budget = f" of a budget of {run.budget}" if run.budget else ""
        text = f"Tool-use learning: {n} trials{budget} ({ok} succeeded)"
        if use.get("stop"):
            text += f"; stopped because {STOP_TEXT.get(use['stop'], use['stop'])}"
        if use.get("converged") and use.get("trials_to_converge"):
            text += f"; converged after {use['trials_to_converge']} trials"
        if run.paper_trials:
            text += f"; the paper's robot used {run.paper_trials}"
        out.lines.append(text + ".")
        out.figures.append(Figure("use.trials", n, f"{n}" + (f" of {run.budget}"
                                                               if run.budget else ""),
                                  "tool-use trials (of the budget)"
                                  + (f"; paper: {run.paper_trials}" if run.paper_trials
                                     else "")))
    if "trials" in ev:
        done, total = ev.get("successes", 0), ev["trials"]
        out.lines.append(f"Evaluation of the learned model on the task it learned: "
                         f"{done} of {total} trials succeeded.")
        out.figures.append(Figure("eval.successes", done, f"{done} / {total}",
                                  "learned model's evaluation: successes / trials"))
    if create:
        out.lines.append(_creation_line(create))
        solved = create.get("solved_by")
        tool = {"catalogue": create.get("catalogue_success"),
                "created": create.get("success")}.get(solved) if solved else None
        if solved:
            out.figures.append(Figure("create.solved_by", solved,
                                      f"{solved}" + (f" {tool}" if tool else ""),
                                      f"harder task ({create.get('variant', '?')}) "
                                      "solved by"))
        done, total = _successes(create.get("eval"))
        if total:
            out.figures.append(Figure("create.eval", done, f"{done} / {total}",
                                      f"created {create.get('success')}'s evaluation: "
                                      "successes / trials"))
        for tool_entry in create.get("created_tools") or []:
            line, figures = _print_line(tool_entry)
            if line:
                out.lines.append(line)
                out.figures += figures
    wall = _dict(s.get("wall_time_s"))
    if "total" in wall:
        parts = ", ".join(f"{k} {number_text(v)} s" for k, v in wall.items() if k != "total")
        out.lines.append(f"Wall time {number_text(wall['total'])} s"
                         + (f" ({parts})." if parts else "."))
        out.figures.append(Figure("wall_time_s.total", wall["total"],
                                  f"{number_text(wall['total'])} s", "wall time"))
    return out


def _creation_line(create: dict[str, Any]) -> str:
    text = f"Tool creation on the harder task {create.get('variant', '?')}"
    predicted = _dict(create.get("predicted"))
    bits = []
    if predicted and predicted.get("feasible") is False:
        bits.append(f"{predicted.get('tool')} was predicted to fail, so its trial was "
                    "not run")
    tried = [c for c in create.get("catalogue") or [] if isinstance(c, dict)]
    if tried:
        bits.append("catalogued objects tried first: " + ", ".join(
            f"{c.get('tool')} ({c.get('outcome')})" for c in tried))
    elif "catalogue" in create:
        bits.append("no catalogued object tried")
    solved = create.get("solved_by")
    if solved == "created":
        trials = create.get("trials")
        bits.append(f"solved by the created {create.get('success')}"
                    + (f" after {trials} creation trial{'s' if trials != 1 else ''}"
                       if isinstance(trials, int) else ""))
    elif solved == "catalogue":
        bits.append(f"solved by the catalogued {create.get('catalogue_success')}")
    elif solved:
        bits.append(f"solved by {solved}")
    elif create.get("needed") is not False:
        bits.append("not solved" + (f" ({create['exhausted']})" if create.get("exhausted")
                                    else ""))
    done, total = _successes(create.get("eval"))
    if total:
        bits.append(f"the created tool's evaluation: {done} of {total} trials succeeded")
    return text + (": " + "; ".join(bits) if bits else "") + "."


def _print_line(tool: Any) -> tuple[str, list[Figure]]:
    """The print figures of a created tool (its ``summary.json`` entry's ``print``)."""
    if not isinstance(tool, dict):
        return "", []
    printed = _dict(tool.get("print"))
    seconds, grams = printed.get("print_time_s"), printed.get("filament_g")
    if not isinstance(seconds, (int, float)) or not isinstance(grams, (int, float)):
        return "", []
    name = tool.get("name", "?")
    pieces = printed.get("pieces") if isinstance(printed.get("pieces"), list) else []
    metres = printed.get("filament_mm")
    count = len(pieces) or 1  # a print record without its pieces is of one piece
    line = (f"Printing {name}: {count} piece{'s' if count != 1 else ''}, "
            f"{duration_text(seconds)} of printing, {grams:.1f} g of filament"
            + (f" ({metres / 1000:.1f} m)" if isinstance(metres, (int, float)) else "")
            + (f"; mass {tool['mass_kg'] * 1000:.1f} g" if isinstance(tool.get("mass_kg"),
                                                                     (int, float)) else "")
            + ".")
    key = f"create.created_tools[{name}].print"
    return line, [Figure(f"{key}.print_time_s", seconds, duration_text(seconds),
                         f"print time of {name}"),
                  Figure(f"{key}.filament_g", grams, f"{grams:.1f} g",
                         f"filament for {name}")]
