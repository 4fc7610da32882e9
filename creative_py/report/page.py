"""``report.html``: a run folder as one page a person opens in a browser.

The page shows the run's summary, the trial plot, every trial (phase, number, tool,
variant, location, pose, tested and violated literals, outcome and reason), the video
clips as HTML5 ``<video controls>``, the created tools with their renders, dimensions and
print figures, the learned hypotheses and model, and the plan (with the PDDL planner's
answer when the summary has one). It is plain HTML with its CSS inline and no script;
every text of the run is escaped (:func:`html.escape`) and every link is relative to the
run folder, so the folder can be moved or zipped with its page. Writing the page writes
``report.html`` and nothing else.
"""

from __future__ import annotations

from html import escape
from pathlib import Path
from typing import Any, Callable
from urllib.parse import quote

from creative_py.records.folder import write_atomic
from creative_py.records.summary import PddlCheck
from creative_py.records.trial import lengths_in_mm
from creative_py.report.contents import (
    Clip, RunContents, ToolEntry, clause_parts, literals_text, number_text,
    plan_steps, read_run, readable_term, relative_inside, state_text, why_text,
)
from creative_py.report.headline import duration_text, headline

Linker = Callable[[str], "str | None"]
"""Returns the relative path of an existing file a JSON value names, or None."""

REPORT_NAME = "report.html"
"""The page's file name in the run folder."""

_CSS = """
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
       color: #1d2330; background: #f6f7f9; margin: 0; }
main { max-width: 1400px; margin: 0 auto; padding: 1.2rem 1rem 3rem; }
h1 { font-size: 1.6rem; margin: 0.4rem 0 0.2rem; }
h2 { font-size: 1.25rem; margin: 2rem 0 0.6rem; padding-bottom: 0.25rem;
     border-bottom: 2px solid #d8dde6; }
h3 { font-size: 1.05rem; margin: 1.1rem 0 0.4rem; }
nav { font-size: 0.9rem; margin: 0.4rem 0 1rem; }
nav a { margin-right: 0.9rem; }
a { color: #1f5fbf; }
.sub { color: #5b6474; margin: 0; }
.cards { display: flex; flex-wrap: wrap; gap: 0.7rem; margin: 1rem 0; }
.card { background: #fff; border: 1px solid #dfe3ea; border-radius: 6px;
        padding: 0.55rem 0.9rem; min-width: 9rem; }
.card b { display: block; font-size: 1.3rem; }
.card span { color: #5b6474; font-size: 0.85rem; }
.panel { background: #fff; border: 1px solid #dfe3ea; border-radius: 6px;
         padding: 0.8rem 1rem; margin: 0.6rem 0; overflow-x: auto; }
table { border-collapse: collapse; background: #fff; font-size: 0.88rem;
        max-width: 100%; }
td { overflow-wrap: break-word; }
table.trials td.num, table.trials td.col-phase, table.trials td.col-tool,
table.trials td.col-variant, table.trials td.col-outcome { white-space: nowrap; }
.headline { background: #fff; border: 1px solid #dfe3ea; border-radius: 6px;
            padding: 0.6rem 1rem; margin: 0.8rem 0; }
.headline p { margin: 0.25rem 0; }
tr.predicted td { background: #f3f0ff; font-style: italic; }
th, td { border: 1px solid #dfe3ea; padding: 0.3rem 0.5rem; text-align: left;
         vertical-align: top; }
th { background: #eef1f5; position: sticky; top: 0; }
table.trials { width: 100%; }
table.trials { font-size: 0.84rem; }
table.trials code { font-size: 0.78rem; }
table.trials td.col-reason { min-width: 10rem; }
table.trials td.col-pose { min-width: 7rem; }
table.trials tr:nth-child(even) td { background: #fafbfc; }
.nw { white-space: nowrap; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
code, pre { font: 0.84rem/1.4 ui-monospace, "DejaVu Sans Mono", monospace; }
pre { background: #fff; border: 1px solid #dfe3ea; border-radius: 6px; padding: 0.7rem;
      overflow-x: auto; white-space: pre-wrap; word-break: break-word; }
.outcome { display: inline-block; padding: 0 0.45rem; border-radius: 9px;
           font-size: 0.8rem; font-weight: 600; color: #fff; background: #6b7280; }
.outcome.success { background: #1f8a4c; }
.outcome.failure { background: #c0392b; }
.outcome.blocked { background: #d68910; }
.outcome.unreachable { background: #7f8c8d; }
.outcome.invalid { background: #222; }
.plot img { max-width: 100%; height: auto; background: #fff; }
.clips { display: grid; grid-template-columns: repeat(auto-fill, minmax(360px, 1fr));
         gap: 0.9rem; }
.clips figure, .tool figure { margin: 0; }
.clips video { width: 100%; background: #000; border-radius: 4px; }
figcaption { font-size: 0.85rem; color: #3c4454; margin-top: 0.3rem; }
.tool { background: #fff; border: 1px solid #dfe3ea; border-radius: 6px;
        padding: 0.3rem 1.1rem 0.9rem; margin: 0.8rem 0; overflow-x: auto; }
.tool img { max-width: 100%; height: auto; border: 1px solid #eef1f5; }
.tool h3 { font-size: 1.15rem; }
h4 { font-size: 0.95rem; margin: 0.9rem 0 0.35rem; }
.facts { display: grid; grid-template-columns: repeat(auto-fit, minmax(280px, 1fr));
         gap: 0 1.2rem; }
.facts table { width: 100%; }
ol.literals, ol.plan { margin: 0.2rem 0 0.4rem; padding-left: 1.6rem; }
.none { color: #7a8291; font-style: italic; }
.warn { background: #fff6e0; border: 1px solid #f0d28a; border-radius: 6px;
        padding: 0.5rem 0.9rem; }
footer { margin-top: 2.5rem; color: #7a8291; font-size: 0.82rem; }
"""


