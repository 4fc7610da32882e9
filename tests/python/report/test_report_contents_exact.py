"""What the reports read of a run folder, exact, from a folder built here by hand.

A run folder of two trials, a summary with three video entries (one good, one outside
the folder, one with no file), a created tool with some of its files and an orphan
tool folder: :func:`read_run` must give exactly the columns, cells, clips, tools and
warnings written below, each worked out from the files (the tested and violated
literals are different, so a column that shows the one for the other fails). The
text helpers of the reports and the summary lines of the terminal report are compared
whole too.
"""

from __future__ import annotations

import json
from pathlib import Path

from creative_py.report.contents import (Clip, ToolEntry, clause_parts, literals_text,
                                         number_text, plan_steps, read_run,
                                         relative_inside, split_top_level)
from creative_py.records.summary import CreatedToolSummary, RunSummary, VideoEntry
from creative_py.report.table import strength_note, summary_lines

TRIALS = [
    {"trial": 1, "phase": "use", "phase_trial": 1, "variant": "standard", "location": 2,
     "tool": "hook_a1", "kind": "experiment", "tested": ["hook_length(hook_a1,short)"],
     "violated": ["handle_length(hook_a1,medium)", "behind(hook_a1,cube1)"],
     "pose": {"dx": 0.0312345678, "dy": 0.0, "roll": -1}, "outcome": "blocked",
     "reason": "the arm hit the tube"},
    {"trial": 2, "phase": "eval", "phase_trial": 1, "variant": "long_tube", "location": 1,
     "tool": "hook_new", "kind": "exploit", "tested": [], "violated": [], "pose": {},
     "outcome": "success"},
]

CREATED = {"name": "hook_new", "replaced": "hook_a2", "instance": "hook_new",
           "dims": {"handle_length": 0.4}, "trial_outcome": "success",
           "strength": {"verdict": "pass", "stress_mpa": 13.84, "safety_factor": 3.6149}}


def _folder(root: Path) -> Path:
    run = root / "run"
    (run / "videos").mkdir(parents=True)
    (run / "trials.jsonl").write_text("".join(json.dumps(t) + "\n" for t in TRIALS))
    (run / "summary.json").write_text(json.dumps({
        "hypotheses": {"hs": "h :- a, b", "hg": "h :- a"},
        "plan": "plan([pick_up(t), pull(t)])",
        "pddl": {"use": {"status": "valid", "plan": ["pick_up t", "pull t"]},
                 "create": "not a table"},
        "create": {"created_tools": [CREATED]},
        "videos": [{"file": "videos/use-1.mp4", "phase": "use", "trial": 1,
                    "tool": "hook_a1", "outcome": "blocked", "why": "first failure"},
                   {"file": "../elsewhere.mp4"}, {"phase": "use"}]}))
    (run / "videos" / "use-1.mp4").write_bytes(b"mp4")
    (run / "model.pl").write_text("model.\n")
    (run / "trials.png").write_bytes(b"png")
    (run / "domain.pddl").write_text("(define)")
    tool = run / "tools" / "hook_new"
    tool.mkdir(parents=True)
    (tool / "hook_new.json").write_text(json.dumps({
        "files": {"urdf": "hook_new.urdf", "stl": ["a.stl", "missing.stl"],
                  "escape": "../../../x.txt"},
        "print": {"grams": 12, "layers": [1, 2]}}))
    for name in ("hook_new.urdf", "a.stl", "hook_new.png"):
        (tool / name).write_text("x")
    (run / "tools" / "orphan").mkdir()
    return run


def test_read_run_exact(tmp_path):
    run = _folder(tmp_path)
    c = read_run(run)
    assert c.path == run
    assert [t.trial for t in c.trials] == [1, 2]
    assert c.model_text == "model.\n"
    assert c.plot == "trials.png"
    assert c.pddl_files == ["domain.pddl"]
    assert c.clips == [Clip("videos/use-1.mp4", True, VideoEntry.from_dict(
        {"file": "videos/use-1.mp4", "phase": "use", "trial": 1, "tool": "hook_a1",
         "outcome": "blocked", "why": "first failure"}))]
    summary = run / "summary.json"
    assert c.warnings == [
        f"{summary}: field 'pddl.create': 'not a table' is not a JSON object; not shown",
        f"{summary}: field 'videos[2].file' is missing; not shown",
        f"{summary}: video ../elsewhere.mp4 is outside the run folder; not shown",
    ]
    manifest = json.loads((run / "tools" / "hook_new" / "hook_new.json").read_text())
    assert c.tools == [
        ToolEntry("hook_new", "tools/hook_new", CreatedToolSummary.from_dict(CREATED), manifest,
                  "tools/hook_new/hook_new.png",
                  [("urdf", "tools/hook_new/hook_new.urdf"), ("stl", "tools/hook_new/a.stl"),
                   ("json", "tools/hook_new/hook_new.json")]),
        ToolEntry("orphan", "tools/orphan", None, None, None, []),
    ]


