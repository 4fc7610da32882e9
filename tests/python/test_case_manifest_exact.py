"""The case manifest read field by field, exact, from manifests written here.

One manifest has every optional field absent (``paper_trials``, ``[randomise]``, a
skill's ``options``, ``pose``/``tool_action`` flags where false, a variant's
``description`` and ``harder``, a pose parameter's ``doc``, a variant's ``set``): it must
read with the documented defaults, not only the shipped manifests, which set them all.
Another sets every optional field, and each value read is compared with the one written.
The error messages are compared whole.
"""

from __future__ import annotations

import math

import pytest

from creative_py.case import (CaseManifest, DemonstrationSpec, LocationJitter, PoseParam,
                              SkillBinding, Variant, broken_cases, case_index, get_case,
                              load_cases, manifest_of_folder, read_manifest)
from creative_py.world import WorldFileError

MINIMAL = """\
id = "mini"
title = "A minimal case"
ontology = "mini_onto"
trial_budget = 3
goal = ["at(box1, shelf1)"]

[roles]
tools = "tool"
target = "box1"
context = "shelf1"

[[skill]]
name = "grab"
primitive = "grasp"
args = ["tool"]

[[skill]]
name = "push"
primitive = "push_at_pose"
args = ["tool", "target", "context"]
pose = true
tool_action = true

[pose]
term = "push_pose"

[[pose.param]]
name = "dx"
unit = "m"
min = -0.1
max = 0.2

[[variant]]
name = "easy"

[[variant]]
name = "hard"
harder = true

[demonstration]
tool = "stick1"
variant = "easy"
location = 2
steps = ["grab", "push"]
[demonstration.pose]
dx = 0.05
"""

FULL_EXTRA = """
[randomise.location.gap]
jitter = 0.01
min = 0.0
max = 0.04

[randomise.location.side]
jitter = 0.0
min = -0.02
max = 0.02

[randomise.catalogue.length]
min = 0.1
short = {max = 0.2}
long = {min = 0.3, max = 0.5}

[randomise.catalogue.width]
max = 0.03
"""


def _write(root, text, folder="mini_world"):
    path = root / folder
    path.mkdir(parents=True, exist_ok=True)
    (path / "case.toml").write_text(text)
    return path


def test_a_manifest_with_every_optional_field_absent_reads_with_the_defaults(tmp_path):
    folder = _write(tmp_path, MINIMAL)
    m = read_manifest(folder)
    assert m == CaseManifest(
        id="mini", title="A minimal case", folder=folder, ontology="mini_onto",
        trial_budget=3, tools_table="tool", target="box1", context="shelf1",
        goal=("at(box1, shelf1)",),
        skills=(SkillBinding("grab", "grasp", ("tool",), False, False, {}),
                SkillBinding("push", "push_at_pose", ("tool", "target", "context"), True,
                             True, {})),
        pose_term="push_pose", pose_params=(PoseParam("dx", "m", -0.1, 0.2, ""),),
        variants=(Variant("easy", "", False, {}), Variant("hard", "", True, {})),
        demonstration=DemonstrationSpec("stick1", "easy", 2, ("grab", "push"), (0.05,)),
        location_jitter=(), paper_trials=None, catalogue_bounds=(),
        catalogue_value_bounds=(), backend="pybullet")
    assert m.harder_variant == "hard"
    assert m.variant_names == ("easy", "hard")
    assert m.pose_names == ("dx",)


def test_a_manifest_with_every_optional_field_set_reads_each_value(tmp_path):
    text = MINIMAL.replace('trial_budget = 3\n', 'trial_budget = 3\npaper_trials = 5\n'
                           'backend = "maniskill"\n')
    text = text.replace('args = ["tool"]\n',
                        'args = ["tool"]\noptions = {speed = 0.2, lift_to = "z"}\n')
    text = text.replace('max = 0.2\n', 'max = 0.2\ndoc = "along the shelf"\n')
    text = text.replace('name = "hard"\nharder = true\n',
                        'name = "hard"\nharder = true\ndescription = "a deep shelf"\n'
                        '[variant.set]\n"shelf1.depth" = 0.4\n')
    m = read_manifest(_write(tmp_path, text + FULL_EXTRA))
    assert m.paper_trials == 5
    assert m.backend == "maniskill"
    assert m.skills[0].options == {"speed": 0.2, "lift_to": "z"}
    assert m.skills[1].options == {}
    assert m.pose_params == (PoseParam("dx", "m", -0.1, 0.2, "along the shelf"),)
    assert m.variants == (Variant("easy", "", False, {}),
                          Variant("hard", "a deep shelf", True, {"shelf1.depth": 0.4}))
    assert m.location_jitter == (LocationJitter("gap", 0.01, 0.0, 0.04),
                                 LocationJitter("side", 0.0, -0.02, 0.02))
    assert m.catalogue_bounds == (("length", 0.1, math.inf), ("width", -math.inf, 0.03))
    assert m.catalogue_value_bounds == (("length", "short", -math.inf, 0.2),
                                        ("length", "long", 0.3, 0.5))


