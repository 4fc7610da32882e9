"""Tests of the strength check of created tools (creative_py/fabrication/strength.py).

The beam formula is checked against hand computations; the thickening and the
rejection use the real size model (Prolog, CLP(R)) on the hook case's created tool as
Algorithm 2 sizes it for the long tube, whose context the simulator perceives.
"""

from __future__ import annotations

import json
from dataclasses import replace

import pytest

from creative_py.bridge import Compound, Engine
from creative_py.fabrication.manufacture import default_context, parse_spec, size_tool
from creative_py.fabrication.strength import (StrengthCheck, cantilever_stress,
                                           check_strength, rejected, required_square_width,
                                           thicker_dims, thickening_fact, write_strength)
from creative_py.mesh.export import read_tool_files, write_tool_files
from creative_py.mesh.spec import MIN_SAFETY_FACTOR, PLA_STRENGTH
from creative_py.kinds import spec_from_dict
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec

# The created hook's literals in the hook case (summary.json of a run, seed 0).
CREATED_HOOK = "handle_length=long,handle_width=thin,hook_angle=right"


@pytest.fixture(scope="module")
def engine() -> Engine:
    """Return the process's one Prolog engine with the default ontology loaded."""
    engine = Engine.instance()
    engine.load_default_ontology()
    return engine


def load(force, x, grasp_x=0.04):
    """A trial's tool_load as the simulator records it (tool frame, metres)."""
    return {"max_force_n": force, "point": [x, -0.03, 0.0], "force": [force, 0.0, 0.0],
            "grasp_point": [grasp_x, 0.0, 0.0], "contacts": 4, "bodies": ["cube1"],
            "step": 100, "steps": 600}


def test_cantilever_stress_is_the_hand_computation():
    # 10 N at 0.5 m: M = 5 N m. A 10 mm square: I = 0.01^4 / 12 = 8.333e-10 m^4,
    # c = 0.005 m, sigma = M c / I = 5 * 0.005 / 8.333e-10 = 30 MPa.
    assert cantilever_stress(10.0, 0.5, 0.01, 0.01) == pytest.approx(30.0e6)
    # Twice as wide across the load: half the stress; twice as high along it: a quarter.
    assert cantilever_stress(10.0, 0.5, 0.02, 0.01) == pytest.approx(15.0e6)
    assert cantilever_stress(10.0, 0.5, 0.01, 0.02) == pytest.approx(7.5e6)


def test_the_required_width_gives_the_required_safety_factor():
    w = required_square_width(10.0, 0.5, 50.0e6, 2.0)
    # 6 F L s / strength = 6 * 10 * 0.5 * 2 / 50e6 = 1.2e-6 m^3
    assert w == pytest.approx(1.2e-6 ** (1 / 3))
    assert 50.0e6 / cantilever_stress(10.0, 0.5, w, w) == pytest.approx(2.0)


def test_a_hook_check_uses_the_lever_arm_from_the_grasp_to_the_contact():
    spec = HookSpec("h", 0.6, handle_width=0.009, hook_length=0.03, hook_width=0.012)
    check = check_strength(spec, load(3.0, 0.589), trial=15)
    assert check.model == "cantilever"
    assert check.lever_arm_m == pytest.approx(0.549)
    assert check.moment_nm == pytest.approx(3.0 * 0.549)
    # 6 F L / w^3 = 6 * 3 * 0.549 / 0.009^3 = 13.556 MPa
    assert check.stress_pa == pytest.approx(6 * 3.0 * 0.549 / 0.009 ** 3)
    assert check.stress_pa == pytest.approx(13.556e6, rel=1e-4)
    assert check.safety_factor == pytest.approx(PLA_STRENGTH / check.stress_pa)
    assert check.verdict == "pass" and check.required_safety_factor == MIN_SAFETY_FACTOR
    d = check.to_dict()
    assert d["strength_mpa"] == 50.0 and d["trial"] == 15 and d["bodies"] == ["cube1"]
    assert d["section_m"] == [0.009, 0.009]
    json.dumps(d)


