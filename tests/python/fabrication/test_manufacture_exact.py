"""Exact tests of the manufacturing path (creative_py/fabrication/manufacture.py).

Whole values: the vocabularies the ontology gives every case (each its kind's), every
line a bad spec or context gets, the dimensions the real CLP(R) size model (Prolog)
solves for each kind, the catalogue facts of the sized tool, the log lines, and one
written tool (no G-code: the slicing is tested in test_manufacture.py). The helpers
that need no Prolog are called directly.

What every case or kind has is derived from the cases that exist (``creative cases``:
:func:`creative_py.case.load_cases`) and the ontology, never from a list of them: a new
world folder with its ontology file, or a new kind, changes nothing here.
"""

from __future__ import annotations

import json
import logging
import re
import time
from pathlib import Path

import pytest

from creative_py.bridge import Compound, Engine, PrologError, Var
from creative_py.case import load_cases
from creative_py.kinds import spec_from_dict
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec
from creative_py.kinds.paddle import PaddleSpec
from creative_py.fabrication import manufacture
from creative_py.fabrication.manufacture import (InfeasibleSpec, SizedTool, ToolVocabulary,
                                              context_facts, make_tool, parse_context,
                                              parse_spec, size_tool, tool_vocabulary)
from creative_py.mesh.printability import PrintSettings

LOGGER = "creative_py.fabrication.manufacture"


def C(name, *args):
    return Compound(name, args)


@pytest.fixture(scope="module")
def engine() -> Engine:
    """Return the process's one Prolog engine with the default ontology loaded."""
    engine = Engine.instance()
    engine.load_default_ontology()
    return engine


# The vocabularies, as the ontology gives them (ontology/kinds/, ontology/ranges.pl).
HOOK_PROPS = {"handle_length": ("short", "medium", "long"), "handle_width": ("thin", "thick"),
              "hook_length": ("short", "long"), "hook_width": ("narrow", "wide"),
              "hook_side": ("right", "left"), "hook_angle": ("acute", "right", "obtuse")}
STICK_PROPS = {"handle_length": ("short", "medium", "long"), "handle_width": ("thin", "thick")}
HOOK_KINDS = {"hook": (("tool", "hook_like", "hook"), HOOK_PROPS),
              "stick": (("tool", "hook_like", "stick"), STICK_PROPS)}
WEDGE_KINDS = {"block": (("object", "block"), {
    "shape": ("triangular_prism", "box", "cylinder"),
    "block_length": ("short", "medium", "long"), "block_width": ("narrow", "wide"),
    "block_height": ("low", "high"), "mechanical_advantage": ("below_one", "above_one")})}
PADDLE_KINDS = {"paddle": (("tool", "paddle"), {
    "shaft_length": ("short", "medium", "long"), "shaft_width": ("thin", "thick"),
    "blade_width": ("narrow", "wide"), "blade_length": ("short", "long")})}
# The vocabulary of each kind's root class (ontology/kinds/<kind>.pl), for every case of
# that kind.
KIND_VOCABULARIES = {"hook_like": HOOK_KINDS, "block": WEDGE_KINDS, "paddle": PADDLE_KINDS}
HOOK_ALLOWED = ("kind=hook|stick; handle_length=short|medium|long; handle_width=thin|thick; "
                "hook_length=short|long; hook_width=narrow|wide; hook_side=right|left; "
                "hook_angle=acute|right|obtuse")
# The task facts the shipped kinds' and cases' size models read, in the ontology's order;
# another case or kind may add its own anywhere among them.
SHIPPED_FACTS = {
    "tube_length_m": 2, "tube_inner_m": 3, "reach_zone": 4, "shelf_depth_m": 2,
    "shelf_clearance_m": 3, "door_gap_m": 2, "max_tool_length": 1, "min_wall_m": 1,
    "min_handle_width_m": 1, "reach_margin_m": 1, "tube_clearance_m": 1,
    "min_prong_m": 1, "shelf_prong_margin_m": 1, "shelf_flat_margin_m": 1,
    "min_tip_height_m": 1}