def write_html_report(run_dir: Path | str) -> Path:
    """Write ``report.html`` into a run folder and return its path.

    Only ``report.html`` is written (through a temporary file in the same folder, so a
    reader never sees half a page); the run's other files are only read.

    Parameters
    ----------
    run_dir : Path or str
        The run folder.

    Raises
    ------
    FileNotFoundError
        When the folder has no ``trials.jsonl``.
    """
    contents = read_run(run_dir)
    return write_atomic(Path(run_dir) / REPORT_NAME, render_html(contents))


def render_html(run: RunContents) -> str:
    """Return the page of a run folder's contents as HTML text."""
    s = run.summary
    title = f"CREATIVE-py run {run.path.name}"
    sections = [
        ("trials", "Trials", _trials_section(run)),
        ("clips", "Video clips", _clips_section(run)),
        ("tools", "Created tools", _tools_section(run)),
        ("hypotheses", "Learned hypotheses", _hypotheses_section(run)),
        ("plan", "Plan", _plan_section(run)),
    ]
    nav = "".join(f'<a href="#{key}">{escape(label)}</a>' for key, label, _ in sections)
    body = "".join(f'<section id="{key}"><h2>{escape(label)}</h2>{html}</section>'
                   for key, label, html in sections)
    subtitle = " · ".join(escape(x) for x in (
        f"case {s.case}" if s.case else "", f"seed {s.seed}" if s.seed is not None else "",
        f"phase {s.phase}" if s.phase is not None else "",
        f"backend {s.backend}" if s.backend else "",
        f"robot {s.robot}" if s.robot else "") if x)
    warnings = ""
    state = state_text(run)
    if state:
        warnings = f'<div class="warn">{escape(state)}</div>'
    if run.warnings:
        warnings += ('<div class="warn"><b>Not everything could be read:</b><ul>'
                    + "".join(f"<li>{escape(w)}</li>" for w in run.warnings) + "</ul></div>")
    return (
        "<!DOCTYPE html>\n"
        f'<html lang="en"><head><meta charset="utf-8">'
        f'<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{escape(title)}</title><style>{_CSS}</style></head><body><main>"
        f"<h1>{escape(title)}</h1><p class=\"sub\">{subtitle}</p>"
        f"<nav>{nav}</nav>{warnings}{_headline_html(run)}{_cards(run)}{body}"
        "<footer>Written from the files of this run folder, at the end of the run or by "
        "<code>creative report RUN --html</code>; every link is relative to the folder."
        "</footer>"
        "</main></body></html>\n")


# --- sections -------------------------------------------------------------------------

def _headline_html(run: RunContents) -> str:
    """The run in a few sentences (:func:`creative_py.report.headline.headline`)."""
    return ('<div class="headline">' + "".join(
        f"<p>{escape(line)}</p>" for line in headline(run).lines) + "</div>")


def _cards(run: RunContents) -> str:
    """The headline's figures as cards, each marked ``data-figure`` with its
    ``summary.json`` key (a test compares them)."""
    return '<div class="cards">' + "".join(
        f'<div class="card" data-figure="{escape(f.key)}" '
        f'data-value="{escape(str(f.raw))}"><b>{escape(f.value)}</b>'
        f'<span>{escape(f.label)}</span></div>' for f in headline(run).figures) + "</div>"


