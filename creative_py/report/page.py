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
from creative_py.report.contents import (
    Clip, RunContents, ToolEntry, clause_parts, literals_text, number_text,
    plan_steps, read_run, relative_inside,
)

Linker = Callable[[str], "str | None"]
"""Returns the relative path of an existing file a JSON value names, or None."""

REPORT_NAME = "report.html"
"""The page's file name in the run folder."""

_CSS = """
body { font: 15px/1.45 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
       color: #1d2330; background: #f6f7f9; margin: 0; }
main { max-width: 1400px; margin: 0 auto; padding: 1.2rem 1.6rem 3rem; }
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
table { border-collapse: collapse; background: #fff; font-size: 0.88rem; }
th, td { border: 1px solid #dfe3ea; padding: 0.3rem 0.5rem; text-align: left;
         vertical-align: top; }
th { background: #eef1f5; position: sticky; top: 0; }
table.trials { width: 100%; }
table.trials { font-size: 0.84rem; }
table.trials code { font-size: 0.78rem; }
table.trials td.col-reason { min-width: 14rem; }
table.trials td.col-pose { min-width: 8rem; }
table.trials tr:nth-child(even) td { background: #fafbfc; }
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
    case = s.get("case", "")
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
        f"case {case}" if case else "", f"seed {s['seed']}" if "seed" in s else "",
        f"phase {s['phase']}" if "phase" in s else "") if x)
    warnings = ""
    if not (run.path / "summary.json").is_file():
        warnings = ('<div class="warn">No <code>summary.json</code>: the run has not finished '
                    "(or was interrupted); only its recorded trials are shown.</div>")
    if run.warnings:
        warnings += ('<div class="warn"><b>Not everything could be read:</b><ul>'
                    + "".join(f"<li>{escape(w)}</li>" for w in run.warnings) + "</ul></div>")
    return (
        "<!DOCTYPE html>\n"
        f'<html lang="en"><head><meta charset="utf-8">'
        f'<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{escape(title)}</title><style>{_CSS}</style></head><body><main>"
        f"<h1>{escape(title)}</h1><p class=\"sub\">{subtitle}</p>"
        f"<nav>{nav}</nav>{warnings}{_cards(run)}{body}"
        "<footer>Written from the files of this run folder, at the end of the run or by "
        "<code>creative report RUN --html</code>; every link is relative to the folder."
        "</footer>"
        "</main></body></html>\n")


# --- sections -------------------------------------------------------------------------

def _cards(run: RunContents) -> str:
    s = run.summary
    cards = []
    counts: dict[str, list[int]] = {}
    for t in run.trials:
        c = counts.setdefault(str(t.get("phase", "")), [0, 0])
        c[0] += 1
        c[1] += t.get("outcome") == "success"
    names = {"use": "tool-use learning", "create": "tool creation", "eval": "evaluation"}
    for phase, (n, ok) in counts.items():
        cards.append((f"{ok} / {n}", f"{names.get(phase, phase)}: successes / trials"))
    use = s.get("use")
    if isinstance(use, dict) and "converged" in use:
        conv = (f"after {use['trials_to_converge']} trials" if use.get("converged")
                and use.get("trials_to_converge") else "yes" if use.get("converged") else "no")
        cards.append((conv, "tool-use learning converged"))
    demo = s.get("demonstration")
    if isinstance(demo, dict) and demo.get("tool"):
        cards.append((str(demo["tool"]), "demonstrated tool"))
    create = s.get("create")
    if isinstance(create, dict):
        cards.append((str(create.get("success") or "none"), "created tool that succeeded"))
    wall = s.get("wall_time_s")
    if isinstance(wall, dict) and "total" in wall:
        parts = ", ".join(f"{k} {number_text(v)} s" for k, v in wall.items() if k != "total")
        cards.append((f"{number_text(wall['total'])} s", f"wall time ({parts})" if parts
                      else "wall time"))
    return '<div class="cards">' + "".join(
        f'<div class="card"><b>{escape(v)}</b><span>{escape(label)}</span></div>'
        for v, label in cards) + "</div>"


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
    for t in run.trials:
        cells = []
        for header, cell in run.columns:
            text = cell(t)
            if header == "outcome":
                cells.append(f"<td>{_outcome(text)}</td>")
            elif header in ("#", "n", "loc"):
                cells.append(f'<td class="num">{escape(text)}</td>')
            elif header in ("tested", "violated", "pose"):
                cells.append(f'<td class="col-{header}"><code>{_breakable(text)}</code></td>')
            else:
                cells.append(f'<td class="col-{escape(header)}">{escape(text)}</td>')
        rows.append(f'<tr class="trial {escape(str(t.get("outcome", "")))}">{"".join(cells)}</tr>')
    return (plot + f'<div class="panel"><table class="trials"><thead><tr>{head}</tr></thead>'
            f'<tbody>{"".join(rows)}</tbody></table></div>')


def _clips_section(run: RunContents) -> str:
    if not run.clips:
        return '<p class="none">This run saved no video clip.</p>'
    figures = []
    for clip in run.clips:
        caption = _clip_caption(clip)
        if clip.exists:
            media = (f'<video controls preload="metadata" src="{_url(clip.file)}">'
                     f'<a href="{_url(clip.file)}">{escape(clip.file)}</a></video>')
        else:
            media = f'<p class="none">missing: {escape(clip.file)}</p>'
        figures.append(f"<figure>{media}<figcaption>{caption}</figcaption></figure>")
    return f'<div class="clips">{"".join(figures)}</div>'


def _clip_caption(clip: Clip) -> str:
    info = clip.info
    if not info:
        return f"<code>{escape(clip.file)}</code>"
    head = " ".join(escape(str(info[k])) for k in ("phase", "trial") if k in info)
    parts = [f"<b>{head}</b>" if head else ""]
    if info.get("tool"):
        parts.append(escape(str(info["tool"])))
    if info.get("tested"):
        parts.append(f"tested <code>{escape(literals_text(info['tested']))}</code>")
    if info.get("outcome"):
        parts.append(_outcome(str(info["outcome"])))
    text = " · ".join(p for p in parts if p)
    if info.get("why"):
        text += f"<br>{escape(str(info['why']))}"
    return text + f' <a href="{_url(clip.file)}">{escape(Path(clip.file).name)}</a>'


def _tools_section(run: RunContents) -> str:
    create = run.summary.get("create")
    intro = ""
    if isinstance(create, dict):
        bits = [f"harder task: <b>{escape(str(create.get('variant', '?')))}</b>"]
        if "needed" in create:
            bits.append("creation needed" if create["needed"] else
                        "creation not needed (a catalogued tool succeeded)")
        if create.get("solved_by"):
            by = {"learned": "the learned model's own tool",
                  "catalogue": f"the catalogued {create.get('catalogue_success')}",
                  "created": f"the created {create.get('success')}"}
            solver = by.get(create["solved_by"], str(create["solved_by"]))
            bits.append(f"solved by {escape(solver)}")
        tried = [c for c in create.get("catalogue") or [] if isinstance(c, dict)]
        if tried:
            bits.append("catalogued objects considered first: " + ", ".join(
                f"{escape(str(c.get('tool')))} ({escape(str(c.get('outcome')))})"
                for c in tried))
        if create.get("exhausted"):
            bits.append(f"search exhausted: {escape(str(create['exhausted']))}")
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
    if c:
        head.append(f"<p><code>{escape(str(c.get('replaced', '')))}</code> &rarr; "
                    f"<code>{escape(str(c.get('general', '')))}</code> &rarr; "
                    f"<code>{escape(str(c.get('instance', '')))}</code></p>")
        outcomes = [f"creation trial {_outcome(str(c.get('trial_outcome', '?')))}"]
        if c.get("eval_outcomes"):
            outcomes.append("evaluation " + " ".join(_outcome(str(o))
                                                      for o in c["eval_outcomes"]))
        head.append(f"<p>{'; '.join(outcomes)}</p>")
    if tool.picture:
        picture = (f'<figure><img src="{_url(tool.picture)}" alt="Render of {escape(tool.name)}">'
                   f"<figcaption>{escape(tool.picture)}</figcaption></figure>")
    else:
        picture = f'<p class="none">No render ({escape(tool.folder)}/{escape(tool.name)}.png).</p>'
    facts = []
    dims = c.get("dims") if isinstance(c.get("dims"), dict) else None
    if dims:
        facts.append("<h4>Dimensions (summary.json; lengths in m, angles in deg)</h4>"
                     + _key_value_table(dims))
    spec = m.get("spec")
    if isinstance(spec, dict):
        facts.append("<h4>Specification (the tool's JSON)</h4>" + _key_value_table(spec))
    physical = {k: m[k] for k in ("mass_kg", "mesh_volume_m3", "spec_volume_m3") if k in m}
    printability = m.get("printability")
    if isinstance(printability, dict):
        if isinstance(printability.get("extent"), list):
            physical["extent_mm"] = " x ".join(
                f"{float(x) * 1000:.1f}" for x in printability["extent"]
                if isinstance(x, (int, float)))
        physical.update({k: v for k, v in printability.items() if k != "extent"})
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
    """The tool JSON's ``print`` key: its pieces as a table (every key a piece has), the
    rest as a key-value table."""
    if printed is None:
        return '<p class="none">Not sliced (the tool\'s JSON has no print figures).</p>'
    if isinstance(printed, list):
        printed = {"pieces": printed}
    if not isinstance(printed, dict):
        return f"<p>{escape(str(printed))}</p>"
    out = []
    pieces = printed.get("pieces")
    if isinstance(pieces, list) and pieces and all(isinstance(p, dict) for p in pieces):
        out.append(_records_table(pieces, link))
    rest = {k: v for k, v in printed.items() if k != "pieces"}
    if rest:
        out.append(_key_value_table(rest, link))
    return "".join(out) or '<p class="none">No print figures.</p>'


def _hypotheses_section(run: RunContents) -> str:
    out = []
    hyp = run.summary.get("hypotheses")
    names = {"hs": "h<sub>s</sub>, the most specific hypothesis",
             "hg": "h<sub>g</sub>, the most general hypothesis"}
    if isinstance(hyp, dict):
        for key in ("hs", "hg"):
            if key in hyp:
                out.append(f"<h3>{names[key]}</h3>{_clause_html(str(hyp[key]))}")
    create = run.summary.get("create")
    models = create.get("model") if isinstance(create, dict) else None
    if isinstance(models, list) and models:
        out.append("<h3>Model of the created tool</h3><pre>"
                   + escape("\n".join(str(x) for x in models)) + "</pre>")
    if run.model_text is not None:
        out.append('<details><summary><a href="model.pl">model.pl</a> (the learned models '
                   f'and hypotheses, loadable in <code>creative repl</code>)</summary>'
                   f"<pre>{escape(run.model_text)}</pre></details>")
    return "".join(out) or '<p class="none">No hypotheses recorded.</p>'


def _clause_html(clause: str) -> str:
    head, body = clause_parts(clause)
    if not body:
        return f"<pre>{escape(clause)}</pre>"
    items = "".join(f"<li><code>{escape(b)}</code></li>" for b in body)
    return (f'<div class="panel"><code>{escape(head)} :-</code>'
            f'<ol class="literals">{items}</ol></div>')


def _plan_section(run: RunContents) -> str:
    out = []
    plan = run.summary.get("plan")
    if isinstance(plan, str):
        steps = plan_steps(plan)
        if steps is None:
            out.append(f"<p>Prolog's planner: <code>{escape(plan)}</code></p>")
        else:
            out.append("<p>Prolog's planner, with the learned model:</p><ol class=\"plan\">"
                       + "".join(f"<li><code>{escape(x)}</code></li>" for x in steps) + "</ol>")
    pddl = run.summary.get("pddl")
    if isinstance(pddl, dict) and pddl:
        out.append("<h3>PDDL planner on the run's files</h3>")
        if all(isinstance(v, dict) for v in pddl.values()):
            out.append(_records_table([{"task": k, **v} for k, v in pddl.items()]))
        else:
            out.append(_key_value_table(pddl))
    if run.pddl_files:
        out.append("<p>PDDL: " + " · ".join(f'<a href="{_url(n)}">{escape(n)}</a>'
                                           for n in run.pddl_files) + "</p>")
    return "".join(out) or '<p class="none">No plan recorded.</p>'


# --- small pieces ---------------------------------------------------------------------

def _url(rel: str) -> str:
    """A relative path as an escaped URL attribute value."""
    return escape(quote(rel), quote=True)


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
    text = escape(number_text(value))
    if isinstance(value, (int, float)) and not isinstance(value, bool) and \
            key.endswith("_s") and value >= 60:
        minutes = round(value / 60)
        text += f" ({minutes // 60} h {minutes % 60} min)" if minutes >= 60 else \
            f" ({minutes} min)"
    target = link(value) if isinstance(value, str) and link is not None else None
    return f'<a href="{_url(target)}">{text}</a>' if target else text


def _key_value_table(mapping: dict[str, Any], link: Linker | None = None) -> str:
    rows = "".join(f"<tr><th>{escape(str(k))}</th><td>{_value_html(str(k), v, link)}</td></tr>"
                   for k, v in mapping.items())
    return f"<table>{rows}</table>"


def _records_table(records: list[dict[str, Any]], link: Linker | None = None) -> str:
    keys: list[str] = []
    for r in records:
        keys += [str(k) for k in r if str(k) not in keys]
    head = "".join(f"<th>{escape(k)}</th>" for k in keys)
    rows = "".join("<tr>" + "".join(f"<td>{_value_html(k, r.get(k), link)}</td>" for k in keys)
                   + "</tr>" for r in records)
    return f"<table><thead><tr>{head}</tr></thead><tbody>{rows}</tbody></table>"
