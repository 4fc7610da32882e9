"""Write the README's figures about runs from the recorded results (``make readme-figures``).

Every figure the README states about runs sits in a marked block::

    <!-- figures:NAME -->
    ...generated text...
    <!-- /figures:NAME -->

and each block is the text of one function of this file, computed from
``bench/results/*.json`` alone (each function names the file it reads). Run without
options, this rewrites every block of ``README.md`` in place; with ``--check`` it
rewrites nothing and lists the blocks whose text differs from the results (exit 1).
``tests/python/test_readme_figures.py`` does the same check in the quick suite, so a
README that disagrees with ``bench/results`` fails the tests, naming the block.

To change a figure, re-run the benchmark that records it (``bench/release_runs.py``,
``bench/learning_bench.py``, ``bench/strategy_bench.py``, ...), then this script.

    .venv/bin/python bench/readme_figures.py [--check] [--readme README.md]
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import sys
from functools import lru_cache
from pathlib import Path
from typing import Any, Callable

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"
README = HERE.parent / "README.md"
BLOCK = re.compile(r"<!-- figures:([a-z0-9-]+) -->\n(.*?)\n?<!-- /figures:\1 -->", re.S)

BLOCKS: dict[str, Callable[[], str]] = {}


def block(name: str) -> Callable[[Callable[[], str]], Callable[[], str]]:
    """Register a function as the text of the README block ``name``."""
    def register(fn: Callable[[], str]) -> Callable[[], str]:
        if name in BLOCKS:
            raise ValueError(f"block {name} defined twice")
        BLOCKS[name] = fn
        return fn
    return register


@lru_cache(maxsize=None)
def result(name: str) -> Any:
    """Return ``bench/results/<name>.json``."""
    return json.loads((RESULTS / f"{name}.json").read_text(encoding="utf-8"))


def run(key: str) -> dict[str, Any]:
    """Return one run of ``bench/results/release_runs.json`` (``hook-default``, ...)."""
    return result("release_runs")["runs"][key]


# --- number formatting ----------------------------------------------------------------

def num(x: float, digits: int = 0) -> str:
    """A number with thousands separators and ``digits`` decimals (trailing ``.0`` of a
    whole median dropped when ``digits`` is 0)."""
    if digits == 0:
        return f"{round(x):,}"
    return f"{x:,.{digits}f}"


def med(x: float) -> str:
    """A median: whole when it is, else one decimal."""
    return f"{int(x)}" if float(x).is_integer() else f"{x:.1f}"


def hours(seconds: float) -> str:
    """Seconds as hours with one decimal (``4.1 h``)."""
    return f"{seconds / 3600:.1f} h"


def mm(values: list[float]) -> str:
    """A bounding box in mm to 0.1 mm, ``248 x 183.6 x 9``."""
    return " x ".join(f"{round(v, 1):g}" for v in values)


def outcome_counts(outcomes: list[str]) -> str:
    """``1 failed + 1 successful`` of a list of trial outcomes."""
    ok = sum(1 for o in outcomes if o == "success")
    bad = len(outcomes) - ok
    parts = ([f"{bad} failed"] if bad else []) + ([f"{ok} successful"] if ok else [])
    return " + ".join(parts) or "none"


# --- Results: ten seeds per case (learning.json) --------------------------------------

def _creation_cell(case: dict[str, Any]) -> str:
    """The creation trials of one case of learning.json, with the seeds that differ."""
    failed, trials = case["create_failed"], case["create_trials"]
    text = (f"{med(failed['median'])} failed + "
            f"{med(trials['median'] - failed['median'])} successful")
    runs = case.get("runs")
    if not runs:
        same = failed["median"] == failed["worst"] and trials["median"] == trials["worst"]
        return text + (", every seed" if same else
                       f" (median; worst {failed['worst']} failed of {trials['worst']})")
    common = statistics.mode(tuple(r["create_outcomes"]) for r in runs)
    others = [r for r in runs if tuple(r["create_outcomes"]) != common]
    text = outcome_counts(list(common)) + (
        ", every seed" if not others else f" in {len(runs) - len(others)} seeds")
    for r in others:
        text += f"; seed {r['seed']}: " + ", ".join(r["create_outcomes"])
    return text


@block("learning-table")
def learning_table() -> str:
    """The paper against ten seeds per case, ``--strategy paper`` (learning.json)."""
    d = result("learning")
    rows = ["| | paper | CREATIVE-py, median (worst) over 10 seeds |", "|---|---|---|"]
    for name in ("hook", "wedge"):
        c = d[name]
        p = c["paper"]
        rows.append(f"| {name}: tool-use trials | {p['use_trials']} | "
                    f"{med(c['use_trials']['median'])} ({c['use_trials']['worst']}); "
                    f"nothing left to test after {med(c['trials_to_converge']['median'])} |")
        paper_tc = (f"{p['create_failed']} failed + {p['create_success']} successful")
        rows.append(f"| {name}: tool-creation trials | {paper_tc} | {_creation_cell(c)} |")
        ev = c["created_tool_eval_successes"]
        paper_eval = "5 of 5" if name == "hook" else "1 of 1"
        every = (f"5 of 5, every seed ({5 * ev['n']} of {5 * ev['n']})"
                 if ev["worst"] == 5 else
                 f"{med(ev['median'])} of 5 ({ev['worst']} in the worst seed)")
        rows.append(f"| {name}: created tool, evaluation | {paper_eval} | {every} |")
        lm = c["learned_model_eval"]
        rows.append(f"| {name}: learned model, evaluation | - | {lm['successes']} of "
                    f"{lm['trials']} trials ({lm['trials'] // c['seeds']} per seed) |")
    w = {k: d[k]["wall_time_s"] for k in ("hook", "wedge")}
    rows.append("| wall time of a whole run | - | " + "; ".join(
        f"{k} {w[k]['total']['median']:.0f} s ({w[k]['total']['worst']:.0f} s)"
        for k in w) + " |")
    rows.append("| wall time per phase (median): tool use / evaluation / creation | - | "
                + "; ".join(f"{k} " + " / ".join(f"{w[k][p]['median']:.0f}"
                                                 for p in ("use", "eval", "create"))
                            + " s" for k in w) + " |")
    return "\n".join(rows)


# --- Results: the strategies on the shipped worlds, seed 0 (release_runs.json) ---------

def _kinds(r: dict[str, Any]) -> str:
    """A run's tool-use trials, with its tests and confirmations when it had both."""
    use = [t for t in r["trial_lines"] if t["phase"] == "use"]
    tests = sum(1 for t in use if t.get("kind") != "exploit")
    confirm = len(use) - tests
    if not confirm:
        return str(len(use))
    return f"{len(use)} ({tests} tests, {confirm} confirmation{'s' if confirm > 1 else ''})"


