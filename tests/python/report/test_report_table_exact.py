"""The terminal report (:mod:`creative_py.report.table`) of a hand-built run folder,
exact: the wide layout (one table), the narrow one (a block per trial, folded), the
width it picks, each outcome's colour and the text of print figures, dimensions and
JSON values. The folder is ``test_report_contents_exact.py``'s, whose cells are worked
out there from the files.
"""

from __future__ import annotations

import io
import json
import sys
from pathlib import Path

from rich.console import Console
from rich.table import Table

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_report_contents_exact import TRIALS, _folder  # noqa: E402

from creative_py.report.contents import read_run  # noqa: E402
from creative_py.report.table import (_plain, dims_text, natural_width,  # noqa: E402
                                      print_report, print_text, report_width,
                                      trial_blocks, trial_table)

SUMMARY = [
    "hs: h :- a, b",
    "hg: h :- a",
    "plan: plan([pick_up(t), pull(t)])",
    "pddl use: valid pick_up t, pull t",
]
HEADLINE = "Tool creation on the harder task ?: not solved."

WIDE = """\
┏━━━┳━━━━━━━┳━━━━━━━━━━┳━━━━━━━━━━━┳━━━━━┳━━━━━━━━━━━━━━━━━━━━━━━━━━━━━┳━━━━━━━━━━━━━━━━━━━━━━━━━━━━┳━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━┳━━━━━━━━━┳━━━━━━━━━━━━━━━━━━━━━━┓
┃ # ┃ phase ┃ tool     ┃ variant   ┃ loc ┃ pose                        ┃ tested                     ┃ violated                                             ┃ outcome ┃ reason               ┃
┡━━━╇━━━━━━━╇━━━━━━━━━━╇━━━━━━━━━━━╇━━━━━╇━━━━━━━━━━━━━━━━━━━━━━━━━━━━━╇━━━━━━━━━━━━━━━━━━━━━━━━━━━━╇━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━━╇━━━━━━━━━╇━━━━━━━━━━━━━━━━━━━━━━┩
│ 1 │ use   │ hook_a1  │ standard  │   2 │ dx 0.0312346, dy 0, roll -1 │ hook_length(hook_a1,short) │ handle_length(hook_a1,medium), behind(hook_a1,cube1) │ blocked │ the arm hit the tube │
│ 2 │ eval  │ hook_new │ long_tube │   1 │ -                           │ -                          │ -                                                    │ success │ -                    │
└───┴───────┴──────────┴───────────┴─────┴─────────────────────────────┴────────────────────────────┴──────────────────────────────────────────────────────┴─────────┴──────────────────────┘"""
"""The table of the two trials, 189 columns wide: every cell whole, # and loc on the
right."""


def _printed(run, width: int | None) -> list[str]:
    out = io.StringIO()
    print_report(read_run(run), Console(file=out, force_terminal=False, color_system=None),
                 width=width)
    return [line.rstrip() for line in out.getvalue().splitlines()]


def test_the_wide_report_is_the_headline_the_table_and_the_summary(tmp_path):
    run = _folder(tmp_path)
    created = ("created hook_new: hook_a2 -> hook_new; handle_length 400.0 mm (success; "
               "strength pass, 13.8 MPa, safety factor 3.61)")
    rest = [created, "print hook_new: 0 pieces",
            "video videos/use-1.mp4: use 1 hook_a1 blocked (kept as first failure)"]
    expected = [HEADLINE, "", str(run), *WIDE.splitlines(), *SUMMARY, *rest]
    assert _printed(run, 200) == expected
    # Into a file, the width is the table's own (189 columns): the same lines.
    assert _printed(run, None) == expected


def test_an_80_column_report_prints_a_block_per_trial(tmp_path):
    run = _folder(tmp_path)
    assert _printed(run, 80) == [
        HEADLINE, "", str(run),
        "  1  use  hook_a1  standard  loc 2  blocked",
        "     pose     dx 0.0312346, dy 0, roll -1",
        "     tested   hook_length(hook_a1,short)",
        "     violated handle_length(hook_a1,medium), behind(hook_a1,cube1)",
        "     reason   the arm hit the tube",
        "  2  eval  hook_new  long_tube  loc 1  success",
        "     pose     -",
        "     tested   -",
        "     violated -",
        "     reason   -",
        *SUMMARY,
        "created hook_new: hook_a2 -> hook_new; handle_length 400.0 mm (success; strength",
        "pass, 13.8 MPa, safety factor 3.61)",
        "print hook_new: 0 pieces",
        "video videos/use-1.mp4: use 1 hook_a1 blocked (kept as first failure)",
    ]


def test_a_40_column_report_folds_every_long_cell(tmp_path):
    run = _folder(tmp_path)
    assert _printed(run, 40) == [
        "Tool creation on the harder task ?: not", "solved.", "", str(run),
        "  1  use  hook_a1  standard  loc 2", "blocked",
        "     pose     dx 0.0312346, dy 0, roll",
        "              -1",
        "     tested   hook_length(hook_a1,short)",
        "     violated handle_length(hook_a1,medi",
        "              um), behind(hook_a1,cube1)",
        "     reason   the arm hit the tube",
        "  2  eval  hook_new  long_tube  loc 1", "success",
        "     pose     -", "     tested   -", "     violated -", "     reason   -",
        *SUMMARY,
        "created hook_new: hook_a2 -> hook_new;", "handle_length 400.0 mm (success;",
        "strength pass, 13.8 MPa, safety factor", "3.61)",
        "print hook_new: 0 pieces",
        "video videos/use-1.mp4: use 1 hook_a1", "blocked (kept as first failure)",
    ]


