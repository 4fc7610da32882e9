"""The trainer's demonstration in the physics and what tool-use learning makes of it
(:func:`run_demonstration`, :meth:`ToolUseLearner.observe_demonstration`), exact, on
the rake case (about 2 CPU seconds a demonstration): the steps, their skills,
arguments and outcomes, the facts chained from one step to the next, the frames and
clip of a run folder, and the two ways a demonstration fails (a skill that does not
end ``ok``, a goal not reached), each message naming the manifest or the drawn world.
The engine is the real one: the example it learns from the observed steps must be the
one ``observe_demonstration`` returns.
"""

from __future__ import annotations

import dataclasses

import pytest

from creative_py.bridge import Compound, Engine, fact_term
from creative_py.case import get_case
from creative_py.learning.poses import pose_resolver
from creative_py.learning.tool_use import (DemonstrationFailed, LearningOptions,
                                           ToolUseLearner, run_demonstration)
from creative_py.learning.trials import TrialRunner
from creative_py.records.folder import RunFolder
from creative_py.backends.pybullet import load_world
from creative_py.backends.pybullet.recorder import Recorder

pytestmark = pytest.mark.sim

STEPS = [("pick_up", ("rake_a2",)), ("position_tool", ("rake_a2", "box1", "shelf1")),
         ("pull", ("rake_a2", "box1", "shelf1"))]


@pytest.fixture(scope="module")
def engine():
    return Engine.instance()


@pytest.fixture(scope="module")
def world():
    return load_world(get_case("rake"))


@pytest.fixture(scope="module")
def engine_example(engine, world):
    """What the engine learns from the demonstration's steps, observed here without a
    verdict, images or recorder (the defaults: seed 0)."""
    demo = run_demonstration(world, pose_target=pose_resolver(engine, world.manifest))
    steps = [Compound("step", (s.skill, list(s.args), [fact_term(f) for f in s.facts_before],
                               [fact_term(f) for f in s.facts_after])) for s in demo.steps]
    _matched, new, example = engine.learn_from_demonstration("rake", steps)
    return str(new), str(example)


def _with_pose(world, pose, variation=""):
    m = world.manifest
    manifest = dataclasses.replace(m, demonstration=dataclasses.replace(m.demonstration,
                                                                         pose=pose))
    return dataclasses.replace(world, manifest=manifest, variation=variation)


def test_the_rake_demonstration_exact(engine, world, tmp_path):
    calls = []
    rec = Recorder(world.scene.video)
    demo = run_demonstration(world, seed=0, images_dir=tmp_path, record=rec,
                             verdict=lambda: calls.append(rec.rendered),
                             pose_target=pose_resolver(engine, world.manifest))
    assert (demo.tool, demo.variant, demo.location, demo.pose, demo.goal_reached) == (
        "rake_a2", "standard", 1, (0.035, 0.0, 0.0), True)
    assert [(s.skill, s.args, s.outcome) for s in demo.steps] == [
        (name, args, "ok") for name, args in STEPS]
    assert [(len(s.facts_before), len(s.facts_after)) for s in demo.steps] == [
        (73, 76), (76, 76), (76, 76)]
    for a, b in zip(demo.steps, demo.steps[1:]):
        assert a.facts_after == b.facts_before   # each step starts where the last ended
    assert all(s.facts_before != s.facts_after for s in demo.steps)
    assert calls == [False]     # once, at the end of the episode
    assert rec.snapshots and any(tmp_path.iterdir())


def test_a_goal_not_reached_names_the_drawn_world_and_gives_no_verdict(engine, world):
    drawn = _with_pose(world, (-0.05, 0.0, 0.0), "world seed 7")
    calls = []
    with pytest.raises(DemonstrationFailed) as info:
        run_demonstration(drawn, seed=0, verdict=lambda: calls.append(1),
                          pose_target=pose_resolver(engine, drawn.manifest))
    assert str(info.value) == (
        f"world seed 7 (drawn from {world.manifest.folder / 'case.toml'}): the "
        "demonstration: rake_a2 at location 1 did not reach the goal in the physics: "
        "nothing to learn from")
    assert calls == []


def test_a_skill_that_fails_names_the_manifest_field(engine, world):
    bad = _with_pose(world, (0.3, 0.3, 0.3))
    with pytest.raises(DemonstrationFailed) as info:
        run_demonstration(bad, seed=0, verdict=lambda: None,
                          pose_target=pose_resolver(engine, bad.manifest))
    assert str(info.value).startswith(
        f"{world.manifest.folder / 'case.toml'}: field 'demonstration': the trainer's skill "
        "position_tool ended unreachable in the physics: position_tool: IK found no arm "
        "posture for gripper at (")


class _Clips:
    """Which trials become clips, as a run's clip keeper answers: ``keep`` says whether
    the demonstration's clip is kept; the calls are recorded."""

    def __init__(self, world, keep: bool):
        self.spec, self.keep, self.calls = world.scene.video, keep, []

    def recorder(self):
        self.rec = Recorder(self.spec)
        return self.rec

    def why(self, *args):
        self.calls.append(("why", args))
        return "the demonstration" if self.keep else None

    def write(self, *args):
        self.calls.append(("write", args))


@pytest.mark.parametrize("keep", [True, False])
def test_observe_demonstration_gives_the_engine_s_example(engine, world, engine_example,
                                                          tmp_path, keep):
    run = RunFolder.create(tmp_path, "rake", 0, "run")
    lines = []
    clips = _Clips(world, keep)
    runner = TrialRunner(engine, world, run, seed=0, progress=lines.append, clips=clips)
    new, example, tool = ToolUseLearner(runner, LearningOptions()).observe_demonstration()
    assert tool == "rake_a2"
    assert lines == ["demonstration: the trainer shows the task with rake_a2 (loc 1)"]
    assert any(run.snapshot_dir("demo", 0).iterdir())
    assert clips.rec.snapshots
    assert clips.calls[0] == ("why", ("demo", "success", "goal reached"))
    assert clips.calls[1:] == ([("write", (clips.rec, "the demonstration", 0, "demo", 0,
                                           "rake_a2", [], "success", "goal reached", 1))]
                               if keep else [])
    assert (str(new), str(example)) == engine_example
    assert "handle_length(" in str(example) and str(example).startswith("tool_pose(")


def test_observe_demonstration_without_a_run_folder_or_clips(engine, world, engine_example):
    runner = TrialRunner(engine, world, None, seed=0)
    new, example, tool = ToolUseLearner(runner).observe_demonstration()
    assert (tool, (str(new), str(example))) == ("rake_a2", engine_example)
