"""Tests of the manufacturing path: qualitative spec -> sized spec -> checked files.

The size model is the real one (Prolog, CLP(R)); the files are read back and checked
against OpenSCAD by :func:`creative_py.mesh.check.check_tool_files`. Expected ranges
are those of the shared vocabulary (ontology/ranges.pl).
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET

import pytest
import trimesh

from creative_py.bridge import Compound, Engine, Var
from creative_py.fabrication.manufacture import (InfeasibleSpec, default_context, make_tool,
                                              parse_context, parse_spec, size_tool,
                                              tool_vocabulary)
from creative_py.mesh.check import check_print_files, check_tool_files
from creative_py.mesh.printability import PrintSettings
from creative_py.mesh.spec import PLA_DENSITY
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec
from creative_py.world_files import WorldFileError


@pytest.fixture(scope="module")
def engine() -> Engine:
    """Return the process's one Prolog engine with the default ontology loaded."""
    engine = Engine.instance()
    engine.load_default_ontology()
    return engine


def C(name, *args):
    return Compound(name, args)


def readback(engine, sized) -> set[str]:
    """Return the structural literals the knowledge base derives from the sized tool."""
    case = "hook" if sized.case == "hook" else "wedge"
    return {str(lit) for lit in engine.abstract_state(case, sized.catalogue_facts())}


def assert_printed(files) -> dict:
    """Check a made tool as a printer would get it, from its files: PLA mass in the URDF,
    pieces inside the build volume, their union, and every piece's G-code; return the
    manifest's "print" entry."""
    urdf_mass = float(ET.parse(files.urdf).getroot().find("link/inertial/mass").get("value"))
    stl_m3 = trimesh.load_mesh(files.stl).volume / 1e9          # the STL is in mm
    assert urdf_mass == pytest.approx(PLA_DENSITY * stl_m3, rel=0.02)
    entry = json.loads(files.manifest.read_text())["print"]
    assert entry["printable"] and entry["sliced"]
    assert abs(entry["union_volume_error_pct"]) <= 0.5
    for row in entry["pieces"]:
        assert (files.directory / row["gcode"]).is_file()
        assert row["print_time_s"] > 0 and row["filament_mm"] > 0 and row["filament_g"] > 0
        assert all(0 < v <= b for v, b in zip(row["bounding_box_mm"], entry["build_volume_mm"]))
    assert entry["print_time_s"] > 0 and entry["filament_g"] > 0
    check = check_print_files(files)
    assert check.ok, check.problems
    assert check.sliced == len(entry["pieces"]) and check.union_mismatch <= 0.005
    return entry


# ---------------------------------------------------------------- parse_spec

def test_parse_spec_gives_class_and_structural_literals_of_a_hook():
    lits = parse_spec("hook", "handle_length=long, hook_side=left,hook_length=long")
    assert [str(x) for x in lits] == [
        "tool(new_tool)", "hook_like(new_tool)", "hook(new_tool)",
        "handle_length(new_tool,long)", "hook_side(new_tool,left)",
        "hook_length(new_tool,long)"]


def test_parse_spec_gives_stick_and_block_classes():
    stick = parse_spec("hook", "kind=stick,handle_length=medium", tool="s1")
    assert [str(x) for x in stick] == ["tool(s1)", "hook_like(s1)", "stick(s1)",
                                       "handle_length(s1,medium)"]
    wedge = parse_spec("wedge", "shape=triangular_prism,block_length=long")
    assert [str(x) for x in wedge] == ["object(new_tool)", "block(new_tool)",
                                       "shape(new_tool,triangular_prism)",
                                       "block_length(new_tool,long)"]


@pytest.mark.parametrize("case, text, expected", [
    ("hook", "handle_lenght=long", r"unknown property 'handle_lenght' \(did you mean "
     r"'handle_length'\?\); allowed properties: kind, handle_length, handle_width, "
     r"hook_length, hook_width, hook_side, hook_angle"),
    ("hook", "handle_length=lon", r"handle_length cannot be 'lon' .*allowed values: "
     r"short, medium, long"),
    ("hook", "block_length=long", r"unknown property 'block_length'"),
    ("wedge", "shape=prism", r"allowed values: triangular_prism, box, cylinder"),
    ("wedge", "handle_length=long", r"allowed properties: shape, block_length, "
     r"block_width, block_height, mechanical_advantage"),
    ("hook", "handle_length", r"'handle_length' is not property=value"),
    ("hook", "handle_length=long,,hook_side=left", r"'' is not property=value"),
    ("hook", "  ", r"empty"),
    ("hook", "handle_length=long,handle_length=short", r"handle_length given twice"),
    ("hook", "kind=stick,hook_length=long", r"a stick has no hook_length"),
    ("door", "shape=box", r"unknown case .door.; known cases: .*hook.*wedge"),
])
def test_parse_spec_refuses_bad_text_naming_what_is_allowed(case, text, expected):
    with pytest.raises(ValueError, match=expected):
        parse_spec(case, text)


