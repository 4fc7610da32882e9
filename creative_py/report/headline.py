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

from creative_py.records.summary import CreateSummary, CreatedToolSummary
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
        Where it is in ``summary.json`` (dotted: ``use.trials``; the field of
        :class:`~creative_py.records.summary.RunSummary` it comes from).
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


def _successes(outcomes: list[str]) -> tuple[int, int]:
    return sum(o == "success" for o in outcomes), len(outcomes)


def headline(run: RunContents) -> Headline:
    """Return the headline of a run folder's contents (empty parts are left out)."""
    out = Headline()
    _add_who(run, out)
    _add_use(run, out)
    _add_eval(run, out)
    _add_create(run, out)
    _add_resumed(run, out)
    _add_wall_time(run, out)
    return out


def _add_who(run: RunContents, out: Headline) -> None:
    """Add the run's case, strategy, seed, backend and robot, and its demonstration."""
    s = run.summary
    strategy = s.strategy
    first = [f"case {s.case}" if s.case is not None else "",
             f"strategy {strategy}" if strategy else "",
             f"seed {s.seed}" if s.seed is not None else "",
             f"backend {s.backend}" if s.backend else "",
             f"robot {s.robot}" if s.robot else ""]
    if any(first):
        out.lines.append(", ".join(x for x in first if x).capitalize() + ".")
    if s.demonstration is not None and s.demonstration.tool:
        out.lines.append(f"One demonstration, with {s.demonstration.tool}.")


def _add_use(run: RunContents, out: Headline) -> None:
    """Add tool-use learning: its trials, stop, the paper's count and the prior taken."""
    use = run.summary.use
    if use is None or use.trials is None:
        return
    n = use.trials
    ok = sum(1 for t in run.trials if t.get("phase") == "use"
             and t.get("outcome") == "success")
    budget = f" of a budget of {run.budget}" if run.budget else ""
    text = f"Tool-use learning: {n} trials{budget} ({ok} succeeded)"
    if use.stop:
        text += f"; stopped because {STOP_TEXT.get(use.stop, use.stop)}"
    if use.converged and use.trials_to_converge:
        text += f"; converged after {use.trials_to_converge} trials"
    if run.paper_trials:
        text += f"; the paper's robot used {run.paper_trials}"
    out.lines.append(text + ".")
    if use.prior is not None:
        pr = use.prior
        out.lines.append(f"Started from case {pr.case}'s learned model: "
                         f"{len(pr.taken)} literal(s) predicted necessary; "
                         f"{len(pr.settled)} settled by a success (untested: the "
                         f"stop is certified relative to them), {len(pr.confirmed)} "
                         f"made necessary by the physics, {len(pr.dropped)} "
                         "contradicted by the physics (dropped, learned afresh).")
    out.figures.append(Figure("use.trials", n, f"{n}" + (f" of {run.budget}"
                                                           if run.budget else ""),
                              "tool-use trials (of the budget)"
                              + (f"; paper: {run.paper_trials}" if run.paper_trials
                                 else "")))


def _add_eval(run: RunContents, out: Headline) -> None:
    """Add the learned model's evaluation on the task it learned."""
    ev = run.summary.eval
    if ev is None or ev.trials is None:
        return
    done, total = ev.successes or 0, ev.trials
    out.lines.append(f"Evaluation of the learned model on the task it learned: "
                     f"{done} of {total} trials succeeded.")
    out.figures.append(Figure("eval.successes", done, f"{done} / {total}",
                              "learned model's evaluation: successes / trials"))


def _add_create(run: RunContents, out: Headline) -> None:
    """Add tool creation: what solved the harder task, the created tool's evaluation,
    and each created tool's printing."""
    create = run.summary.create
    if create is None or not create.to_dict():
        return
    out.lines.append(_creation_line(create))
    solved = create.solved_by
    tool = create.solver if solved else None
    if solved:
        out.figures.append(Figure("create.solved_by", solved,
                                  f"{solved}" + (f" {tool}" if tool else ""),
                                  f"harder task ({create.variant or '?'}) "
                                  "solved by"))
    done, total = _successes(create.eval)
    if total:
        out.figures.append(Figure("create.eval", done, f"{done} / {total}",
                                  f"created {create.success}'s evaluation: "
                                  "successes / trials"))
    for tool_entry in create.created_tools:
        line, figures = _print_line(tool_entry)
        if line:
            out.lines.append(line)
            out.figures += figures


