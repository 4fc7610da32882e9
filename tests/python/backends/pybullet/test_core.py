"""The Sim object: settings, stepping, saved states, blow-up detection."""

import math

import pybullet as pb
import pytest

from creative_py.mesh.spec import Box
from creative_py.backends.pybullet.bodies import Surface, frame_pose, set_frame_pose, spawn_parts
from creative_py.backends.pybullet.core import Sim
from creative_py.world_files import PhysicsSettings

pytestmark = pytest.mark.sim


def _cube(sim, z=1.0):
    return spawn_parts(sim, [Box((0, 0, 0.015), (0.03, 0.03, 0.03))], ((0, 0, z), (0, 0, 0, 1)),
                       0.05, Surface())


def test_time_step_and_gravity_come_from_the_settings():
    with Sim(PhysicsSettings(time_step=0.01, solver_iterations=10, gravity=(0, 0, -2.0))) as sim:
        params = pb.getPhysicsEngineParameters(physicsClientId=sim.client)
        assert params["fixedTimeStep"] == pytest.approx(0.01)
        assert params["numSolverIterations"] == 10
        body = _cube(sim)
        sim.step(100)
        assert sim.time == pytest.approx(1.0)
        # Free fall for 1 s at 2 m/s^2 (semi-implicit Euler: within a step of 1 m).
        assert frame_pose(sim, body)[0][2] == pytest.approx(0.0, abs=0.03)


def test_saved_restores_poses_and_the_step_count():
    with Sim(PhysicsSettings()) as sim:
        body = _cube(sim)
        with sim.saved():
            sim.step(120)
            assert frame_pose(sim, body)[0][2] < 0.9
        assert sim.steps == 0
        assert frame_pose(sim, body)[0][2] == pytest.approx(1.0)


def test_blow_up_names_a_thrown_or_broken_body():
    with Sim(PhysicsSettings()) as sim:
        body = _cube(sim)
        assert sim.blow_up(body) == ""
        pb.resetBaseVelocity(body, (30, 0, 0), (0, 0, 0), physicsClientId=sim.client)
        assert "m/s" in sim.blow_up(body)
        set_frame_pose(sim, body, ((100.0, 0, 0), (0, 0, 0, 1)))
        assert "left the scene" in sim.blow_up(body)


def test_close_is_idempotent_and_frees_the_client():
    sim = Sim(PhysicsSettings())
    client = sim.client
    sim.close()
    sim.close()
    assert not pb.isConnected(physicsClientId=client)


def test_hidden_parts_collide_but_are_invisible():
    with Sim(PhysicsSettings()) as sim:
        lid = spawn_parts(sim, [Box((0, 0, 0), (0.2, 0.2, 0.01))], ((0, 0, 0.1), (0, 0, 0, 1)),
                          0.0, Surface(), hidden=[0])
        ball = _cube(sim, z=0.2)
        sim.step(240)
        assert frame_pose(sim, ball)[0][2] == pytest.approx(0.105, abs=0.003)  # rests on it
        shapes = pb.getVisualShapeData(lid, physicsClientId=sim.client)
        assert shapes and all(s[7][3] == 0.0 for s in shapes)  # alpha 0
        assert math.isfinite(frame_pose(sim, ball)[0][0])