def _model_eval(r: dict[str, Any]) -> str:
    """A run's evaluation of the learned model, ``model 4 of 4``."""
    e = r["eval"]
    return f"model {e['successes']} of {e['trials']}"


@block("strategies-seed0")
def strategies_seed0() -> str:
    """Tool-use trials per strategy, seed 0 of each shipped world (release_runs.json:
    ``CASE-paper``, ``CASE-default`` (informative), ``CASE-random``)."""
    rows = ["| | paper | informative (default) | random |", "|---|---|---|---|"]
    cases = ("hook", "wedge", "rake")
    for case in cases:
        p, i, r = run(f"{case}-paper"), run(f"{case}-default"), run(f"{case}-random")
        rows.append(f"| {case}: tool-use trials | {_kinds(p)}, {p['use']['stop']}; "
                    f"{_model_eval(p)} | **{i['use']['trials']}**, {i['use']['stop']} stop; "
                    f"{_model_eval(i)} | {r['use']['trials']}, {r['use']['stop']}; "
                    f"{_model_eval(r)} |")
    first = [run(f"{c}-default") for c in cases]
    rows.append("| hypotheses after the demonstration (`info_bound_trials`) | "
                + ", ".join(f"{c} {num(x['vs_count_initial'])} ({x['info_bound_trials']})"
                            for c, x in zip(cases, first)) + " | "
                + " | ".join(", ".join(f"{c} {num(run(f'{c}-{k}')['vs_count_initial'])}"
                                       for c in cases) for k in ("default", "random"))
                + " |")
    same = [", ".join(f"{c} {'yes' if run(f'{c}-{k}')['hypotheses']['hg'] == run(f'{c}-paper')['hypotheses']['hg'] else 'no'}"
                      for c in cases) for k in ("default", "random")]
    rows.append(f"| h_g the same as `paper`'s | - | {same[0]} | {same[1]} |")
    rows.append("| hypotheses left at the end | " + " | ".join(
        ", ".join(f"{c} {num(run(f'{c}-{k}')['vs_count_final'])}" for c in cases)
        for k in ("paper", "default", "random")) + " |")
    return "\n".join(rows)


def _solved(r: dict[str, Any]) -> str:
    """What a run's creation phase tried, in order, and what solved the harder task."""
    c = r["create"]
    cat = c.get("catalogue") or []
    created = r["created_tools"]
    n = c["trials"]
    parts = []
    pred = c.get("predicted") or {}
    if c.get("predicted_failure_skipped"):
        parts.append(f"the learned model's {pred['tool']} is predicted to fail, not run")
    else:
        first = next((t for t in r["trial_lines"] if t["phase"] == "create"), None)
        if first:
            parts.append(f"the learned model's {first['tool']}: {first['outcome']}")
    for entry in cat:
        if entry.get("trial") is not None:
            parts.append(f"the catalogued {entry['tool']}: {entry['outcome']}")
        else:
            parts.append(f"the catalogued {entry['tool']} predicted to fail, not run")
    if not cat:
        parts.append("no catalogued object admitted")
    for t in created:
        parts.append(f"{t['name']} made: {t['trial_outcome']}")
    what = {"catalogue": "a catalogued object", "created": "a made tool",
            "learned": "the learned model's tool", None: "nothing"}[c.get("solved_by")]
    return (f"{n} creation trial{'s' if n != 1 else ''} ({'; '.join(parts)}); "
            f"solved by {what}")


@block("catalogue-first")
def catalogue_first() -> str:
    """Per case, seed 0, informative, catalogued objects first (release_runs.json,
    ``CASE-default``): tool-use trials, what solved the harder task, creation trials."""
    rows = ["| case (seed 0, `creative run CASE`) | tool-use trials | the harder task |",
            "|---|---|---|"]
    for case in TABLED:
        r = run(f"{case}-default")
        rows.append(f"| {case} ({r['create']['variant']}) | {r['use']['trials']}, "
                    f"{r['use']['stop']} | {_solved(r)} |")
    return "\n".join(rows)


def _strength(t: dict[str, Any]) -> str:
    """A created tool's strength check: model, robust and peak force, stress, verdict."""
    s = t["strength"]
    where = (f" at {s['lever_arm_m']:.3f} m from the grasp" if s.get("lever_arm_m")
             else " over its footprint")
    return (f"{s['model']}, {s['force_n']:.2f} N (the robust force; one-step peak "
            f"{s['peak_force_n']:.2f} N){where}, {s['stress_mpa']:.3g} MPa, safety "
            f"factor {s['safety_factor']:.1f} (with the peak {s['peak_safety_factor']:.1f}), "
            f"{s['verdict']}")