def _add_resumed(run: RunContents, out: Headline) -> None:
    """Add how a resumed run went on: the trials replayed, the times, a trial lost with
    its backend."""
    resumed = run.summary.resumed
    if resumed is None:
        return
    text = "Resumed after an interruption"
    if resumed.replayed is not None:
        text += (f": {resumed.replayed} trial{'s' if resumed.replayed != 1 else ''} "
                 "of the interrupted run replayed from its records")
    if resumed.earlier_wall_time_s is not None:
        text += (f"; the interrupted run took {number_text(resumed.earlier_wall_time_s)}"
                 " s to its last recorded trial")
    if resumed.total_wall_time_s is not None:
        text += f"; {number_text(resumed.total_wall_time_s)} s in all"
    out.lines.append(text + ".")
    lost = resumed.lost_trial
    if lost:
        skill = f", in skill {lost['skill']}" if lost.get("skill") else ""
        out.lines.append(f"Trial #{lost.get('trial')} ({lost.get('tool')} at location "
                         f"{lost.get('location')}) did not go as planned: the backend "
                         f"was lost{skill} ({lost.get('reason')}); nothing was learned "
                         "from it and the resume ran it again.")


def _add_wall_time(run: RunContents, out: Headline) -> None:
    """Add the wall time, in all and by phase."""
    s = run.summary
    wall = s.wall_time_s
    if wall is None or wall.total is None:
        return
    parts = ", ".join(f"{k} {number_text(v)} s" for k, v in wall.phases())
    out.lines.append(f"Wall time {number_text(wall.total)} s"
                     + (" of the resumed session" if s.resumed is not None else "")
                     + (f" ({parts})." if parts else "."))
    out.figures.append(Figure("wall_time_s.total", wall.total,
                              f"{number_text(wall.total)} s", "wall time"))


def _creation_line(create: CreateSummary) -> str:
    text = f"Tool creation on the harder task {create.variant or '?'}"
    predicted = create.predicted
    bits = []
    if predicted is not None and predicted.feasible is False:
        bits.append(f"{predicted.tool} was predicted to fail, so its trial was "
                    "not run")
    if create.catalogue:
        bits.append("catalogued objects tried first: " + ", ".join(
            f"{c.tool} ({c.outcome})" for c in create.catalogue))
    elif create.catalogue_recorded:
        bits.append("no catalogued object tried")
    solved = create.solved_by
    if solved == "created":
        trials = create.trials
        bits.append(f"solved by the created {create.success}"
                    + (f" after {trials} creation trial{'s' if trials != 1 else ''}"
                       if isinstance(trials, int) else ""))
    elif solved == "catalogue":
        bits.append(f"solved by the catalogued {create.catalogue_success}")
        if create.needed is False and create.created_tools:
            names = ", ".join(str(c.name) for c in create.created_tools)
            bits.append(f"{names} made all the same, as a demonstration "
                        "(--demonstrate-creation)")
    elif solved:
        bits.append(f"solved by {solved}")
    elif create.needed is not False:
        why = create.exhausted_words or create.exhausted  # an older summary: the term
        bits.append("not solved" + (f": no literal left to generalise ({why})"
                                    if why else ""))
    done, total = _successes(create.eval)
    if total:
        bits.append(f"the created tool's evaluation: {done} of {total} trials succeeded")
    return text + (": " + "; ".join(bits) if bits else "") + "."


def _print_line(tool: CreatedToolSummary) -> tuple[str, list[Figure]]:
    """The print figures of a created tool (its ``summary.json`` entry's ``print``)."""
    printed = tool.print
    if printed is None:
        return "", []
    seconds, grams = printed.print_time_s, printed.filament_g
    if seconds is None or grams is None:
        return "", []
    name = tool.name or "?"
    metres = printed.filament_mm
    count = len(printed.pieces) or 1  # a print record without its pieces is of one piece
    line = (f"Printing {name}: {count} piece{'s' if count != 1 else ''}, "
            f"{duration_text(seconds)} of printing, {grams:.1f} g of filament"
            + (f" ({metres / 1000:.1f} m)" if metres is not None else "")
            + (f"; mass {tool.mass_kg * 1000:.1f} g" if tool.mass_kg is not None else "")
            + ".")
    key = f"create.created_tools[{name}].print"
    return line, [Figure(f"{key}.print_time_s", seconds, duration_text(seconds),
                         f"print time of {name}"),
                  Figure(f"{key}.filament_g", grams, f"{grams:.1f} g",
                         f"filament for {name}")]
