"""``insert_at_pose``'s ``clearance`` is set by data alone: a negative value (a plain
stick lowered to the target's side) is accepted from case.toml, a value below the
primitive's own bound is refused in one line naming case.toml and the field; a grasp's
``clearance`` keeps the general bound (no negative value)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from creative_py.backends.pybullet import load_world
from creative_py.case import manifest_of_folder
from creative_py.world.skills import MIN_INSERT_CLEARANCE_M, OPTION_BOUNDS, option_bound
from creative_py.world_files import WORLDS_ROOT, WorldFileError


def _world_with(tmp_path: Path, folder: str, old: str, new: str) -> Path:
    d = tmp_path / folder
    shutil.copytree(WORLDS_ROOT / folder, d)
    case = d / "case.toml"
    text = case.read_text()
    assert text.count(old) == 1
    case.write_text(text.replace(old, new))
    return d


def _insert_skill(d: Path) -> tuple[int, str]:
    """Return the index and the name of the skill that binds insert_at_pose."""
    m = manifest_of_folder(d)
    return next((i, s.name) for i, s in enumerate(m.skills)
                if s.primitive == "insert_at_pose")


def test_the_bound_is_the_primitive_s_own():
    assert option_bound("insert_at_pose", "clearance") == (MIN_INSERT_CLEARANCE_M, 1.0, "m")
    assert MIN_INSERT_CLEARANCE_M < 0
    assert option_bound("grasp", "clearance") == OPTION_BOUNDS["clearance"]
    assert OPTION_BOUNDS["clearance"][0] == 0.0
    assert option_bound("insert_at_pose", "speed") == OPTION_BOUNDS["speed"]
    assert option_bound("insert_at_pose", "posture_search") is None


def test_a_negative_clearance_in_case_toml_is_accepted(tmp_path):
    d = _world_with(tmp_path, "hook_tube", "clearance = 0.008", "clearance = -0.02")
    world = load_world(manifest_of_folder(d), d)
    _, name = _insert_skill(d)
    assert world.skills[name].options["clearance"] == -0.02


@pytest.mark.parametrize("value", ["-0.2", "-0.0501", "1.5"])
def test_a_nonsense_clearance_is_refused_in_one_line(tmp_path, value):
    d = _world_with(tmp_path, "hook_tube", "clearance = 0.008", f"clearance = {value}")
    i, _ = _insert_skill(d)
    with pytest.raises(WorldFileError) as caught:
        load_world(manifest_of_folder(d), d)
    assert str(caught.value) == (
        f"{d / 'case.toml'}: field 'skill[{i}].options.clearance': must lie within "
        f"[-0.05, 1] m, got {float(value):g}")


def test_a_grasp_clearance_may_not_be_negative(tmp_path):
    d = _world_with(tmp_path, "wedge_door", "clearance = 0.004", "clearance = -0.02")
    m = manifest_of_folder(d)
    i = next(i for i, s in enumerate(m.skills) if s.primitive == "grasp")
    with pytest.raises(WorldFileError) as caught:
        load_world(m, d)
    assert str(caught.value) == (f"{d / 'case.toml'}: field 'skill[{i}].options.clearance': "
                                 f"must lie within [0, 1] m, got -0.02")