@block("created-tools")
def created_tools() -> str:
    """The tools ``make hook``/``make wedge``/``make rake`` create, seed 0
    (release_runs.json, ``CASE-make``): size, mass, strength, print."""
    lines = []
    for case in ("hook", "wedge", "rake"):
        r = run(f"{case}-make")
        for t in r["created_tools"]:
            size = ", ".join(f"{k} {v * 1000:.1f} mm" if isinstance(v, float)
                             else f"{k} {v}" for k, v in t["dims"].items())
            p = t["print"]
            pieces = "; ".join(f"{q['role']} {mm(q['bounding_box_mm'])} mm "
                               f"({q['print_time']}, {q['filament_g']:.1f} g)"
                               for q in p["pieces"])
            n = len(p["pieces"])
            ev = t.get("eval_outcomes") or []
            evaluation = (f", evaluation {sum(o == 'success' for o in ev)} of {len(ev)}"
                          if ev else "")
            lines.append(
                f"- {case}, `{t['name']}` ({t['instance'].replace('_G0', 'T')}, "
                f"{t['trial_outcome']}{evaluation}): {size}; {t['mass_kg'] * 1000:.1f} g; "
                f"{n} piece{'s' if n != 1 else ''} ({pieces}); in all "
                f"{hours(p['print_time_s'])} and {p['filament_g']:.1f} g of filament "
                f"(union {p['union_volume_error_pct']:+.2f} % of the design's volume; "
                f"splitting, writing and slicing {p['wall_time_s']:.1f} s of the run); "
                f"strength: {_strength(t)}.")
    return "\n".join(lines)


@block("verdicts")
def verdicts() -> str:
    """Whether every failure of the seed-0 runs carries its measured quantity and
    threshold, and every wedge trial the door's angle (release_runs.json)."""
    by: dict[str, list[dict[str, Any]]] = {}
    for key in sorted(result("release_runs")["runs"]):
        by.setdefault(key.rsplit("-", 1)[0], []).append(run(key)["verdicts"])
    parts = []
    for case, vs in by.items():
        text = (f"{case} {sum(v['failures_with_quantity_and_threshold'] for v in vs)} of "
                f"{sum(v['failures'] for v in vs)} failures")
        if case == "wedge":
            text += (f", the door's angle in "
                     f"{sum(v['trials_with_door_angle'] for v in vs)} of "
                     f"{sum(v['trials'] for v in vs)} trials")
        parts.append(text + f" ({len(vs)} runs)")
    return ("In the seed-0 runs of `bench/release_runs.py`, the failures whose `verdict` "
            "gives the measured quantity, its value and its threshold: "
            + "; ".join(parts) + ".")


@block("clips")
def clips() -> str:
    """The clips a hook run keeps (release_runs.json, ``hook-make`` and
    ``hook-default``)."""
    out = []
    for key, what in (("hook-make", "`make hook`"),
                      ("hook-default", "`creative run hook`")):
        v = run(key)["videos"]
        dur = [c["duration_s"] for c in v]
        fr = [c["frames"] for c in v]
        kb = [c["bytes"] / 1000 for c in v]
        out.append(f"{what} (seed 0) keeps {len(v)} clips of {min(dur):.1f}-"
                   f"{max(dur):.1f} s ({min(fr)}-{max(fr)} frames, {min(kb):.0f}-"
                   f"{max(kb):.0f} KB each, {sum(kb):.0f} KB in all): "
                   + ", ".join(f"{c['phase']} {c['trial']} ({c['why'].split(':')[0]})"
                               for c in v) + ".")
    return " ".join(out)


@block("video-cost")
def video_cost() -> str:
    """A whole hook run with and without clips (video_cost.json)."""
    d = result("video_cost")
    parts = []
    for p in d["pairs"]:
        n, k = p["none"], p["key"]
        parts.append(f"{n['wall_s']:.1f} s of wall time with `--video none`, {k['wall_s']:.1f} s "
                     f"with `--video key` ({(p['wall_ratio'] - 1) * 100:+.0f} %; CPU time of "
                     f"the run and its encoders {n['cpu_s']:.1f} s and {k['cpu_s']:.1f} s) at "
                     f"load {n['load_before']:.1f} and {k['load_before']:.1f}; "
                     f"`trials.jsonl` {'the same' if p['same_trials'] else 'DIFFERENT'} "
                     f"(tool, tested literal, outcome, reason and pose of every trial)")
    return (f"Cost (`bench/video_cost_bench.py`, `{d['command']}`, one run after the "
            f"other on this shared {d['cores']}-core machine): " + "; ".join(parts) + ".")


def _pretty(line: str) -> list[str]:
    """A ``learned_model/4`` or ``learned_hypothesis/3`` fact of ``model.pl`` (one line)
    wrapped at 88 columns, each list or body under its first argument."""
    name = line[:line.index("(")]
    args = _top_level(line[len(name) + 1:-len(").")])
    indent = " " * (len(name) + 1)
    if name == "learned_hypothesis":
        head, body = args[2][1:-1].split(":-", 1)
        lines = _wrap(f"{name}({args[0]}, {args[1]}, ({head} :- ", _top_level(body), indent)
        lines[-1] += "))."
        return lines
    lines = [f"{name}({args[0]}, {args[1]},"]
    for k, lst in enumerate(args[2:]):
        part = _wrap(indent + "[", _top_level(lst[1:-1]), indent + " ")
        part[-1] += "]" + ("," if k == 0 else ").")
        lines += part
    return lines


def _models(text: str) -> str:
    """The learned models and h_g of a ``model.pl`` (not h_s), wrapped, as a code block."""
    keep = [line for line in text.splitlines()
            if line.startswith(("learned_model(", "learned_hypothesis("))
            and ", hs," not in line]
    return "```prolog\n" + "\n".join(x for line in keep for x in _pretty(line)) + "\n```"


@block("hook-model")
def hook_model() -> str:
    """The learned hook models, ``model.pl`` of ``make hook`` (release_runs.json)."""
    return _models(run("hook-make")["model_pl"])