def _trials_section(run: RunContents) -> str:
    if run.plot:
        plot = (f'<figure class="panel plot"><img src="{_url(run.plot)}" '
                f'alt="Outcome of every trial per tool (trials.png)">'
                "<figcaption>Outcome of every trial per tool: TUL tool-use learning, TC tool "
                "creation, EV evaluation (trials.png).</figcaption></figure>")
    else:
        plot = '<p class="none">No trials.png in this run folder.</p>'
    if not run.trials:
        return plot + '<p class="none">No readable trial.</p>'
    head = "".join(f"<th>{escape(h)}</th>" for h, _ in run.columns)
    rows = []
    predicted = _predicted_row(run)
    for t in run.trials:
        if predicted and t.get("phase") == "create":
            rows.append(predicted)
            predicted = ""
        cells = []
        for header, cell in run.columns:
            text = readable_term(cell(t))
            if header == "outcome":
                cells.append(f'<td class="col-outcome">{_outcome(text)}</td>')
            elif header in ("#", "loc"):
                cells.append(f'<td class="num">{escape(text)}</td>')
            elif header == "pose":   # breaks between its numbers, never inside one
                cells.append('<td class="col-pose"><code>' + ", ".join(
                    f'<span class="nw">{escape(p)}</span>' for p in text.split(", "))
                    + "</code></td>")
            elif header in ("tested", "violated"):
                cells.append(f'<td class="col-{header}"><code>{_breakable(text)}</code></td>')
            elif header == "reason" and " -- " in text:
                # The reason in the row; what the physics measured, folded under it (a
                # guard's stop and its contacts run to many lines).
                reason, measured = text.split(" -- ", 1)
                cells.append(f'<td class="col-reason">{escape(reason)}<details><summary>'
                             f'measured</summary>{escape(measured)}</details></td>')
            else:
                cells.append(f'<td class="col-{escape(header)}">{escape(text)}</td>')
        rows.append(f'<tr class="trial {escape(t.outcome)}">{"".join(cells)}</tr>')
    rows.append(predicted)
    return (plot + f'<div class="panel"><table class="trials"><thead><tr>{head}</tr></thead>'
            f'<tbody>{"".join(rows)}</tbody></table></div>')


def _predicted_row(run: RunContents) -> str:
    """The creation trial that was predicted to fail and not run, as a row of the trial
    table (``summary.json``'s ``create.predicted``), or ``""``."""
    create = run.summary.create
    predicted = create.predicted if create is not None else None
    if predicted is None or predicted.feasible is not False:
        return ""
    values = {"#": "-", "phase": "create", "tool": _or(predicted.tool, "?"),
              "variant": _or(predicted.variant, ""), "loc": _or(predicted.location, ""),
              "pose": "-", "tested": "-",
              "violated": literals_text(predicted.conflict),
              "outcome": "predicted failure, not run",
              "reason": lengths_in_mm(_or(predicted.why, ""))}
    cells = "".join(f'<td class="col-{escape(h)}">{escape(readable_term(str(values.get(h, ""))))}'
                    "</td>" for h, _ in run.columns)
    return f'<tr class="predicted">{cells}</tr>'


def _clips_section(run: RunContents) -> str:
    if not run.clips:
        return '<p class="none">This run saved no video clip.</p>'
    figures = []
    for clip in run.clips:
        caption = _clip_caption(clip)
        if clip.exists:
            poster = _poster(run.path, clip.file)
            media = (f'<video controls preload="metadata" src="{_url(clip.file)}"'
                     + (f' poster="{_url(poster)}"' if poster else "") + ">"
                     f'<a href="{_url(clip.file)}">{escape(clip.file)}</a></video>')
        else:
            media = f'<p class="none">missing: {escape(clip.file)}</p>'
        figures.append(f"<figure>{media}<figcaption>{caption}</figcaption></figure>")
    return f'<div class="clips">{"".join(figures)}</div>'


def _poster(root: Path, clip: str) -> str | None:
    """Return the poster of a clip (its last frame, written beside it:
    :data:`creative_py.video.POSTER_SUFFIX`) when the folder has it, else None (a clip
    written before posters were: the browser shows its first frame)."""
    name = clip.removesuffix(".mp4") + ".poster.jpg"
    rel = relative_inside(root, name)
    return rel if rel is not None and (root / rel).is_file() else None


