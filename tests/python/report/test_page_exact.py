"""The HTML page of a run (:func:`creative_py.report.page.render_html`), exact, against
pages recorded in ``tests/fixtures/report/`` (the run folder's path written ``{RUN}``).

Two hand-built folders: a full one (``test_report_contents_exact.py``'s folder, with a
summary that has every part the page shows: headline figures, a predicted creation
trial, clips kept and missing, a created tool with its print pieces, placements, joints
and other figures, the hypotheses, Prolog's plan and PDDL answers that agree and that do
not) and a bare one (trials only, as a run still going). A change of the page shows as
a failing test here: read the new page, then record it again by hand, e.g.
``render_html(read_run(folder)).replace(str(folder), "{RUN}")`` with the style sheet
written ``{CSS}``: the recorded pages hold every byte the page's code writes, and the
CSS, a constant, stays in ``page.py`` alone.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_report_contents_exact import CREATED, TRIALS, _folder  # noqa: E402

from creative_py.records.folder import RunFolder  # noqa: E402
from creative_py.report.contents import read_run  # noqa: E402
from creative_py.report.page import _CSS, render_html, write_html_report  # noqa: E402

FIXTURES = Path(__file__).resolve().parents[2] / "fixtures" / "report"

PRINT = {
    "print_time_s": 5400, "filament_g": 12.34, "filament_mm": 4120,
    "build_volume_mm": [250, 210, 210.5], "profile": "PLA 0.2 mm",
    "how_they_join": "two pieces joined by a square pin",
    "pieces": [
        {"name": "handle", "role": "shaft", "bounding_box_mm": [120.04, 20, 10.55],
         "up_axis": "z", "yaw_deg": 90,
         "placement": [[1, 0, 0, 12.34], [0, 1, 0, -5], [0, 0, 1, 0], [0, 0, 0, 1]],
         "volume_mm3": 12345, "print_time_s": 3725, "filament_g": 8.25,
         "filament_mm": 2750, "stl": "handle.stl", "gcode": "handle.gcode"},
        {"name": "prong", "placement": [[1, 0], [0, 1]], "stl": "missing.stl"},
        "not a piece"],
    "joints": [{"pin": "pin1", "joins": ["handle", "prong"], "cut_mm": 60, "axis": "x",
                "pin_section_mm": 6, "pin_length_mm": 20, "hole_section_mm": 6.2,
                "hole_depth_mm": 10.5}, {}],
    "layer_height_mm": 0.2, "mass_g": 12.3, "support": False, "slicer_s": 75,
    "bed_mm": [250, 210], "note": "first try", "tiny_s": 5, "slicer_total_s": 7250,
    "retries": [{"piece": "handle", "slicer_s": 61}, {"piece": "prong", "ok": True}],
    "settings": {"nozzle_mm": 0.4, "log": "handle.gcode", "none": None},
    "layers": [1, 2.5], "empty": [], "missing": None,
}

MANIFEST = {
    "spec": {"handle_length": 0.4, "hook_angle_deg": 90, "side": "left", "pieces": 2},
    "mass_kg": 0.0123, "mesh_volume_m3": 1.1e-05, "spec_volume_m3": 1.2e-05,
    "printability": {"extent": [0.4, 0.02, "x", 0.06], "printable": True,
                     "overhang_deg": 45},
}
"""The created tool's JSON beyond its files and print figures."""