# The cases that exist, as `creative cases` lists them and an unknown case's error names
# them.
KNOWN_CASES = ", ".join(sorted(load_cases()))
ATOM_RULE = "must be a Prolog atom: a lower-case ASCII letter followed by letters, digits or underscores"
LONG_TUBE = [C("tube_length_m", "tube1", 0.45), C("tube_inner_m", "tube1", 0.1, 0.07)]
SHELF = [C("shelf_depth_m", "shelf1", 0.3), C("shelf_clearance_m", "shelf1", 0.24, 0.04)]


# ---------------------------------------------------------------- without Prolog

def test_infeasible_spec_message_names_spec_and_task_items():
    both = InfeasibleSpec("h1", ["handle_length(h1,long)", "hook(h1)"], ["max_tool_length(0.3)"])
    assert (both.name, both.conflicts) == ("h1", ["handle_length(h1,long)", "hook(h1)",
                                                  "max_tool_length(0.3)"])
    assert str(both) == ("h1: no tool satisfies the spec's handle_length(h1,long), hook(h1) "
                         "together with the task's max_tool_length(0.3) (a minimal conflict: "
                         "dropping any one of these makes the spec feasible)")
    facts = InfeasibleSpec("h2", [], ("door_gap_m(door1,0.05)", "min_wall_m(0.01)"))
    assert facts.conflicts == ["door_gap_m(door1,0.05)", "min_wall_m(0.01)"]
    assert str(facts) == ("h2: no tool satisfies the task's door_gap_m(door1,0.05), "
                          "min_wall_m(0.01) (a minimal conflict: dropping any one of these "
                          "makes the spec feasible)")
    assert str(InfeasibleSpec("h3", ("hook(h3)",), ())) == (
        "h3: no tool satisfies the spec's hook(h3) (a minimal conflict: dropping any one of "
        "these makes the spec feasible)")


def test_printer_limits_are_added_unless_the_context_gives_them():
    settings = PrintSettings(min_feature=0.003, min_tip=0.001)
    tube = C("tube_length_m", "tube1", 0.3)
    assert manufacture._with_printer((tube,), settings) == [
        tube, C("min_wall_m", 0.003), C("min_tip_height_m", 0.001)]
    assert manufacture._with_printer([], PrintSettings()) == [
        C("min_wall_m", 0.002), C("min_tip_height_m", 0.0008)]
    own = [C("min_tip_height_m", 0.004), tube, C("min_wall_m", 0.02)]
    assert manufacture._with_printer(own, settings) == own
    assert manufacture._with_printer([C("min_wall_m", 0.02)], settings) == [
        C("min_wall_m", 0.02), C("min_tip_height_m", 0.001)]
    assert manufacture._with_printer([C("min_tip_height_m", 0.004), "max_tool_length"],
                                     settings) == [
        C("min_tip_height_m", 0.004), "max_tool_length", C("min_wall_m", 0.003)]


def test_replace_renames_the_tool_inside_compounds_and_lists_only():
    t = Var("T")
    term = C("touching", t, ["a", t, C("part", t, "T")], 1)
    assert manufacture._replace(term, t, "tool1") == C(
        "touching", "tool1", ["a", "tool1", C("part", "tool1", "T")], 1)
    assert manufacture._replace([t, "b"], t, "x") == ["x", "b"]
    assert manufacture._replace(C("hook", "a", "b", "a"), "a", "x") == C("hook", "x", "b", "x")
    assert manufacture._replace(1, 1.0, "x") == 1          # equal but not the same type


def test_did_you_mean_names_the_closest_choice_or_nothing():
    assert manufacture._did_you_mean("hok", ["hook", "stick", "hooks"]) == \
        " (did you mean 'hook'?)"
    assert manufacture._did_you_mean("xyz", {"hook": 1, "stick": 2}) == ""


