"""The case manifest (worlds/<folder>/case.toml): reading, errors, listing, and its
agreement with the ontology."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys

import pytest

from creative_py.case import get_case, load_cases, read_manifest
from creative_py.world_files import WORLDS_ROOT, WorldFileError


def _copy(tmp_path, folder="hook_tube"):
    dst = tmp_path / folder
    shutil.copytree(WORLDS_ROOT / folder, dst)
    return dst


def _edit(path, old, new):
    text = (path / "case.toml").read_text()
    assert old in text
    (path / "case.toml").write_text(text.replace(old, new, 1))


def test_the_shipped_cases_are_found_with_their_harder_variants():
    cases = load_cases()
    assert {"hook", "wedge"} <= set(cases)
    assert cases["hook"].harder_variant == "long_tube"
    assert cases["wedge"].harder_variant == "big_door"
    assert cases["hook"].trial_budget == 12 and cases["wedge"].trial_budget == 9
    hook = get_case("hook")
    assert [s.name for s in hook.skills] == ["pick_up", "position_tool", "pull"]
    assert hook.skill_args(hook.skill("pull"), "t9") == ("t9", "cube1", "tube1")
    assert hook.demonstration.pose == (0.03, 0.0, 0.0)


def test_a_pose_is_parsed_and_bounded_by_the_manifest():
    hook = get_case("hook")
    assert hook.parse_pose("0.04, 0, 0.1") == (0.04, 0.0, 0.1)
    with pytest.raises(ValueError, match=r"--pose: roll must be within \[-1.57\d*, 1.57\d*\] rad"):
        hook.parse_pose("0.03,0,1e9")
    with pytest.raises(ValueError, match="--pose must be DX,DY,ROLL"):
        hook.parse_pose("0.03,zero,0")
    with pytest.raises(ValueError, match="poses have 3 numbers"):
        hook.parse_pose("0.03,0")


def test_unknown_case_lists_the_known_ones():
    with pytest.raises(KeyError, match="unknown case 'hok'; known cases: .*hook"):
        get_case("hok")


@pytest.mark.parametrize("old, new, message", [
    ('trial_budget = 12', 'trial_budgt = 12', r"field 'trial_budget': missing \(is 'trial_budgt' a typo"),
    ('harder = true', 'harder = false', "exactly one variant must be marked harder"),
    ('tool_action = true', 'tool_action = false', "exactly one skill must set tool_action"),
    ('args = ["tool", "target", "context"]\npose = true', 'args = ["tool", "goal"]\npose = true',
     r"field 'skill\[1\].args': must be a list of roles"),
    ('steps = ["pick_up", "position_tool", "pull"]', 'steps = ["pick_up", "push"]',
     "field 'demonstration.steps'"),
    ('dx = 0.03', 'dx = 3.0', r"field 'demonstration.pose': .*dx must be within"),
    ('id = "hook"', 'id = "Hook"', "must be a lower-case Prolog atom"),
    ('medium = {min = 0.27, max = 0.35}', 'medium = {min = 0.37, max = 0.35}',
     r"field 'randomise.catalogue.handle_length.medium.max': must be >= min"),
    ('short = {min = 0.15, max = 0.20}', 'short = {min = 0.15, mx = 0.20}',
     r"randomise.catalogue.handle_length.short"),
])
def test_a_bad_manifest_names_its_file_and_field(tmp_path, old, new, message):
    folder = _copy(tmp_path)
    _edit(folder, old, new)
    with pytest.raises(WorldFileError, match=message) as err:
        read_manifest(folder)
    assert str(folder / "case.toml") in str(err.value)


@pytest.mark.parametrize("old, new, message", [
    ('name = "robotoolbench"', 'name = "RoboToolBench"',
     r"field 'benchmark.name': must be a lower-case word"),
    ('task = "BringCube"', 'tsk = "BringCube"', r"field 'benchmark.task': missing"),
])
def test_a_bad_benchmark_table_names_its_field(tmp_path, old, new, message):
    folder = _copy(tmp_path, "bring_cube")
    _edit(folder, old, new)
    with pytest.raises(WorldFileError, match=message) as err:
        read_manifest(folder)
    assert str(folder / "case.toml") in str(err.value)


def test_a_case_names_the_benchmark_and_task_it_re_expresses():
    assert (get_case("bring_cube").benchmark, get_case("bring_cube").benchmark_task) == (
        "robotoolbench", "BringCube")
    assert (get_case("hook").benchmark, get_case("hook").benchmark_task) == (None, None)


def test_two_folders_with_one_id_are_refused(tmp_path):
    _copy(tmp_path, "hook_tube")
    shutil.copytree(WORLDS_ROOT / "hook_tube", tmp_path / "another")
    with pytest.raises(WorldFileError, match="case 'hook' is declared by 2 folders: "):
        load_cases(tmp_path)


def test_the_manifest_must_agree_with_the_ontology(tmp_path):
    from creative_py.bridge import Engine
    from creative_py.learning.checks import check_manifest

    engine = Engine.instance()
    check_manifest(engine, get_case("hook"))
    folder = _copy(tmp_path)
    _edit(folder, 'goal = ["out_of_tube(cube1, tube1)"]', 'goal = ["out_of_tube(tube1, cube1)"]')
    with pytest.raises(ValueError, match=r"case.toml: field 'goal': .* differs from the "
                                         r"ontology's \['out_of_tube\(cube1,tube1\)'\]"):
        check_manifest(engine, read_manifest(folder))
    _edit(folder, 'id = "hook"', 'id = "kitchen"')
    # issue 25: the manifest's ontology field is checked when the manifest is read
    with pytest.raises(WorldFileError, match=r"case.toml: field 'ontology': .*hook.pl does "
                                             r"not declare case\(kitchen\)\."):
        read_manifest(folder)


@pytest.mark.sim
def test_every_catalogue_is_described_in_the_ontology_s_vocabulary():
    from creative_py.bridge import Engine
    from creative_py.learning.checks import check_catalogue
    from creative_py.backends.pybullet import load_world
    from creative_py.simulator import BackendUnavailable, backend_for

    engine = Engine.instance()
    for manifest in load_cases().values():
        try:
            sim = backend_for(manifest)
        except BackendUnavailable:
            continue  # an optional backend (the maniskill extra) is not installed here
        check_catalogue(engine, sim.load_world(manifest))
    wedge = load_world(get_case("wedge"))
    hook_tools = load_world(get_case("hook")).catalogue
    mixed = wedge.with_tool(hook_tools["hook_a2"])
    with pytest.raises(ValueError, match=r"objects.toml: hook_a2: the catalogue fact "
                                         r"handle_length_m/2 is not in the ontology's"):
        check_catalogue(engine, mixed)


def test_creative_cases_lists_every_case_as_json():
    out = subprocess.run([sys.executable, "-m", "creative_py.cli", "cases", "--json"],
                         capture_output=True, text=True, check=True).stdout
    cases = {c["id"]: c for c in json.loads(out)}
    assert cases["hook"]["world"].endswith("hook_tube")
    assert cases["hook"]["trial_budget"] == 12
    assert [v["name"] for v in cases["wedge"]["variants"]] == ["standard", "big_door"]
    assert cases["wedge"]["harder_variant"] == "big_door"