def test_a_block_gets_a_compression_check_not_a_beam_check():
    spec = BlockSpec("w", "triangular_prism", 0.16, 0.085, 0.0275, tip_height=0.0024)
    check = check_strength(spec, {"max_force_n": 40.0, "point": [0.05, 0.0, 0.01],
                                  "bodies": ["door1", "floor1"]})
    assert check.model == "compression" and check.lever_arm_m is None
    assert check.stress_pa == pytest.approx(40.0 / (0.16 * 0.085))
    assert check.verdict == "pass"
    assert "does not apply" in check.note
    with pytest.raises(ValueError, match="only a failed cantilever check"):
        thickening_fact(check)


def test_the_check_uses_the_robust_force_and_keeps_the_peak_with_a_caveat():
    spec = HookSpec("h", 0.6, handle_width=0.009, hook_length=0.03, hook_width=0.012)
    robust = {**load(600.0, 0.589), "robust_force_n": 3.0, "contact_steps": 420}
    check = check_strength(spec, robust)
    assert check.force_n == 3.0 and check.peak_force_n == 600.0
    # The same model under each force: the stress is linear in it.
    assert check.stress_pa == pytest.approx(6 * 3.0 * 0.549 / 0.009 ** 3)
    assert check.verdict == "pass"
    assert check.peak_safety_factor == pytest.approx(check.safety_factor * 3.0 / 600.0)
    assert check.peak_safety_factor < MIN_SAFETY_FACTOR   # the spike alone would fail it
    assert "3.0 N" in check.caveat and "600.0 N" in check.caveat
    assert "420 steps" in check.caveat and "peak" in check.caveat
    d = check.to_dict()
    assert d["force_n"] == 3.0 and d["peak_force_n"] == 600.0
    assert d["peak_safety_factor"] == pytest.approx(check.peak_safety_factor, abs=1e-3)
    assert d["caveat"] == check.caveat


def test_a_load_recorded_before_the_robust_force_is_checked_at_its_peak():
    spec = HookSpec("h", 0.6, handle_width=0.009, hook_length=0.03, hook_width=0.012)
    check = check_strength(spec, load(3.0, 0.589))
    assert check.force_n == check.peak_force_n == 3.0
    assert check.peak_safety_factor == pytest.approx(check.safety_factor)


def test_no_recorded_load_is_unmeasured_not_passed_silently():
    check = check_strength(HookSpec("h", 0.3), None)
    assert check.verdict == "unmeasured" and check.force_n == 0.0
    assert check.peak_force_n is None and check.caveat == ""


@pytest.mark.sim
def test_a_weak_created_hook_is_thickened_by_the_size_model(engine):
    context = default_context("hook", "long_tube")
    sized = size_tool(engine, "hook", parse_spec("hook", CREATED_HOOK), context, "hook_new1")
    assert sized.spec.handle_width == pytest.approx(0.009)
    # 7.6 N at 0.549 m needs a 10.0 mm handle: the 9 mm one fails.
    weak = check_strength(sized.spec, load(7.6, 0.589))
    assert weak.verdict == "fail" and weak.safety_factor < MIN_SAFETY_FACTOR
    assert weak.required_handle_width_m == pytest.approx(0.0101)
    assert str(thickening_fact(weak)) == "min_handle_width_m(0.0101)"
    reply = thicker_dims(engine, "hook", "hook", [l for l in parse_spec("hook", CREATED_HOOK)],
                         context, weak)
    assert reply.name == "dims"
    dims = {str(eq.args[0]): eq.args[1] for eq in reply.args[0]}
    # The size model keeps the tool thin (its literal) and wide enough: [10.1, 12) mm.
    assert 0.0101 <= dims["handle_width"] < 0.012
    assert dims["handle_length"] == sized.dims["handle_length"]
    thick = spec_from_dict({"kind": "hook", "name": "hook_new2", **dims})
    again = check_strength(thick, load(7.6, 0.589), thickened_from="hook_new1")
    assert again.verdict == "pass" and again.safety_factor >= MIN_SAFETY_FACTOR
    assert again.thickened_from == "hook_new1"


