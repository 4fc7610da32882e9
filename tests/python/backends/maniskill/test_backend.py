"""The ManiSkill backend on a real episode of PullCubeTool-v1 (skipped without the extra).

Each test resets ManiSkill's environment on the CPU backend and steps it; about 10-20 s
each on this machine (SAPIEN's first scene takes a few seconds).
"""

from __future__ import annotations

import importlib.util

import pytest

# Skipped without the extra, which is looked for, not imported: importing mani_skill (and
# torch) costs about 8 CPU s, which every pytest-xdist worker paid at collection, also
# the one that runs none of these tests; the episodes import it when they run.
if importlib.util.find_spec("mani_skill") is None:
    pytest.skip("the maniskill extra is not installed (make setup-maniskill or pip install "
                "-e '.[maniskill]')", allow_module_level=True)

from creative_py.case import get_case  # noqa: E402
from creative_py.backends.maniskill import load_world, open_episode  # noqa: E402
from creative_py.simulator.trial import run_trial  # noqa: E402
from creative_py.world_files import WorldFileError  # noqa: E402

CASE = "pull_cube_tool"


def _place(facts, tool, pose):
    """The pose's world target as the case's ontology gives it (pose_target/5): the
    prong's centre x and the handle's y relative to the perceived cube."""
    cube = next(f for f in facts if f[0] == "pose")
    return ("place", cube[2] + pose[0], cube[3] + pose[1], 0.0)


@pytest.fixture(scope="module")
def world():
    return load_world(get_case(CASE))


def test_demonstration_succeeds_by_maniskills_evaluate(world):
    """The trainer's tool and pose pull the cube in: ManiSkill's evaluate() says success,
    within ManiSkill's 100 control steps."""
    m = world.manifest
    r = run_trial(world, m.demonstration.tool, "standard", m.demonstration.location,
                  pose_target=_place)
    assert r.outcome == "success", r.reason
    assert r.verdict["measures"]["evaluate_success"] is True
    assert 0 < r.steps <= world.max_steps
    assert r.verdict["value"] < 0.6
    # the load on the tool while it pulled, read from SAPIEN's contacts
    assert r.max_tool_force_n > 0 and r.tool_load["contact_steps"] > 0
    # the task's contact alone: the tool against the case's target (not the table)
    assert r.tool_load["bodies"] == [m.target] and r.tool_load["window_s"] == 0.1


def test_prong_in_front_of_the_cube_fails(world):
    """The same tool with its prong in front of the cube does not pull it in."""
    m = world.manifest
    r = run_trial(world, m.demonstration.tool, "standard", m.demonstration.location,
                  pose=(-0.08, -0.06), pose_target=_place)
    assert r.outcome == "failure"
    assert r.verdict["measures"]["evaluate_success"] is False


def test_facts_come_from_the_simulators_state(world):
    """Before anything moves: the cube's pose and size, the goal disc about the robot
    base, every object's catalogue facts; no held tool."""
    m = world.manifest
    with open_episode(world, "standard", 1, m.demonstration.tool) as ep:
        facts = ep.observe().facts
    names = {f[0] for f in facts}
    assert {"pose", "size", "reach_zone", "handle_length_m"} <= names
    assert "held" not in names
    cube = next(f for f in facts if f[0] == "pose")
    assert 0.04 <= cube[2] <= 0.26  # ManiSkill draws the cube's x in [0.05, 0.25] m
    zone = next(f for f in facts if f[0] == "reach_zone")
    assert zone[2:] == pytest.approx((-0.615, 0.0, 0.6), abs=1e-3)


def test_unknown_variant_value_names_the_file(tmp_path):
    """A variant setting a value the backend does not know is one error naming case.toml."""
    import shutil

    from creative_py.case import read_manifest

    folder = tmp_path / "w"
    shutil.copytree(get_case(CASE).folder, folder)
    text = (folder / "case.toml").read_text().replace("cube_dx =", "cube_dz =")
    (folder / "case.toml").write_text(text)
    with pytest.raises(WorldFileError, match=r"case.toml: variant 'standard': set: unknown value 'cube_dz'"):
        load_world(read_manifest(folder))


def test_world_and_episode_have_the_protocol_s_members(world):
    """The ManiSkill world and episode offer what the learning loop uses of any backend."""
    from creative_py.backends.maniskill import Episode as ManiSkillEpisode
    from creative_py.simulator import Episode, World
    from tests.python.test_simulator_registry import signature_mismatches

    assert signature_mismatches(World, world) == []
    assert signature_mismatches(Episode, ManiSkillEpisode) == []


def test_the_tool_s_mass_comes_from_its_spec_alone(world):
    """A catalogued tool's mass is its spec's (objects.toml's ``mass``, kg), and a spec
    put in its place (a drawn world's) brings its own: the catalogue keeps no copy."""
    from dataclasses import replace

    from creative_py.backends.maniskill.episode import tool_mass

    name = world.manifest.demonstration.tool
    item = world.item(name)
    assert tool_mass(item) == item.spec.mass == 0.5
    drawn = world.with_spec(name, replace(item.spec, mass=0.3))
    assert tool_mass(drawn.item(name)) == 0.3