def test_each_outcome_has_its_colour_in_the_narrow_layout(tmp_path):
    run = _folder(tmp_path)
    outcomes = ["success", "failure", "blocked", "unreachable", "invalid"]
    (run / "trials.jsonl").write_text("".join(
        json.dumps({**TRIALS[1], "trial": i, "outcome": o}) + "\n"
        for i, o in enumerate(outcomes, 1)))
    heads = trial_blocks(read_run(run)).renderables[::2]
    assert [h.plain for h in heads] == [
        f"{i:>3}  eval  hook_new  long_tube  loc 1  {o}" for i, o in enumerate(outcomes, 1)]
    assert [[(s.start, s.end, s.style) for s in h.spans] for h in heads] == [
        [(39, 46, "bold green")], [(39, 46, "bold red")], [(39, 46, "bold yellow")],
        [(39, 50, "bold")], [(39, 46, "bold magenta")]]


def test_the_width_is_the_one_asked_else_the_terminal_s_else_the_table_s(tmp_path):
    run = read_run(_folder(tmp_path))
    table = trial_table(run)
    assert table.title == str(run.path) and table.title_justify == "left"
    assert [(c.header, c.justify, c.overflow) for c in table.columns] == [
        (h, "right" if h in ("#", "loc") else "left", "fold")
        for h in ["#", "phase", "tool", "variant", "loc", "pose", "tested",
                  "violated", "outcome", "reason"]]
    assert natural_width(table) == 189
    pipe = Console(file=io.StringIO(), force_terminal=False, width=120)
    assert report_width(pipe, table, 57) == 57
    assert report_width(pipe, table, None) == 189
    terminal = Console(file=io.StringIO(), force_terminal=True, width=123)
    assert report_width(terminal, table, None) == 123
    small = Table("a")  # a table narrower than 80 columns is printed at 80
    small.add_row("b" * 70)
    assert natural_width(small) == 74
    assert report_width(pipe, small, None) == 80
    small.add_row("c" * 90)
    assert report_width(pipe, small, None) == 94


def test_print_figures_dimensions_and_json_values_exact():
    assert print_text({
        "pieces": [{"name": "handle", "bounding_box_mm": [120.4, 20, 10.6],
                    "print_time_s": 3725, "filament_g": 12.345},
                   {"name": "hook"},
                   {"bounding_box_mm": "x", "print_time_s": "n", "filament_g": None},
                   "not a piece"],
        "print_time_s": 4000.0, "filament_g": 20.04}) == (
        "3 pieces; 1 h 07 min; 20.0 g of filament; handle 120 x 20 x 11 mm 1 h 02 min "
        "12.3 g; hook ?; ? ?")
    assert print_text({"pieces": [{"name": "one", "print_time_s": 42, "filament_g": 1}],
                       "print_time_s": "x", "filament_g": "y"}) == "1 piece; one ? 42 s 1.0 g"
    assert print_text({}) == "0 pieces" and print_text({"pieces": None}) == "0 pieces"
    assert dims_text({"handle_length": 0.4, "hook_angle_deg": 90, "side": "left"}) == (
        "handle_length 400.0 mm, hook_angle_deg 90, side left")
    assert dims_text([1, 2]) == "[1, 2]" and dims_text(None) == "None"
    assert _plain({"a": [1, "b"], "c": {"d": 2}}) == "a=1, b, c=d=2"
    assert _plain([{"x": 1}, {"y": [2]}]) == "[x=1]; [y=2]"
    assert _plain(["p", "q"]) == "p, q" and _plain([]) == "" and _plain(3.5) == "3.5"


def test_text_is_printed_as_written_and_the_path_in_italics(tmp_path):
    """No Rich markup or highlighting in the headline and summary lines (a plan may hold
    brackets, a figure is not coloured); the narrow layout's path line is italic."""
    run = _folder(tmp_path)
    summary = json.loads((run / "summary.json").read_text())
    summary.update({"plan": "[bold]p[/bold] 42", "wall_time_s": {"total": 5},
                    "demonstration": {"tool": "[bold]t[/bold]"},
                    "pddl": {"use": {"plan": []}, "create": {"status": "none"}},
                    "videos": [{"file": "videos/gone.mp4"},
                               {"file": "videos/use-1.mp4", "why": "x"}]})
    (run / "summary.json").write_text(json.dumps(summary))
    (run / "trials.jsonl").write_text(json.dumps(TRIALS[1]) + "\n")
    out = io.StringIO()
    print_report(read_run(run), Console(file=out, force_terminal=True,
                                        color_system="standard"), width=60)
    lines = out.getvalue().splitlines()
    assert lines[:5] == ["One demonstration, with [bold]t[/bold].", HEADLINE,
                         "Wall time 5 s.", "", f"\x1b[3m{run}\x1b[0m"]
    assert lines[-10:-1] == [
        "hs: h :- a, b", "hg: h :- a", "plan: [bold]p[/bold] 42", "pddl use: ?",
        "pddl create: none",
        "created hook_new: hook_a2 -> hook_new; handle_length 400.0 ",
        "mm (success; strength pass, 13.8 MPa, safety factor 3.61)",
        "print hook_new: 0 pieces", "video videos/gone.mp4 (missing)"]
    assert lines[-1] == "video videos/use-1.mp4:  (kept as x)"


def test_a_block_s_labels_never_wrap_and_its_values_fold(tmp_path):
    grid = trial_blocks(read_run(_folder(tmp_path))).renderables[1]
    assert [(c.no_wrap, c.overflow) for c in grid.columns] == [(True, "ellipsis"),
                                                               (False, "fold")]
    assert grid.padding == (0, 1, 0, 1)
