"""The simulator's public API (creative_py.backends.pybullet): one world, episode and trial for every case."""

import pytest

from creative_py.case import load_cases
from creative_py.backends.pybullet import SkillOutcome, load_world, open_episode
from creative_py.simulator.trial import run_trial
from creative_py.world_files import WorldFileError

from _poses import poses

# The pybullet backend's cases (tests/python/backends/maniskill/ tests the ManiSkill one's).
CASES = sorted(c for c, m in load_cases().items() if m.backend == "pybullet")


@pytest.mark.parametrize("case", CASES)
def test_every_case_loads_with_its_demonstration_and_variants(case):
    manifest = load_cases()[case]
    world = load_world(manifest)
    assert world.manifest is manifest
    assert manifest.demonstration.tool in world.catalogue
    assert world.locations and world.locations[0] == 1
    listing = world.listing()
    assert set(listing["variants"]) == set(manifest.variant_names)
    assert list(listing["default_pose"].values()) == list(manifest.demonstration.pose)
    assert set(listing["objects"]) == set(world.catalogue)


def test_a_missing_world_file_is_named(tmp_path):
    manifest = load_cases()[CASES[0]]
    with pytest.raises(WorldFileError, match="file not found"):
        load_world(manifest, tmp_path)


# MoveBall's demonstration cannot pass the benchmark's done(): its formula gives a ball
# at rest at most 0.884 (docs/robotoolbench.md); the test holds it to failing.
_CAPPED = pytest.mark.xfail(strict=True, reason="the reward of a ball at rest is at most 0.884")


@pytest.mark.sim
@pytest.mark.parametrize("case", [pytest.param(c, marks=_CAPPED) if c == "move_ball" else c
                                  for c in CASES])
def test_the_demonstration_succeeds_through_the_manifest_skills(case):
    manifest = load_cases()[case]
    world = load_world(manifest)
    demo = manifest.demonstration
    result = run_trial(world, demo.tool, demo.variant, demo.location, pose_target=poses(world))
    assert result.outcome == "success", result.reason
    assert result.case == manifest.id and result.pose == demo.pose


@pytest.mark.sim
def test_run_skill_returns_a_skill_outcome_and_unknown_skills_are_named():
    manifest = load_cases()[CASES[0]]
    world = load_world(manifest)
    demo = manifest.demonstration
    with open_episode(world, demo.variant, demo.location, demo.tool) as ep:
        first = manifest.skills[0].name
        out = ep.run_skill(first)
        assert isinstance(out, SkillOutcome) and out.ok
        with pytest.raises(KeyError, match="unknown skill"):
            ep.run_skill("juggle")


@pytest.mark.sim
@pytest.mark.parametrize("case", ["hook", "wedge", "rake"])
def test_a_scene_without_the_robot_is_perceived_as_with_it(case):
    # The learner observes a task without building Baxter (learning/trials.task_facts).
    from creative_py.case import get_case
    from creative_py.backends.pybullet import load_world, open_episode

    m = get_case(case)
    world = load_world(m)
    variant = m.harder_variant
    seen = []
    for robot in (True, False):
        with open_episode(world, variant, world.locations[-1], m.demonstration.tool, seed=0,
                          robot=robot) as ep:
            seen.append(list(ep.observe().facts))
    assert seen[0] == seen[1]