@pytest.mark.parametrize("name", ["Tool", "_t", "1t", "t-1", "t\n", "", None, 3])
def test_check_atom_refuses_what_is_not_a_plain_prolog_atom(name):
    with pytest.raises(ValueError) as info:
        manufacture._check_atom(name, "tool name")
    assert str(info.value) == f"tool name {name!r} {ATOM_RULE}"


def test_check_atom_accepts_a_plain_atom():
    assert manufacture._check_atom("hook_new1", "tool") is None
    assert manufacture._check_atom("hB9_", "tool") is None


def test_vocabulary_properties_and_subject_names():
    hook = ToolVocabulary("hook", HOOK_KINDS)
    assert hook.default_kind == "hook"
    assert hook.properties == {"kind": ("hook", "stick"), **HOOK_PROPS}
    assert hook.subject_names() == {"tool", "hook_like", "hook", "stick", *HOOK_PROPS}
    wedge = ToolVocabulary("wedge", WEDGE_KINDS)
    assert wedge.properties == WEDGE_KINDS["block"][1]
    assert wedge.subject_names() == {"object", "block", "shape", "block_length",
                                     "block_width", "block_height", "mechanical_advantage"}
    # A kind's class literals and properties both count, each kind's own.
    two = ToolVocabulary("x", {"a": (("top", "a"), {"p": ("v",)}),
                               "b": (("top", "b"), {"q": ("w",)})})
    assert two.subject_names() == {"top", "a", "b", "p", "q"}


# ---------------------------------------------------------------- vocabulary

@pytest.fixture
def fresh_vocabularies(monkeypatch):
    """Ask the ontology again: no vocabulary kept from an earlier test."""
    monkeypatch.setattr(manufacture, "_VOCABULARIES", {})


def test_tool_vocabulary_of_every_case_is_its_kinds(engine, fresh_vocabularies):
    roots = {}
    for case in sorted(load_cases()):
        root = str(engine.tool_vocabulary(case)[0].args[0])     # case_tool_class/2
        roots[case] = root
        if root in KIND_VOCABULARIES:
            assert tool_vocabulary(engine, case) == ToolVocabulary(case,
                                                                   KIND_VOCABULARIES[root])
    # the paper's two cases and the paddle case are among them, with their kinds
    assert {c: roots.get(c) for c in ("hook", "wedge", "paddle_tube")} == {
        "hook": "hook_like", "wedge": "block", "paddle_tube": "paddle"}
    assert tool_vocabulary(engine, "hook") is tool_vocabulary(engine, "hook")   # asked once
    with pytest.raises(ValueError) as info:
        tool_vocabulary(engine, "door")
    assert str(info.value) == f"unknown case 'door'; known cases: {KNOWN_CASES}"
    assert "door" not in KNOWN_CASES.split(", ")


def _ontology_text() -> str:
    root = Path(__file__).resolve().parents[3] / "ontology"
    return "\n".join(p.read_text() for p in sorted(root.rglob("*.pl")))


def test_context_facts_are_the_size_models(engine):
    facts = context_facts(engine)
    # the shipped size models' facts, whole and in the ontology's order
    assert {n: a for n, a in facts.items() if n in SHIPPED_FACTS} == SHIPPED_FACTS
    # one case's: its own size model's, whole and in its ontology's order (the list
    # over every case follows the order the cases load in, which a new case changes)
    assert context_facts(engine, "hook") == {
        "tube_length_m": 2, "tube_inner_m": 3, "max_tool_length": 1, "min_wall_m": 1,
        "min_handle_width_m": 1, "reach_margin_m": 1, "tube_clearance_m": 1}
    assert context_facts(engine, "wedge") == {
        "door_gap_m": 2, "max_tool_length": 1, "min_wall_m": 1, "min_tip_height_m": 1}
    assert list(context_facts(engine, "wedge")) == ["door_gap_m", "max_tool_length",
                                                    "min_wall_m", "min_tip_height_m"]
    # any other is a context fact some size_constraint/3 or a margin size_parameter/3 names
    text = _ontology_text()
    for name, arity in facts.items():
        assert isinstance(arity, int) and arity >= 1
        if name not in SHIPPED_FACTS:
            assert (re.search(rf"size_constraint\(\w+,\s*{name}\(", text)
                    or re.search(rf"size_parameter\({name},", text)), name


