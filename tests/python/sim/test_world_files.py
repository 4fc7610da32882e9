"""World files: every error names the file and the field, and says why."""

import shutil
from pathlib import Path

import pytest

from creative_py.sim.trial import load_case_world, open_episode
from creative_py.world import WORLDS_ROOT, Fields, WorldFileError

SHIPPED = WORLDS_ROOT / "hook_tube"


@pytest.fixture
def world_dir(tmp_path) -> Path:
    d = tmp_path / "hook_tube"
    shutil.copytree(SHIPPED, d)
    return d


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{old!r} not in {path.name}"
    path.write_text(text.replace(old, new, 1))


def test_the_shipped_world_loads():
    w = load_case_world("hook")
    assert set(w.variants) == {"standard", "long_tube"}
    assert len(w.locations) == 4
    assert sum(1 for t in w.tools.values() if t.is_stick) == 2
    assert {w.tool_sets[n] for n in w.tools} == {"a", "b"}


def test_a_missing_field_names_file_and_field(world_dir):
    _edit(world_dir / "scene.toml", "inner_height = 0.07\n", "")
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'tube\.inner_height': missing"):
        load_case_world("hook", world_dir)


def test_a_typo_is_caught_with_a_suggestion(world_dir):
    _edit(world_dir / "scene.toml", "inner_width =", "inner_widht =")
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'tube\.inner_width': missing "
                                             r"\(is 'inner_widht' a typo for it\?\)"):
        load_case_world("hook", world_dir)


def test_an_unknown_extra_field_is_rejected_with_a_suggestion(world_dir):
    _edit(world_dir / "scene.toml", "wall = 0.005", "wall = 0.005\nwalls = 0.004")
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'tube\.walls': unknown field "
                                             r"\(did you mean 'wall'\?\)"):
        load_case_world("hook", world_dir)


def test_a_wrong_type_names_the_field(world_dir):
    _edit(world_dir / "scene.toml", "inner_height = 0.07", 'inner_height = "tall"')
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'tube\.inner_height': "
                                             r"must be a number"):
        load_case_world("hook", world_dir)


def test_a_bad_tool_field_names_the_object(world_dir):
    _edit(world_dir / "objects.toml", "handle_length = 0.35", "handle_lenght = 0.35")
    with pytest.raises(WorldFileError, match=r"objects\.toml.*hook_a2.*unknown field.*handle_lenght"):
        load_case_world("hook", world_dir)


def test_a_missing_file_is_named(world_dir):
    (world_dir / "physics.toml").unlink()
    with pytest.raises(WorldFileError, match=r"physics\.toml: file not found"):
        load_case_world("hook", world_dir)


def test_broken_toml_names_the_file(world_dir):
    _edit(world_dir / "physics.toml", "solver_iterations = 50", "solver_iterations = = 50")
    with pytest.raises(WorldFileError, match=r"physics\.toml: not valid TOML"):
        load_case_world("hook", world_dir)


def test_the_demonstration_must_name_a_known_tool(world_dir):
    _edit(world_dir / "case.toml", 'tool = "hook_a2"', 'tool = "hook_z9"')
    with pytest.raises(WorldFileError, match=r"case\.toml: field 'demonstration\.tool': must "
                                             r"be one of hook_a1"):
        load_case_world("hook", world_dir)


def test_a_cube_inside_a_wall_is_rejected(world_dir):
    _edit(world_dir / "tasks.toml", "lateral = 0.02", "lateral = 0.2")
    with pytest.raises(WorldFileError, match=r"location\[1\]\.lateral"):
        load_case_world("hook", world_dir)


def test_an_unknown_tool_lists_the_available_ones():
    w = load_case_world("hook")
    with pytest.raises(KeyError, match=r"unknown tool 'hook_z9'; available tools: hook_a1"):
        with open_episode("hook", w, "standard", 1, "hook_z9"):
            pass


def test_unknown_variant_and_location_are_named():
    w = load_case_world("hook")
    with pytest.raises(KeyError, match=r"variant 'huge'.*standard"):
        with open_episode("hook", w, "huge", 1, "hook_a2"):
            pass
    with pytest.raises(KeyError, match=r"location 7.*1\.\.4"):
        with open_episode("hook", w, "standard", 7, "hook_a2"):
            pass


def test_fields_checks_ranges_and_vectors():
    f = Fields({"a": -1.0, "v": [1, 2], "s": "x"}, "f.toml", "t")
    with pytest.raises(WorldFileError, match=r"f\.toml: field 't\.a': must be >= 0"):
        f.float("a", minimum=0)
    with pytest.raises(WorldFileError, match=r"'t\.v': must be a list of 3 numbers"):
        f.vec("v", 3)
    with pytest.raises(WorldFileError, match=r"'t\.s': must be one of y, z"):
        f.str("s", choices=("y", "z"))
    assert f.float("missing", 2.5) == 2.5
