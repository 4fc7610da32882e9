"""Scenes from data: scene expressions, overrides, body kinds (no robot, quick)."""

import math

import pytest

from creative_py.backends.pybullet.core import Sim
from creative_py.backends.pybullet.scene import BODY_BUILDERS, make_bodies
from creative_py.world.bodies import BODY_KINDS, REQUIRED, BodyTable
from creative_py.world.expressions import Namespace
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

    cls = BODY_BUILDERS[kind]
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
    bodies = make_bodies(world.scene.bodies, ns)
    body = bodies[tables[0].name]
    assert isinstance(body, cls)
    with Sim(PhysicsSettings()) as sim:
        # A body id, or -1 for a kind whose parts are bodies of their own (a scatter:
        # its cubes are the scene's other bodies, built beside it).
        assert isinstance(body.build(sim), int)
        for other in bodies.values():
            if other is not body:
                other.build(sim)
        facts = body.facts(sim)
        centre = body.centre(sim)
    assert all(isinstance(f, tuple) and f[1] == body.name for f in facts), facts
    assert len(centre) == 4 and all(math.isfinite(x) for x in centre)
def _defaults(kind):
    return {k: v for k, v in BODY_KINDS[kind].FIELDS.items()
            if k in ("friction", "colour", "room") and v is not REQUIRED}


def _first_hit(sim, start, end):
    import pybullet as pb

    hit = pb.rayTest(start, end, physicsClientId=sim.client)[0]
    return hit[0], tuple(hit[3])


def test_a_standing_shelf_is_a_passage_over_its_top_with_its_facts():
    # HighObject's shelf: the plate's top at 0.90, its front at 1.10 (x 1.10-1.50).
    fields = {**_defaults("standing_shelf"), "front_x": 1.1, "axis_y": 0.0, "top_z": 0.9,
              "floor_z": 0.0, "depth": 0.4, "width": 1.2, "board": 0.03,
              "post_radius": 0.015, "post_inset": 0.01, "post_side_inset": 0.03,
              "runner_width": 0.05, "runner_height": 0.03}
    shelf = _build("standing_shelf", **fields)
    with Sim(PhysicsSettings()) as sim:
        body = shelf.build(sim)
        facts = shelf.facts(sim)
        # Straight down onto the plate's top, and under the plate onto a runner.
        hit, point = _first_hit(sim, (1.3, 0.0, 2.0), (1.3, 0.0, 0.0))
        assert hit == body and point[2] == pytest.approx(0.9, abs=1e-4)
        hit, point = _first_hit(sim, (1.11, 0.2, 0.8), (1.11, 0.2, -0.5))
        assert hit == body and point[2] == pytest.approx(0.03, abs=1e-4)
        # In front of the front edge nothing stands.
        assert _first_hit(sim, (1.08, 0.0, 2.0), (1.08, 0.0, -0.5))[0] == -1
    assert facts == [("shelf_top", "thing", 1.1, 0.0, 0.9), ("shelf_top_depth_m", "thing", 0.4)]
    assert (shelf.mouth_x, shelf.passage_floor_z, shelf.inner_width, shelf.inner_height) == \
        (1.1, 0.9, 1.2, 0.3)


def test_an_open_box_is_open_at_the_top_with_its_facts():
    # HighObject's box: 0.38 x 1.20 outside, walls 0.10 high and 0.015 thick.
    box = _build("open_box", **_defaults("open_box"), position=[0.8, 0.0], floor_z=0.0,
                 size=[0.38, 1.2, 0.1], wall=0.015)
    with Sim(PhysicsSettings()) as sim:
        body = box.build(sim)
        facts = box.facts(sim)
        hit, point = _first_hit(sim, (0.8, 0.0, 1.0), (0.8, 0.0, -0.5))
        assert hit == body and point[2] == pytest.approx(0.015, abs=1e-4)   # the floor
        hit, point = _first_hit(sim, (0.98, 0.0, 1.0), (0.98, 0.0, -0.5))
        assert hit == body and point[2] == pytest.approx(0.1, abs=1e-4)     # a wall's top
    assert facts[0] == ("open_box_rim", "thing", 0.8, 0.0, 0.1)
    assert facts[1] == ("open_box_inner_m", "thing", pytest.approx(0.35), pytest.approx(1.17),
                        0.015, 0.1)


def test_bookends_carry_the_row_and_give_a_room_above_it():
    # OneBook's bookends: uprights' inner faces at y -0.08 and 0.12, plates 0.012 thick.
    bookends = _build("bookends", **_defaults("bookends"), centre_x=0.6, left_y=-0.08,
                      right_y=0.12, floor_z=0.0, depth=0.28, height=0.188, plate=0.012,
                      plate_width=0.11, thickness=0.01, room=0.40)
    with Sim(PhysicsSettings()) as sim:
        body = bookends.build(sim)
        facts = bookends.facts(sim)
        for y in (-0.07, 0.02, 0.11):        # the plates meet under the whole row
            hit, point = _first_hit(sim, (0.6, y, 1.0), (0.6, y, -0.5))
            assert hit == body and point[2] == pytest.approx(0.012, abs=1e-4)
        hit, point = _first_hit(sim, (0.6, -0.2, 0.1), (0.6, 0.3, 0.1))     # the left upright
        assert hit == body and point[1] == pytest.approx(-0.09, abs=1e-4)
    assert facts == [("bookends_front", "thing", pytest.approx(0.46), pytest.approx(0.02), 0.012),
                     ("bookends_room_m", "thing", pytest.approx(0.2), 0.40, 0.28)]
    assert bookends.passage_floor_z == 0.012 and bookends.inner_height == 0.40


@pytest.mark.parametrize("kind, fields, message", [
    ("open_box", {"position": [0.8, 0.0], "floor_z": 0.0, "size": [0.38, 1.2, 0.1],
                  "wall": 0.2}, "wall must be positive and thinner"),
    ("bookends", {"centre_x": 0.6, "left_y": 0.1, "right_y": -0.1, "floor_z": 0.0,
                  "depth": 0.28, "height": 0.2, "plate": 0.01, "plate_width": 0.1,
                  "thickness": 0.01, "room": 0.4}, "right_y must be greater than left_y"),
    ("standing_shelf", {"front_x": 1.1, "axis_y": 0.0, "top_z": 0.02, "floor_z": 0.0,
                        "depth": 0.4, "width": 1.2, "board": 0.03, "post_radius": 0.015,
                        "post_inset": 0.01, "post_side_inset": 0.03, "runner_width": 0.05,
                        "runner_height": 0.03}, "top_z must lie more than board above"),
])
def test_a_body_of_the_new_kinds_that_cannot_be_built_is_named(kind, fields, message):
    with pytest.raises(WorldFileError, match=rf"s\.toml: body\[0\]: body thing: {message}"):
        _build(kind, **_defaults(kind), **fields)


def test_a_lane_has_no_walls_and_reports_its_passage_and_goal():
    import pybullet as pb

    lane = BODY_BUILDERS["lane"]("lane1", {"mouth_x": 0.95, "axis_y": 0.0, "floor_z": 0.0,
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
        BODY_BUILDERS["lane"]("lane1", {**lane.v, "length": 0.0})
