"""Scenes from data: scene expressions, overrides, body kinds (no robot, quick)."""

import math

import pytest

from creative_py.backends.pybullet.core import Sim
from creative_py.backends.pybullet.scene import BODY_KINDS, BodyTable, Namespace, make_bodies
from creative_py.world_files import PhysicsSettings, WorldFileError


def _ns(**bodies):
    return Namespace({"top": -0.2, "gap": "top + 0.1"}, bodies, {"reach": 0.03}, "s.toml")


def test_expressions_use_values_fields_tool_quantities_and_functions():
    ns = _ns(b1={"size": [0.1, 0.2, "b2.size[0] * 3"], "x": "max(gap, 0) + tool.reach"},
             b2={"size": [0.1, 0.1, 0.1]})
    assert ns.get("b1.size") == pytest.approx((0.1, 0.2, 0.3))
    assert ns.get("b1.x") == pytest.approx(0.03)
    assert ns.evaluate("cos(pi) + sqrt(4) - abs(-1) + radians(180) / pi", "w") == \
        pytest.approx(1.0)


def test_overrides_change_what_is_built_from_them():
    ns = _ns(b1={"x": "gap * 2"})
    ns.override({"top": 0.0, "b1.x": "gap * 3"}, "case.toml")
    assert ns.get("b1.x") == pytest.approx(0.3)
    with pytest.raises(WorldFileError, match=r"case\.toml: key 'b1\.y': no such scene value"):
        ns.override({"b1.y": 1.0}, "case.toml")
    with pytest.raises(WorldFileError, match=r"case\.toml: key 'bottom'"):
        ns.override({"bottom": 1.0}, "case.toml")


@pytest.mark.parametrize("text, message", [
    ("nope + 1", "'nope': no such value"),
    ("b1.x", "defined through itself"),
    ("__import__('os')", "uses something an expression cannot"),
    ("1 +", "not an expression"),
    ("tool.mass", "the tool has no such quantity"),
    ("1 / 0", "division by zero"),
])
def test_bad_expressions_are_named(text, message):
    ns = _ns(b1={"x": "b1.x + 1"})
    with pytest.raises(WorldFileError, match=message):
        ns.evaluate(text, "field")


def _build(kind, **fields):
    table = BodyTable("thing", kind, fields, "s.toml: body[0]")
    return make_bodies((table,), Namespace({}, {"thing": fields}, {}, "s.toml"))["thing"]


def test_a_box_with_top_z_has_its_top_there():
    box = _build("box", size=[0.4, 0.4, 0.1], position=[0.5, 0.0], top_z=-0.1,
                 **{k: v for k, v in BODY_KINDS["box"].FIELDS.items()
                    if k not in ("size", "position", "top_z")})
    assert box.top == -0.1 and box.frame_z == pytest.approx(-0.15)


def test_a_shelf_is_a_passage_with_its_facts():
    defaults = {k: v for k, v in BODY_KINDS["shelf"].FIELDS.items()
                if k in ("board", "leg", "friction", "clear_board", "colour")}
    fields = {**defaults, "mouth_x": 0.8, "axis_y": -0.2, "floor_z": -0.2, "depth": 0.3,
              "inner_width": 0.4, "inner_height": 0.05}
    shelf = _build("shelf", **fields)
    with Sim(PhysicsSettings()) as sim:
        assert shelf.build(sim) >= 0
        facts = shelf.facts(sim)
    assert ("shelf_front", "thing", 0.8, -0.2, pytest.approx(-0.175)) == facts[0]
    assert shelf.inner_height == 0.05 and shelf.length == 0.3
    assert not math.isnan(shelf.floor_z)
    assert shelf.dynamic is False


# ---------------------------------------------------------- what every body kind must do
# A new body kind (one BODY_KINDS entry) is checked by this; no line of it changes.

@pytest.mark.parametrize("kind", list(BODY_KINDS))
def test_every_body_kind_builds_from_a_shipped_scene_and_gives_its_facts(kind):
    """Each kind is a SceneBody with bounds for its numeric fields, is built by some
    shipped world's scene.toml, and built there gives a pybullet body, facts about
    itself and a finite centre."""
    from creative_py.backends.pybullet import load_world
    from creative_py.backends.pybullet.scene import SceneBody
    from creative_py.case import load_cases

    cls = BODY_KINDS[kind]
    assert issubclass(cls, SceneBody) and cls.FIELDS
    assert cls.build is not SceneBody.build
    assert set(cls.BOUNDS) <= set(cls.FIELDS), (kind, set(cls.BOUNDS) - set(cls.FIELDS))
    for _, manifest in sorted(load_cases().items()):
        if manifest.backend != "pybullet":
            continue
        world = load_world(manifest)
        tables = [t for t in world.scene.bodies if t.kind == kind]
        if tables:
            break
    else:
        pytest.fail(f"no shipped world's scene.toml has a body of kind {kind!r}")
    demo = world.manifest.demonstration
    ns = world.namespace(demo.variant, demo.location, demo.tool)
    body = make_bodies(world.scene.bodies, ns)[tables[0].name]
    assert isinstance(body, cls)
    with Sim(PhysicsSettings()) as sim:
        # A body id, or -1 for a kind whose parts are bodies of their own (a scatter).
        assert isinstance(body.build(sim), int)
        facts = body.facts(sim)
        centre = body.centre(sim)
    assert all(isinstance(f, tuple) and f[1] == body.name for f in facts), facts
    assert len(centre) == 4 and all(math.isfinite(x) for x in centre)


def test_a_lane_has_no_walls_and_reports_its_passage_and_goal():
    import pybullet as pb

    lane = BODY_KINDS["lane"]("lane1", {"mouth_x": 0.95, "axis_y": 0.0, "floor_z": 0.0,
                                        "length": 0.25, "inner_width": 0.3,
                                        "inner_height": 0.3, "goal_x": 0.6, "mark": 0.07,
                                        "colour": (0.2, 0.8, 0.2, 0.5)})
    assert lane.facts(None) == [("lane_start", "lane1", 0.95, 0.0, 0.15),
                                ("lane_length_m", "lane1", 0.25),
                                ("lane_room_m", "lane1", 0.3, 0.3),
                                ("lane_goal", "lane1", 0.6, 0.0)]
    with Sim(PhysicsSettings()) as sim:
        body = lane.build(sim)
        assert pb.getCollisionShapeData(body, -1, physicsClientId=sim.client) == ()
        assert lane.centre(sim)[:2] == (0.6, 0.0)
    with pytest.raises(ValueError, match="length must be positive"):
        BODY_KINDS["lane"]("lane1", {**lane.v, "length": 0.0})