# ---------------------------------------------------------------- parse_spec

def test_parse_spec_gives_the_whole_literal_lists(engine, fresh_vocabularies):
    assert parse_spec("rake", " kind = stick , handle_width=thick,handle_width=thick", "s1",
                      engine=engine) == [
        C("tool", "s1"), C("hook_like", "s1"), C("stick", "s1"), C("handle_width", "s1", "thick")]
    assert parse_spec("pull_cube_tool", "kind=hook") == [
        C("tool", "new_tool"), C("hook_like", "new_tool"), C("hook", "new_tool")]
    assert parse_spec("paddle_tube", "blade_width=wide,shaft_length=long", "p1") == [
        C("tool", "p1"), C("paddle", "p1"), C("blade_width", "p1", "wide"),
        C("shaft_length", "p1", "long")]
    assert parse_spec("wedge", "mechanical_advantage=above_one,block_height=high", "w") == [
        C("object", "w"), C("block", "w"), C("mechanical_advantage", "w", "above_one"),
        C("block_height", "w", "high")]


@pytest.mark.parametrize("case, text, message", [
    ("hook", "handle_lenght=long",
     "hook spec 'handle_lenght=long': unknown property 'handle_lenght' (did you mean "
     "'handle_length'?); allowed properties: kind, handle_length, handle_width, hook_length, "
     "hook_width, hook_side, hook_angle"),
    ("hook", "handle_length=lon",
     "hook spec 'handle_length=lon': handle_length cannot be 'lon' (did you mean 'long'?); "
     "allowed values: short, medium, long"),
    ("hook", "kind=stik",
     "hook spec 'kind=stik': kind cannot be 'stik' (did you mean 'stick'?); allowed values: "
     "hook, stick"),
    ("wedge", "xyz=1",
     "wedge spec 'xyz=1': unknown property 'xyz'; allowed properties: shape, block_length, "
     "block_width, block_height, mechanical_advantage"),
    ("wedge", "shape=prism",
     "wedge spec 'shape=prism': shape cannot be 'prism'; allowed values: triangular_prism, "
     "box, cylinder"),
    ("paddle_tube", "kind=paddle",
     "paddle_tube spec 'kind=paddle': unknown property 'kind'; allowed properties: "
     "shaft_length, shaft_width, blade_width, blade_length"),
    ("hook", "handle_length=long=x",
     "hook spec 'handle_length=long=x': handle_length cannot be 'long=x' (did you mean "
     "'long'?); allowed values: "
     "short, medium, long"),
    ("hook", "hook_side=left, handle_length",
     f"hook spec 'hook_side=left, handle_length': 'handle_length' is not property=value; "
     f"allowed: {HOOK_ALLOWED}"),
    ("hook", "=long", f"hook spec '=long': '=long' is not property=value; allowed: "
                      f"{HOOK_ALLOWED}"),
    ("hook", "handle_length=",
     f"hook spec 'handle_length=': 'handle_length=' is not property=value; allowed: "
     f"{HOOK_ALLOWED}"),
    ("hook", "handle_length=long,handle_length=short",
     "hook spec 'handle_length=long,handle_length=short': handle_length given twice (long "
     "and short)"),
    ("hook", "kind=stick,hook_length=long,hook_side=left",
     "hook spec 'kind=stick,hook_length=long,hook_side=left': a stick has no hook_length, "
     "hook_side (its properties: handle_length, handle_width)"),
    ("hook", " ", f"hook spec: empty; give property=value pairs separated by commas, from: "
                  f"{HOOK_ALLOWED}"),
    ("hook", None, f"hook spec: empty; give property=value pairs separated by commas, from: "
                   f"{HOOK_ALLOWED}"),
    ("wedge", "", "wedge spec: empty; give property=value pairs separated by commas, from: "
                  "shape=triangular_prism|box|cylinder; block_length=short|medium|long; "
                  "block_width=narrow|wide; block_height=low|high; "
                  "mechanical_advantage=below_one|above_one"),
    ("door", "shape=box", f"unknown case 'door'; known cases: {KNOWN_CASES}"),
])
def test_parse_spec_refuses_a_bad_spec_in_one_whole_line(case, text, message):
    with pytest.raises(ValueError) as info:
        parse_spec(case, text)
    assert str(info.value) == message


