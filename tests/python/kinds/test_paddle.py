"""The paddle kind (``creative_py/kinds/paddle.py``, ``ontology/kinds/paddle.pl``): a tool
kind added as one module and one ontology file, working like the others.

Its spec and solid, its size model (CLP(R), through the engine as Algorithm 2 calls it),
its files (URDF, SDF, SCAD rendered by OpenSCAD, STL, print pieces with dowel pins and
their G-code), its strength check and thickening, and the simulator's handling of it.
"""

from __future__ import annotations

import math
import shutil

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.kinds import kind_of, spec_classes, spec_from_dict
from creative_py.kinds.paddle import PaddleSpec
from creative_py.fabrication.strength import check_strength, thicker_dims
from creative_py.mesh.check import check_print_files, check_tool_files
from creative_py.mesh.export import read_tool_files, write_tool_files
from creative_py.mesh.solid import mass_properties, tool_mesh, tool_solid
from creative_py.mesh.spec import PLA_DENSITY, spec_mass

PADDLE = PaddleSpec("paddle_a1", 0.30, 0.010, 0.080, 0.030, mass=None)
"""A 300 mm paddle with an 80 x 30 mm blade on a 10 mm shaft (fits the printer)."""

LONG_PADDLE = PaddleSpec("paddle_a2", 0.55, 0.012, 0.100, 0.040, mass=None)
"""A 550 mm paddle: longer than the build volume, printed in pieces."""


@pytest.fixture(scope="module")
def engine() -> Engine:
    """Return the process's one Prolog engine with the default ontology loaded."""
    engine = Engine.instance()
    engine.load_default_ontology()
    return engine


def test_the_paddle_is_registered_by_its_ontology_file():
    assert spec_classes()["paddle"] is PaddleSpec
    spec = spec_from_dict({"kind": "paddle", "name": "p1", "shaft_length": 0.3,
                           "shaft_width": 0.01, "blade_width": 0.05, "blade_length": 0.02})
    assert spec == PaddleSpec("p1", 0.3, 0.01, 0.05, 0.02)
    assert kind_of(spec) == "paddle" and spec.kind == "paddle"


def test_a_paddle_whose_blade_is_narrower_than_its_shaft_or_gripped_on_the_blade_is_refused():
    with pytest.raises(ValueError, match="blade_width .* must be at least shaft_width"):
        PaddleSpec("p1", 0.3, 0.02, 0.01, 0.02)
    with pytest.raises(ValueError, match="grip_offset must lie on the bare shaft"):
        PaddleSpec("p1", 0.1, 0.01, 0.05, 0.07)
    with pytest.raises(ValueError, match="unknown field.*hook_length"):
        spec_from_dict({"kind": "paddle", "name": "p1", "shaft_length": 0.3,
                        "shaft_width": 0.01, "blade_width": 0.05, "blade_length": 0.02,
                        "hook_length": 0.02})


def test_the_solid_is_one_shell_with_the_spec_s_volume_and_pla_mass():
    w, L, bw, bl = 0.010, 0.30, 0.080, 0.030
    by_hand = L * w * w + bl * (bw - w) * w
    assert PADDLE.volume() == pytest.approx(by_hand, rel=1e-12)
    mesh = tool_mesh(PADDLE)
    assert mesh.is_watertight
    assert mesh.volume == pytest.approx(by_hand, rel=1e-9)
    assert mesh.bounds.ravel().tolist() == pytest.approx([0, -bw / 2, -w / 2, L, bw / 2, w / 2])
    assert spec_mass(PADDLE) == pytest.approx(PLA_DENSITY * by_hand)
    assert len(tool_solid(PADDLE).decompose()) == 1


def test_the_catalogue_facts_are_the_ontology_s_primitive_predicates():
    text = open("ontology/kinds/paddle.pl").read()
    facts = PADDLE.catalogue_facts()
    assert facts[0] == ("object_kind", "paddle_a1", "paddle")
    for name, *_ in facts:
        assert f"catalogue_predicate(paddle, {name}/2)." in text
    assert set(PaddleSpec.FACT_FIELDS) == {f[0] for f in facts[1:]}