def test_the_listing_exact(tmp_path):
    folder = _write(tmp_path, MINIMAL)
    assert read_manifest(folder).listing() == {
        "id": "mini", "title": "A minimal case", "world": str(folder),
        "ontology": "mini_onto", "backend": "pybullet", "trial_budget": 3,
        "variants": [{"name": "easy", "harder": False, "description": ""},
                     {"name": "hard", "harder": True, "description": ""}],
        "harder_variant": "hard", "skills": ["grab", "push"],
        "pose": {"term": "push_pose", "params": ["dx"]}}


def test_lookups_and_their_errors_exact(tmp_path):
    m = read_manifest(_write(tmp_path, MINIMAL))
    assert m.variant("hard") is m.variants[1]
    assert m.skill("push") is m.skills[1]
    assert m.skill_args(m.skill("push"), "t7") == ("t7", "box1", "shelf1")
    assert m.role_object("context", "t7") == "shelf1"
    with pytest.raises(KeyError) as caught:
        m.variant("medium")
    assert caught.value.args[0] == "unknown variant 'medium' of case mini; variants: easy, hard"
    with pytest.raises(KeyError) as caught:
        m.skill("pull")
    assert caught.value.args[0] == "unknown skill 'pull' of case mini; skills: grab, push"


def test_pose_bounds_are_inclusive_and_errors_exact(tmp_path):
    m = read_manifest(_write(tmp_path, MINIMAL))
    assert m.check_pose((-0.1,)) == (-0.1,)
    assert m.check_pose((0.2,)) == (0.2,)
    assert m.parse_pose(" 0.1") == (0.1,)
    with pytest.raises(ValueError) as caught:
        m.check_pose((0.3,), "src")
    assert str(caught.value) == "src: dx must be within [-0.1, 0.2] m, got 0.3"
    with pytest.raises(ValueError) as caught:
        m.check_pose((-0.11,))
    assert str(caught.value) == "pose: dx must be within [-0.1, 0.2] m, got -0.11"
    with pytest.raises(ValueError) as caught:
        m.check_pose((float("nan"),))
    assert str(caught.value) == "pose: dx must be within [-0.1, 0.2] m, got nan"
    with pytest.raises(ValueError) as caught:
        m.check_pose((0.1, 0.1))
    assert str(caught.value) == "pose: mini poses have 1 numbers (dx), got 2"
    with pytest.raises(ValueError) as caught:
        m.parse_pose("x")
    assert str(caught.value) == "--pose must be DX (m), got 'x'"


@pytest.mark.parametrize("old,new,message", [
    ('id = "mini"', 'id = "Mini"', "field 'id': must be a lower-case Prolog atom, got 'Mini'"),
    ('trial_budget = 3\n', 'trial_budget = 3\npaper_trials = 0\n', "paper_trials"),
    ('goal = ["at(box1, shelf1)"]', 'goal = []',
     "field 'goal': must be a non-empty list of literals written as text"),
    ('args = ["tool"]\n', 'args = ["tool", "hand"]\n',
     "must be a list of roles among tool, target, context, got ['tool', 'hand']"),
    ('args = ["tool"]\n', 'args = ["tool"]\noptions = 3\n', "field 'skill[0].options': must be a table"),
    ('pose = true\n', '', "exactly one skill must set pose = true, got 0 (none)"),
    ('min = -0.1\nmax = 0.2', 'min = 0.3\nmax = 0.2', "must be >= min (0.3), got 0.2"),
    ('name = "hard"\nharder = true\n', 'name = "easy"\nharder = true\n',
     "needs at least one [[variant]] with unique names, got ['easy', 'easy']"),
    ('name = "hard"\nharder = true\n', 'name = "hard"\n',
     "exactly one variant must be marked harder = true"),
    ('steps = ["grab", "push"]', 'steps = ["grab", "pull"]',
     "must be a list of the case's skills (grab, push), got ['grab', 'pull']"),
    ('dx = 0.05', 'dx = 0.5',
     "field 'demonstration.pose': demonstration.pose: dx must be within [-0.1, 0.2] m, "
     "got 0.5"),
    ('trial_budget = 3\n', 'trial_budget = 3\nbackend = "mujoco"\n',
     "field 'backend': must be one of maniskill, pybullet, got 'mujoco'"),
    ('trial_budget = 3\n', 'trial_budget = 3\nbackend = "PyBullet"\n',
     "field 'backend': must be one of maniskill, pybullet, got 'PyBullet' (did you mean"),
    ('trial_budget = 3\n', 'trial_budget = 3\nbackend = 1\n',
     "field 'backend': must be a string, got 1"),
])
def test_manifest_errors_name_the_file_and_field(tmp_path, old, new, message):
    assert old in MINIMAL
    folder = _write(tmp_path, MINIMAL.replace(old, new, 1))
    with pytest.raises(WorldFileError) as caught:
        read_manifest(folder)
    assert str(caught.value).startswith(str(folder / "case.toml") + ": ")
    assert message in str(caught.value)