@pytest.mark.parametrize("case", ["hook", "wedge"])
def test_vocabulary_agrees_with_the_replacement_operators(engine, case):
    # Each replacement operator of the ontology lists all values of one property.
    props = tool_vocabulary(engine, case).properties
    assert len(props) >= 5
    for prop, values in props.items():
        literal = C(values[0], "t") if prop == "kind" else C(prop, "t", values[0])
        _, alternatives = engine.replacement(literal)
        found = {values[0]} | {a.name if prop == "kind" else a.args[1] for a in alternatives}
        assert found == set(values), prop


# ---------------------------------------------------------------- sizing and making

def test_long_hook_for_the_long_tube_is_sized_inside_its_ranges_and_printed(engine, tmp_path):
    context = default_context("hook", "long_tube")
    assert C("tube_length_m", "tube1", 0.45) in context
    lits = parse_spec("hook", "handle_length=long,hook_side=left,hook_length=long")
    sized = size_tool(engine, "hook", lits, context, "hook_new1")
    d = sized.dims
    assert sized.kind == "hook" and isinstance(sized.spec, HookSpec)
    assert 0.45 < d["handle_length"] < 0.70          # long, strictly inside
    assert d["handle_length"] >= 0.45 + 0.05           # reaches behind a cube at the far end
    assert 0.025 < d["hook_length"] < 0.050            # long prong
    assert d["hook_side"] == "left"
    inner = next(f for f in context if f.name == "tube_inner_m")
    assert d["handle_width"] + d["hook_length"] <= min(inner.args[1:]) - 0.005
    assert sized.spec.mass is None                     # printed PLA
    assert "handle_length(hook_new1,long)" in sized.literals
    assert {"hook(hook_new1)", "handle_length(hook_new1,long)", "hook_side(hook_new1,left)",
            "hook_length(hook_new1,long)"} <= readback(engine, sized)

    files = make_tool(engine, "hook", lits, context, "hook_new1", tmp_path, picture=False)
    assert files.spec == sized.spec
    assert [p.name for p in tmp_path.iterdir()] == ["hook_new1"]
    check = check_tool_files(files)
    assert check.ok, check.problems
    assert check.scad_volume is not None and check.scad_mismatch_rel < 1e-3
    # Longer than the bed: split into parts joined by a dowel pin, each sliced.
    assert not files.fits_build_volume
    entry = assert_printed(files)
    assert entry["joint"] == "square_dowel_pin"
    assert [p["role"] for p in entry["pieces"]].count("part") >= 2


def test_long_triangular_prism_for_the_door_is_sized_and_printed(engine, tmp_path):
    context = default_context("wedge")
    gap = next(f for f in context if f.name == "door_gap_m").args[1]
    lits = parse_spec("wedge", "shape=triangular_prism,block_length=long")
    sized = size_tool(engine, "wedge", lits, context, "wedge_new1")
    assert isinstance(sized.spec, BlockSpec) and sized.spec.shape == "triangular_prism"
    assert 0.12 < sized.spec.length < 0.20
    assert sized.spec.height > gap
    assert {"shape(wedge_new1,triangular_prism)",
            "block_length(wedge_new1,long)"} <= readback(engine, sized)
    files = make_tool(engine, "wedge", lits, context, "wedge_new1", tmp_path, picture=True)
    assert files.png is not None and files.png.is_file()
    check = check_tool_files(files)
    assert check.ok, check.problems
    assert check.scad_volume is not None
    entry = assert_printed(files)                      # fits: one piece, no joint
    assert len(entry["pieces"]) == 1 and entry["joint"] is None


def test_stick_is_sized_without_a_prong_and_printed(engine, tmp_path):
    lits = parse_spec("hook", "kind=stick,handle_length=short,handle_width=thin")
    files = make_tool(engine, "hook", lits, [], "stick_new1", tmp_path, picture=False,
                      gcode=False)
    assert files.spec.is_stick and 0.10 < files.spec.handle_length < 0.25
    assert 0.006 < files.spec.handle_width < 0.012
    assert check_tool_files(files, openscad=False).ok


def test_infeasible_spec_names_both_conflicting_items_and_writes_nothing(engine, tmp_path):
    lits = parse_spec("hook", "handle_length=long")
    out = tmp_path / "tools"
    with pytest.raises(InfeasibleSpec) as info:
        make_tool(engine, "hook", lits, [C("max_tool_length", 0.3)], "hook_bad", out)
    assert info.value.conflicts == ["handle_length(hook_bad,long)", "max_tool_length(0.3)"]
    assert "handle_length(hook_bad,long)" in str(info.value)
    assert "max_tool_length(0.3)" in str(info.value)
    assert isinstance(info.value, ValueError)
    assert not out.exists()
    out.mkdir()
    with pytest.raises(InfeasibleSpec):
        make_tool(engine, "hook", lits, [C("max_tool_length", 0.3)], "hook_bad", out)
    assert list(out.iterdir()) == []