@pytest.mark.parametrize("tool", ["New", 3])
def test_parse_spec_refuses_a_bad_tool_name(tool):
    with pytest.raises(ValueError) as info:
        parse_spec("hook", "kind=stick", tool)
    assert str(info.value) == f"tool {tool!r} {ATOM_RULE}"


# ---------------------------------------------------------------- parse_context

def test_parse_context_gives_the_facts_or_one_whole_line(engine):
    known = ", ".join(f"{n}/{a}" for n, a in context_facts(engine).items())
    assert set(SHIPPED_FACTS) <= set(context_facts(engine))
    assert parse_context(engine, "reach_zone(zone1, -0.6, 0, 0.6), min_wall_m(0.004)") == [
        C("reach_zone", "zone1", -0.6, 0, 0.6), C("min_wall_m", 0.004)]
    assert parse_context(engine, "") == []
    for text, why in [("max_tool_length", "unknown task fact max_tool_length"),
                      ("foo", "unknown task fact foo"),
                      ("max_tool_length(0.3, 1)", "unknown task fact max_tool_length(0.3,1)"),
                      ("door_gap_m(0.01)", "unknown task fact door_gap_m(0.01)")]:
        with pytest.raises(ValueError) as info:
            parse_context(engine, text)
        assert str(info.value) == (f"--context {text!r}: {why}; the size model "
                                   f"understands {known}")
    with pytest.raises(ValueError) as info:
        parse_context(engine, "min_wall_m(0.01), tube_length_m(tube1, X)")
    assert str(info.value) == ("--context 'min_wall_m(0.01), tube_length_m(tube1, X)': "
                               "tube_length_m(tube1,X) must be ground (atoms and numbers)")
    with pytest.raises(ValueError) as info:
        parse_context(engine, "max_tool_length(0.3")
    assert str(info.value) == ("--context 'max_tool_length(0.3': not Prolog facts (syntax "
                               "error: operator expected at line 1, column 20)")


# ---------------------------------------------------------------- size_tool

HOOK_LONG = {"handle_length": 0.6, "handle_width": 0.018, "hook_length": 0.036,
             "hook_width": 0.012, "hook_angle_deg": 90, "hook_side": "left"}


def test_size_tool_solves_a_long_hook_for_the_long_tube(engine, caplog):
    lits = parse_spec("hook", "handle_length=long,hook_side=left,hook_length=long")
    caplog.set_level(logging.INFO, logger=LOGGER)
    start = time.perf_counter()
    sized = size_tool(engine, "hook", lits, LONG_TUBE, "hook_new1")
    wall = time.perf_counter() - start
    assert sized == SizedTool(
        name="hook_new1", case="hook", kind="hook",
        literals=("tool(hook_new1)", "hook_like(hook_new1)", "hook(hook_new1)",
                  "handle_length(hook_new1,long)", "hook_side(hook_new1,left)",
                  "hook_length(hook_new1,long)"),
        dims=HOOK_LONG, spec=HookSpec(name="hook_new1", mass=None, **HOOK_LONG),
        seconds=sized.seconds)
    assert 0 < sized.seconds <= wall
    assert [str(f) for f in sized.catalogue_facts()] == [
        "object_kind(hook_new1,hook)", "handle_length_m(hook_new1,0.6)",
        "handle_width_m(hook_new1,0.018)", "hook_length_m(hook_new1,0.036)",
        "hook_width_m(hook_new1,0.012)", "hook_side_is(hook_new1,left)",
        "hook_angle_deg(hook_new1,90)"]
    assert [(r.name, r.levelno, r.getMessage()) for r in caplog.records] == [
        (LOGGER, logging.INFO, f"sized hook hook_new1 in {1e3 * sized.seconds:.1f} ms: "
                               f"{HOOK_LONG}")]