def test_randomise_bounds_errors(tmp_path):
    bad = FULL_EXTRA.replace("min = 0.0\nmax = 0.04", "min = 0.05\nmax = 0.04")
    with pytest.raises(WorldFileError, match=r"must be >= min \(0.05\), got 0.04"):
        read_manifest(_write(tmp_path, MINIMAL + bad))
    bad = FULL_EXTRA.replace("long = {min = 0.3, max = 0.5}", "long = {min = 0.6, max = 0.5}")
    with pytest.raises(WorldFileError, match=r"must be >= min \(0.6\), got 0.5"):
        read_manifest(_write(tmp_path, MINIMAL + bad, "other"))


def test_a_case_index_with_a_duplicate_and_a_broken_manifest(tmp_path):
    _write(tmp_path, MINIMAL, "a_world")
    _write(tmp_path, MINIMAL, "b_world")
    _write(tmp_path, "id = [", "c_world")
    _write(tmp_path, MINIMAL.replace('id = "mini"', 'id = "other"')
           .replace("trial_budget = 3", "trial_budget = 0"), "d_world")
    index = case_index(tmp_path)
    assert index.folders == {"mini": tmp_path / "a_world", "other": tmp_path / "d_world"}
    assert sorted(index.broken) == [tmp_path / "b_world" / "case.toml",
                                    tmp_path / "c_world" / "case.toml"]
    assert index.broken[tmp_path / "b_world" / "case.toml"] == (
        f"{tmp_path / 'b_world' / 'case.toml'}: field 'id': case 'mini' is already "
        f"declared by {tmp_path / 'a_world' / 'case.toml'}")
    assert get_case("mini", tmp_path).id == "mini"
    assert get_case("mini", tmp_path) is get_case("mini", tmp_path)
    assert set(load_cases(tmp_path, strict=False)) == {"mini"}
    with pytest.raises(WorldFileError):
        load_cases(tmp_path)
    assert sorted(broken_cases(tmp_path)) == [tmp_path / f"{x}_world" / "case.toml"
                                              for x in "bcd"]
    assert broken_cases(tmp_path)[tmp_path / "d_world" / "case.toml"].startswith(
        f"{tmp_path / 'd_world' / 'case.toml'}: field 'trial_budget'")
    with pytest.raises(KeyError) as caught:
        get_case("nope", tmp_path)
    assert caught.value.args[0] == (
        f"unknown case 'nope'; known cases: mini, other; {tmp_path / 'b_world' / 'case.toml'}"
        f" does not load; {tmp_path / 'c_world' / 'case.toml'} does not load")


def test_load_cases_strict_raises_for_a_case_that_does_not_read(tmp_path):
    _write(tmp_path, MINIMAL, "a_world")
    _write(tmp_path, MINIMAL.replace('id = "mini"', 'id = "other"')
           .replace("trial_budget = 3", "trial_budget = 0"), "d_world")
    assert case_index(tmp_path).broken == {}
    with pytest.raises(WorldFileError, match="trial_budget"):
        load_cases(tmp_path)
    assert set(load_cases(tmp_path, strict=False)) == {"mini"}


def test_a_world_folder_s_manifest_and_a_three_number_pose_error(tmp_path):
    folder = _write(tmp_path, MINIMAL)
    assert manifest_of_folder(str(folder)) == read_manifest(folder)
    hook = get_case("hook")
    with pytest.raises(ValueError) as caught:
        hook.parse_pose("1,x,0")
    assert str(caught.value) == "--pose must be DX,DY,ROLL (m, m, rad), got '1,x,0'"
    with pytest.raises(ValueError) as caught:
        hook.check_pose((0.0, 0.0))
    assert str(caught.value) == "pose: hook poses have 3 numbers (dx,dy,roll), got 2"
