"""The pusher kind (``creative_py/kinds/pusher.py``, ``ontology/kinds/pusher.pl``): a walled
head hung below a pole (RoboToolBench's MoveBall and CleanTable), added as one module
and one ontology file.

Its spec and solid, its catalogue facts, its size model (CLP(R), through the engine as
Algorithm 2 calls it, with the clean_table case's sizing of the mouth), its strength
model and how the simulator holds it.
"""

from __future__ import annotations

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.fabrication.strength import check_strength
from creative_py.kinds import kind_of, spec_classes, spec_from_dict
from creative_py.kinds.parts import Box, Hull
from creative_py.kinds.pusher import PusherSpec
from creative_py.mesh.solid import tool_mesh

FUNNEL = PusherSpec("funnel_a1", 0.25, 0.014, 0.22, 0.05, 0.11, mass=None)
"""A 0.25 m pole, a 0.22 m plate, wings 5 cm long spreading 11 cm each: a 0.44 m mouth."""


@pytest.fixture(scope="module")
def engine() -> Engine:
    """Return the process's one Prolog engine with the default ontology loaded."""
    engine = Engine.instance()
    engine.load_default_ontology()
    return engine


def test_the_pusher_is_registered_by_its_ontology_file():
    assert spec_classes()["pusher"] is PusherSpec
    spec = spec_from_dict({"kind": "pusher", "name": "p1", "pole_length": 0.25,
                           "pole_width": 0.014, "plate_width": 0.22})
    assert spec == PusherSpec("p1", 0.25, 0.014, 0.22)
    assert kind_of(spec) == "pusher" and spec.kind == "pusher"
    assert spec.wing_length == 0.0 and spec.mouth_width() == pytest.approx(0.22)


@pytest.mark.parametrize("fields, message", [
    (dict(wing_length=0.0, wing_spread=0.05), "a wing_spread needs wings"),
    (dict(plate_width=0.01), "plate_width must be at least the pole and two walls"),
    (dict(wing_length=-0.01), "must not be negative"),
    (dict(pole_length=0.05), "grip_offset must lie on the pole"),
])
def test_an_impossible_pusher_is_refused(fields, message):
    base = dict(name="p1", pole_length=0.25, pole_width=0.014, plate_width=0.22)
    with pytest.raises(ValueError, match=message):
        PusherSpec(**{**base, **fields})


def test_its_head_hangs_below_the_pole_and_its_wings_spread_forward():
    parts = FUNNEL.parts()
    assert [type(p) for p in parts] == [Box, Box, Box, Hull, Hull]
    plate = parts[2]
    assert plate.center == pytest.approx((0.25 - 0.005, 0.10 + 0.03, 0.0))
    assert plate.size == pytest.approx((0.01, 0.06, 0.22))
    tips = [v for v in parts[3].vertices if v[0] == pytest.approx(0.30)]
    assert max(v[2] for v in tips) == pytest.approx(0.11 + 0.11)
    assert FUNNEL.working_point() == pytest.approx((0.275, 0.13, 0.0))
    assert FUNNEL.reach() == pytest.approx(0.16)
    assert FUNNEL.mouth_width() == pytest.approx(0.44)
    mesh = tool_mesh(FUNNEL)
    assert mesh.is_watertight
    assert mesh.bounds.ravel().tolist() == pytest.approx(
        [0.0, -0.007, -0.22, 0.30, 0.16, 0.22], abs=1e-6)


def test_the_catalogue_facts_are_the_ontology_s_primitive_predicates():
    text = open("ontology/kinds/pusher.pl").read()
    facts = FUNNEL.catalogue_facts()
    assert facts[0] == ("object_kind", "funnel_a1", "pusher")
    for name, *_ in facts:
        assert f"catalogue_predicate(pusher, {name}/2)." in text
    assert set(PusherSpec.FACT_FIELDS) == {f[0] for f in facts[1:]}


def test_the_clean_table_sizes_a_funnel_wider_than_the_field_of_cubes(engine):
    literals = [Compound("tool", ("p",)), Compound("pusher", ("p",)),
                Compound("pole_length", ("p", "short")), Compound("plate_width", ("p", "medium")),
                Compound("wing_length", ("p", "short")), Compound("wing_spread", ("p", "flared"))]
    facts = [Compound("size", ("cubes", 0.40, 0.43, 0.03)),
             Compound("reach_zone", ("goal1", 1.1, 0.0, 0.15)),
             Compound("max_tool_length", (0.8,)), Compound("min_wall_m", (0.0008,))]
    reply = engine.solve_size("clean_table", "pusher", literals, facts)
    assert reply.name == "dims"
    dims = {eq.args[0]: eq.args[1] for eq in reply.args[0]}
    assert dims["plate_width"] + 2 * dims["wing_spread"] >= 0.43 + 0.04 - 1e-9
    assert 0.22 <= dims["plate_width"] <= 0.24 and 0.22 <= dims["pole_length"] <= 0.24
    assert 0.06 <= dims["wing_length"] <= 0.08
    assert dims["wing_spread"] <= 2 * dims["wing_length"] + 1e-9
    spec = spec_from_dict({"kind": "pusher", "name": "pusher_new1", "mass": None, **dims})
    assert spec.mouth_width() >= 0.47 - 1e-9
    narrow = [*literals[:3], Compound("plate_width", ("p", "narrow")),
              Compound("wing_length", ("p", "short")), Compound("wing_spread", ("p", "none"))]
    assert engine.solve_size("clean_table", "pusher", narrow, facts).name == "infeasible"


def test_the_strength_check_is_the_pole_as_a_cantilever():
    load = {"max_force_n": 10.0, "point": [0.25, 0.13, 0.1], "grasp_point": [0.04, 0, 0]}
    check = check_strength(FUNNEL, load)
    assert check.model == "cantilever"
    assert check.lever_arm_m == pytest.approx(0.21)
    assert check.stress_pa == pytest.approx(6 * 10.0 * 0.21 / 0.014 ** 3)


def test_the_simulator_holds_it_by_the_pole_like_a_handle():
    from creative_py.backends.pybullet.tools import HandleHeld, tool_kind

    assert isinstance(tool_kind(FUNNEL), HandleHeld)
    assert FUNNEL.handle_length == 0.25 and FUNNEL.handle_width == 0.014
    assert FUNNEL.head_width == pytest.approx(0.014)  # the pedestal stops short of the neck
    q = FUNNEL.quantities()
    assert q["inner_half"] == pytest.approx(0.10) and q["wall_height"] == pytest.approx(0.06)


@pytest.mark.parametrize("wings", [{"wing_length": 0.05, "wing_spread": 0.0},
                                   {"wing_length": 0.0, "wing_spread": 0.0},
                                   {"wing_length": 0.05, "wing_spread": 0.11}],
                         ids=["parallel wings (a U)", "no wings (a blade)", "a funnel"])
def test_a_pusher_is_printable_and_its_volume_is_its_solid_s(tmp_path, wings):
    # The wings' spread places them (0: parallel) and is no printed feature; a blade has
    # no wings to print. Both are pushers the size model may ask for (wing_spread none).
    # The check holds the STL's volume to the spec's (what a created tool's mass is
    # made from) within 0.1 %: the wings overlap the base plate, counted once.
    from creative_py.mesh.check import check_tool_files
    from creative_py.mesh.export import write_tool_files

    spec = PusherSpec("u_a1", 0.25, 0.014, 0.22, mass=None, **wings)
    report = check_tool_files(write_tool_files(spec, tmp_path / "u_a1", picture=False))
    assert report.ok, report