@pytest.mark.sim
def test_a_hook_the_size_model_cannot_thicken_is_rejected_naming_the_conflict(engine):
    context = default_context("hook", "long_tube")
    literals = parse_spec("hook", CREATED_HOOK)
    sized = size_tool(engine, "hook", literals, context, "hook_new1")
    weak = check_strength(sized.spec, load(30.0, 0.589))
    assert weak.required_handle_width_m > 0.012
    reply = thicker_dims(engine, "hook", "hook", literals, context, weak)
    assert reply.name == "infeasible"
    conflict = [str(t) for t in reply.args[0]]
    assert "handle_width(new_tool,thin)" in conflict
    assert f"min_handle_width_m({weak.required_handle_width_m})" in conflict
    out = rejected(weak, reply.args[0])
    assert out.verdict == "rejected" and not out.passed
    assert "handle_width(new_tool,thin)" in out.reason and "15.9 mm" in out.reason


@pytest.mark.sim
def test_a_rake_under_a_shelf_cannot_be_thickened_beyond_the_shelf_clearance(engine):
    context = default_context("rake", "deep_shelf")
    literals = parse_spec("rake", "handle_length=long")
    sized = size_tool(engine, "rake", literals, context, "rake_new1")
    weak = check_strength(sized.spec, load(60.0, sized.spec.handle_length - 0.01))
    reply = thicker_dims(engine, "rake", "hook", literals, context, weak)
    assert reply.name == "infeasible"
    assert any(str(t).startswith("shelf_clearance_m(") for t in reply.args[0])


def test_the_figures_go_into_the_tool_json(tmp_path):
    spec = HookSpec("h", 0.2, handle_width=0.009)
    files = write_tool_files(spec, tmp_path, picture=False)
    check = check_strength(spec, load(3.0, 0.19))
    write_strength(files.manifest, check)
    data = json.loads(files.manifest.read_text())
    assert data["strength"]["verdict"] == "pass"
    assert data["strength"]["lever_arm_m"] == pytest.approx(0.15)
    assert read_tool_files(files.directory).spec == spec


FULL_CHECK = StrengthCheck(
    "h", "cantilever", 3.123456789, 0.1512345678, (0.0091234567, 0.012), 1.23456789e-5,
    1.234567891e-9, 2.345678912e-7, 0.46851852, 13.84567891e6, 50.12345678e6, 3.61234, 3.0,
    "fail", (0.1, 0.2012345678, 0.3), (0.0, 0.01, 0.0212345678), ("cube1", "tube1"), 4,
    0.0112345678,
    "h0", "h2", "a note", "", 9.87654321, 1.23456, "a caveat")
"""A check with every field set, its numbers with more digits than the JSON keeps."""

FULL_DICT = {
    "model": "cantilever", "force_n": 3.123457, "lever_arm_m": 0.151235,
    "section_m": [0.009123, 0.012], "area_m2": 1.2345679e-05, "second_moment_m4": 1.23457e-09,
    "section_modulus_m3": 2.34568e-07, "moment_nm": 0.468519, "stress_mpa": 13.845679,
    "strength_mpa": 50.123457, "safety_factor": 3.612, "required_safety_factor": 3.0,
    "verdict": "fail", "contact_point_m": [0.1, 0.201235, 0.3],
    "grasp_point_m": [0.0, 0.01, 0.021235],
    "bodies": ["cube1", "tube1"], "trial": 4, "required_handle_width_m": 0.011235,
    "thickened_from": "h0", "thickened_into": "h2", "note": "a note", "reason": "",
    "peak_force_n": 9.876543, "peak_safety_factor": 1.235, "caveat": "a caveat"}