def _clip_caption(clip: Clip) -> str:
    info = clip.info
    if info is None or not {k: v for k, v in info.to_dict().items() if k != "file"}:
        return f"<code>{escape(clip.file)}</code>"
    head = " ".join(escape(str(x)) for x in (info.phase, info.trial) if x is not None)
    parts = [f"<b>{head}</b>" if head else ""]
    if info.tool:
        parts.append(escape(info.tool))
    if info.tested:
        parts.append(f"tested <code>{escape(literals_text(info.tested))}</code>")
    if info.outcome:
        parts.append(_outcome(info.outcome))
    text = " · ".join(p for p in parts if p)
    if info.reason:
        text += f"<br>{escape(lengths_in_mm(info.reason))}"
    if info.why:
        text += f"<br><i>kept as {escape(why_text(info.why))}</i>"
    return text + f' <a href="{_url(clip.file)}">{escape(Path(clip.file).name)}</a>'


def _tools_section(run: RunContents) -> str:
    create = run.summary.create
    intro = ""
    if create is not None:
        bits = [f"harder task: <b>{escape(_or(create.variant, '?'))}</b>"]
        if create.needed is not None:
            bits.append("creation needed" if create.needed else
                        "creation not needed (a catalogued tool succeeded)")
            if not create.needed and create.created_tools:
                names = ", ".join(escape(str(c.name)) for c in create.created_tools)
                bits.append(f"{names} made all the same, as a demonstration "
                            "(<code>--demonstrate-creation</code>)")
        if create.solved_by:
            by = {"learned": "the learned model's own tool",
                  "catalogue": f"the catalogued {create.catalogue_success}",
                  "created": f"the created {create.success}"}
            solver = by.get(create.solved_by, create.solved_by)
            bits.append(f"solved by {escape(solver)}")
        if create.catalogue:
            bits.append("catalogued objects considered first: " + ", ".join(
                f"{escape(str(c.tool))} ({escape(str(c.outcome))})"
                for c in create.catalogue))
        if create.exhausted_words:
            bits.append(f"no literal left to generalise: {escape(create.exhausted_words)}")
        elif create.exhausted:  # an older summary: the term only
            bits.append("no literal left to generalise (what was tried of each: "
                        f"<code>{escape(create.exhausted)}</code>)")
        intro = f"<p>{'; '.join(bits)}.</p>"
    if not run.tools:
        return intro + '<p class="none">This run created no tool.</p>'
    return intro + "".join(_tool_card(run.path, t) for t in run.tools)


def _tool_card(root: Path, tool: ToolEntry) -> str:
    c, m = tool.created, tool.manifest or {}

    def link(name: str) -> str | None:  # a file of the tool's folder that exists
        rel = relative_inside(root, f"{tool.folder}/{name}")
        return rel if rel is not None and (root / rel).is_file() else None

    head = [f"<h3>{escape(tool.name)}</h3>"]
    if c is not None:
        head.append("<p>" + " &rarr; ".join(
            f"<code>{escape(readable_term(_or(x, '')))}</code>"
            for x in (c.replaced, c.general, c.instance)) + "</p>")
        outcomes = [f"creation trial {_outcome(_or(c.trial_outcome, '?'))}"
                    + (f" ({escape(c.reason)})" if c.reason else "")]
        if c.eval_outcomes:
            outcomes.append("evaluation " + " ".join(_outcome(o) for o in c.eval_outcomes))
        head.append(f"<p>{'; '.join(outcomes)}</p>")
    if tool.picture:
        picture = (f'<figure><img src="{_url(tool.picture)}" alt="Render of {escape(tool.name)}">'
                   f"<figcaption>{escape(tool.picture)}</figcaption></figure>")
    else:
        picture = f'<p class="none">No render ({escape(tool.folder)}/{escape(tool.name)}.png).</p>'
    facts = []
    sizes = _tool_sizes(c.dims if c is not None else None, m.get("spec"))
    if sizes:
        facts.append("<h4>Dimensions</h4>" + _key_value_table(sizes))
    physical = _tool_physical(m)
    if physical:
        facts.append("<h4>Mass and printability</h4>" + _key_value_table(physical))
    tail = ["<h4>Print time and filament</h4>" + _print_html(m.get("print"), link)]
    if tool.files:
        tail.append("<h4>Files</h4><p>" + " · ".join(
            f'<a href="{_url(rel)}">{escape(kind)}</a>' for kind, rel in tool.files) + "</p>")
    return (f'<article class="tool" id="tool-{escape(tool.name)}">{"".join(head)}{picture}'
            f'<div class="facts">{"".join(f"<div>{x}</div>" for x in facts)}</div>'
            f'{"".join(tail)}</article>')


