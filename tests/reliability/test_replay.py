"""Issue 19 item 2: ``--resume`` reads ``run.json`` and every line of ``trials.jsonl``
through one schema and checks the replay against the record; a refused resume writes
nothing; a resume keeps the earlier clip and timing records."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from _runs import SHORT, one_error_line, run_cli, shared_short_run, trials, tree_digest
from creative_py.learning.options import run_json_check
from creative_py.records.folder import read_resume

RUN_JSON = {"case": "rake", "options": {"phase": "use", "max_trials": 3, "eval_trials": 1},
            "world": None, "drawn_world": None}


def _line(n: int, **extra) -> str:
    record = {"trial": n, "phase": "use", "phase_trial": n, "variant": "standard",
              "location": 1, "tool": "rake_a1", "outcome": "failure", "hs": "h", "hg": "g",
              "facts": [["object_kind", "rake_a1", "rake"]]}
    record.update(extra)
    return json.dumps(record)


def _folder(tmp_path: Path, lines: list[str], meta=RUN_JSON) -> Path:
    folder = tmp_path / "run"
    (folder / "snapshots" / "use-001").mkdir(parents=True)
    (folder / "snapshots" / "use-001" / "frame.png").write_bytes(b"png")
    if isinstance(meta, dict):  # its check as run_json writes it
        meta = {**meta, "check": run_json_check(meta)}
    (folder / "run.json").write_text(meta if isinstance(meta, str) else json.dumps(meta))
    (folder / "trials.jsonl").write_text("".join(line + "\n" for line in lines))
    return folder


def _refused(folder: Path) -> str:
    """Resume ``folder``, check it is refused in one line and wrote nothing."""
    before = tree_digest(folder)
    line = one_error_line(run_cli("run", "rake", "--resume", str(folder), timeout=300))
    after = tree_digest(folder)
    after.pop(".lock", None)
    assert after == before
    return line


@pytest.mark.parametrize("bad, field", [
    ({"outcome": "exploded"}, "outcome"),
    ({"location": "one"}, "location"),
    ({"tool": 7}, "tool"),
    ({"facts": [["object_kind", "rake_a1", "rake"], 5]}, "facts"),
    ({"facts": [[]]}, "facts"),
    ({"facts": "object_kind(rake_a1, rake)"}, "facts"),
    ({"trial": 5}, "trial"),
])
def test_an_invalid_line_stops_the_resume_naming_line_and_field(tmp_path, bad, field):
    folder = _folder(tmp_path, [_line(1), _line(2, **bad), _line(3)])
    line = _refused(folder)
    assert f"trials.jsonl: line 2" in line and field in line, line


def test_a_line_that_is_not_json_before_the_last_stops_the_resume(tmp_path):
    folder = _folder(tmp_path, [_line(1), '{"trial": 2, "pha', _line(3)])
    assert "trials.jsonl: line 2 is not a JSON object" in _refused(folder)


def test_a_torn_last_line_is_dropped_only_once_the_replay_is_checked(tmp_path):
    folder = _folder(tmp_path, [_line(1), '{"trial": 2, "pha'])
    warnings = []
    records, lines = read_resume(folder, warn=warnings.append)
    assert [r.trial for r in records] == [1] and lines == [1]
    assert "line 2" in warnings[0] and "torn" in warnings[0]


@pytest.mark.parametrize("meta, field", [
    ("{not json", "not JSON"),
    ("[1, 2]", "a JSON object"),
    ({"case": "rake"}, "'options' is missing"),
    ({"options": {}}, "'case' is missing"),
    ({**RUN_JSON, "options": {"phase": "use", "speed": 3}}, "options.speed"),
    ({**RUN_JSON, "options": ["use"]}, "'options' must be an object"),
    ({**RUN_JSON, "options": {"phase": "later"}}, "'options'"),
    ({**RUN_JSON, "drawn_world": [1, 2]}, "drawn_world"),
])
def test_a_corrupt_run_json_stops_the_resume_in_one_line(tmp_path, meta, field):
    folder = _folder(tmp_path, [_line(1)], meta)
    line = _refused(folder)
    assert "run.json" in line and field in line, line


@pytest.mark.sim
def test_a_garbage_drawn_world_stops_the_resume_in_one_line(tmp_path):
    meta = {**RUN_JSON, "options": {**RUN_JSON["options"], "world_seed": 1},
            "drawn_world": {"order": 5, "objects": "x"}}
    line = _refused(_folder(tmp_path, [_line(1)], meta))
    assert "run.json: field 'drawn_world'" in line, line


@pytest.fixture(scope="module")
def finished(tmp_path_factory) -> Path:
    """A finished short rake run (with its clips): the session's, shared with
    ``test_early_kill.py`` (the tests copy it before changing it)."""
    return shared_short_run(tmp_path_factory)


def _copy(run: Path, where: Path) -> Path:
    shutil.copytree(run, where)
    (where / ".lock").unlink(missing_ok=True)
    return where


@pytest.mark.sim
def test_an_edited_outcome_is_refused_with_its_line_number(finished, tmp_path):
    run = _copy(finished, tmp_path / "edited")
    lines = (run / "trials.jsonl").read_text().splitlines()
    n, record = next((i, json.loads(line)) for i, line in enumerate(lines, 1)
                     if json.loads(line)["outcome"] == "failure")
    record["outcome"] = "success"
    lines[n - 1] = json.dumps(record)
    (run / "trials.jsonl").write_text("\n".join(lines) + "\n")
    line = _refused(run)
    assert f"trials.jsonl: line {n}: fields 'outcome' and 'hs' disagree" in line or \
        f"trials.jsonl: line {n}: fields 'outcome' and 'hg' disagree" in line, line


@pytest.mark.sim
def test_resuming_a_finished_run_keeps_its_clips_and_wall_times(finished, tmp_path):
    run = _copy(finished, tmp_path / "again")
    before = json.loads((run / "summary.json").read_text())
    text = (run / "trials.jsonl").read_bytes()
    frames = tree_digest(run / "snapshots")
    proc = run_cli("run", "rake", "--resume", str(run))
    assert proc.returncode == 0, proc.stderr[-2000:]
    after = json.loads((run / "summary.json").read_text())
    assert after["wall_time_s"] == before["wall_time_s"]
    assert after["videos"] == before["videos"]
    assert all(v["frames"] and v["duration_s"] for v in after["videos"])
    assert (run / "trials.jsonl").read_bytes() == text
    assert tree_digest(run / "snapshots") == frames


@pytest.mark.sim
def test_a_resumed_run_keeps_the_replayed_clips_entries(finished, tmp_path):
    run = _copy(finished, tmp_path / "cut")
    lines = (run / "trials.jsonl").read_text().splitlines()
    # as a run killed after its last tool-use trial leaves it: the resume replays the
    # three trials (and their clips' entries) and runs the evaluation trial (a resume
    # within a phase is test_resume_quick.py's and test_lock.py's)
    (run / "trials.jsonl").write_text("\n".join(lines[:3]) + "\n")
    (run / "summary.json").unlink()
    before = json.loads((finished / "summary.json").read_text())
    proc = run_cli("run", "rake", "--resume", str(run))
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert trials(run) == trials(finished)
    after = json.loads((run / "summary.json").read_text())
    kept = {v["file"]: v for v in before["videos"]}
    for v in after["videos"]:
        assert v["frames"] == kept[v["file"]]["frames"], v
        assert v["duration_s"] == kept[v["file"]]["duration_s"], v
    # The replayed trials' records are the recorded ones, timings included.
    assert (run / "trials.jsonl").read_text().splitlines()[:3] == lines[:3]


RESUME_WRITES = ("model.pl", "domain.pddl", "problem.pddl", ".lock")
"""What a resume writes again, the same text, before its evaluation trials replay (the
learned model and its PDDL; the lock)."""


@pytest.mark.sim
def test_an_edited_evaluation_outcome_is_refused_with_its_line_number(finished, tmp_path):
    # Issue 25: evaluation trials are not labelled (no h_s/h_g to disagree with); the
    # physics runs them again on resume and contradicts the edited record. Before the
    # fix the resume accepted it (exit 0, the summary said 0 of 1).
    run = _copy(finished, tmp_path / "edited-eval")
    lines = (run / "trials.jsonl").read_text().splitlines()
    n, record = next((i, json.loads(line)) for i, line in enumerate(lines, 1)
                     if json.loads(line)["phase"] == "eval")
    record["outcome"] = "failure" if record["outcome"] == "success" else "success"
    lines[n - 1] = json.dumps(record)
    (run / "trials.jsonl").write_text("\n".join(lines) + "\n")
    before = tree_digest(run)
    line = one_error_line(run_cli("run", "rake", "--resume", str(run), timeout=300))
    assert line.startswith(f"error: {run}/trials.jsonl: line {n}: field 'outcome' is "
                           f"{record['outcome']!r}, but the physics gives "), line
    assert line.endswith("the record was changed, the run cannot be resumed"), line
    after = tree_digest(run)
    for name in RESUME_WRITES:
        before.pop(name, None), after.pop(name, None)
    assert after == before


@pytest.mark.sim
def test_a_clip_missing_after_a_kill_is_rendered_again_on_resume(finished, tmp_path):
    # Issue 25: a clip whose process was killed with the run was listed in
    # videos/clips.jsonl, dropped from summary.json, and nothing said so. Its trial is
    # run again in the physics on resume and the clip rendered.
    run = _copy(finished, tmp_path / "lost-clip")
    before = json.loads((run / "summary.json").read_text())
    lost = before["videos"][-1]["file"]
    (run / lost).unlink()
    (run / "summary.json").unlink()
    proc = run_cli("run", "rake", "--resume", str(run))
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert (run / lost).is_file()
    after = json.loads((run / "summary.json").read_text())
    assert [v["file"] for v in after["videos"]] == [v["file"] for v in before["videos"]]
    trial = int(Path(lost).name[:3])
    assert (f"#{trial}: its clip was missing; the trial was run again and the clip "
            f"rendered ({lost})") in proc.stderr