def test_the_json_figures_of_a_check_exact():
    assert FULL_CHECK.to_dict() == FULL_DICT
    bare = StrengthCheck("b", "compression", 2.0, None, (0.02, 0.03), None, None, None,
                         None, 0.0, 50e6, None, 3.0, "unmeasured")
    assert bare.to_dict() == {
        "model": "compression", "force_n": 2.0, "lever_arm_m": None, "section_m": [0.02, 0.03],
        "area_m2": None, "second_moment_m4": None, "section_modulus_m3": None,
        "moment_nm": None, "stress_mpa": 0.0, "strength_mpa": 50.0, "safety_factor": None,
        "required_safety_factor": 3.0, "verdict": "unmeasured", "contact_point_m": None,
        "grasp_point_m": None, "bodies": [], "trial": None, "required_handle_width_m": None,
        "thickened_from": None, "thickened_into": None, "note": "", "reason": "",
        "peak_force_n": None, "peak_safety_factor": None, "caveat": ""}
    assert bare.passed and not FULL_CHECK.passed


def test_a_rejected_check_says_the_width_the_force_and_the_conflict():
    out = rejected(FULL_CHECK, ["a(x)", "b(y)"])
    assert (out.verdict, out.tool, out.force_n) == ("rejected", "h", FULL_CHECK.force_n)
    assert out.reason == (
        "its handle would need to be at least 11.2 mm wide for a safety factor of 3 under "
        "3.12 N at 151 mm, and the size model cannot give that: a(x), b(y) cannot hold "
        "together")
    wide = rejected(replace(FULL_CHECK, required_handle_width_m=0.09999, lever_arm_m=0.9996),
                    [])
    assert wide.reason.startswith("its handle would need to be at least 100.0 mm wide for a "
                                  "safety factor of 3 under 3.12 N at 1000 mm, ")
    assert thickening_fact(FULL_CHECK) == Compound("min_handle_width_m", (0.0112345678,))
    with pytest.raises(ValueError) as info:
        thickening_fact(out)
    assert str(info.value) == ("h: only a failed cantilever check asks for a thicker handle "
                               "(this is a rejected cantilever check)")
    block = replace(FULL_CHECK, model="compression")
    with pytest.raises(ValueError, match=r"\(this is a fail compression check\)$"):
        thickening_fact(block)


def test_write_strength_replaces_the_json_whole_and_keeps_its_mode(tmp_path):
    manifest = tmp_path / "t.json"
    manifest.write_text(json.dumps({"name": "t", "strength": {"old": 1}}))
    manifest.chmod(0o640)
    write_strength(manifest, FULL_CHECK)
    assert manifest.read_text(encoding="utf-8") == json.dumps(
        {"name": "t", "strength": FULL_DICT}, indent=2) + "\n"
    assert manifest.stat().st_mode & 0o777 == 0o640
    assert [p.name for p in tmp_path.iterdir()] == ["t.json"]
    (tmp_path / "bad.json").write_text("{}")
    (tmp_path / "bad.json").chmod(0o644)
    with pytest.raises(TypeError):
        write_strength(tmp_path / "bad.json", replace(FULL_CHECK, bodies=(object(),)))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.json", "t.json"]
    assert (tmp_path / "bad.json").read_text() == "{}"


HOOK = HookSpec("h", 0.6, handle_width=0.009, hook_length=0.03, hook_width=0.012)
NOTE = "the handle as a cantilever from the grasp to the contact, the whole force across it"


def _caveat(force, steps, peak, sf):
    return (f"checked with {force} N, the 95th percentile of the per-step contact force over "
            f"{steps} steps with contact; the one-step peak {peak} N (a contact spike, "
            f"sensitive to the time step) would give a safety factor of {sf}")


