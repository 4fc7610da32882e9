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