@block("wedge-model")
def wedge_model() -> str:
    """The learned wedge models, ``model.pl`` of ``make wedge`` (release_runs.json)."""
    return _models(run("wedge-make")["model_pl"])


@block("rake-model")
def rake_model() -> str:
    """The learned rake models, ``model.pl`` of ``make rake`` (release_runs.json)."""
    return _models(run("rake-make")["model_pl"])


def _top_level(text: str) -> list[str]:
    """Split a Prolog argument list at its top-level commas."""
    out, depth, cur = [], 0, ""
    for ch in text:
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur.strip())
            cur = ""
        else:
            cur += ch
    return out + [cur.strip()] if cur.strip() else out


def _wrap(head: str, items: list[str], indent: str, width: int = 88) -> list[str]:
    """``head`` then items joined by ``, ``, wrapped under ``indent``."""
    lines, cur = [], head
    for k, item in enumerate(items):
        piece = item + (", " if k < len(items) - 1 else "")
        if len(cur) + len(piece.rstrip()) > width and cur.strip():
            lines.append(cur.rstrip())
            cur = indent
        cur += piece
    return lines + [cur]


@block("repl-example")
def repl_example() -> str:
    """The first answer of ``learned_model/4`` in ``creative repl`` of a wedge run, from
    ``model.pl`` of ``make wedge`` (release_runs.json): Prolog prints the clause's
    variables as ``_A``, ``_B``."""
    line = next(x for x in run("wedge-make")["model_pl"].splitlines()
                if x.startswith("learned_model(wedge,"))
    args = _top_level(line[len("learned_model("):-len(").")])
    task, action, pre, eff = (re.sub(r"\b([A-Z])\b", r"_\1", a) for a in args)
    out = ["```prolog", "?- learned_model(Task, Action, Pre, Eff).",
           f"Task = {task}, Action = {action},"]
    out += _wrap("Pre = [", _top_level(pre[1:-1]), "       ")
    out[-1] += "],"
    out.append(f"Eff = {eff} .")
    return "\n".join(out + ["```"])


@block("trial-sequences")
def trial_sequences() -> str:
    """Each case's trials, seed 0, informative, ``make CASE`` (release_runs.json)."""
    lines = []
    for case in ("hook", "wedge", "rake"):
        r = run(f"{case}-make")
        parts = []
        for t in r["trial_lines"]:
            if t["phase"] == "eval":
                continue
            tested = ", ".join(re.sub(r"\(.*", "", x) for x in t.get("tested") or [])
            parts.append(f"{t['phase']} {t['trial']} {t['tool']} {t['outcome']}"
                         + (f" ({tested})" if tested else ""))
        lines.append(f"- {case}: " + "; ".join(parts) + ".")
    return "\n".join(lines)


TABLED = ("hook", "wedge", "rake")
"""The cases of the README's seed-0 tables; every other case of release_runs.json gets
a paragraph of its own (``other-cases``)."""


def _hg_body(hg: str) -> str:
    """The body literals of an h_g clause, the tool variable shown as ``T``."""
    body = hg.split(":-", 1)[1].strip()
    return ", ".join(f"`{lit}`" for lit in _top_level(body)).replace("_G3", "T").replace(
        "_G4", "C")


def _made_tool(t: dict[str, Any]) -> str:
    """A tool made in a ManiSkill run: its sizes and what the physics said of it."""
    d = t["dims"]
    text = (f"`{t['name']}` ({d['handle_length']:.2f} m handle, {d['hook_side']} prong at "
            f"{d['hook_angle_deg']} degrees; `{t['instance'].replace('_G0', 'T')}` for "
            f"`{t['replaced'].replace('_G0', 'T')}`): {t['trial_outcome']}")
    st = t["strength"]
    if st.get("verdict"):
        text += (f", strength {st['verdict']} at {st['force_n']:.1f} N (safety factor "
                 f"{st['safety_factor']:,.0f})")
    if t["eval_outcomes"]:
        ok = t["eval_outcomes"].count("success")
        text += f", evaluation {ok} of {len(t['eval_outcomes'])}"
    return text


@block("maniskill")
def maniskill() -> str:
    """The ManiSkill case's learning run and its learned model on fresh ManiSkill seeds
    against the demonstration's tool and pose (maniskill.json,
    maniskill_demonstration.json; ``make bench-maniskill``)."""
    m, d = result("maniskill"), result("maniskill_demonstration")
    lr = m["learning"]
    ok = lr["eval"].count("success")
    cr = lr["create"]
    tried = ", ".join(f"`{c['tool']}` {c['outcome']}" for c in cr["sequence"])
    made = "; ".join(_made_tool(t) for t in cr["made"])
    seeds = m["seeds"]
    need = m["seeds_needing_tool"]
    lines = [
        f"The learning run of `make bench-maniskill` (`creative run pull_cube_tool --seed 0 "
        f"--video none`, run `{lr['run']}`, {lr['wall_time_s']['total']:.0f} s of wall "
        f"time; `make run CASE=pull_cube_tool` makes the same run with clips): the demonstration with "
        f"ManiSkill's tool, then {lr['trials']} tool-use trials ({lr['strategy']}, stop "
        f"{lr['stop']}, budget {lr['budget']}; {lr['env_steps']} ManiSkill control steps "
        f"besides the demonstration's). h_g: {_hg_body(lr['hg'])}; the plan takes "
        f"`{m['tool']}`, evaluation {ok} of {len(lr['eval'])}. In `{cr['variant']}`, "
        f"{cr['trials']} creation trials ({tried}); the tools made: {made}.",
        "",
        f"`make bench-maniskill` (`bench/maniskill_bench.py`, {len(seeds)} fresh seeds "
        f"{seeds[0]}-{seeds[-1]}, none a learning location; each seed is also tried with a "
        f"bare-finger pull, and {len(seeds) - need} of the {len(seeds)} need no tool that way):",
        "",
        f"| evaluated on seeds {seeds[0]}-{seeds[-1]} | all {len(seeds)} seeds | "
        f"the {need} that need a tool | control steps |",
        "|---|---|---|---|",
    ]
    for label, r, name in (("the learned model", m, "maniskill"),
                           ("the demonstration's tool and pose", d,
                            "maniskill_demonstration")):
        lines.append(f"| {label} (`{r['tool']}`, `bench/results/{name}.json`) | "
                     f"{r['successes']} / {len(r['seeds'])} | {r['successes_needing_tool']} / "
                     f"{r['seeds_needing_tool']} | {r['env_steps']} |")
    lines += ["", f"So the learner reached a model that succeeds on {m['successes']} of "
              f"{len(seeds)} fresh seeds after one demonstration and {lr['trials']} trials "
              f"({lr['env_steps']} simulated control steps)."]
    return "\n".join(lines)


