"""Which trials become clips (``--video all|key|none``) and the options that choose it."""

import json
import os
import time
from pathlib import Path

import imageio.v2 as imageio
import numpy as np
import pybullet as pb
import pytest
from typer.testing import CliRunner

from creative_py.cli import app
from creative_py.learning.clips import CLIP_NICE, ClipKeeper, failure_reason
from creative_py.learning.options import RunOptions
from creative_py.records.trial import TrialRecord
from creative_py.backends.pybullet import recorder
from creative_py.backends.pybullet.recorder import Recorder
from creative_py.video import Captioner
from creative_py.world.cameras import VideoSpec

BLOCKED = "position_tool: gripper lagged its target by {} cm at (0.978, -0.250, -0.052) m"

# phase, outcome, reason of a run's trials, in order (a hook run's shape).
RUN = [("demo", "success", "goal reached"),
       ("use", "blocked", BLOCKED.format(3.1)),
       ("use", "failure", "goal not reached"),
       ("use", "failure", "goal not reached"),
       ("use", "success", "goal reached"),
       ("use", "blocked", BLOCKED.format(3.4)),
       ("use", "unreachable", "the camera does not see cube1"),
       ("eval", "success", "goal reached"),
       ("create", "blocked", BLOCKED.format(2.9)),
       ("create", "success", "goal reached")]


def _whys(mode):
    keeper = ClipKeeper(mode, "/nonexistent", spec=object(), new_recorder=lambda spec: None)
    return [keeper.why(*t) for t in RUN]


def test_key_keeps_the_demonstration_first_success_creation_and_first_of_each_failure():
    assert _whys("key") == [
        "demonstration",
        "failure:blocked: position_tool: gripper lagged its target by N cm at (N, N, N) m",
        "failure:failure: goal not reached",
        None,
        "first_success",
        None,                      # the same reason as trial 1, other numbers
        "failure:unreachable: the camera does not see cube1",
        None,
        "creation",
        "creation"]


def test_all_keeps_every_trial_and_none_none():
    whys = _whys("all")
    assert None not in whys and whys[3] == whys[5] == whys[7] == "trial"
    assert _whys("none") == [None] * len(RUN)
    assert ClipKeeper("none", "/nonexistent", spec=object()).recorder() is None


def test_a_world_without_a_camera_records_nothing():
    assert ClipKeeper("all", "/nonexistent", spec=None).why("use", "failure", "x") is None


def test_failure_reasons_ignore_numbers_only():
    assert failure_reason("blocked", "lag 3.1 cm") == failure_reason("blocked", "lag -2 cm")
    assert failure_reason("blocked", "lag 3.1 cm") != failure_reason("failure", "lag 3.1 cm")
    assert failure_reason("failure", "") == "failure"
    assert failure_reason("unreachable", "cube1 at 0.5 m") == "unreachable: cube1 at N m"


@pytest.mark.parametrize("kw, message", [
    ({"video": "some"}, "option video must be one of all, key, none, got 'some'"),
    ({"video": None}, "option video must be one of"),
    ({"gui": "yes"}, "option gui must be true or false"),
])
def test_run_options_check_video_and_gui(kw, message):
    with pytest.raises(ValueError, match=message):
        RunOptions(**kw)
    with pytest.raises(ValueError, match="option video"):
        ClipKeeper("loud", "/nonexistent", spec=object())


runner = CliRunner()


def test_video_option_errors_in_one_line():
    res = runner.invoke(app, ["run", "hook", "--video", "most"])
    assert res.exit_code == 2
    assert res.output.strip() == "error: --video must be all, key or none, got 'most'"


@pytest.mark.parametrize("args", [["run", "hook", "--gui"],
                                  ["trial", "hook", "--tool", "hook_a2", "--gui"]])
def test_gui_without_a_display_is_one_line_and_exit_2(args, monkeypatch):
    monkeypatch.delenv("DISPLAY", raising=False)
    res = runner.invoke(app, args)
    assert res.exit_code == 2
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --gui: no display"), res.output
    assert "Traceback" not in res.output


# ---------------------------------------------------------------- writing clips
# A real recorder (the pybullet backend's, what ``new_recorder`` gives a run) films a
# box falling in a scene of its own for 0.2 s of simulated time: three snapshots (the
# first, one 1/fps later, the last), rendered and encoded as a run's clips are (7 frames
# a second: 3 frames last 0.428571 s, rounded to 0.43 in the entry). The
# picture is 320 x 48 pixels: the captions are a run's, the rendering is cheap.