def _print_html(printed: Any, link: Linker) -> str:
    """The tool JSON's ``print`` key: its totals in a sentence, one row per printed piece
    (size, place on the bed as an offset in mm and a turn, volume, print time,
    filament, G-code) and one per joint."""
    if printed is None:
        return '<p class="none">Not sliced (the tool\'s JSON has no print figures).</p>'
    if isinstance(printed, list):
        printed = {"pieces": printed}
    if not isinstance(printed, dict):
        return f"<p>{escape(str(printed))}</p>"
    out = []
    total = []
    if isinstance(printed.get("print_time_s"), (int, float)):
        total.append(f"{duration_text(printed['print_time_s'])} of printing")
    if isinstance(printed.get("filament_g"), (int, float)):
        metres = printed.get("filament_mm")
        total.append(f"{printed['filament_g']:.1f} g of filament"
                     + (f" ({metres / 1000:.1f} m)" if isinstance(metres, (int, float))
                        else ""))
    if isinstance(printed.get("build_volume_mm"), list):
        total.append("build volume " + " x ".join(
            f"{v:g}" for v in printed["build_volume_mm"]) + " mm")
    if printed.get("profile"):
        total.append(f"profile {printed['profile']}")
    if total:
        out.append(f"<p><b>{escape('; '.join(total))}</b></p>")
    if printed.get("how_they_join"):
        out.append(f"<p>{escape(str(printed['how_they_join']))}</p>")
    pieces = [p for p in printed.get("pieces") or [] if isinstance(p, dict)]
    if pieces:
        out.append(_pieces_table(pieces, link))
    joints = [j for j in printed.get("joints") or [] if isinstance(j, dict)]
    if joints:
        rows = "".join(
            f"<tr><td>{escape(str(j.get('pin', '')))}</td>"
            f"<td>{escape(' + '.join(str(x) for x in j.get('joins') or []))}</td>"
            f"<td>{escape(_mm(j.get('cut_mm')))} along {escape(str(j.get('axis', '?')))}</td>"
            f"<td>{escape(_mm(j.get('pin_section_mm')))} square, "
            f"{escape(_mm(j.get('pin_length_mm')))} long</td>"
            f"<td>{escape(_mm(j.get('hole_section_mm')))} square, "
            f"{escape(_mm(j.get('hole_depth_mm')))} deep</td></tr>" for j in joints)
        out.append("<table><thead><tr><th>pin</th><th>joins</th><th>cut at</th>"
                   "<th>pin</th><th>holes</th></tr></thead>"
                   f"<tbody>{rows}</tbody></table>")
    shown = {"pieces", "joints", "print_time_s", "filament_g", "filament_mm",
             "build_volume_mm", "profile", "how_they_join"}
    rest = {_print_label(k): _print_value(k, v) for k, v in printed.items()
            if k not in shown}
    if rest:
        out.append("<details><summary>Other print figures</summary>"
                   + _key_value_table(rest, link) + "</details>")
    return "".join(out) or '<p class="none">No print figures.</p>'


PRINT_LABELS = {
    "printable": "printable",
    "nozzle_mm": "nozzle diameter",
    "min_feature_mm": "smallest feature the printer makes",
    "joint": "joint between the parts",
    "clearance_mm": "clearance of a pin in its hole",
    "design_volume_mm3": "volume of the tool as designed",
    "union_volume_mm3": "volume of the printed pieces put together",
    "union_volume_error_pct": "pieces put together against the design (volume)",
    "union_mismatch_pct": "volume where the pieces and the design differ",
    "sliced": "sliced into G-code",
    "wall_time_s": "time to split and slice it",
}
"""The words for each key of a tool JSON's ``print`` entry that the print table does
not show in its own columns (:func:`_print_label` makes words of any other key)."""

_PRINT_WORDS = {"square_dowel_pin": "square dowel pin"}


def _print_label(key: str) -> str:
    """A print figure's key in words: :data:`PRINT_LABELS`, else the key without its
    unit suffix, underscores as spaces (the unit goes with the value)."""
    if key in PRINT_LABELS:
        return PRINT_LABELS[key]
    for suffix, _unit in _UNITS:
        if key.endswith(suffix):
            key = key[: -len(suffix)]
            break
    return key.replace("_", " ")