@pytest.mark.parametrize("case, spec, context, kind, dims", [
    ("rake", "kind=stick,handle_length=long", SHELF, "stick",
     {"handle_length": 0.575, "handle_width": 0.01, "hook_length": 0.0, "hook_width": 0.0,
      "hook_side": "none", "hook_angle_deg": 90}),
    ("rake", "hook_angle=obtuse,hook_width=wide", SHELF, "hook",
     {"handle_length": 0.525, "handle_width": 0.01, "hook_length": 0.017,
      "hook_width": 0.014, "hook_angle_deg": 128, "hook_side": "right"}),
    ("pull_cube_tool", "hook_side=left", [C("reach_zone", "zone1", -0.615, 0.0, 0.6)], "hook",
     {"handle_length": 0.4, "handle_width": 0.018, "hook_length": 0.045, "hook_width": 0.012,
      "hook_angle_deg": 90, "hook_side": "left"}),
    ("paddle_tube", "shaft_length=long,blade_width=wide", LONG_TUBE, "paddle",
     {"shaft_length": 0.6, "shaft_width": 0.018, "blade_width": 0.0625,
      "blade_length": 0.035}),
    ("wedge", "shape=triangular_prism,block_length=long", [C("door_gap_m", "door1", 0.01)],
     "block", {"length": 0.16, "width": 0.085, "height": 0.0475, "tip_height": 0.0024,
               "shape": "triangular_prism"}),
])
def test_size_tool_solves_each_kind_exactly(engine, case, spec, context, kind, dims):
    lits = parse_spec(case, spec, "t1")
    sized = size_tool(engine, case, lits, context, "t2")
    assert (sized.name, sized.case, sized.kind, sized.dims) == ("t2", case, kind, dims)
    assert sized.literals == tuple(str(lit).replace("t1", "t2") for lit in lits)
    assert sized.spec == spec_from_dict({"kind": kind, "name": "t2", "mass": None, **dims})
    assert type(sized.spec) is {"stick": HookSpec, "hook": HookSpec, "paddle": PaddleSpec,
                                "block": BlockSpec}[kind]


def test_size_tool_catalogue_facts_of_a_stick_and_a_block(engine):
    stick = size_tool(engine, "rake", parse_spec("rake", "kind=stick"), [], "s")
    assert [str(f) for f in stick.catalogue_facts()] == [
        "object_kind(s,stick)", "handle_length_m(s,0.4)", "handle_width_m(s,0.018)",
        "hook_length_m(s,0.0)", "hook_width_m(s,0.0)", "hook_side_is(s,none)"]
    box = size_tool(engine, "wedge", parse_spec("wedge", "shape=box"), [], "b")
    assert [str(f) for f in box.catalogue_facts()] == [
        "object_kind(b,block)", "block_shape(b,box)", "block_length_m(b,0.115)",
        "block_width_m(b,0.085)", "block_height_m(b,0.0475)"]


