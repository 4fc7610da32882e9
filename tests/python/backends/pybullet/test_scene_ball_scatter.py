"""The ball and the scatter of cubes as scene bodies (no robot, quick)."""

import math

import pybullet as pb
import pytest

from creative_py.backends.pybullet.core import Sim
from creative_py.backends.pybullet.scene import make_bodies
from creative_py.world.bodies import BODY_KINDS, BodyTable
from creative_py.world.expressions import Namespace
from creative_py.world_files import PhysicsSettings, WorldFileError


def _bodies(kind, name="cubes", **fields):
    full = {k: v for k, v in BODY_KINDS[kind].FIELDS.items() if k not in fields
            and not (v is not None and type(v) is object)}
    full.update(fields)
    table = BodyTable(name, kind, full, "s.toml: body[0]")
    return make_bodies((table,), Namespace({}, {name: full}, {}, "s.toml"))


SCATTER = dict(count=8, size=0.03, x_range=[0.5, 0.9], y_range=[-0.2, 0.2], floor_z=0.0,
               min_gap=0.06, seed=3)


def test_a_scatter_draws_its_cubes_in_the_rectangle_apart_and_by_its_seed():
    bodies = _bodies("scatter", **SCATTER)
    cubes = [bodies[f"cubes{i}"] for i in range(1, 9)]
    assert set(bodies) == {"cubes", *(f"cubes{i}" for i in range(1, 9))}
    xy = [c.position[:2] for c in cubes]
    assert all(0.5 <= x <= 0.9 and -0.2 <= y <= 0.2 for x, y in xy)
    assert min(math.dist(a, b) for i, a in enumerate(xy) for b in xy[i + 1:]) > 0.06
    assert all(c.size == (0.03, 0.03, 0.03) and c.mass == 1.0 for c in cubes)
    again = _bodies("scatter", **SCATTER)
    assert [again[f"cubes{i}"].position for i in range(1, 9)] == [c.position for c in cubes]
    other = _bodies("scatter", **{**SCATTER, "seed": 4})
    assert other["cubes1"].position != cubes[0].position


def test_a_scatter_that_cannot_place_its_cubes_is_named():
    with pytest.raises(WorldFileError, match=r"s\.toml: body\[0\]: body cubes: cube 2 found no place 0\.06 m"):
        _bodies("scatter", **{**SCATTER, "x_range": [0.5, 0.52], "y_range": [0.0, 0.02]})


def test_the_cubes_rest_on_the_floor_and_the_scatter_reports_their_field():
    bodies = _bodies("scatter", **SCATTER)
    with Sim(PhysicsSettings()) as sim:
        _bodies("box", name="floor", size=[2.0, 2.0, 0.05],
                position=[0.6, 0.0, -0.025])["floor"].build(sim)
        for body in bodies.values():
            body.build(sim)
        sim.step(240)
        centres = [bodies[f"cubes{i}"].centre(sim) for i in range(1, 9)]
        facts = bodies["cubes"].facts(sim)
    assert all(c[2] == pytest.approx(0.015, abs=1e-3) for c in centres)
    xs, ys = [c[0] for c in centres], [c[1] for c in centres]
    pose, size = facts
    assert pose[:2] == ("pose", "cubes")
    assert pose[2] == pytest.approx((min(xs) + max(xs)) / 2, abs=1e-6)
    assert size[2] == pytest.approx(max(xs) - min(xs) + 0.03, abs=1e-6)


def test_a_ball_is_a_sphere_of_its_radius_and_mass():
    ball = _bodies("sphere", name="ball1", radius=0.08, position=[0.6, 0.3, 0.08],
                   mass=1.0)["ball1"]
    with Sim(PhysicsSettings()) as sim:
        ball.build(sim)
        info = pb.getDynamicsInfo(ball.id, -1, physicsClientId=sim.client)
        shape = pb.getCollisionShapeData(ball.id, -1, physicsClientId=sim.client)[0]
    assert info[0] == pytest.approx(1.0) and info[1] == pytest.approx(0.5)
    assert shape[2] == pb.GEOM_SPHERE and shape[3][0] == pytest.approx(0.08)
    assert ball.height == pytest.approx(0.16) and ball.dynamic


def test_a_zone_is_a_goal_disc_that_nothing_touches():
    zone = _bodies("zone", name="goal1", x=1.1, y=0.0, radius=0.15)["goal1"]
    with Sim(PhysicsSettings()) as sim:
        zone.build(sim)
        assert pb.getCollisionShapeData(zone.id, -1, physicsClientId=sim.client) == ()
        facts = zone.facts(sim)
    assert facts == [("reach_zone", "goal1", 1.1, 0.0, 0.15)]
    assert not zone.dynamic
    with pytest.raises(WorldFileError, match="radius must be positive"):
        _bodies("zone", name="goal1", x=1.1, y=0.0, radius=0.0)
