"""Perception inside the real worlds, through their own loaders and observe()."""

from __future__ import annotations

import math

import pytest

pytestmark = pytest.mark.sim


@pytest.fixture(scope="module")
def hook_world():
    from creative_py.sim.hook_tube import load_hook_world

    return load_hook_world()


@pytest.mark.parametrize("location", [1, 2, 3, 4])
def test_hook_world_observation_places_the_cube_within_2_mm(hook_world, angle_error, location):
    from creative_py.sim.hook_tube import open_hook_episode

    ep = open_hook_episode(hook_world, "standard", location, hook_world.demonstration.tool, seed=3)
    try:
        obs = ep.observe()
    finally:
        ep.close()
    name = hook_world.cube.name
    x, y, z, yaw = obs.perceived_poses()[name]
    tx, ty, tz, tyaw = obs.truth[name]
    # bench/perception_error.py: 0.6 mm mean, 1.5 mm worst (one pixel is 3.1 mm here),
    # 2.3 degrees worst over every variant and location with and without noise.
    assert math.hypot(x - tx, y - ty) < 0.002
    assert abs(z - tz) < 0.001
    assert abs(math.degrees(angle_error(yaw, tyaw, math.pi / 2))) < 3.0
    sizes = [f for f in obs.facts if f[0] == "size" and f[1] == name]
    assert len(sizes) == 1 and sizes[0][2:] == pytest.approx((0.03, 0.03, 0.03), abs=0.0035)


@pytest.fixture(scope="module")
def wedge_world():
    from creative_py.sim.wedge_door import load_wedge_world

    return load_wedge_world()


# Door-relative placements (r m, gap m, yaw rad): tip towards the door, and reversed.
WEDGE_PLACES = [(0.55, 0.02, 0.0), (0.45, 0.10, math.pi)]


@pytest.mark.parametrize("name", ["wedge_a2", "wedge_b1"])
def test_wedge_world_observation_finds_the_tip_direction(wedge_world, angle_error, name):
    import pybullet as pb

    from creative_py.sim.bodies import set_frame_pose
    from creative_py.sim.wedge_door import WedgePose, open_wedge_episode, place_from_pose

    spec = wedge_world.object(name).spec
    ep = open_wedge_episode(wedge_world, wedge_world.default_variant, 1, name, seed=5)
    try:
        for pose in WEDGE_PLACES:
            x, y, yaw = place_from_pose(wedge_world.door, ep.door_angle(), spec.length,
                                        WedgePose(*pose))
            set_frame_pose(ep.sim, ep.body, ((x, y, wedge_world.stage.top_z),
                                             pb.getQuaternionFromEuler((0, 0, yaw))))
            obs = ep.observe()
            px, py, pz, pyaw = obs.perceived_poses()[name]
            tx, ty, tz, tyaw = obs.truth[name]
            # bench/perception_error.py: wedges 0.5 mm mean, 1.9 mm worst, heading
            # 3.6 degrees worst with the world's 1 mm depth noise; tip never reversed.
            assert abs(math.degrees(angle_error(pyaw, tyaw, 2 * math.pi))) < 6.0
            assert math.hypot(px - tx, py - ty) < 0.003
            assert abs(pz - tz) < 0.003
    finally:
        ep.close()