def _print_value(key: str, value: Any) -> Any:
    """A print figure with its unit: volumes in cm³ (as the piece table has them), a
    percentage to two decimals, a joint's kind in words, else :func:`_with_unit`."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if key.endswith("_mm3"):
            return f"{value / 1000:.2f} cm³"
        if key.endswith("_pct"):
            return f"{value:+.2f} %" if key.endswith("error_pct") else f"{value:.2f} %"
    if isinstance(value, str):
        return _PRINT_WORDS.get(value, value)
    return _with_unit(key, value)


def _pieces_table(pieces: list[dict[str, Any]], link: Linker) -> str:
    rows = []
    for p in pieces:
        box = p.get("bounding_box_mm")
        size = (" x ".join(f"{v:.1f}" for v in box) + " mm"
                if isinstance(box, list) else "-")
        place = _placement_text(p)
        volume = p.get("volume_mm3")
        grams, metres = p.get("filament_g"), p.get("filament_mm")
        filament = (f"{grams:.1f} g" if isinstance(grams, (int, float)) else "-") + (
            f" ({metres / 1000:.2f} m)" if isinstance(metres, (int, float)) else "")
        seconds = p.get("print_time_s")
        files = " · ".join(
            f'<a href="{_url(target)}">{escape(kind)}</a>' for kind, target in
            ((k, link(p[k]) if isinstance(p.get(k), str) else None) for k in ("stl", "gcode"))
            if target)
        rows.append(
            f"<tr><td>{escape(str(p.get('name', '')))}</td>"
            f"<td>{escape(str(p.get('role', '')))}</td><td>{escape(size)}</td>"
            f"<td>{escape(place)}</td>"
            f"<td class=\"num\">{escape(f'{volume / 1000:.1f} cm³' if isinstance(volume, (int, float)) else '-')}</td>"
            f"<td class=\"num\">{escape(duration_text(seconds) if isinstance(seconds, (int, float)) else '-')}</td>"
            f"<td class=\"num\">{escape(filament)}</td><td>{files or '-'}</td></tr>")
    return ("<table><thead><tr><th>piece</th><th>role</th><th>size</th><th>on the bed</th>"
            "<th>volume</th><th>print time</th><th>filament</th><th>files</th></tr></thead>"
            f"<tbody>{''.join(rows)}</tbody></table>")


def _placement_text(piece: dict[str, Any]) -> str:
    """Where a piece lies on the bed: the tool-frame axis up, the turn about the bed's
    normal and the offset of the piece's origin on the bed (the translation of its 4 x 4
    ``placement``), in mm."""
    bits = []
    if piece.get("up_axis"):
        bits.append(f"{piece['up_axis']} axis up")
    if isinstance(piece.get("yaw_deg"), (int, float)):
        bits.append(f"turned {piece['yaw_deg']:g} deg")
    matrix = piece.get("placement")
    if (isinstance(matrix, list) and len(matrix) >= 3
            and all(isinstance(r, list) and len(r) >= 4 for r in matrix[:3])):
        bits.append("origin at (" + ", ".join(f"{float(r[3]):.1f}" for r in matrix[:3])
                    + ") mm")
    return ", ".join(bits) or "-"


def _mm(value: Any) -> str:
    return f"{value:.1f} mm" if isinstance(value, (int, float)) else "-"


_UNITS = (("_mm3", "mm³"), ("_m3", "m³"), ("_mm", "mm"), ("_kg", "kg"), ("_deg", "deg"),
          ("_pct", "%"), ("_mpa", "MPa"), ("_m", "m"), ("_g", "g"), ("_s", "s"))


_SPEC_HIDDEN = ("name", "mass", "kind")
"""Keys of a tool's JSON spec the Dimensions table leaves out: the card's title says the
name, the headline the kind; ``mass`` is None for a printed tool (its mass is below)."""


def _tool_sizes(dims: Any, spec: Any) -> dict[str, Any]:
    """One table of a created tool's sizes: its dimensions (the created tool's ``dims``,
    then what its JSON spec adds, such as the grip offset), lengths (the JSON's floats,
    in metres) in millimetres and angles in degrees as the print tables write them,
    counts as they are; nothing twice."""
    out: dict[str, str] = {}
    for source in (dims, spec):
        if not isinstance(source, dict):
            continue
        for key, value in source.items():
            name = str(key).removesuffix("_deg").replace("_", " ")
            if key in _SPEC_HIDDEN or name in out or value is None:
                continue
            if isinstance(value, bool) or not isinstance(value, (int, float)):
                out[name] = value
            elif str(key).endswith("_deg"):
                out[name] = f"{value:g} deg"
            elif isinstance(value, float):  # a length of the run's JSON, in metres
                out[name] = f"{value * 1000:.1f} mm"
            else:  # a count
                out[name] = str(value)
    return out


def _tool_physical(manifest: dict[str, Any]) -> dict[str, str]:
    """A created tool's mass, volume and printability in words and print units (g,
    cm³, mm), from its JSON manifest; the keys it leaves empty are not shown."""
    out: dict[str, str] = {}
    mass = manifest.get("mass_kg")
    if isinstance(mass, (int, float)) and not isinstance(mass, bool):
        out["mass"] = f"{mass * 1000:.1f} g (PLA)"
    for key, label in (("mesh_volume_m3", "volume (mesh)"),
                       ("spec_volume_m3", "volume (specification)")):
        v = manifest.get(key)
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            out[label] = f"{v * 1e6:.2f} cm³"
    printability = manifest.get("printability")
    if isinstance(printability, dict):
        extent = printability.get("extent")
        if isinstance(extent, list):
            out["size"] = " x ".join(f"{float(x) * 1000:.1f}" for x in extent
                                     if isinstance(x, (int, float))) + " mm"
        for key, value in printability.items():
            if key == "extent" or value in (None, "", [], {}):
                continue
            label = str(key).replace("_", " ")
            if isinstance(value, bool):
                out[label] = "yes" if value else "no"
            elif str(key).endswith("_deg") and isinstance(value, (int, float)):
                out[label.removesuffix(" deg")] = f"{value:g} deg"
            else:
                out[label] = str(value)
    return out


def _with_unit(key: str, value: Any, default: str = "") -> Any:
    """A number of the run's JSON with the unit its key names (``mass_kg`` → kg), or
    ``default``; anything else as it is."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        if isinstance(value, list) and key.endswith("_mm") and all(
                isinstance(v, (int, float)) for v in value):
            return " x ".join(f"{v:g}" for v in value) + " mm"
        return value
    for suffix, unit in _UNITS:
        if key.endswith(suffix):
            if unit == "s" and value >= 60:
                return f"{number_text(value)} s ({duration_text(value)})"
            return f"{number_text(value)} {unit}"
    return f"{number_text(value)} {default}" if default else value