def test_size_tool_renames_an_atom_tool_and_keeps_other_objects(engine):
    body = [C("in_tube", "cube1", "tube1"), C("hook", "a"), C("behind", "cube1", "a"),
            C("handle_length", "a", "long"), C("in_tube", "a", "tube1")]
    sized = size_tool(engine, "hook", body, [], "x")
    assert (sized.kind, sized.literals) == ("hook", (
        "in_tube(cube1,tube1)", "hook(x)", "behind(cube1,x)", "handle_length(x,long)",
        "in_tube(x,tube1)"))
    assert sized.dims == {"handle_length": 0.575, "handle_width": 0.018, "hook_length": 0.03,
                          "hook_width": 0.012, "hook_angle_deg": 90, "hook_side": "right"}
    stick = size_tool(engine, "hook", [C("stick", Var("S")), C("handle_length", Var("S"),
                                                                "short")], [], "y")
    assert (stick.kind, stick.literals, stick.dims["handle_length"]) == (
        "stick", ("stick(y)", "handle_length(y,short)"), 0.175)


def test_size_tool_gives_the_cases_first_kind_when_no_literal_names_one(engine):
    hook = size_tool(engine, "hook", [C("hook_like", Var("T")),
                                      C("handle_length", Var("T"), "short")], [], "z")
    assert (hook.kind, hook.literals, hook.dims) == (
        "hook", ("hook_like(z)", "handle_length(z,short)"),
        {"handle_length": 0.175, "handle_width": 0.018, "hook_length": 0.03,
         "hook_width": 0.012, "hook_angle_deg": 90, "hook_side": "right"})
    block = size_tool(engine, "wedge", [C("block_length", "w", "short")], [], "z")
    assert (block.kind, block.literals, block.dims) == (
        "block", ("block_length(z,short)",),
        {"length": 0.05, "width": 0.085, "height": 0.0475, "tip_height": 0.0024,
         "shape": "triangular_prism"})


def test_size_tool_names_a_minimal_conflict_in_one_line(engine):
    cases = [
        ("hook", "handle_length=long", [C("max_tool_length", 0.3)], "hb",
         ["handle_length(hb,long)"], ["max_tool_length(0.3)"]),
        ("wedge", "block_height=low", [C("door_gap_m", "door1", 0.05)], "wb",
         ["block_height(wb,low)"], ["door_gap_m(door1,0.05)"]),
        ("paddle_tube", "shaft_length=medium", LONG_TUBE, "pb",
         ["shaft_length(pb,medium)"], ["tube_length_m(tube1,0.45)"]),
    ]
    for case, spec, context, name, lits, facts in cases:
        with pytest.raises(InfeasibleSpec) as info:
            size_tool(engine, case, parse_spec(case, spec), context, name)
        assert (info.value.name, info.value.conflicts) == (name, lits + facts)
        assert str(info.value) == str(InfeasibleSpec(name, lits, facts))


@pytest.mark.parametrize("literals, message", [
    ([C("hook", "a"), C("handle_length", "b", "long")],
     "x: the literals describe more than one tool: a, b"),
    ([C("in_tube", "a", "tube1"), C("behind", "a", "cube1")],
     "x: no class or structural literal of the hook case among in_tube(a,tube1), "
     "behind(a,cube1)"),
    ([], "x: no class or structural literal of the hook case among no literals"),
    (C("hook", "a"), "x: literals must be a list of terms, got Compound(name='hook', "
                     "args=('a',))"),
    ("hook(a)", "x: literals must be a list of terms, got 'hook(a)'"),
    ([C("hook", "a"), "hook"], "x: literal 'hook' is not a compound term"),
    ([C("hook", Var("_"))], "x: the tool argument of the literals is the anonymous variable"),
    ([C("hook", "a"), C("frobble", "a")],
     "x: the knowledge base does not know the literal frobble(x) (solve_size: "
     "error(domain_error(structural_literal(hook),frobble(x)),_G0)); load the ontology "
     "first (engine.load_default_ontology())"),
])
def test_size_tool_refuses_bad_literals_in_one_whole_line(engine, literals, message):
    with pytest.raises(ValueError) as info:
        size_tool(engine, "hook", literals, [], "x")
    assert type(info.value) is ValueError and str(info.value) == message