def test_every_column_and_cell_exact(tmp_path):
    c = read_run(_folder(tmp_path))
    # One trial number: the run's (#); no phase count column (issue 25).
    assert [h for h, _ in c.columns] == ["#", "phase", "tool", "variant", "loc", "pose",
                                         "tested", "violated", "outcome", "reason"]
    rows = [[cell(t) for _, cell in c.columns] for t in c.trials]
    assert rows == [
        ["1", "use", "hook_a1", "standard", "2", "dx 0.0312346, dy 0, roll -1",
         "hook_length(hook_a1,short)", "handle_length(hook_a1,medium), behind(hook_a1,cube1)",
         "blocked", "the arm hit the tube"],
        ["2", "eval", "hook_new", "long_tube", "1", "-", "-", "-", "success", "-"],
    ]


def test_clips_without_a_summary_are_the_videos_folder_s(tmp_path):
    run = _folder(tmp_path)
    (run / "summary.json").unlink()
    (run / "videos" / "eval-2.mp4").write_bytes(b"mp4")
    c = read_run(run)
    assert c.summary == RunSummary() and c.warnings == []
    assert c.clips == [Clip("videos/eval-2.mp4", True), Clip("videos/use-1.mp4", True)]
    assert [t.name for t in c.tools] == ["hook_new", "orphan"]
    assert c.tools[0].created is None


def test_a_summary_that_is_not_an_object_or_not_json(tmp_path):
    run = _folder(tmp_path)
    (run / "summary.json").write_text("[1, 2]")
    c = read_run(run)
    assert c.summary == RunSummary()
    assert c.warnings == [f"{run / 'summary.json'}: not a JSON object, but list; no summary "
                          f"shown"]
    (run / "summary.json").write_text("{\n oops")
    c = read_run(run)
    assert c.summary == RunSummary()
    assert c.warnings == [f"{run / 'summary.json'}: not JSON (Expecting property name "
                          f"enclosed in double quotes, line 2); no summary shown"]


def test_a_missing_clip_is_listed_as_missing(tmp_path):
    run = _folder(tmp_path)
    (run / "videos" / "use-1.mp4").unlink()
    assert read_run(run).clips[0].exists is False


def test_summary_lines_exact(tmp_path):
    c = read_run(_folder(tmp_path))
    assert summary_lines(c) == [
        "hs: h :- a, b",
        "hg: h :- a",
        "plan: plan([pick_up(t), pull(t)])",
        "pddl use: valid pick_up t, pull t",
        "created hook_new: hook_a2 -> hook_new; handle_length 400.0 mm (success; strength "
        "pass, 13.8 MPa, safety factor 3.61)",
        "print hook_new: 0 pieces",  # this print record names no pieces
        "video videos/use-1.mp4: use 1 hook_a1 blocked (kept as first failure)",
    ]


def test_summary_lines_of_a_run_with_no_summary(tmp_path):
    (tmp_path / "trials.jsonl").write_text(json.dumps(TRIALS[0]) + "\n")
    assert summary_lines(read_run(tmp_path)) == ["hs: ?", "hg: ?"]


def test_strength_note_exact():
    assert strength_note(None) == ""
    assert strength_note({}) == ""
    assert strength_note({"verdict": "fail", "stress_mpa": 41.25, "safety_factor": None,
                          "thickened_into": "hook_new_2", "reason": "too thin",
                          "caveat": "one load case"}) == (
        "; strength fail, 41.2 MPa, safety factor -, thickened into hook_new_2: too thin "
        "(one load case)")
    assert strength_note({"verdict": "pass"}) == "; strength pass, 0.0 MPa, safety factor -"