def _hypotheses_section(run: RunContents) -> str:
    out = []
    hyp = run.summary.hypotheses
    names = {"hs": "h<sub>s</sub>, the most specific hypothesis",
             "hg": "h<sub>g</sub>, the most general hypothesis"}
    if hyp is not None:
        for key, clause in (("hs", hyp.hs), ("hg", hyp.hg)):
            if clause is not None:
                out.append(f"<h3>{names[key]}</h3>{_clause_html(clause)}")
    prior = run.summary.use.prior if run.summary.use is not None else None
    if prior is not None:
        out.append(f"<h3>Predicted necessary by the prior (case "
                   f"{escape(prior.case or '?')}), open until the physics settles "
                   "them</h3><pre>" + escape("\n".join(prior.taken) or "none") + "</pre>")
        for title, items in (
                ("Settled by a success consistent with the prior (untested: the stop "
                 "is certified relative to them)", prior.settled),
                ("Made necessary by the physics, as the prior predicted",
                 prior.confirmed),
                ("Prior literals the physics contradicted (dropped, learned afresh)",
                 prior.dropped)):
            if items:
                out.append(f"<h3>{title}</h3><pre>" + escape("\n".join(
                    f"{d.literal} (trial {d.trial})" for d in items)) + "</pre>")
    create = run.summary.create
    models = create.model if create is not None else None
    if models:
        out.append("<h3>Model of the created tool</h3><pre>"
                   + escape("\n".join(readable_term(str(x)) for x in models)) + "</pre>")
    if run.model_text is not None:
        out.append('<details><summary><a href="model.pl">model.pl</a> (the learned models '
                   f'and hypotheses, loadable in <code>creative repl</code>)</summary>'
                   f"<pre>{escape(run.model_text)}</pre></details>")
    return "".join(out) or '<p class="none">No hypotheses recorded.</p>'


def _clause_html(clause: str) -> str:
    head, body = clause_parts(readable_term(clause))
    if not body:
        return f"<pre>{escape(clause)}</pre>"
    items = "".join(f"<li><code>{escape(b)}</code></li>" for b in body)
    return (f'<div class="panel"><code>{escape(head)} :-</code>'
            f'<ol class="literals">{items}</ol></div>')


def _plan_section(run: RunContents) -> str:
    out = []
    plan = run.summary.plan
    if plan is not None:
        steps = plan_steps(plan)
        if steps is None:
            out.append(f"<p>Prolog's planner: <code>{escape(plan)}</code></p>")
        else:
            out.append("<p>Prolog's planner, with the learned model:</p><ol class=\"plan\">"
                       + "".join(f"<li><code>{escape(x)}</code></li>" for x in steps) + "</ol>")
    tasks = run.summary.pddl.tasks() if run.summary.pddl is not None else []
    if tasks:
        out.append("<h3>PDDL planner on the run's files</h3>")
        for task, answer in tasks:
            out.append(_pddl_html(run.path, task, answer))
    if run.pddl_files:
        out.append("<p>PDDL: " + " · ".join(f'<a href="{_url(n)}">{escape(n)}</a>'
                                           for n in run.pddl_files) + "</p>")
    return "".join(out) or '<p class="none">No plan recorded.</p>'


