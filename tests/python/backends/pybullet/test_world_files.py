"""World files: every error names the file and the field, and says why."""

import shutil
from pathlib import Path

import pytest

from creative_py.case import get_case, manifest_of_folder
from creative_py.backends.pybullet import load_world, open_episode
from creative_py.world_files import WORLDS_ROOT, Fields, WorldFileError

SHIPPED = WORLDS_ROOT / "hook_tube"


@pytest.fixture
def world_dir(tmp_path) -> Path:
    d = tmp_path / "hook_tube"
    shutil.copytree(SHIPPED, d)
    return d


def _load(d: Path):
    return load_world(manifest_of_folder(d), d)


def _edit(path: Path, old: str, new: str) -> None:
    text = path.read_text()
    assert old in text, f"{old!r} not in {path.name}"
    path.write_text(text.replace(old, new, 1))


def test_the_shipped_world_loads():
    w = load_world(get_case("hook"))
    assert set(w.manifest.variant_names) == {"standard", "long_tube"}
    assert w.locations == (1, 2, 3, 4)
    assert sum(1 for t in w.catalogue.values() if t.is_stick) == 2
    assert {i.set for i in w.items.values()} == {"a", "b"}


def test_a_missing_field_names_file_and_field(world_dir):
    _edit(world_dir / "scene.toml", "inner_height = 0.07\n", "")
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'body\[2\]\.inner_height': "
                                             r"missing"):
        _load(world_dir)


def test_a_typo_is_caught_with_a_suggestion(world_dir):
    _edit(world_dir / "scene.toml", "inner_width =", "inner_widht =")
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'body\[2\]\.inner_width': "
                                             r"missing \(is 'inner_widht' a typo for it\?\)"):
        _load(world_dir)


def test_an_unknown_extra_field_is_rejected_with_a_suggestion(world_dir):
    _edit(world_dir / "scene.toml", "wall = 0.005", "wall = 0.005\nwalls = 0.004")
    with pytest.raises(WorldFileError, match=r"scene\.toml: field 'body\[2\]\.walls': unknown "
                                             r"field \(did you mean 'wall'\?\)"):
        _load(world_dir)


def test_a_bad_expression_names_the_value(world_dir):
    _edit(world_dir / "scene.toml", '"table_top + riser_height + tube1.wall"',
          '"table_top + riser_hieght + tube1.wall"')
    with pytest.raises(WorldFileError, match=r"scene\.toml: 'riser_hieght': no such value"):
        _load(world_dir)


def test_a_location_setting_an_unknown_value_is_named(world_dir):
    _edit(world_dir / "tasks.toml", "lateral = 0.02", "latteral = 0.02")
    with pytest.raises(WorldFileError, match=r"tasks\.toml: location\[1\]: set: key "
                                             r"'latteral'"):
        _load(world_dir)


def test_a_bad_tool_field_names_the_object(world_dir):
    _edit(world_dir / "objects.toml", "handle_length = 0.35", "handle_lenght = 0.35")
    with pytest.raises(WorldFileError, match=r"objects\.toml.*hook_a2.*unknown field.*handle_lenght"):
        _load(world_dir)


def test_a_missing_file_is_named(world_dir):
    (world_dir / "physics.toml").unlink()
    with pytest.raises(WorldFileError, match=r"physics\.toml: file not found"):
        _load(world_dir)


def test_broken_toml_names_the_file(world_dir):
    _edit(world_dir / "physics.toml", "solver_iterations = 50", "solver_iterations = = 50")
    with pytest.raises(WorldFileError, match=r"physics\.toml: not valid TOML"):
        _load(world_dir)


def test_the_demonstration_must_name_a_known_tool(world_dir):
    _edit(world_dir / "case.toml", 'tool = "hook_a2"', 'tool = "hook_z9"')
    with pytest.raises(WorldFileError, match=r"case\.toml: field 'demonstration\.tool': must "
                                             r"be one of hook_a1"):
        _load(world_dir)


def test_an_unknown_primitive_or_option_is_named(world_dir):
    _edit(world_dir / "case.toml", 'primitive = "pull_along_axis"', 'primitive = "yank"')
    with pytest.raises(WorldFileError, match=r"case\.toml: field 'skill\[2\]\.primitive': "
                                             r"unknown primitive 'yank'"):
        _load(world_dir)
    _edit(world_dir / "case.toml", 'primitive = "yank"', 'primitive = "pull_along_axis"')
    _edit(world_dir / "case.toml", "settle_steps = 60", "settle = 60")
    with pytest.raises(WorldFileError, match=r"skill\[2\]\.options\.settle': unknown option"):
        _load(world_dir)


def test_an_unknown_oracle_kind_is_named(world_dir):
    _edit(world_dir / "tasks.toml", 'kind = "below"', 'kind = "beneath"')
    with pytest.raises(WorldFileError, match=r"tasks\.toml: field 'oracle\.kind': must be one "
                                             r"of"):
        _load(world_dir)


def test_an_unknown_tool_lists_the_available_ones():
    w = load_world(get_case("hook"))
    with pytest.raises(KeyError, match=r"unknown tool 'hook_z9'; available tools: hook_a1"):
        with open_episode(w, "standard", 1, "hook_z9"):
            pass


def test_unknown_variant_and_location_are_named():
    w = load_world(get_case("hook"))
    with pytest.raises(KeyError, match=r"variant 'huge'.*standard"):
        with open_episode(w, "huge", 1, "hook_a2"):
            pass
    with pytest.raises(KeyError, match=r"location 7.*1\.\.4"):
        with open_episode(w, "standard", 7, "hook_a2"):
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