def test_the_size_model_sizes_a_paddle_for_its_literals_and_the_task(engine):
    literals = [Compound("tool", ("p",)), Compound("paddle", ("p",)),
                Compound("shaft_length", ("p", "long")), Compound("blade_width", ("p", "wide"))]
    reply = engine.solve_size("paddle_tube", "paddle", literals, [Compound("max_tool_length", (0.5,)),
                                                   Compound("min_wall_m", (0.0008,))])
    assert reply.name == "dims"
    dims = {eq.args[0]: eq.args[1] for eq in reply.args[0]}
    assert 0.45 <= dims["shaft_length"] <= 0.5
    assert 0.06 <= dims["blade_width"] <= 0.12
    spec = spec_from_dict({"kind": "paddle", "name": "paddle_new1", "mass": None, **dims})
    assert spec.shaft_length == dims["shaft_length"]
    too_short = engine.solve_size("paddle_tube", "paddle", literals, [Compound("max_tool_length", (0.3,))])
    assert too_short.name == "infeasible"
    assert Compound("shaft_length", ("p", "long")) in too_short.args[0]


@pytest.mark.skipif(shutil.which("openscad") is None, reason="openscad is not installed")
def test_its_files_pass_every_check_including_openscad(tmp_path):
    files = write_tool_files(PADDLE, tmp_path, gcode=False)
    report = check_tool_files(files)
    assert report.ok, report.problems
    assert "blade_width = 80;" in files.scad.read_text()
    again = read_tool_files(files.directory)
    assert again.spec == PADDLE
    assert again.mass.mass == pytest.approx(mass_properties(PADDLE).mass)


@pytest.mark.skipif(shutil.which("prusa-slicer") is None, reason="prusa-slicer is not installed")
def test_a_long_paddle_is_printed_in_pieces_joined_by_a_pin_and_sliced(tmp_path):
    files = write_tool_files(LONG_PADDLE, tmp_path, picture=False, gcode=True)
    assert not files.fits_build_volume
    roles = [p.stem.rsplit("_", 1)[1] for p in files.pieces]
    assert roles == ["part1", "part2", "pin1"]
    assert len(files.gcode) == len(files.pieces)
    check = check_print_files(files)
    assert check.ok, check.problems


def test_the_strength_check_is_the_shaft_as_a_cantilever():
    load = {"max_force_n": 20.0, "point": [0.28, 0.03, 0.0], "grasp_point": [0.04, 0, 0],
            "bodies": ["box1"]}
    check = check_strength(PADDLE, load)
    assert check.model == "cantilever"
    assert check.lever_arm_m == pytest.approx(0.24)
    w = PADDLE.shaft_width
    assert check.stress_pa == pytest.approx(6 * 20.0 * 0.24 / w ** 3)
    assert check.verdict == "fail"  # 28.8 MPa: a safety factor of 1.7
    assert check.required_handle_width_m == pytest.approx(
        math.ceil((6 * 20.0 * 0.24 * 2.0 / 50e6) ** (1 / 3) / 1e-4) * 1e-4)


def test_a_weak_paddle_is_thickened_by_its_size_model_or_rejected(engine):
    load = {"max_force_n": 20.0, "point": [0.28, 0.0, 0.0], "grasp_point": [0.04, 0, 0]}
    weak = check_strength(PADDLE, load)
    literals = [Compound("paddle", ("p",)), Compound("shaft_length", ("p", "medium"))]
    reply = thicker_dims(engine, "paddle_tube", "paddle", literals, [], weak)
    assert reply.name == "dims"
    dims = {eq.args[0]: eq.args[1] for eq in reply.args[0]}
    assert dims["shaft_width"] >= weak.required_handle_width_m
    thicker = spec_from_dict({"kind": "paddle", "name": "p2", "mass": None, **dims})
    assert check_strength(thicker, load).verdict == "pass"
    thin = literals + [Compound("shaft_width", ("p", "thin"))]
    assert thicker_dims(engine, "paddle_tube", "paddle", thin, [], weak).name == "dims"  # 10.5 mm is thin
    weaker = check_strength(PADDLE, {**load, "max_force_n": 60.0})  # needs 15.2 mm
    reply = thicker_dims(engine, "paddle_tube", "paddle", thin, [], weaker)
    assert reply.name == "infeasible"
    assert Compound("shaft_width", ("p", "thin")) in reply.args[0]