def _other_cases() -> list[str]:
    """The cases of release_runs.json outside :data:`TABLED`."""
    cases = sorted({k.rsplit("-", 1)[0] for k in result("release_runs")["runs"]})
    return [c for c in cases if c not in TABLED]


@block("other-cases")
def other_cases() -> str:
    """Each case outside the README's tables (the paddle), seed 0 (release_runs.json,
    ``CASE-default`` and ``CASE-make``)."""
    out = []
    for case in _other_cases():
        d, m = run(f"{case}-default"), run(f"{case}-make")
        body = re.sub(r"_G\d+,?", "", d["hypotheses"]["hg"].split(":-", 1)[1])
        hg = body.replace("()", "").replace(",", ", ").replace(",  ", ", ")
        budget = f" within the budget of {d['trial_budget']}" if d.get("trial_budget") else ""
        text = (f"Seed 0 (`creative run {case}`, "
                f"{d['summary_wall_time_s']['total'] / 60:.1f} min): {d['use']['trials']} "
                f"tool-use trials{budget} ({d['use']['stop']} stop), h_g `{hg.strip()}`; "
                f"the harder task: {_solved(d)}.")
        for t in m["created_tools"]:
            p = t["print"]
            text += (f" With `--demonstrate-creation` (`make run CASE={case}`): "
                     f"`{t['name']}` ({t['instance'].replace('_G0', 'T')}), "
                     + ", ".join(f"{k} {v * 1000:.1f} mm" for k, v in t["dims"].items()
                                 if isinstance(v, float))
                     + f", {t['trial_outcome']}; {len(p['pieces'])} printed pieces "
                     f"({hours(p['print_time_s'])}, {p['filament_g']:.1f} g); strength "
                     f"{t['strength']['verdict']} (safety factor "
                     f"{t['strength']['safety_factor']:.1f}).")
        out.append(text)
    return "\n\n".join(out)


# --- randomised worlds (strategies.json, creation_worlds_hook.json) --------------------

@block("randomised-table")
def randomised_table() -> str:
    """Tool-use trials over 20 drawn worlds per case and strategy (strategies.json)."""
    d = result("strategies")
    by = {(r["case"], r["strategy"]): r for r in d["records"]}
    rows = ["| case (paper's count; ceil(log2 N0)) | `paper` | `informative` (default) "
            "| `random` |", "|---|---|---|---|"]
    for case in ("hook", "wedge", "rake"):
        first = by[(case, "paper")]
        paper = first["paper_trials"] if first["paper_trials"] else "-"
        cells = []
        for s in ("paper", "informative", "random"):
            r = by[(case, s)]
            m = med(r["trials_median"])
            cells.append(f"{'**' + m + '**' if s == 'informative' else m} "
                         f"[{r['trials_min']}-{r['trials_max']}]; model "
                         f"{r['eval_successes']}/{r['eval_trials']}")
        rows.append(f"| {case} ({paper}; {med(first['info_bound_median'])}) | "
                    + " | ".join(cells) + " |")
    return "\n".join(rows)


@block("randomised-sweep")
def randomised_sweep() -> str:
    """The sweep behind the randomised table (strategies.json)."""
    d = result("strategies")
    ok = sum(r["ok"] for r in d["records"])
    cmp = d["compared_with_previous"]
    return (f"{d['runs']} runs, {'all ok' if ok == d['runs'] else f'{ok} ok'}, "
            f"{num(d['wall_time_s'])} s on a local Ray instance with "
            f"{d['ray']['num_cpus']} cores; {cmp['runs_identical']} runs as before, "
            f"{cmp['runs_different']} differ by physics (`compared_with_previous`).")


@block("randomised-notes")
def randomised_notes() -> str:
    """How the strategies stopped and which evaluations failed over the drawn worlds
    (strategies.json)."""
    d = result("strategies")
    seeds = d["world_seeds"]
    by = {(r["case"], r["strategy"]): r for r in d["records"]}
    stops = []
    for s in ("paper", "informative", "random"):
        kinds = sorted({k for c in ("hook", "wedge", "rake") for k in by[(c, s)]["stops"]})
        stops.append(f"`{s}` stopped {' or '.join(kinds)}")
    text = ", ".join(stops[:-1]) + f" and {stops[-1]} in every run. "
    rnd = by[("hook", "random")]
    text += (f"`random` learned a hook model that failed evaluation in "
             f"{len(rnd['worlds_with_eval_failures'])} of {rnd['runs']} worlds. ")
    fails = [f"`{s}` in world{'s' if len(w) > 1 else ''} " + " and ".join(map(str, w))
             for s in ("paper", "informative")
             if (w := by[("hook", s)]["worlds_with_eval_failures"])]
    if fails:
        text += "The hook's other evaluation failures: " + "; ".join(fails) + ". "
    reached, total, odd = 0, 0, []
    for c in ("hook", "wedge", "rake"):
        r = by[(c, "informative")]
        low = r["trials_min"]
        for seed, n in zip(seeds, r["trials"]):
            total += 1
            if n == low:
                reached += 1
            else:
                odd.append(f"{c} world {seed}: {n}")
    text += (f"`informative` took its case's fewest trials in {reached} of {total} worlds"
             + (f" (the others: {', '.join(odd)})" if odd else "") + ".")
    return text