SPEC = VideoSpec.from_table({"eye": [1.0, -1.0, 0.8], "target": [0.0, 0.0, 0.1],
                             "fov_deg": 50.0, "width": 320, "height": 48, "fps": 7.0},
                            "test")


@pytest.fixture
def film():
    """Return ``film(recorder)``: the recorder attached to a new scene in which a box falls
    for 0.2 s (48 physics steps); the scenes are closed after the test."""
    clients = []

    def run(rec):
        c = pb.connect(pb.DIRECT)
        clients.append(c)
        pb.setGravity(0, 0, -9.8, physicsClientId=c)
        box = pb.createCollisionShape(pb.GEOM_BOX, halfExtents=[0.1, 0.1, 0.1],
                                      physicsClientId=c)
        pb.createMultiBody(1.0, box, -1, (0.0, 0.0, 0.5), physicsClientId=c)
        rec.attach(c)
        for _ in range(48):
            pb.stepSimulation(physicsClientId=c)
            rec.tick(1 / 240)
        return rec

    yield run
    for c in clients:
        pb.disconnect(physicsClientId=c)


def _keeper(run_dir, mode="key", **kw):
    return ClipKeeper(mode, run_dir, SPEC, new_recorder=recorder, **kw)


def _decoded(path):
    with imageio.get_reader(str(path)) as reader:
        return [np.asarray(f) for f in reader]


def _captioned_as(path, frames, lines, times):
    """Return how many pixels of the clip at ``path`` differ by more than 100 grey levels
    from ``frames`` captioned with ``lines`` and ``times`` (x264 blurs an edge by less;
    one character of a caption changed moves twenty or more)."""
    draw = Captioner(SPEC.camera.width, SPEC.camera.height, lines)
    got = _decoded(path)
    assert len(got) == len(frames) == len(times)
    wrong = 0
    for f, t, g in zip(frames, times, got):
        want = draw(f, f"t = {t:.1f} s").astype(int).mean(axis=2)
        wrong += int((np.abs(want - g.astype(int).mean(axis=2)) > 100).sum())
    return wrong


def test_a_keeper_starts_empty_and_reads_no_earlier_clips(tmp_path):
    keeper = _keeper(tmp_path)
    assert (keeper.mode, keeper.run_dir, keeper.spec, keeper.new_recorder) == (
        "key", tmp_path, SPEC, recorder)
    assert (keeper.entries, keeper.seen, keeper.succeeded, keeper.wall_time_s) == (
        [], set(), False, 0.0)
    assert (keeper.background, keeper.max_children, keeper.children, keeper.held,
            keeper.earlier) == (True, 2, {}, False, {})
    rec = keeper.recorder()
    assert isinstance(rec, Recorder) and rec.spec is SPEC and rec.snapshots == []
    assert ClipKeeper("all", str(tmp_path), None).mode == "none"
    assert isinstance(ClipKeeper("none", str(tmp_path), SPEC).run_dir, Path)
    with pytest.raises(ValueError) as err:
        ClipKeeper("key", tmp_path, SPEC)
    assert str(err.value) == ("a clip keeper that records needs the backend's recorder "
                              "(new_recorder)")
    assert ClipKeeper.file_name(7, "create", "hook_new1") == "videos/007-create-hook_new1.mp4"
    with pytest.raises(ValueError) as err:
        ClipKeeper("loud", tmp_path, SPEC)
    assert str(err.value) == "option video must be one of all, key, none, got 'loud'"