def _pddl_html(root: Path, task: str, answer: PddlCheck) -> str:
    """One PDDL planner answer: status, planner, files (linked when they are in the run
    folder), whether it agrees with Prolog's plan, and the plan once."""
    names = [n for n in (answer.domain, answer.problem) if n is not None]
    targets = [(n, relative_inside(root, n)) for n in names]
    files = " · ".join(f'<a href="{_url(rel)}">{escape(rel)}</a>' if rel and
                       (root / rel).is_file() else escape(n) for n, rel in targets)
    bits = [f"<b>{escape(task)}</b>"
            + (f" ({escape(answer.variant)} task)" if answer.variant else ""),
            f"{escape(_or(answer.status, '?'))}"
            + (f" by {escape(answer.planner)}" if answer.planner else "")]
    if answer.equals_prolog is not None:
        bits.append("the same plan as Prolog's" if answer.equals_prolog else
                    "a plan other than Prolog's")
    if answer.prolog_plan_valid is not None:
        bits.append("Prolog's plan is valid in PDDL" if answer.prolog_plan_valid else
                    "Prolog's plan is NOT valid in PDDL")
    if files:
        bits.append(files)
    plan = answer.plan
    steps = ("<ol class=\"plan\">" + "".join(f"<li><code>{escape(x)}</code></li>"
                                             for x in plan) + "</ol>"
             if plan else "")
    if not answer.equals_prolog and answer.prolog_plan is not None:
        steps += ("<p>Prolog's plan:</p><ol class=\"plan\">" + "".join(
            f"<li><code>{escape(x)}</code></li>" for x in answer.prolog_plan)
            + "</ol>")
    return f"<p>{'; '.join(bits)}</p>{steps}"


# --- small pieces ---------------------------------------------------------------------

def _or(value: Any, default: str) -> str:
    """A value of the summary as text, ``default`` for None."""
    return default if value is None else str(value)


def _url(rel: str) -> str:
    """A relative path as a URL attribute value: percent-encoded, which leaves no
    character that HTML would need escaped (``&``, ``<``, ``>`` and quotes become
    ``%26``, ``%3C``, ``%3E``, ``%22``, ``%27``)."""
    return quote(rel)


def _breakable(text: str) -> str:
    """Escaped text that may wrap after each comma (inside a literal too)."""
    return escape(text).replace(",", ",<wbr>")


def _outcome(text: str) -> str:
    return f'<span class="outcome {escape(text)}">{escape(text)}</span>'


def _value_html(key: str, value: Any, link: Linker | None = None) -> str:
    """A value of the run's JSON as HTML: a list of records as a table, a mapping as a
    key-value table, a number with its hours and minutes when the key is in seconds, the
    name of a file that ``link`` finds as a link to it."""
    if value is None:
        return "-"
    if isinstance(value, dict):
        return _key_value_table(value, link)
    if isinstance(value, list):
        if value and all(isinstance(v, dict) for v in value):
            return _records_table(value, link)
        return escape(", ".join(number_text(v) for v in value)) or "-"
    # A number with the unit its key names (its label leaves the suffix out), seconds
    # from a minute on with their hours and minutes.
    number = isinstance(value, (int, float)) and not isinstance(value, bool)
    text = escape(str(_with_unit(key, value)) if number else number_text(value))
    target = link(value) if isinstance(value, str) and link is not None else None
    return f'<a href="{_url(target)}">{text}</a>' if target else text


def _key_value_table(mapping: dict[str, Any], link: Linker | None = None) -> str:
    rows = "".join(f"<tr><th>{escape(_print_label(str(k)))}</th>"
                   f"<td>{_value_html(str(k), v, link)}</td></tr>"
                   for k, v in mapping.items())
    return f"<table>{rows}</table>"


def _records_table(records: list[dict[str, Any]], link: Linker | None = None) -> str:
    keys: list[str] = []
    for r in records:
        keys += [str(k) for k in r if str(k) not in keys]
    head = "".join(f"<th>{escape(_print_label(k))}</th>" for k in keys)
    rows = "".join("<tr>" + "".join(f"<td>{_value_html(k, r.get(k), link)}</td>" for k in keys)
                   + "</tr>" for r in records)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>"