def test_medium_handle_is_too_short_for_the_long_tube(engine):
    # The paper's tool-creation trigger: the demonstrated medium hook cannot reach.
    lits = parse_spec("hook", "handle_length=medium")
    with pytest.raises(InfeasibleSpec) as info:
        size_tool(engine, "hook", lits, default_context("hook", "long_tube"), "hook_m")
    assert info.value.conflicts == ["handle_length(hook_m,medium)",
                                    "tube_length_m(tube1,0.45)"]


def test_printer_minimum_feature_is_a_sizing_constraint(engine, tmp_path):
    lits = parse_spec("hook", "hook_width=narrow")
    sized = size_tool(engine, "hook", lits, [], "hook_n",
                      settings=PrintSettings(min_feature=0.005))
    assert 0.005 <= sized.spec.hook_width < 0.008
    with pytest.raises(InfeasibleSpec) as info:
        make_tool(engine, "hook", lits, [], "hook_n", tmp_path,
                  settings=PrintSettings(min_feature=0.009))
    assert info.value.conflicts == ["hook_width(hook_n,narrow)", "min_wall_m(0.009)"]
    assert list(tmp_path.iterdir()) == []


def test_hypothesis_literals_with_a_variable_tool_are_renamed(engine):
    t = Var("T")
    body = [C("hook_like", t), C("hook", t), C("handle_length", t, "long"),
            C("in_tube", t, "tube1"), C("behind", t, "cube1"), C("hook_down", t)]
    sized = size_tool(engine, "hook", body, [C("tube_length_m", "tube1", 0.30)], "hook_v")
    assert sized.literals == ("hook_like(hook_v)", "hook(hook_v)",
                              "handle_length(hook_v,long)", "in_tube(hook_v,tube1)",
                              "behind(hook_v,cube1)", "hook_down(hook_v)")
    assert 0.45 < sized.spec.handle_length < 0.70


def test_literals_about_two_tools_or_none_are_refused(engine):
    with pytest.raises(ValueError, match="more than one tool: a, b"):
        size_tool(engine, "hook", [C("hook", "a"), C("handle_length", "b", "long")], [], "x")
    with pytest.raises(ValueError, match="no class or structural literal"):
        size_tool(engine, "hook", [C("in_tube", "a", "tube1")], [], "x")
    with pytest.raises(ValueError, match="must be a Prolog atom"):
        size_tool(engine, "hook", parse_spec("hook", "kind=hook"), [], "Bad name")


# ---------------------------------------------------------------- context

@pytest.mark.sim
def test_default_context_is_what_the_robot_perceives_of_the_variant():
    assert default_context("hook", "long_tube") == [
        C("tube_length_m", "tube1", 0.45), C("tube_inner_m", "tube1", 0.1, 0.07)]
    assert default_context("hook") == [
        C("tube_length_m", "tube1", 0.3), C("tube_inner_m", "tube1", 0.1, 0.07)]
    assert default_context("wedge", "big_door") == [C("door_gap_m", "door1", 0.01)]
    with pytest.raises(ValueError, match="unknown variant 'huge' of case hook; variants: "
                                         "standard, long_tube"):
        default_context("hook", "huge")
    with pytest.raises(ValueError, match="unknown case 'rack'"):
        default_context("rack")


@pytest.mark.sim
def test_default_context_names_a_missing_file_of_a_world_folder(tmp_path):
    import shutil

    from creative_py.world_files import WORLDS_ROOT

    folder = tmp_path / "mine"
    shutil.copytree(WORLDS_ROOT / "hook_tube", folder)
    (folder / "scene.toml").unlink()
    with pytest.raises(WorldFileError, match=r"mine/scene.toml: file not found"):
        default_context("hook", world_dir=folder)


def test_parse_context_reads_task_facts_and_refuses_unknown_ones(engine):
    assert parse_context(engine, "max_tool_length(0.3), tube_length_m(tube1, 0.45)") == [
        C("max_tool_length", 0.3), C("tube_length_m", "tube1", 0.45)]
    assert parse_context(engine, " ") == []
    with pytest.raises(ValueError, match="unknown task fact max_length"):
        parse_context(engine, "max_length(0.3)")
    with pytest.raises(ValueError, match="must be ground"):
        parse_context(engine, "max_tool_length(X)")
    with pytest.raises(ValueError, match="not Prolog facts"):
        parse_context(engine, "max_tool_length(0.3")