def test_text_helpers_exact(tmp_path):
    assert number_text(True) == "yes" and number_text(False) == "no"
    assert number_text(0.123456789) == "0.123457"
    assert number_text(3) == "3" and number_text("x") == "x"
    assert literals_text(["a(x)", "b"]) == "a(x), b"
    assert literals_text([]) == "-" and literals_text(None) == "-"
    assert literals_text("") == "-" and literals_text("c") == "c"
    assert split_top_level("f(a, b), g([1, 2]), 'x, y', \"p,q\", h") == [
        "f(a, b)", "g([1, 2])", "'x, y'", '"p,q"', "h"]
    assert split_top_level("a;b ; c", ";") == ["a", "b", "c"]
    assert split_top_level("") == []
    assert plan_steps("plan([pick_up(t), pull(t, c)])") == ["pick_up(t)", "pull(t, c)"]
    assert plan_steps(" plan([]) ") == []
    assert plan_steps("no_plan(no_tool)") is None
    assert clause_parts("h(X) :- a(X), b(X, [1, 2])") == ("h(X)", ["a(X)", "b(X, [1, 2])"])
    assert clause_parts("h(X)") == ("h(X)", [])
    assert relative_inside(tmp_path, "a/b.txt") == "a/b.txt"
    assert relative_inside(tmp_path, str(tmp_path / "c")) == "c"
    assert relative_inside(tmp_path, "../d") is None


def test_odd_entries_are_skipped_with_a_warning_and_the_rest_kept(tmp_path):
    run = _folder(tmp_path)
    summary = json.loads((run / "summary.json").read_text())
    # Bad video entries first: the good one after them is still shown.
    summary["videos"] = ["videos/use-1.mp4", {"file": 7}] + summary["videos"][:1]
    summary["create"]["created_tools"] = [{"dims": 1}, "hook_x", CREATED]
    (run / "summary.json").write_text(json.dumps(summary))
    with (run / "trials.jsonl").open("a") as fh:
        fh.write('{"trial": 3, "pha\n')
    (run / "model.pl").write_bytes(b"model(\xff).\n")
    (run / "trials.png").unlink()
    (run / "problem.pddl").write_text("(define)")
    odd = run / "tools" / "odd"
    odd.mkdir()
    (odd / "odd.json").write_text(json.dumps({"files": ["odd.stl"]}))
    broken = run / "tools" / "broken"
    broken.mkdir()
    (broken / "broken.json").write_text("{")
    numbered = run / "tools" / "numbered"
    numbered.mkdir()
    (numbered / "numbered.json").write_text(json.dumps({"files": {"stl": [3, "n.stl"]}}))
    for name in ("3", "n.stl"):
        (numbered / name).write_text("x")
    c = read_run(run)
    assert [t.trial for t in c.trials] == [1, 2]
    assert c.model_text == "model(\ufffd).\n"
    assert c.plot is None
    assert c.pddl_files == ["domain.pddl", "problem.pddl"]
    assert [clip.file for clip in c.clips] == ["videos/use-1.mp4"]
    s = run / "summary.json"
    assert c.warnings == [
        f"{run / 'trials.jsonl'}: line 3 is not a JSON object (Unterminated string "
        f"starting at); skipped",
        f"{s}: field 'pddl.create': 'not a table' is not a JSON object; not shown",
        f"{s}: field 'create.created_tools[0].dims': 1 is not of type dict[str, "
        f"Any]; not shown",
        f"{s}: field 'create.created_tools[1]': 'hook_x' is not a JSON object; not shown",
        f"{s}: field 'videos[0]': 'videos/use-1.mp4' is not a JSON object; not shown",
        f"{s}: field 'videos[1].file': 7 is not of type str; not shown",
        f"{broken / 'broken.json'}: not JSON (Expecting property name enclosed in double "
        f"quotes, line 1); not shown",
    ]
    assert [t.name for t in c.tools] == ["hook_new", "broken", "numbered", "odd", "orphan"]
    by_name = {t.name: t for t in c.tools}
    assert by_name["broken"].manifest is None and by_name["broken"].files == []
    assert by_name["odd"].files == [("json", "tools/odd/odd.json")]
    assert by_name["numbered"].files == [("stl", "tools/numbered/n.stl"),
                                         ("json", "tools/numbered/numbered.json")]


def test_a_creation_summary_without_created_tools(tmp_path):
    run = _folder(tmp_path)
    (run / "summary.json").write_text(json.dumps({"create": {"trials": 1}}))
    assert [(t.name, t.created) for t in read_run(run).tools] == [("hook_new", None),
                                                                  ("orphan", None)]


def test_plan_steps_needs_the_whole_plan_term():
    assert plan_steps("no_plan([a])") is None
    assert plan_steps("plan([a]) extra") is None