SUMMARY = {
    "case": "hook", "seed": 3, "phase": "all", "options": {"strategy": "paper"},
    # the case's facts a run writes for the reports (learning/run.py)
    "pose_units": {"dx": "m", "dy": "m", "roll": "rad"}, "trial_budget": 12,
    "paper_trials": 12,
    "demonstration": {"tool": "hook_a2"},
    "use": {"trials": 1, "stop": "budget", "strategy": "paper"},
    "eval": {"trials": 1, "successes": 1},
    "hypotheses": {"hs": "tool_pose(T, P, L) :- handle_length(T, long), hook_length(T, short)",
                   "hg": "tool_pose(T, P, L) :- handle_length(T, long)"},
    "plan": "plan([pick_up(hook_new), pull(hook_new, cube1)])",
    "pddl": {
        "use": {"status": "valid", "planner": "pyperplan", "variant": "standard",
                "domain": "domain.pddl", "problem": "/elsewhere/problem.pddl",
                "equals_prolog": True, "prolog_plan_valid": True,
                "plan": ["pick_up hook_new", "pull hook_new cube1"]},
        "create": {"status": "solved", "equals_prolog": False, "prolog_plan_valid": False,
                   "plan": ["a"], "prolog_plan": ["b", "c"]},
        "eval": "not run",
    },
    "create": {"variant": "long_tube", "needed": True, "solved_by": "created",
               "success": "hook_new", "trials": 1, "exhausted": "no more shapes",
               "catalogue": [{"tool": "stick", "outcome": "failure"}],
               "predicted": {"feasible": False, "tool": "hook_a2", "variant": "long_tube",
                             "location": 2, "conflict": ["behind(hook_a2,cube1)"],
                             "why": "dx_reach = -0.011 m"},
               "created_tools": [{**CREATED, "general": "hook(H, long)",
                                  "eval_outcomes": ["success", "failure"],
                                  "print": PRINT, "mass_kg": 0.0123}]},
    "wall_time_s": {"total": 83.5, "use": 40},
    "videos": [{"file": "videos/use-1.mp4", "phase": "use", "trial": 1, "tool": "hook_a1",
                "outcome": "blocked", "why": "first failure"},
               {"file": "videos/gone.mp4", "phase": "eval", "trial": 2}],
}


def _full(root: Path) -> Path:
    run = _folder(root)
    (run / "summary.json").write_text(json.dumps(SUMMARY))
    (run / "problem.pddl").write_text("(define)")
    tool = run / "tools" / "hook_new"
    manifest = json.loads((tool / "hook_new.json").read_text())
    manifest.update(MANIFEST, print=PRINT)
    (tool / "hook_new.json").write_text(json.dumps(manifest))
    for name in ("handle.stl", "handle.gcode"):
        (tool / name).write_text("x")
    return run


def _expected(name: str, run: Path) -> str:
    page = (FIXTURES / name).read_text(encoding="utf-8")
    return page.replace("{CSS}", _CSS).replace("{RUN}", str(run))


def test_the_page_of_a_full_run_exact(tmp_path):
    run = _full(tmp_path)
    assert render_html(read_run(run)) == _expected("page_full.html", run)


def test_the_page_of_a_run_still_going_exact(tmp_path):
    run = tmp_path / "going"
    run.mkdir()
    # a line that is no trial record, and the last line torn, as a run killed while
    # writing it leaves it: each a warning on the page
    (run / "trials.jsonl").write_text("".join(json.dumps(t) + "\n" for t in TRIALS)
                                      + '{"trial": 3}\n{"trial": 4, "pha')
    folder = RunFolder(run)
    folder.lock()  # the run writing it holds its lock
    try:
        path = write_html_report(run)
    finally:
        folder.release()
    assert path == run / "report.html"
    assert path.read_text(encoding="utf-8") == _expected("page_going.html", run).replace(
        "{PID}", str(os.getpid()))
    assert sorted(p.name for p in run.iterdir()) == [".lock", "report.html", "trials.jsonl"]


def test_the_page_of_an_interrupted_run_says_how_to_go_on(tmp_path):
    # Issue 32: the page said "has not finished (or was interrupted)" of both a live
    # run and an interrupted one; a live one is "still running" (see the test above).
    run = tmp_path / "gone"
    run.mkdir()
    (run / "trials.jsonl").write_text("".join(json.dumps(t) + "\n" for t in TRIALS))
    (run / "run.json").write_text(json.dumps({"case": "hook"}))
    (run / ".lock").write_text("12345\n")  # the pid of a process long gone
    page = render_html(read_run(run))
    assert ('<div class="warn">Interrupted after 2 trials (no summary.json, and no '
            f"process is running it); to go on: creative run hook --resume {run}.</div>"
            ) in page
    assert "Still running" not in page
