"""The parts of the HTML page (:mod:`creative_py.report.page`) that the two recorded pages
of ``test_page_exact.py`` do not reach, exact, from small inputs built here: a clip
without a phase, a created model, a plan that is no plan, PDDL answers without a status
or plan, pieces without a name or with odd placements, print figures as a list or a
word, tools without their summary's fields, each way a creation is solved, the trial
table with a creation trial, and the numbers of the run's JSON at their thresholds
(60 s, 1 h). Every fragment is compared whole; no file beyond ``tmp_path`` is read.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Union

from creative_py.records import TrialRecord
from creative_py.records.summary import CreatedToolSummary, PddlCheck, VideoEntry
from creative_py.report.contents import Clip, RunContents, ToolEntry
from creative_py.report.page import (
    _clip_caption, _hypotheses_section, _key_value_table, _pddl_html, _pieces_table,
    _placement_text, _plan_section, _predicted_row, _print_html, _records_table,
    _tool_card, _tools_section, _trials_section, _value_html, _with_unit,
)

PIECES_HEAD = ("<table><thead><tr><th>piece</th><th>role</th><th>size</th>"
               "<th>on the bed</th><th>volume</th><th>print time</th><th>filament</th>"
               "<th>files</th></tr></thead>")


def _run(path: Path, summary: dict | None = None, trials: list | None = None,
         **kw) -> RunContents:
    return RunContents(path=path, trials=trials or [], summary=summary or {},
                       model_text=None, plot=None, clips=[], tools=[], pddl_files=[],
                       warnings=[], **kw)


def _link(name: str) -> str | None:
    """The linker of a tool folder holding ``a.gcode`` only."""
    return "tools/t/a.gcode" if name == "a.gcode" else None


def _trial(n: int, phase: str, outcome: str) -> TrialRecord:
    return TrialRecord.from_dict({
        "trial": n, "phase": phase, "phase_trial": 1, "variant": "standard",
        "location": 1, "tool": "t", "tested": [], "violated": [], "pose": {},
        "outcome": outcome})


@dataclass(kw_only=True)
class _WithNote(TrialRecord):
    """A record with one more column, as a later version might add one."""

    note: Union[str, None] = field(default=None, metadata={"column": "note"})


def test_a_clip_caption_without_info_is_its_file():
    assert _clip_caption(Clip("videos/a b.mp4", False)) == "<code>videos/a b.mp4</code>"
    bare = VideoEntry.from_dict({"file": "videos/a b.mp4"})
    assert _clip_caption(Clip("videos/a b.mp4", False, bare)) == "<code>videos/a b.mp4</code>"


def test_a_clip_caption_without_phase_or_trial_has_no_bold_head():
    info = VideoEntry.from_dict({"file": "videos/x y.mp4", "tool": "stick",
                                 "tested": ["a(b)", "c<d"], "reason": "it & slid"})
    assert _clip_caption(Clip("videos/x y.mp4", True, info)) == (
        "stick · tested <code>a(b), c&lt;d</code><br>it &amp; slid"
        ' <a href="videos/x%20y.mp4">x y.mp4</a>')


def test_the_created_tool_s_model_and_a_hypothesis_without_body(tmp_path):
    run = _run(tmp_path, {"hypotheses": {"hs": "p(a<b)"},
                          "create": {"model": ["q(x)", "r & s"]}})
    assert _hypotheses_section(run) == (
        "<h3>h<sub>s</sub>, the most specific hypothesis</h3><pre>p(a&lt;b)</pre>"
        "<h3>Model of the created tool</h3><pre>q(x)\nr &amp; s</pre>")
    empty = _run(tmp_path, {"create": {"model": []}})
    assert _hypotheses_section(empty) == '<p class="none">No hypotheses recorded.</p>'


def test_a_plan_that_is_not_a_plan_and_no_pddl_answer(tmp_path):
    run = _run(tmp_path, {"plan": "no_plan(a<b)", "pddl": {}})
    assert _plan_section(run) == "<p>Prolog's planner: <code>no_plan(a&lt;b)</code></p>"


def test_a_pddl_answer_without_status_or_plan_that_equals_prolog_s(tmp_path):
    answer = PddlCheck.from_dict({"equals_prolog": True, "prolog_plan": ["b"], "plan": []})
    assert _pddl_html(tmp_path, "use", answer) == (
        "<p><b>use</b>; ?; the same plan as Prolog's</p>")
    assert _pddl_html(tmp_path, "eval", PddlCheck(status="unsolvable")) == (
        "<p><b>eval</b>; unsolvable</p>")


def test_a_piece_without_a_name_or_print_time():
    piece = {"volume_mm3": 123456, "filament_mm": 12345}
    assert _pieces_table([piece], _link) == PIECES_HEAD + (
        '<tbody><tr><td></td><td></td><td>-</td><td>-</td><td class="num">123.5 cm³</td>'
        '<td class="num">-</td><td class="num">- (12.35 m)</td><td>-</td></tr>'
        "</tbody></table>")


def test_a_placement_needs_three_rows_of_four_numbers():
    assert _placement_text({"placement": [[1, 0, 0, 5], [0, 1, 0, 6]]}) == "-"
    assert _placement_text({"placement": [[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1]]}) == "-"
    three = [[1, 0, 0, 5], [0, 1, 0, 6], [0, 0, 1, 7]]
    assert _placement_text({"placement": three}) == "origin at (5.0, 6.0, 7.0) mm"
    assert _placement_text({"placement": [*three, [0]]}) == "origin at (5.0, 6.0, 7.0) mm"


def test_print_figures_as_a_list_a_word_or_nothing():
    assert _print_html([{"name": "p", "gcode": "a.gcode"}, "x"], _link) == PIECES_HEAD + (
        "<tbody><tr><td>p</td><td></td><td>-</td><td>-</td><td class=\"num\">-</td>"
        '<td class="num">-</td><td class="num">-</td>'
        '<td><a href="tools/t/a.gcode">gcode</a></td></tr></tbody></table>')
    assert _print_html("sliced by <hand>", _link) == "<p>sliced by &lt;hand&gt;</p>"
    assert _print_html({}, _link) == '<p class="none">No print figures.</p>'


def test_print_totals_with_and_without_the_filament_length():
    assert _print_html({"filament_g": 3}, _link) == "<p><b>3.0 g of filament</b></p>"
    assert _print_html({"filament_g": 3, "filament_mm": 100000}, _link) == (
        "<p><b>3.0 g of filament (100.0 m)</b></p>")


def test_records_and_their_files_are_linked():
    table = ("<table><thead><tr><th>log</th><th>n</th></tr></thead><tbody>"
             '<tr><td><a href="tools/t/a.gcode">a.gcode</a></td><td>2</td></tr>'
             "<tr><td>-</td><td>3</td></tr></tbody></table>")
    records = [{"log": "a.gcode", "n": 2}, {"n": 3}]
    assert _records_table(records, _link) == table
    assert _value_html("retries", records, _link) == table


def test_seconds_at_a_minute_and_an_hour():
    assert _value_html("t_s", 59) == "59 s"
    assert _value_html("t_s", 60) == "60 s (1 min)"
    assert _value_html("t_s", 3600) == "3600 s (1 h 00 min)"
    assert _value_html("t_s", 7290) == "7290 s (2 h 02 min)"
    # The label a word, the unit with the number (issue 32: the page showed keys such
    # as union_volume_error_pct).
    assert _key_value_table({"wait_s": 75}) == (
        "<table><tr><th>wait</th><td>75 s (1 min)</td></tr></table>")
    assert _with_unit("wait_s", 60) == "60 s (1 min)"
    assert _with_unit("count", 5) == 5


def test_a_tool_card_without_the_summary_s_fields(tmp_path):
    dropped = []
    created = CreatedToolSummary.from_dict({"name": "t", "replaced": "a", "dims": "big"},
                                           warn=dropped.append)
    assert dropped == ["field 'dims': 'big' is not of type dict[str, Any]; not shown"]
    bare = ToolEntry("t", "tools/t", created, None, None, [])
    assert _tool_card(tmp_path, bare) == (
        '<article class="tool" id="tool-t"><h3>t</h3>'
        "<p><code>a</code> &rarr; <code></code> &rarr; <code></code></p>"
        '<p>creation trial <span class="outcome ?">?</span></p>'
        '<p class="none">No render (tools/t/t.png).</p><div class="facts"></div>'
        "<h4>Print time and filament</h4>"
        "<p class=\"none\">Not sliced (the tool's JSON has no print figures).</p></article>")
    sized = ToolEntry("u", "tools/u",
                      CreatedToolSummary(dims={"edge_mm": [1, 2.5], "n": 2}), {}, None, [])
    card = _tool_card(tmp_path, sized)
    assert card[card.index('<div class="facts">'):card.index("<h4>Print")] == (
        '<div class="facts"><div><h4>Dimensions</h4><table>'
        "<tr><th>edge mm</th><td>1, 2.5</td></tr><tr><th>n</th><td>2</td></tr>"
        "</table></div></div>")


def test_each_way_a_creation_is_solved(tmp_path):
    def intro(create: dict) -> str:
        return _tools_section(_run(tmp_path, {"create": create}))

    none = '<p class="none">This run created no tool.</p>'
    assert intro({"needed": False, "solved_by": "learned", "catalogue": [
        {"tool": "a", "outcome": "failure"}, {"tool": "b", "outcome": "success"}]}) == (
        "<p>harder task: <b>?</b>; creation not needed (a catalogued tool succeeded); "
        "solved by the learned model&#x27;s own tool; catalogued objects considered "
        "first: a (failure), b (success).</p>" + none)
    assert intro({"variant": "v", "solved_by": "catalogue",
                  "catalogue_success": "stick"}) == (
        "<p>harder task: <b>v</b>; solved by the catalogued stick.</p>" + none)
    assert intro({"variant": "v", "solved_by": "oracle"}) == (
        "<p>harder task: <b>v</b>; solved by oracle.</p>" + none)


def test_no_literal_left_reads_as_words_and_an_older_summary_as_its_term(tmp_path):
    def intro(create: dict) -> str:
        return _tools_section(_run(tmp_path, {"create": create}))

    term = "[size_a(A,wide)-infeasible([size(c,0.25)])]"
    assert intro({"variant": "v", "exhausted": term,
                  "exhausted_words": "size_a(A, wide) cannot be sized, as size(c, 250 mm) "
                                     "cannot hold together"}).split("<p class")[0] == (
        "<p>harder task: <b>v</b>; no literal left to generalise: size_a(A, wide) cannot "
        "be sized, as size(c, 250 mm) cannot hold together.</p>")
    assert intro({"variant": "v", "exhausted": term}).split("<p class")[0] == (
        "<p>harder task: <b>v</b>; no literal left to generalise (what was tried of "
        f"each: <code>{term}</code>).</p>")


def test_a_run_without_readable_trials(tmp_path):
    assert _trials_section(_run(tmp_path)) == (
        '<p class="none">No trials.png in this run folder.</p>'
        '<p class="none">No readable trial.</p>')


def test_the_predicted_creation_trial_comes_before_the_first_creation_trial(tmp_path):
    run = _run(tmp_path, {"create": {"predicted": {"feasible": False}}},
               [_trial(1, "use", "blocked"), _trial(2, "create", "success"),
                _trial(3, "create", "failure")])
    section = _trials_section(run)
    body = section[section.index("<tbody>") + len("<tbody>"):]
    assert body.endswith("</tr></tbody></table></div>")
    assert [row[:row.index(">") + 1] for row in body.split("</tr>")[:-1]] == [
        '<tr class="trial blocked">', '<tr class="predicted">',
        '<tr class="trial success">', '<tr class="trial failure">']
    assert _predicted_row(run) in body


def test_a_predicted_row_has_an_empty_cell_for_a_column_of_its_own(tmp_path):
    record = _WithNote.from_dict({**_trial(1, "use", "failure").to_dict(), "note": "n"})
    run = _run(tmp_path, {"create": {"predicted": {"feasible": False}}}, [record])
    assert _predicted_row(run) == (
        '<tr class="predicted"><td class="col-#">-</td><td class="col-phase">create</td>'
        '<td class="col-tool">?</td><td class="col-variant"></td>'
        '<td class="col-loc"></td><td class="col-pose">-</td><td class="col-tested">-</td>'
        '<td class="col-violated">-</td>'
        '<td class="col-outcome">predicted failure, not run</td>'
        '<td class="col-reason"></td><td class="col-note"></td></tr>')


def test_the_print_figures_read_as_words_with_one_unit_a_quantity():
    # Issue 32: "Other print figures" showed the JSON's keys (union_volume_error_pct
    # -0.194792 %) and volumes in mm³ beside the cm³ of the piece table.
    page = _print_html({"nozzle_mm": 0.4, "design_volume_mm3": 51840.0,
                        "union_volume_mm3": 51739.02, "union_volume_error_pct": -0.194792,
                        "union_mismatch_pct": 0.194792, "joint": "square_dowel_pin",
                        "wall_time_s": 2.452}, _link)
    rows = re.findall(r"<tr><th>([^<]*)</th><td>([^<]*)</td></tr>", page)
    assert rows == [("nozzle diameter", "0.4 mm"),
                    ("volume of the tool as designed", "51.84 cm³"),
                    ("volume of the printed pieces put together", "51.74 cm³"),
                    ("pieces put together against the design (volume)", "-0.19 %"),
                    ("volume where the pieces and the design differ", "0.19 %"),
                    ("joint between the parts", "square dowel pin"),
                    ("time to split and slice it", "2.452 s")]
    assert "_" not in "".join(label for label, _ in rows)
