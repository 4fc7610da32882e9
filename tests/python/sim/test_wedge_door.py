"""Tests of the door-and-wedge world (creative_py.sim.wedge_door).

The ``sim`` tests run the pybullet physics: the door's closer pushes on the object and
the simulator decides whether the door is held.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from creative_py.sim.trial import run_trial
from creative_py.sim.wedge_door import (WedgeDoorCase, WedgePose, load_wedge_world,
                                        open_wedge_episode, place_from_pose,
                                        pose_from_place)
from creative_py.world import WORLDS_ROOT, WorldFileError


@pytest.fixture(scope="module")
def world():
    return load_wedge_world()


def _copy_world(tmp_path: Path) -> Path:
    dst = tmp_path / "wedge_door"
    shutil.copytree(WORLDS_ROOT / "wedge_door", dst)
    return dst


# ------------------------------------------------------------------ world files
def test_world_has_two_sets_of_blocks_and_two_variants(world):
    sets = {item.set for item in world.objects.values()}
    shapes = {item.spec.shape for item in world.objects.values()}
    assert sets == {"a", "b"}
    assert shapes == {"triangular_prism", "box", "cylinder"}
    width = {s: max(i.spec.width for i in world.objects.values() if i.set == s) for s in sets}
    assert width["b"] > width["a"]
    assert set(world.variants) == {"standard", "big_door"}
    assert world.demonstration.object == "wedge_a2"
    assert world.objects["wedge_a2"].spec.shape == "triangular_prism"


def test_bad_field_names_file_and_field(tmp_path):
    d = _copy_world(tmp_path)
    scene = d / "scene.toml"
    scene.write_text(scene.read_text().replace("mass = 15.0", 'mass = "heavy"'))
    with pytest.raises(WorldFileError, match=r"scene\.toml.*door\.mass.*must be a number"):
        load_wedge_world(d)


def test_typo_in_objects_file_is_reported_with_its_field(tmp_path):
    d = _copy_world(tmp_path)
    objects = d / "objects.toml"
    objects.write_text(objects.read_text().replace("height = 0.03", "hieght = 0.03", 1))
    with pytest.raises(WorldFileError, match=r"objects\.toml.*hieght"):
        load_wedge_world(d)


def test_missing_world_file_is_named(tmp_path):
    d = _copy_world(tmp_path)
    (d / "tasks.toml").unlink()
    with pytest.raises(WorldFileError, match=r"tasks\.toml: file not found"):
        load_wedge_world(d)


def test_demonstration_must_name_a_known_object(tmp_path):
    d = _copy_world(tmp_path)
    demo = d / "case.toml"
    demo.write_text(demo.read_text().replace('tool = "wedge_a2"', 'tool = "wedge_z9"'))
    with pytest.raises(WorldFileError, match=r"case\.toml.*demonstration\.tool"):
        load_wedge_world(d)


def test_unknown_object_lists_the_available_ones(world):
    with pytest.raises(KeyError, match=r"wedge_z9.*available objects: .*wedge_a1.*box_a1"):
        world.object("wedge_z9")


def test_parse_pose_rejects_bad_text():
    case = WedgeDoorCase()
    assert case.parse_pose("0.6, 0.03, 0") == WedgePose(0.6, 0.03, 0.0)
    for bad in ("0.6,0.03", "a,b,c", "-0.6,0.03,0", "0.6,nan,0"):
        with pytest.raises(ValueError, match="R,GAP,YAW"):
            case.parse_pose(bad)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(0.2, 0.8), gap=st.floats(0.0, 0.3), yaw=st.floats(-3.0, 3.0),
       length=st.floats(0.03, 0.2))
def test_pose_numbers_round_trip(world, r, gap, yaw, length):
    x, y, heading = place_from_pose(world.door, 0.7, length, WedgePose(r, gap, yaw))
    back = pose_from_place(world.door, 0.7, length, x, y, heading)
    assert back.r == pytest.approx(r, abs=1e-9)
    assert back.gap == pytest.approx(gap, abs=1e-9)
    assert back.yaw == pytest.approx(yaw, abs=1e-9)


def test_tip_towards_the_door_points_against_the_closing_motion(world):
    # At yaw 0 the tip points from the object towards the open door (counter-clockwise).
    d = world.door
    x, y, heading = place_from_pose(d, 0.7, 0.1, WedgePose(0.6, 0.05, 0.0))
    door_dir = d.closed_heading + 0.7
    door_point = (d.hinge[0] + 0.6 * math.cos(door_dir), d.hinge[1] + 0.6 * math.sin(door_dir))
    to_door = math.atan2(door_point[1] - y, door_point[0] - x)
    assert abs(math.remainder(heading - to_door, 2 * math.pi)) < 0.15


# ------------------------------------------------------------------- physics
def _door_trial(world, name, variant, pose, seed=0):
    with_ep = open_wedge_episode(world, variant, 1, name, seed=seed, with_robot=False)
    try:
        assert with_ep.trainer_place(pose).ok
        res = with_ep.act()
        assert res.ok, res.reason
        return with_ep.goal_reached(), with_ep.door_outcome, with_ep.truth()
    finally:
        with_ep.close()


@pytest.mark.sim
@pytest.mark.parametrize("name,held_standard,held_big", [
    ("wedge_a3", True, True),     # long prism: holds both doors
    ("wedge_a2", True, False),    # medium prism: only the weak closer
    ("wedge_a1", False, False),   # short prism
    ("box_a1", False, False),     # a box slides
])
def test_which_objects_hold_which_door(world, name, held_standard, held_big):
    demo = world.demonstration.pose
    for variant, expected in (("standard", held_standard), ("big_door", held_big)):
        held, door, _ = _door_trial(world, name, variant, demo)
        assert door.touched, f"{name}/{variant}: the door never reached the object"
        assert held is expected, f"{name}/{variant}: {door.describe()}"


@pytest.mark.sim
@pytest.mark.parametrize("pose,why", [
    (WedgePose(0.6, 0.03, math.pi), "tip away from the door"),
    (WedgePose(0.75, 0.33, 0.0), "far from the door"),
])
def test_a_good_wedge_badly_placed_fails(world, pose, why):
    held, door, _ = _door_trial(world, "wedge_a3", "standard", pose)
    assert not held, f"{why}: {door.describe()}"


@pytest.mark.sim
def test_same_seed_same_outcome_and_final_pose(world):
    a = _door_trial(world, "wedge_a2", "standard", world.demonstration.pose, seed=3)
    b = _door_trial(world, "wedge_a2", "standard", world.demonstration.pose, seed=3)
    assert a[0] == b[0] and a[1] == b[1]
    assert a[2] == b[2]  # bit-identical


@pytest.mark.sim
def test_observation_has_perceived_pose_door_facts_and_catalogue(world):
    ep = open_wedge_episode(world, "standard", 1, "wedge_a2", seed=0, with_robot=False)
    try:
        assert ep.trainer_place(world.demonstration.pose).ok
        obs = ep.observe()
    finally:
        ep.close()
    facts = {f[0]: f for f in obs.facts}
    x, y, z, yaw = obs.perceived_poses()["wedge_a2"]
    tx, ty, tz, tyaw = obs.truth["wedge_a2"]
    assert math.dist((x, y, z), (tx, ty, tz)) < 0.01
    assert abs(math.remainder(yaw - tyaw, 2 * math.pi)) < 0.1
    assert facts["hinge"] == ("hinge", "door1", *world.door.hinge)
    assert facts["door_angle"][2] == pytest.approx(world.door.open_angle, abs=1e-3)
    assert "door_held" not in facts
    kinds = [f for f in obs.facts if f[0] == "object_kind"]
    assert len(kinds) == len(world.objects)
    # The perceived pose gives back the pose numbers asked for.
    size = next(f for f in obs.facts if f[0] == "size")
    pose = pose_from_place(world.door, facts["door_angle"][2], size[2], x, y, yaw)
    demo = world.demonstration.pose
    assert pose.r == pytest.approx(demo.r, abs=0.01)
    assert pose.gap == pytest.approx(demo.gap, abs=0.015)
    assert pose.yaw == pytest.approx(demo.yaw, abs=0.1)


@pytest.mark.sim
def test_robot_places_the_demonstrated_wedge_and_it_holds_the_door(world):
    result = run_trial("wedge", world, "wedge_a2", "standard", 1, seed=0)
    assert result.outcome == "success", result.reason
    assert result.perceived_final is not None and "wedge_a2" in result.perceived_final
    assert result.sim_time_s > world.held.duration


@pytest.mark.sim
def test_robot_skills_need_a_robot(world):
    ep = open_wedge_episode(world, "standard", 1, "wedge_a2", with_robot=False)
    try:
        with pytest.raises(RuntimeError, match="no robot"):
            ep.pick_up()
    finally:
        ep.close()


@pytest.mark.sim
def test_unknown_object_in_an_episode_is_refused(world):
    with pytest.raises(KeyError, match="available objects"):
        open_wedge_episode(world, "standard", 1, "hammer", seed=0)
    with pytest.raises(KeyError, match="variants: standard, big_door"):
        open_wedge_episode(world, "huge_door", 1, "wedge_a2", seed=0)
