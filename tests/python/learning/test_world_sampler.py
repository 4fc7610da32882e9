"""Randomised worlds (``--world-seed N``): the sampler on every shipped case.

The engine gives each catalogued number's qualitative range; the sampler draws inside
it. Checked here: the same seed gives the same world, different seeds differ, every
drawn number lies inside its object's own range (the range of the value the shipped
object has), every object keeps its structural literals, the catalogue is a
permutation, a number stays within the manifest's bounds for its field and for its
object's value (``short = {max = 0.20}``), the locations stay within the manifest's
[randomise] bounds, and the
drawn world passes the run's own checks (check_catalogue, the loader's scene checks),
and every drawn tool lies still on its stand (the physics: a sim test).
"""

import dataclasses

import pytest

from creative_py.bridge import Engine, fact_term
from creative_py.case import load_cases
from creative_py.learning.checks import check_catalogue
from creative_py.learning.drawn_world import draw_catalogue_world
from creative_py.backends.pybullet import load_world, tool_rests
from creative_py.backends.pybullet.tools import catalogue_facts
from creative_py.simulator.randomise import apply_drawn

# The pybullet cases: drawn worlds are that backend's (the ManiSkill backend draws none).
# move_ball's demonstration cannot pass the benchmark's done() (a ball at rest scores
# 0.884 at most), so no drawn world keeps it: test_no_world_is_drawn_where_the_... below.
UNDRAWABLE = ("move_ball",)
CASES = sorted(c for c, m in load_cases().items()
               if m.backend == "pybullet" and c not in UNDRAWABLE)

pytestmark = pytest.mark.sim


def _inside(x, lo, hi, bounds):
    return {"closed_open": lo <= x < hi, "closed_closed": lo <= x <= hi,
            "open_closed": lo < x <= hi}[bounds]


@pytest.fixture(scope="module")
def engine():
    return Engine.instance()


_DRAWS: dict = {}


def _drawn(engine, case, seed):
    """Each case's world seeds 0 and 1 are drawn once for the module."""
    if (case, seed) not in _DRAWS:
        _DRAWS[(case, seed)] = draw_catalogue_world(engine, load_world(load_cases()[case]),
                                                    seed)
    return _DRAWS[(case, seed)]


@pytest.mark.parametrize("case", UNDRAWABLE)
def test_no_world_is_drawn_where_the_demonstration_cannot_reach_the_goal(engine, case):
    with pytest.raises(ValueError, match="world seed 0: the demonstration .* failed in the "
                                         "physics"):
        draw_catalogue_world(engine, load_world(load_cases()[case]), 0)


@pytest.mark.parametrize("case", CASES)
def test_same_seed_same_world_and_different_seeds_differ(engine, case):
    world = load_world(load_cases()[case])
    a = _drawn(engine, case, 0)
    # The second draw runs the demonstration (physics, the dearest part) only where the
    # first one needed a redraw (paddle_tube's seed 0): when the first demonstration
    # reaches the goal, draw_world returns the draw as it stands, so the check changes
    # nothing in the world and the same sampler code is compared without it.
    b = draw_catalogue_world(engine, world, 0, check_demonstration=a["redraws"] > 0)
    assert a == b
    c = _drawn(engine, case, 1)
    assert c["objects"] != a["objects"]
    assert c["order"] != a["order"] or c["locations"] != a["locations"]
    assert apply_drawn(world, a).catalogue == apply_drawn(world, b).catalogue


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("seed", [0, 1])
def test_every_drawn_number_lies_inside_its_own_range(engine, case, seed):
    world = load_world(load_cases()[case])
    facts = [fact_term(f) for spec in world.catalogue.values() for f in catalogue_facts(spec)]
    ranges, values = {}, {}
    for r in engine.catalogue_ranges(case, facts):
        obj, fact, _x, _p, v, lo, hi, bounds = r.args
        ranges[(str(obj), str(fact))] = (float(lo), float(hi), str(bounds))
        values[(str(obj), str(fact))] = str(v)
    # a cylinder's width is its drawn length (its diameter), not a number of its own
    tied_free = lambda s: ({"length", "height"} if getattr(s, "shape", "") == "cylinder"
                           else {f.name for f in dataclasses.fields(s)})
    bounded = 0
    drawn = _drawn(engine, case, seed)
    new = apply_drawn(world, drawn)
    assert sorted(drawn["order"]) == sorted(world.items)
    assert list(new.items) == drawn["order"]
    demo = world.manifest.demonstration.tool
    assert new.items[demo].spec == world.items[demo].spec   # the trainer's tool is kept
    changed = 0
    for name, spec in new.catalogue.items():
        old = world.catalogue[name]
        fields = spec.FACT_FIELDS
        for fact, fld in fields.items():
            if (name, fact) not in ranges:
                assert getattr(spec, fld) == getattr(old, fld)
                continue
            lo, hi, bounds = ranges[(name, fact)]
            assert _inside(getattr(spec, fld), lo, hi, bounds), (name, fld, getattr(spec, fld))
            for f, a, b in world.manifest.catalogue_bounds:   # [randomise.catalogue]
                if f == fld:
                    assert a <= getattr(spec, fld) <= b, (name, fld, getattr(spec, fld))
            for f, v, a, b in world.manifest.catalogue_value_bounds:   # short = {...}
                if f == fld and v == values[(name, fact)] and fld in tied_free(spec):
                    assert a <= getattr(spec, fld) <= b, (name, fld, v, getattr(spec, fld))
                    bounded += 1
            changed += getattr(spec, fld) != getattr(old, fld)
        lits = lambda s: {str(x) for x in engine.abstract_state(
            case, [fact_term(f) for f in catalogue_facts(s)])}
        assert lits(spec) == lits(old), name
    assert changed > len(world.items)
    assert bounded or not world.manifest.catalogue_value_bounds
    check_catalogue(engine, new)
    assert all(tool_rests(new, name) for name in new.items)
    jitters = world.manifest.location_jitter
    if not jitters:     # a case whose locations are fixed (a benchmark's scene) keeps them
        assert new.location_sets == world.location_sets, case
    for i, (before, after) in enumerate(zip(world.location_sets, new.location_sets), 1):
        ns = world.namespace(world.manifest.demonstration.variant, i, demo)
        for j in jitters:
            base = float(before[j.key]) if j.key in before else float(ns.get(j.key))
            assert j.min - 1e-9 <= after[j.key] <= j.max + 1e-9
            assert abs(after[j.key] - base) <= j.jitter + 1e-9


def test_a_value_table_naming_no_catalogued_value_is_refused(engine, tmp_path):
    """A typo in a value table (``shrot``) would narrow nothing: it is an error naming
    the file, the table and the values the catalogue has."""
    import shutil

    from creative_py.case import read_manifest
    from creative_py.world_files import WORLDS_ROOT

    folder = tmp_path / "hook_tube"
    shutil.copytree(WORLDS_ROOT / "hook_tube", folder)
    text = (folder / "case.toml").read_text()
    old = "short = {min = 0.15, max = 0.20}"
    assert old in text
    (folder / "case.toml").write_text(text.replace(old, "shrot = {min = 0.15, max = 0.20}"))
    world = load_world(read_manifest(folder), folder)
    with pytest.raises(ValueError, match=r"hook_tube/case.toml: \[randomise.catalogue."
                       r"handle_length\] 'shrot': no catalogued object has this value "
                       r"\(values of handle_length: long, medium, short\)"):
        draw_catalogue_world(engine, world, 0)