@block("creation-worlds-hook")
def creation_worlds_hook() -> str:
    """Tool creation over the 20 drawn hook worlds (creation_worlds_hook.json)."""
    d = result("creation_worlds_hook")
    other = [w for w in d["per_world"] if w["trials"] != 1]
    return (f"{d['ok']} of {d['worlds']} runs ok; the reach check predicted the learned "
            f"model's failure in {d['predicted']}; creation took one trial in "
            f"{d['one_trial_where_predicted']}"
            + ("" if not other else " (" + ", ".join(
                f"world {w['world_seed']}: {', '.join(w['outcomes'])}" for w in other) + ")")
            + f"; the created hooks passed {d['created_eval_successes']} of "
            f"{d['created_eval_trials']} evaluation trials.")


@block("sweep-speedup")
def sweep_speedup() -> str:
    """Serial against Ray, the same 12 runs (sweep_speedup.json)."""
    d = result("sweep_speedup")
    a, b = d["reused_workers"], d["fresh_workers"]
    same = "the same" if a["same_trial_counts"] and b["same_trial_counts"] else "different"
    return (f"The same {a['runs']} runs ({', '.join(a['cases'])}, world seeds "
            f"{a['world_seeds']}, `{a['strategy']}`, phase {a['phase']}) took "
            f"{a['serial_s']:.1f} s one after another in one process (`--serial`) and "
            f"{a['ray_s']:.1f} s on a local Ray instance with {a['cores']} cores: "
            f"{a['speedup']:.2f}x, with {same} trial counts. With `--fresh-workers` "
            f"it was {b['ray_s']:.1f} s against {b['serial_s']:.1f} s, {b['speedup']:.2f}x.")


@block("hook-world-sweep")
def hook_world_sweep() -> str:
    """The hook over 100 drawn worlds (hook_world_sweep.json, drawn_worlds.json)."""
    d, w = result("hook_world_sweep"), result("drawn_worlds")
    t = d["tool_use_trials"]
    return (f"`{d['command']}`: {d['status'].get('ok', 0)} of {d['runs']} runs ok, "
            f"{d['crashed']} crashed; tool-use trials median {med(t['median'])} "
            f"[{t['min']}-{t['max']}]; the learned models passed {d['eval_successes']} of "
            f"{d['eval_trials']} evaluation trials. Drawing the {w['worlds']} worlds: "
            f"{w['needed_redraw']} needed a redraw of the demonstration's location, "
            f"{w['failed']} failed.")


# --- the worlds' outcome tables (sim_hook.json, sim_wedge.json, sim_rake.json) --------

@block("hook-world-table")
def hook_world_table() -> str:
    """Outcome per tool, variant and location at the demonstration's pose (sim_hook.json)."""
    return result("sim_hook")["table_markdown"].strip()


@block("wedge-world-table")
def wedge_world_table() -> str:
    """Outcome per object and door, with the degrees the door closed after first contact
    (sim_wedge.json)."""
    return result("sim_wedge")["table_markdown"].strip()


@block("rake-world-table")
def rake_world_table() -> str:
    """Outcome per tool, variant and location at the demonstration's pose (sim_rake.json)."""
    d = result("sim_rake")
    t = d["trial_wall_s"]
    return (d["table_markdown"].strip() + f"\n\n({t['median']:.1f} s median wall time a "
            f"trial, {t['max']:.1f} s worst.)")


@block("hook-trial-cost")
def hook_trial_cost() -> str:
    """What a hook trial costs (sim_hook.json)."""
    d = result("sim_hook")
    sim = statistics.median(t["sim_time_s"] for t in d["trials"])
    return (f"A hook trial takes {d['trial_wall_s']['median']:.1f} s of wall time (median, "
            f"worst {d['trial_wall_s']['max']:.1f} s) for {sim:.1f} s simulated (median); a "
            f"scene after the first builds in {d['startup_s']['later_median']:.2f} s (first "
            f"{d['startup_s']['first']:.1f} s).")


# --- speed, cost, mutation -------------------------------------------------------------

@block("robot-cost")
def robot_cost() -> str:
    """The light robot against the full one (robot_cost.json)."""
    c = result("robot_cost")["cases"]
    return ("A trial costs " + " and ".join(
        f"{c[k]['ratio_light_over_heavy']:.2f}x ({k})" for k in ("hook", "wedge"))
        + " the CPU time of the full robot; the exact mode (the full physics model, the "
          "rest light) gives bit for bit the full robot's results ("
        + ", ".join(f"{k}: {'yes' if c[k]['exact_bitwise_same_as_heavy'] else 'no'}"
                    for k in ("hook", "wedge"))
        + ") at " + "-".join(f"{c[k]['ratio_exact_over_heavy']:.2f}" for k in ("hook", "wedge"))
        + "x the cost.")


def _engine_row(size: dict[str, Any]) -> str:
    """The four engine timings of one clause size of engine.json, in ms."""
    keys = ("clause_lgg_ms", "theta_subsumes_ms", "clause_reduce_ms", "nbr_reduce_ms")
    vals = []
    for k in keys:
        v = size.get(k)
        vals.append("-" if v is None else (f"{v:,.0f}" if v >= 100 else
                                           f"{v:.2g}" if v < 1 else f"{v:.1f}"))
    return " / ".join(vals)