def test_a_clip_written_here_is_the_trial_s_frames_under_its_caption(tmp_path, film):
    keeper = _keeper(tmp_path, background=False)
    rec = film(keeper.recorder())
    entry = keeper.write(rec, "failure:blocked: lag N cm", 3, "use", 2, "hook_a1",
                         ["handle_length(hook_a1,medium)"], "blocked", "lag 3.1 cm", 1,
                         measured=["stopped: gripper lag 0.031 m", "moved 1.1 cm"])
    clip = tmp_path / "videos" / "003-use-hook_a1.mp4"
    want = {"file": "videos/003-use-hook_a1.mp4", "phase": "use", "trial": 3,
            "tool": "hook_a1", "tested": ["handle_length(hook_a1,medium)"],
            "outcome": "blocked", "reason": "lag 3.1 cm",
            "verdict": "stopped: gripper lag 0.031 m; moved 1.1 cm",
            "why": "failure:blocked: lag N cm", "frames": 3, "duration_s": 0.43,
            "bytes": None}
    assert entry == want and keeper.entries == [entry] and keeper.children == {}
    assert rec.times == pytest.approx([0.0, 35 / 240, 0.2]) and len(rec.frames) == 3
    assert _captioned_as(clip, rec.frames, [
        "#3 TUL  hook_a1  loc 1", "tested handle_length(hook_a1,medium)",
        "blocked: lag 3.1 cm", "stopped: gripper lag 0.031 m", "moved 1.1 cm"],
        rec.times) == 0
    assert (tmp_path / "videos" / "clips.jsonl").read_text() == json.dumps(
        {k: v for k, v in want.items() if k != "bytes"}) + "\n"
    assert keeper.wall_time_s > 0
    keeper.wall_time_s = 1000.0   # finish adds its wait to what the clips took
    assert keeper.finish() == [{**want, "bytes": clip.stat().st_size}] == keeper.entries
    assert 1000.0 < keeper.wall_time_s < 1100.0


def test_a_clip_without_location_reason_or_test_is_captioned_so(tmp_path, film):
    keeper = _keeper(tmp_path, background=False)
    keeper.wall_time_s = 1000.0   # each clip adds the time it took
    rec = film(keeper.recorder())
    entry = keeper.write(rec, "demonstration", 0, "demo", 0, "hook_a2", [], "success", "")
    assert 1000.0 < keeper.wall_time_s < 1100.0
    assert (entry["file"], entry["tested"], entry["verdict"], entry["why"]) == (
        "videos/000-demo-hook_a2.mp4", [], "", "demonstration")
    assert _captioned_as(tmp_path / entry["file"], rec.frames,
                         ["#0 DEMO  hook_a2", "tested -", "success"], rec.times) == 0
    rec = film(keeper.recorder())
    entry = keeper.write(rec, "trial", 12, "walk", 1, "hook_a2", ["a", "b"], "success",
                         "", location=2)
    assert _captioned_as(tmp_path / entry["file"], rec.frames,
                         ["#12 walk  hook_a2  loc 2", "tested a, b", "success"],
                         rec.times) == 0
    assert [json.loads(line)["file"] for line in
            (tmp_path / "videos" / "clips.jsonl").read_text().splitlines()] == [
        "videos/000-demo-hook_a2.mp4", "videos/012-walk-hook_a2.mp4"]


def _nice_when_done(pid):
    """Return the scheduling niceness of child ``pid`` once it has exited (a zombie until
    it is waited for: its last niceness is still read in /proc)."""
    stat = Path(f"/proc/{pid}/stat")
    for _ in range(6000):
        fields = stat.read_text().rsplit(")", 1)[1].split()
        if fields[0] == "Z":
            return int(fields[16])
        time.sleep(0.005)
    raise AssertionError(f"clip process {pid} did not end")


def test_clips_written_in_the_background_wait_for_the_oldest(tmp_path, film, caplog):
    keeper = _keeper(tmp_path, max_children=1)
    names = ["videos/001-eval-hook_a2.mp4", "videos/002-eval-hook_a2.mp4"]
    keeper.write(film(keeper.recorder()), "trial", 1, "eval", 1, "hook_a2", [], "success", "")
    assert list(keeper.children.values()) == names[:1]
    # The clip is rendered and encoded at CLIP_NICE lower priority than the run.
    assert _nice_when_done(next(iter(keeper.children))) == min(os.nice(0) + CLIP_NICE, 19)
    keeper.write(film(keeper.recorder()), "trial", 2, "eval", 2, "hook_a2", [], "success", "")
    assert list(keeper.children.values()) == names[1:]   # the oldest was waited for
    assert (tmp_path / names[0]).is_file()
    kept = keeper.finish()
    assert keeper.children == {}
    assert [(e["file"], e["frames"], e["bytes"]) for e in kept] == [
        (n, 3, (tmp_path / n).stat().st_size) for n in names]
    assert [len(_decoded(tmp_path / n)) for n in names] == [3, 3]
    assert caplog.records == []


