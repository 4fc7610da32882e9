"""Trial clips: the recorder keeps the physics the oracle, and its clips decode.

A real hook trial runs twice, with and without a recorder: the outcome, the steps and
every final pose must be identical to the last bit (recording only reads the physics).
The recorded frames are encoded, and the MP4 is decoded back with imageio: as many
frames as snapshots, the world's size, a caption; a forked child renders a clip too.
"""

import os

import imageio.v2 as imageio
import numpy as np
import pytest

from creative_py.case import get_case
from creative_py.backends.pybullet import load_world
from creative_py.simulator.trial import run_trial

from _poses import poses
from creative_py.backends.pybullet.recorder import Recorder
from creative_py.world.cameras import CameraSpec, VideoSpec
from creative_py.video import band_height, caption, write_clip

pytestmark = pytest.mark.sim


@pytest.fixture(scope="module")
def recorded(tmp_path_factory):
    world = load_world(get_case("hook"))
    plain = run_trial(world, "hook_a1", "standard", 1, seed=3, pose_target=poses(world))
    rec = Recorder(world.scene.video)
    seen = run_trial(world, "hook_a1", "standard", 1, seed=3, record=rec,
                     pose_target=poses(world))
    return world, plain, seen, rec, tmp_path_factory.mktemp("clips")


def test_recording_leaves_the_trial_unchanged(recorded):
    world, plain, seen, rec, _ = recorded
    assert (seen.outcome, seen.reason, seen.steps) == (plain.outcome, plain.reason, plain.steps)
    assert seen.true_final == plain.true_final
    assert seen.perceived_final == plain.perceived_final
    # Recorded from the settled scene on: one snapshot per 1/fps s of simulated time,
    # plus the first and the last.
    assert rec.duration_s == pytest.approx(seen.sim_time_s - world.scene.settle_time,
                                           abs=1e-6)
    assert abs(len(rec.snapshots) - (rec.duration_s * rec.spec.fps + 2)) <= 1


def test_the_frames_show_the_scene_moving(recorded):
    world, _, _, rec, _ = recorded
    frames = rec.frames
    cam = world.scene.video.camera
    assert len(frames) == len(rec.snapshots) > 10
    assert frames[0].shape == (cam.height, cam.width, 3) and frames[0].dtype == np.uint8
    # The robot's stand-in and the tool move: first and middle frames differ.
    diff = np.abs(frames[0].astype(int) - frames[len(frames) // 2].astype(int)).sum(axis=2)
    assert (diff > 30).mean() > 0.01


def test_a_clip_decodes_with_its_caption(recorded):
    world, _, _, rec, tmp = recorded
    path = tmp / "clip.mp4"
    lines = ["#1 TUL 1  hook_a1  loc 1", "tested handle_length(hook_a1,medium)", "blocked"]
    info = write_clip(path, rec.frames, rec.spec.fps, lines, rec.times)
    frames = _decode(path)
    cam = world.scene.video.camera
    assert info["frames"] == len(frames) == len(rec.frames) > 0
    # The caption is a band above the picture: the frame is that much taller, and the
    # picture under the band is the camera's whole picture (beyond the codec's loss).
    band = band_height(len(lines))
    assert frames.shape[1:] == (cam.height + band, cam.width, 3)
    assert info["height"] == cam.height + band and info["width"] == cam.width
    assert info["duration_s"] == pytest.approx(len(frames) / rec.spec.fps, abs=0.01)
    raw, enc = rec.frames[5].astype(int), frames[5].astype(int)
    assert np.abs(raw - enc[band:]).mean() < 6
    assert enc[:band].mean() < 90 and (enc[:band] > 200).any()   # white text on dark


def test_render_then_in_a_child_writes_the_clip(recorded, tmp_path):
    world, _, _, _, _ = recorded
    rec = Recorder(world.scene.video)
    path = tmp_path / "child.mp4"
    from creative_py.backends.pybullet import open_episode

    level = tmp_path / "nice.txt"

    def use(frames, times):
        level.write_text(str(os.nice(0)))  # the child's priority, lowered before rendering
        write_clip(path, frames, 10.0, ["child"], times)

    with open_episode(world, "standard", 2, "hook_a2", record=rec) as ep:
        ep.run_skill("pick_up")
        pid = rec.render_then(use, nice=3)
    assert pid is not None
    _, status = os.waitpid(pid, 0)
    assert os.waitstatus_to_exitcode(status) == 0
    assert len(_decode(path)) == len(rec.snapshots)
    assert int(level.read_text()) == min(19, os.nice(0) + 3)


def test_a_caption_is_drawn_in_the_band():
    frame = np.full((240, 320, 3), 200, np.uint8)
    out = caption(frame, ["#3 TUL 3  hook_a2", "tested behind(hook_a2,cube1)", "failure"],
                  "t = 2.0 s")
    band = band_height(3)
    assert out.shape == (240 + band, 320, 3)
    assert (out[:band] == 255).any() and out[:band].mean() < 120
    assert (out[band:] == frame).all()           # the whole picture, untouched


def test_bad_video_tables_name_the_field():
    cam = CameraSpec("video", (1.0, -1.0, 0.7), (0.9, -0.3, -0.1))
    with pytest.raises(ValueError, match="fps"):
        VideoSpec(cam, fps=0)
    with pytest.raises(ValueError, match=r"scene.toml: \[video\]: camera 'video': unknown "):
        VideoSpec.from_table({"eye": [1, 0, 1], "target": [0, 0, 0], "zoom": 2},
                             "scene.toml")


def _decode(path):
    """Return every frame of an MP4 file (imageio's ffmpeg reader)."""
    with imageio.get_reader(str(path)) as reader:
        return np.stack([f for f in reader])  # its len() is inf