@block("speed-table")
def speed_table() -> str:
    """The speed table (decisions, engine, bridge, sim_hook, sim_wedge, perception,
    soak, bad_input)."""
    dec, eng, br = result("decisions"), result("engine"), result("bridge")
    sh, sw, soak, bad = (result("sim_hook"), result("sim_wedge"), result("soak"),
                         result("bad_input"))
    rows = ["| what | figure | aim |", "|---|---|---|"]
    rows.append(
        "| one learning decision (`next_experiment`, through the bridge) | "
        f"hook {dec['hook']['next_experiment']['median_ms']} ms, wedge "
        f"{dec['wedge']['next_experiment']['median_ms']} ms median (worst "
        f"{max(dec[c]['next_experiment']['worst_ms'] for c in ('hook', 'wedge'))} ms); "
        f"`label_trial` {dec['hook']['label_trial']['median_ms']:.1f} ms, "
        f"{dec['wedge']['label_trial']['median_ms']:.1f} ms | < 50 ms |")
    vs = eng["vs_update"]
    rows.append(f"| `vs_update` at the hook case's size ({vs['example_body_literals']} "
                f"literals) | {vs['pos_update_ms']:.1f} ms (positive), "
                f"{vs['neg_update_ms']:.1f} ms (negative) | |")
    rows.append(f"| hook trial, wall time | {sh['trial_wall_s']['median']:.1f} s median, "
                f"{sh['trial_wall_s']['max']:.1f} s worst | < 2 s |")
    door = [t["phases"]["release_door_s"] for t in sw["trials"]]
    rows.append(f"| wedge trial, wall time | {sw['trial_wall_s']['median']:.1f} s median, "
                f"{sw['trial_wall_s']['max']:.1f} s worst (door phase "
                f"{statistics.mean(door):.2f} s mean) | door phase < 0.5 s |")
    rows.append(f"| bridge round trip (ping) | "
                f"{br['ping_round_trip']['median_us']:.0f} us median | |")
    rows.append(f"| `clause_lgg` of two 20-literal clauses, through the bridge | "
                f"{br['clause_lgg_20_literals_via_bridge']['median_us'] / 1000:.0f} ms "
                f"median | |")
    for size in eng["sizes"]:
        rows.append(f"| engine: `clause_lgg` / `theta_subsumes` / `clause_reduce` / "
                    f"`nbr_reduce` at {size['body_literals']} literals | "
                    f"{_engine_row(size)} ms | |")
    per = result("perception")
    for name, what in (("hook", "hook cube"), ("wedge", "wedges")):
        p = per[name]
        n = p["noisy"] if name == "hook" else p["wedges_only"]["noisy"]
        cams = len(p["cameras"])
        rows.append(f"| perception, {what} ({cams} camera{'s' if cams > 1 else ''}, "
                    f"{p['noise']['depth_sigma_m'] * 1000:g} mm depth noise) | "
                    f"{n['xy_mm_mean']:.1f} mm mean, {n['xy_mm_worst']:.1f} mm worst; yaw "
                    f"{n['yaw_deg_mean']:.2f} deg mean, {n['yaw_deg_worst']:.1f} deg worst | |")
    kinds = result("mesh")["kinds"].values()
    write = [k["write_urdf_sdf_scad_stl_ms"] for k in kinds]
    check = [k["check_ms"] for k in kinds]
    rows.append(f"| writing a tool's files (without the PNG) | {min(write):.0f}-"
                f"{max(write):.0f} ms; OpenSCAD check {min(check):.0f}-{max(check):.0f} ms "
                f"| |")
    cp = soak["checkpoints"]
    rows.append(f"| soak: {soak['trials']} trials of the {len(soak['cases'])} cases in one "
                f"process (`bench/soak_bench.py`) | RSS " + ", ".join(
                    f"{c['rss_mb']:.1f} MiB at trial {c['trial']}" for c in cp)
                + f" ({soak['rss_growth_after_first_checkpoint'] * 100:+.1f} %); trial "
                f"wall time {soak['trial_wall_s']['median']:.1f} s median, "
                f"{soak['trial_wall_s']['max']:.0f} s worst | memory flat within 10 % "
                f"after trial 10 |")
    meds = [r["median_s"] for r in bad["rows"]]
    codes = {c for r in bad["rows"] for c in r["exit_codes"]}
    rows.append(f"| refusing a bad input (`bench/bad_input_bench.py`, the {len(bad['rows'])} "
                f"rows of the corpus, {bad['repeat']} times each, the process start "
                f"included) | {statistics.median(meds):.2f} s median, "
                f"{bad['worst_s']:.1f} s worst; exit codes {sorted(codes)} | under "
                f"{bad['aim_s']:.0f} s |")
    return "\n".join(rows)


@block("engine-note")
def engine_note() -> str:
    """How large the engine's generated clauses' LGG grows (engine.json)."""
    sizes = result("engine")["sizes"]
    big = max(sizes, key=lambda x: x["body_literals"] if x["body_literals"] <= 100 else 0)
    return (f"The engine figures are for generated non-determinate clauses, whose Plotkin "
            f"LGG grows quadratically ({num(big['lgg_body_literals'])} literals from two "
            f"{big['body_literals']}-literal clauses).")