def test_a_clip_that_fails_in_the_background_is_dropped_with_a_warning(tmp_path, film,
                                                                        caplog):
    keeper = _keeper(tmp_path)
    (tmp_path / "videos" / "001-use-hook_a1.mp4").mkdir(parents=True)  # not writable
    keeper.write(film(keeper.recorder()), "trial", 1, "use", 1, "hook_a1", [], "failure", "x")
    assert len(keeper.children) == 1 and keeper.entries[0]["bytes"] is None
    assert keeper.finish() == [] == keeper.entries
    assert [(r.name, r.levelname, r.getMessage()) for r in caplog.records] == [
        ("creative_py.learning.clips", "WARNING",
         "videos/001-use-hook_a1.mp4: the clip was not written: its process failed "
         "(the line above says why)")]


def _earlier(run_dir, *files):
    """Write clips.jsonl with entries of ``files`` (and a torn last line) and the files."""
    lines = [json.dumps({"file": f, "trial": i, "frames": 9, "why": "old"})
             for i, f in enumerate(files)]
    (run_dir / "videos").mkdir(parents=True, exist_ok=True)
    for f in files:
        (run_dir / f).write_bytes(b"mp4")
    (run_dir / "videos" / "clips.jsonl").write_text("\n".join(lines) + '\n{"file": "vid')


def test_earlier_entries_are_read_by_file_the_last_of_each(tmp_path):
    _earlier(tmp_path, "videos/001-use-a.mp4")
    with open(tmp_path / "videos" / "clips.jsonl", "a") as fh:
        fh.write("\n" + "\n".join([
            "[1, 2]", '{"file": 3}', '{"trial": 4}', "",
            json.dumps({"file": "videos/001-use-a.mp4", "trial": 5})]) + "\n")
    keeper = _keeper(tmp_path)
    assert keeper.earlier == {"videos/001-use-a.mp4": {"file": "videos/001-use-a.mp4",
                                                       "trial": 5}}


def test_a_held_keeper_keeps_the_clips_made_before_and_writes_none(tmp_path, film):
    _earlier(tmp_path, "videos/001-use-a.mp4")
    keeper = _keeper(tmp_path, background=False)
    keeper.held = True
    rec = film(keeper.recorder())
    assert keeper.write(rec, "failure:x", 1, "use", 1, "a", [], "failure", "x") == {
        "file": "videos/001-use-a.mp4", "trial": 0, "frames": 9, "why": "failure:x",
        "bytes": None}
    assert keeper.write(rec, "failure:y", 2, "use", 2, "a", [], "failure", "y") is None
    assert [e["file"] for e in keeper.entries] == ["videos/001-use-a.mp4"]
    assert not rec.rendered and rec.frames == []
    assert sorted(p.name for p in (tmp_path / "videos").iterdir()) == [
        "001-use-a.mp4", "clips.jsonl"]


def _record(trial, outcome, tool="a", phase="use"):
    return TrialRecord(trial=trial, phase=phase, variant="standard", location=1, tool=tool,
                       tested=[f"t{trial}"], outcome=outcome, reason=f"why {trial}")