def test_the_simulator_holds_it_by_the_shaft_like_a_handle():
    from creative_py.backends.pybullet.tools import (HandleHeld, catalogue_facts, prong_centre,
                                       prong_reach, roll_of, tool_kind, tool_orientation)

    assert isinstance(tool_kind(PADDLE), HandleHeld)
    assert catalogue_facts(PADDLE) == PADDLE.catalogue_facts()
    assert prong_centre(PADDLE) == pytest.approx((0.285, 0.0, 0.0))
    assert prong_reach(PADDLE) == pytest.approx(0.04)
    for roll in (-1.2, 0.0, 0.7, math.pi / 2):
        assert roll_of(PADDLE, tool_orientation(PADDLE, roll)) == pytest.approx(roll)


@pytest.mark.sim
def test_its_urdf_and_its_spec_make_the_same_pybullet_body_lying_flat(tmp_path):
    import pybullet as pb

    from creative_py.backends.pybullet.bodies import frame_pose, load_tool_urdf, spawn_spec
    from creative_py.backends.pybullet.core import Sim
    from creative_py.world_files import PhysicsSettings

    files = write_tool_files(PADDLE, tmp_path, picture=False, gcode=False)
    flat = ((0.0, 0.0, PADDLE.shaft_width / 2 + 0.001), (0.0, 0.0, 0.0, 1.0))
    with Sim(PhysicsSettings()) as sim:
        plane = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE,
                                                              physicsClientId=sim.client),
                                   physicsClientId=sim.client)
        assert plane >= 0
        bodies = [load_tool_urdf(sim, files.urdf, flat),
                  spawn_spec(sim, PADDLE, ((0.0, 0.3, flat[0][2]), flat[1]))]
        for _ in range(240):
            sim.step()
        for body in bodies:
            links = range(-1, pb.getNumJoints(body, physicsClientId=sim.client))
            mass = sum(pb.getDynamicsInfo(body, k, physicsClientId=sim.client)[0]
                       for k in links)
            assert mass == pytest.approx(spec_mass(PADDLE), rel=1e-6)
            pos, quat = frame_pose(sim, body)
            assert pos[2] == pytest.approx(PADDLE.shaft_width / 2, abs=1e-3)
            assert abs(quat[0]) < 1e-3 and abs(quat[1]) < 1e-3  # still blade-flat


@pytest.mark.sim
def test_in_the_tube_world_a_paddle_is_picked_up_inserted_and_pulls_the_cube_out():
    """The simulator's handled-tool motion works for the paddle with no code of its own:
    added to the hook world's catalogue (in memory; the hook case's files and learning
    are unchanged), it lies on the pedestal, is gripped by its shaft, carried, inserted
    blade-flat above the cube, lowered and turned upright behind it, and the pull brings
    the cube out of the tube (the physics decides)."""
    from creative_py.case import get_case
    from creative_py.backends.pybullet import load_world, open_episode
    from creative_py.simulator.trial import run_trial

    paddle = PaddleSpec("paddle_t1", 0.35, 0.010, 0.050, 0.012)
    world = load_world(get_case("hook")).with_tool(paddle)
    from creative_py.bridge import Engine
    from creative_py.learning.poses import pose_resolver

    with open_episode(world, "standard", 1, paddle.name, seed=0) as ep:
        facts = ep.observe().facts
        assert ("object_kind", paddle.name, "paddle") in facts
        assert ep.run_skill("pick_up").ok
        held = ep.observe().facts
        assert ("held", paddle.name) in held
        assert {f[0] for f in held} >= {"tip_position", "tool_roll"}
    result = run_trial(world, paddle.name, "standard", 1, pose=(0.03, 0.0, 0.0),
                       pose_target=pose_resolver(Engine.instance(), world.manifest))
    assert result.outcome == "success", result.reason
    assert result.max_tool_force_n > 0