def test_size_tool_refuses_a_bad_name_or_case_and_passes_other_prolog_errors(engine):
    with pytest.raises(ValueError) as info:
        size_tool(engine, "hook", [C("hook", "a")], [], "X1")
    assert str(info.value) == f"tool name 'X1' {ATOM_RULE}"
    with pytest.raises(ValueError) as info:
        size_tool(engine, "lever", [C("hook", "a")], [], "x")
    assert str(info.value) == f"unknown case 'lever'; known cases: {KNOWN_CASES}"
    with pytest.raises(PrologError) as info:
        size_tool(engine, "hook", [C("hook", "a")], [C("tube_length_m", "tube1", "far")], "x")
    assert str(info.value) == "solve_size: error(existence_error(size_parameter,far),_G0)"


def test_size_tool_keeps_the_printers_least_wall(engine):
    lits = parse_spec("hook", "kind=stick,handle_width=thin")
    thin = size_tool(engine, "hook", lits, [], "s", settings=PrintSettings(min_feature=0.010))
    assert thin.dims["handle_width"] == 0.011
    own = size_tool(engine, "hook", lits, [C("min_wall_m", 0.002)], "s",
                    settings=PrintSettings(min_feature=0.010))
    assert own.dims["handle_width"] == 0.009


# ---------------------------------------------------------------- make_tool

def test_make_tool_writes_the_sized_tool_with_its_printer(engine, tmp_path, caplog):
    """The one written tool of this module (no G-code): a thin stick, whose least wall
    and build volume are the printer's."""
    lits = parse_spec("hook", "kind=stick,handle_length=short,handle_width=thin")
    settings = PrintSettings(min_feature=0.010, build_volume=(0.2, 0.2, 0.2))
    old = tmp_path / "stick_x"
    old.mkdir()
    (old / "old.txt").write_text("old")
    with pytest.raises(FileExistsError):
        make_tool(engine, "hook", lits, [], "stick_x", tmp_path, settings=settings)
    caplog.set_level(logging.INFO, logger=LOGGER)
    caplog.clear()
    start = time.perf_counter()
    files = make_tool(engine, "hook", lits, [], "stick_x", tmp_path, settings=settings,
                      overwrite=True, gcode=False)
    wall_ms = 1e3 * (time.perf_counter() - start)
    assert files.spec == spec_from_dict({
        "kind": "stick", "name": "stick_x", "mass": None, "handle_length": 0.175,
        "handle_width": 0.011, "hook_length": 0.0, "hook_width": 0.0, "hook_side": "none",
        "hook_angle_deg": 90})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["stick_x"]
    assert not (old / "old.txt").exists() and files.png == old / "stick_x.png"
    assert files.png.is_file() and files.gcode == ()
    entry = json.loads(files.manifest.read_text())["print"]
    assert (entry["build_volume_mm"], entry["min_feature_mm"], entry["sliced"]) == (
        [200.0, 200.0, 200.0], 10.0, False)
    sized_line, made_line = [r.getMessage() for r in caplog.records if r.name == LOGGER]
    sized_ms = re.fullmatch(r"sized stick stick_x in (\d+\.\d) ms: \{.*\}", sized_line).group(1)
    made = re.fullmatch(r"made stick_x: sized in (\d+\.\d) ms, written in (\d+\.\d) ms",
                        made_line)
    written_ms = float(made.group(2))
    assert made.group(1) == sized_ms
    assert 0.9 * (wall_ms - float(sized_ms)) <= written_ms <= wall_ms - float(sized_ms) + 0.1
    # Without the picture (cheap now that the mesh code is warm).
    bare = make_tool(engine, "hook", lits, [], "stick_y", tmp_path, settings=settings,
                     picture=False, gcode=False)
    assert bare.png is None and sorted(p.name for p in bare.directory.glob("*.png")) == []