def test_a_failing_hook_check_exact():
    # 6 F L / w^3 = 6 * 20 * 0.549 / 0.009^3 = 90.37 MPa; 50 / 90.37 = 0.553
    loaded = {"max_force_n": 30.0, "robust_force_n": 20.0, "point": [0.589, -0.03, 0.0],
              "grasp_point": [0.04, 0.0, 0.0], "bodies": ["cube1"], "contact_steps": 42}
    check = check_strength(HOOK, loaded, trial=7, thickened_from="h0")
    assert check.tool == "h"
    assert check.to_dict() == {
        "model": "cantilever", "force_n": 20.0, "lever_arm_m": 0.549,
        "section_m": [0.009, 0.009], "area_m2": None, "second_moment_m4": 5.4675e-10,
        "section_modulus_m3": 1.215e-07, "moment_nm": 10.98, "stress_mpa": 90.37037,
        "strength_mpa": 50.0, "safety_factor": 0.553, "required_safety_factor": 2.0,
        "verdict": "fail", "contact_point_m": [0.589, -0.03, 0.0],
        "grasp_point_m": [0.04, 0.0, 0.0], "bodies": ["cube1"], "trial": 7,
        "required_handle_width_m": 0.0139, "thickened_from": "h0", "thickened_into": None,
        "note": NOTE, "reason": "", "peak_force_n": 30.0, "peak_safety_factor": 0.369,
        "caveat": _caveat("20.0", 42, "30.0", "0.4")}


def test_a_load_without_force_steps_or_bodies_passes_with_no_safety_factor():
    bare = {"point": [0.589, -0.03, 0.0], "grasp_point": [0.04, 0.0, 0.0]}
    check = check_strength(HOOK, bare)
    assert (check.force_n, check.stress_pa, check.safety_factor, check.verdict) == (
        0.0, 0.0, None, "pass")
    assert (check.bodies, check.peak_force_n, check.peak_safety_factor) == ((), 0.0, None)
    assert check.caveat == _caveat("0.0", 0, "0.0", "-")
    # A robust force with no recorded peak: no peak safety factor either.
    robust_only = check_strength(HOOK, {**bare, "robust_force_n": 2.0})
    assert (robust_only.peak_force_n, robust_only.peak_safety_factor) == (0.0, None)
    assert robust_only.caveat == _caveat("2.0", 0, "0.0", "-")


def test_small_forces_still_have_safety_factors_and_the_limit_passes():
    tiny = check_strength(HOOK, {"max_force_n": 1e-7, "point": [0.589, -0.03, 0.0],
                                 "grasp_point": [0.04, 0.0, 0.0]})
    assert 0 < tiny.stress_pa < 1
    assert tiny.safety_factor == pytest.approx(50e6 / tiny.stress_pa)
    assert tiny.peak_safety_factor == pytest.approx(tiny.safety_factor)
    half = {"max_force_n": 0.5, "point": [0.589, -0.03, 0.0], "grasp_point": [0.04, 0.0, 0.0]}
    check = check_strength(HOOK, half)
    assert check.caveat == _caveat("0.5", 0, "0.5", "22.1")
    # The lever arm runs from the recorded grasp; the width asked follows the factor.
    assert check_strength(HOOK, {**half, "grasp_point": [0.1, 0.0, 0.0]}).lever_arm_m == \
        pytest.approx(0.489)
    assert (check.required_handle_width_m,
            check_strength(HOOK, half, safety_factor=4.0).required_handle_width_m) == (
        0.0041, 0.0051)   # (6 F L SF / strength)^(1/3), up to the next 0.1 mm
    # A safety factor exactly the required one passes.
    limit = check_strength(HOOK, half, strength_pa=2.0 * check.stress_pa)
    assert (limit.safety_factor, limit.verdict) == (2.0, "pass")


def test_a_windowed_load_says_its_window_in_the_caveat():
    loaded = {"max_force_n": 3.0, "robust_force_n": 0.0961, "point": [0.589, -0.03, 0.0],
              "grasp_point": [0.04, 0.0, 0.0], "bodies": ["cube1"], "contact_steps": 60,
              "window_s": 0.1}
    check = check_strength(HOOK, loaded)
    assert check.caveat.startswith(
        "checked with 0.0961 N, the 95th percentile of the contact force averaged over "
        "0.1 s windows (60 steps with contact); the one-step peak 3.0 N")
