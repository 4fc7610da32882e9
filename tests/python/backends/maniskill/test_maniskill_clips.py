"""Clips on the ManiSkill backend: a recorded trial is the unrecorded one, and its frames
come out after the verdict (skipped without the extra).

The first frame a process renders costs 15-20 s on lavapipe (the shaders are compiled);
each later frame about 0.15 s at 320x240.
"""

from __future__ import annotations

import dataclasses
import importlib.util

import numpy as np
import pytest

# Skipped without the extra, which is looked for, not imported: importing mani_skill (and
# torch) costs about 8 CPU s, which every pytest-xdist worker paid at collection, also
# the one that runs none of these tests; the episodes import it when they run.
if importlib.util.find_spec("mani_skill") is None:
    pytest.skip("the maniskill extra is not installed (make setup-maniskill or pip install "
                "-e '.[maniskill]')", allow_module_level=True)

from creative_py.case import get_case  # noqa: E402
from creative_py.backends.maniskill import (Recorder, load_world, open_episode,  # noqa: E402
                                            recorder)
from creative_py.simulator.trial import run_trial  # noqa: E402
from creative_py.world_files import WorldFileError  # noqa: E402

CASE = "pull_cube_tool"


def _place(facts, tool, pose):
    """The pose's world target as the case's ontology gives it (see test_backend.py)."""
    cube = next(f for f in facts if f[0] == "pose")
    return ("place", cube[2] + pose[0], cube[3] + pose[1], 0.0)


@pytest.fixture(scope="module")
def world():
    return load_world(get_case(CASE))


def _judged(result) -> dict:
    """Everything a trial's result says but its wall time."""
    data = dataclasses.asdict(result)
    data.pop("wall_time_s")
    return data


def test_recorded_trial_is_the_unrecorded_one_and_has_frames(world):
    """The same trial with and without a recorder gives the same result (outcome,
    final poses, steps, load, facts, verdict); the recorder's frames, rendered in the
    verdict callback, are one per kept state, of the camera's size, and show motion."""
    m = world.manifest
    args = (world, m.demonstration.tool, "standard", 2)
    kw = dict(pose=(-0.08, -0.06), seed=1, pose_target=_place)
    plain = run_trial(*args, **kw)
    rec = recorder(world.video)
    seen = {}

    def verdict(outcome, reason, measured):
        seen["outcome"] = outcome
        seen["frames"] = rec.render()

    recorded = run_trial(*args, record=rec, verdict=verdict, **kw)
    assert _judged(recorded) == _judged(plain)
    assert seen["outcome"] == plain.outcome
    frames, cam = seen["frames"], world.video
    # a state every 1/fps s of simulated time, and the last one
    assert len(frames) == len(rec.snapshots) >= int(plain.sim_time_s * cam.fps)
    assert rec.times[-1] == pytest.approx(plain.sim_time_s)
    assert all(f.shape == (cam.height, cam.width, 3) and f.dtype == np.uint8 for f in frames)
    assert frames[0].std() > 10  # not a blank picture
    assert np.abs(frames[0].astype(int) - frames[-1].astype(int)).mean() > 1.0  # it moved


def test_rendering_after_the_verdict_changes_nothing_judged(world):
    """Rendering sets earlier states back; afterwards the scene is the one judged (the
    cube's and the tool's poses exactly, the goal, the facts)."""
    m = world.manifest
    rec = Recorder(world.video)
    with open_episode(world, "standard", 1, m.demonstration.tool, pose_target=_place,
                      record=rec) as ep:
        for s in m.skills:
            assert ep.run_skill(s.name, m.demonstration.pose if s.pose else None).ok
        truth, reached, facts = ep.truth(), ep.verdict().holds, ep.observe().facts
        frames = rec.render()
        assert ep.truth() == truth
        assert ep.verdict().holds == reached is True
        # the robot base's pose comes back within 1e-9 m (SAPIEN sets the articulation's
        # root through its own float conversions); the cube and the tool exactly
        after = ep.observe().facts
        assert [f[:2] for f in after] == [f[:2] for f in facts]
        for a, b in zip(after, facts):
            assert a == pytest.approx(b, abs=1e-9)
    assert len(frames) == len(rec.snapshots) > 10
    with pytest.raises(RuntimeError, match="rendered already"):
        rec.render()


def test_video_table_errors_name_the_file_and_field(tmp_path):
    """A bad [video] value is one error naming tasks.toml and the field."""
    import shutil

    from creative_py.case import read_manifest

    folder = tmp_path / "w"
    shutil.copytree(get_case(CASE).folder, folder)
    tasks = folder / "tasks.toml"
    tasks.write_text(tasks.read_text().replace("fps = 5.0", "fps = 50.0"))
    with pytest.raises(WorldFileError, match=r"tasks.toml: field 'video.fps': must be <= 20"):
        load_world(read_manifest(folder))


def test_recorder_and_camera_have_the_protocol_s_members(world):
    """The backend's recorder and the world's camera offer what ClipKeeper uses."""
    from creative_py.simulator import ClipCamera, ClipRecorder
    from tests.python.test_simulator_registry import signature_mismatches

    assert signature_mismatches(ClipCamera, world.video) == []
    assert signature_mismatches(ClipRecorder, recorder(world.video)) == []