def test_replayed_trials_keep_the_clips_the_interrupted_run_made(tmp_path):
    # Trial 1's clip has its entry in clips.jsonl; trial 2's has none (a version
    # without clips.jsonl wrote it); trial 3 made no clip; trial 4 is not kept (the
    # same failure as trial 3), its file aside; trial 5, the first success, has an
    # entry but its clip was never written (the run was killed first).
    _earlier(tmp_path, "videos/001-use-a.mp4", "videos/005-use-a.mp4")
    (tmp_path / "videos" / "005-use-a.mp4").unlink()
    (tmp_path / "videos" / "002-use-a.mp4").write_bytes(b"mp4")
    (tmp_path / "videos" / "004-use-a.mp4").write_bytes(b"mp4")
    (tmp_path / "videos" / "006-create-a.mp4").write_bytes(b"mp4")
    keeper = _keeper(tmp_path)
    for rec in [_record(1, "blocked"), _record(2, "failure"), _record(3, "unreachable"),
                _record(4, "unreachable"), _record(5, "success"),
                _record(6, "success", phase="create")]:
        rec.reason = "same" if rec.trial in (3, 4) else rec.reason
        keeper.replayed(rec)
    assert keeper.entries == [
        {"file": "videos/001-use-a.mp4", "trial": 0, "frames": 9,
         "why": "failure:blocked: why N", "bytes": None},
        {"file": "videos/002-use-a.mp4", "phase": "use", "trial": 2, "tool": "a",
         "tested": ["t2"], "outcome": "failure", "reason": "why 2",
         "why": "failure:failure: why N", "frames": None, "duration_s": None,
         "bytes": None},
        {"file": "videos/006-create-a.mp4", "phase": "create", "trial": 6, "tool": "a",
         "tested": ["t6"], "outcome": "success", "reason": "why 6", "why": "creation",
         "frames": None, "duration_s": None, "bytes": None}]
    assert keeper.seen == {"blocked: why N", "failure: why N", "unreachable: same"}
    assert keeper.succeeded
    assert keeper.finish() == [{**e, "bytes": 3} for e in keeper.entries[:3]]
    none = ClipKeeper("none", tmp_path, SPEC)
    none.replayed(_record(1, "blocked"))
    assert none.entries == [] and none.seen == {"blocked: why N"}


def test_finish_drops_the_entries_of_missing_clips(tmp_path):
    keeper = _keeper(tmp_path)
    (tmp_path / "videos").mkdir()
    (tmp_path / "videos" / "b.mp4").write_bytes(b"12345")
    keeper.entries = [{"file": "videos/a.mp4", "bytes": None},
                      {"file": "videos/b.mp4", "bytes": None}]
    assert keeper.finish() == [{"file": "videos/b.mp4", "bytes": 5}] == keeper.entries
    assert keeper.wall_time_s > 0


def test_an_entry_is_noted_in_a_run_folder_not_made_yet(tmp_path):
    keeper = ClipKeeper("none", tmp_path / "runs" / "run1", SPEC)
    keeper._note({"file": "videos/001-use-a.mp4", "trial": 1, "bytes": 10})
    assert (tmp_path / "runs" / "run1" / "videos" / "clips.jsonl").read_text() == (
        '{"file": "videos/001-use-a.mp4", "trial": 1}\n')


def test_a_long_caption_line_is_wrapped_not_cut():
    # Issue 25: clip captions were cut with "..." ("blocked: position_tool: gripper
    # lagged its target b...").
    from PIL import Image, ImageDraw

    from creative_py.video import LINE_PX, Captioner, _font, band_height

    long = ("blocked: position_tool: gripper lagged its target by 3.0 cm at (0.978, -0.250, "
            "-0.052) m: something is in the way")
    draw = Captioner(320, 48, ["#1 TUL  hook_a1  loc 1", long])
    assert draw.lines[0] == "#1 TUL  hook_a1  loc 1"
    assert " ".join(draw.lines[1:]) == long and len(draw.lines) >= 3
    assert not any(line.endswith("...") for line in draw.lines)
    probe = ImageDraw.Draw(Image.new("L", (1, 1)))
    assert all(probe.textlength(line, font=_font(LINE_PX)) <= 312 for line in draw.lines)
    assert draw.band == band_height(len(draw.lines))


def test_a_clip_has_a_poster_of_its_last_frame(tmp_path):
    # Issue 25: the report's clips all showed frame 0 (t = 0.0 s, before anything
    # happened); the poster is the last frame, the scene at the verdict, captioned.
    from creative_py.video import Captioner, poster_name, write_clip

    frames = [np.full((48, 320, 3), 40 * i, np.uint8) for i in range(4)]
    path = tmp_path / "videos" / "003-use-hook_a1.mp4"
    write_clip(path, frames, 5.0, ["#3 TUL  hook_a1  loc 1"], [0.0, 0.2, 0.4, 0.6])
    poster = Path(poster_name(str(path)))
    assert poster == tmp_path / "videos" / "003-use-hook_a1.poster.jpg"
    image = np.asarray(imageio.imread(poster)).astype(int)
    expected = Captioner(320, 48, ["#3 TUL  hook_a1  loc 1"])(frames[-1], "t = 0.6 s")
    assert image.shape == expected.shape
    assert np.abs(image - expected.astype(int)).mean() < 3   # JPEG's error only