@block("mutation-table")
def mutation_table() -> str:
    """The mutation scores measured so far, and each module's first run (mutation.json)."""
    d = result("mutation")
    rows = ["| module | mutants | killed | survived | not reached | not checked | score of "
            "the checked | first run |",
            "| --- | ---: | ---: | ---: | ---: | ---: | ---: | --- |"]
    keys = ("killed", "survived", "timeout", "suspicious", "no_tests", "not_checked")
    for name, m in d["modules"].items():
        total = sum(m[k] for k in keys)
        score = f"{m['score'] * 100:.1f} %"
        if m["score_non_equivalent"] != m["score"] and m["equivalent"]:
            score += f", {m['score_non_equivalent'] * 100:.1f} % of the non-equivalent"
        first = next(h["modules"][name] for h in d["history"] if name in h["modules"])
        before = ("(this run)" if all(first.get(k) == m.get(k)
                                      for k in ("killed", "survived", "no_tests"))
                  else f"{first['score'] * 100:.1f} % ({first['killed']} killed, "
                       f"{first['survived']} survived, {first['no_tests']} not reached)")
        rows.append(f"| `{name.removeprefix('creative_py/')}` | {total} | {m['killed']} | "
                    f"{m['survived']} | {m['no_tests']} | {m.get('not_checked', 0)} | "
                    f"{score} | {before} |")
    t = d["total"]
    reached = t["killed"] + t["survived"] + t["timeout"] + t["suspicious"]
    missing = d.get("modules_not_run", [])
    return ("\n".join(rows) + f"\n\nOver the {len(d['modules'])} modules: {t['killed']} "
            f"of {reached} reached mutants killed, {t['equivalent']} survivors equivalent, "
            f"{t['no_tests']} not reached by a quick test"
            + (f", {t['not_checked']} not checked (runs stopped before the end)"
               if t.get("not_checked") else "")
            + f": {t['score_non_equivalent'] * 100:.1f} % of the checked non-equivalent "
            "mutants killed. "
            + (f"Not run yet: {', '.join(f'`{m}`' for m in missing)}." if missing
               else "Every configured module has a recorded run.")
            + "".join(f"\n\nA random sample (seed {e['seed']}) of {e['sample']} of the "
                      f"{e['of']} mutants of `{name.removeprefix('creative_py/')}`: "
                      f"{e['killed']} killed, {e['survived'] + e['no_tests']} not, "
                      f"{len(e['equivalent'])} of these equivalent: an estimated "
                      f"{e['score_non_equivalent'] * 100:.1f} % of its non-equivalent mutants "
                      f"killed (95 % interval "
                      f"{e['interval95_non_equivalent'][0] * 100:.1f}-"
                      f"{e['interval95_non_equivalent'][1] * 100:.1f} %)."
                      for name, e in sorted(d.get("samples", {}).items())))


@block("test-suite")
def test_suite() -> str:
    """How many tests ``make test`` runs and how long it took (test_time.json's latest
    run of ``bench/test_time.py``)."""
    d = result("test_time")["latest"]
    c, py = d["counts"], d["counts"]["pytest"]
    minutes = lambda x: f"{int(x // 60)} min {x % 60:02.0f} s"  # noqa: E731
    return (f"`make test` ({c['plunit_tests']} plunit and {py.get('passed', 0)} pytest tests"
            + (f", {py['skipped']} skipped" if py.get("skipped") else "")
            + f") took {minutes(d['total_wall_s'])} of wall time and {d['total_cpu_s']:.0f} s "
            f"of CPU after set-up on this {d['cpus']}-core machine (load "
            f"{d['load_average_before'][0]:.1f} at the start; pytest "
            f"{minutes(d['python']['wall_s'])} of it; `{d['label']}`).")


# --- the README -------------------------------------------------------------------------

def render(errors: list[str] | None = None) -> dict[str, str]:
    """Return every block's text, by name. A block whose result is missing or lacks a
    field raises, unless ``errors`` is given: then it is left out and a sentence naming
    the block and the cause is appended there."""
    out = {}
    for name, fn in BLOCKS.items():
        try:
            out[name] = fn().rstrip("\n")
        except (OSError, KeyError, ValueError, TypeError, StopIteration) as exc:
            if errors is None:
                raise RuntimeError(f"block {name}: {type(exc).__name__}: {exc}") from exc
            errors.append(f"block {name}: not written ({type(exc).__name__}: {exc})")
    return out


def blocks_in(text: str) -> dict[str, list[str]]:
    """Return the texts of the marked blocks of a README, by name (a list: a name may
    wrongly occur twice)."""
    found: dict[str, list[str]] = {}
    for m in BLOCK.finditer(text):
        found.setdefault(m.group(1), []).append(m.group(2))
    return found


def disagreements(text: str, rendered: dict[str, str]) -> list[str]:
    """Return one sentence per block of the README that is missing, doubled, unknown or
    differs from ``rendered``."""
    found = blocks_in(text)
    out = []
    for name, want in rendered.items():
        have = found.get(name, [])
        if not have:
            out.append(f"block {name}: missing from the README")
        elif len(have) > 1:
            out.append(f"block {name}: appears {len(have)} times")
        elif have[0] != want:
            out.append(f"block {name}: the README differs from bench/results "
                       f"(run make readme-figures)")
    out += [f"block {name}: no function writes it" for name in found if name not in BLOCKS]
    return out


def rewrite(text: str, rendered: dict[str, str]) -> str:
    """Return the README with every known block's text replaced by ``rendered``."""
    def sub(m: re.Match) -> str:
        name = m.group(1)
        body = rendered.get(name, m.group(2))
        return f"<!-- figures:{name} -->\n{body}\n<!-- /figures:{name} -->"
    return BLOCK.sub(sub, text)


def main(argv: list[str] | None = None) -> int:
    """Rewrite (or ``--check``) the README's figure blocks; return 1 on disagreement."""
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="rewrite nothing; list differences")
    ap.add_argument("--readme", type=Path, default=README)
    args = ap.parse_args(argv)
    text = args.readme.read_text(encoding="utf-8")
    errors: list[str] = []
    rendered = render(errors)
    if args.check:
        problems = errors + disagreements(text, rendered)
        for p in problems:
            print(p)
        return 1 if problems else 0
    new = rewrite(text, rendered)
    problems = errors + disagreements(new, rendered)
    if new != text:
        args.readme.write_text(new, encoding="utf-8")
    for p in problems:
        print(p, file=sys.stderr)
    print(f"{args.readme}: {len(rendered)} of {len(BLOCKS)} blocks written")
    return 1 if problems else 0


if __name__ == "__main__":
    raise SystemExit(main())
