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
from creative_py.backends import BACKENDS
from creative_py.world_files import WorldFileError

BACKEND_NAMES = ", ".join(sorted(BACKENDS))
"""The registry's backends as the manifest's error lists them (a new backend changes
no line here)."""

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


@pytest.fixture(autouse=True)
def _ontology_file(tmp_path_factory, monkeypatch):
    """The ontology file these manifests name: a manifest's ``ontology`` must be a file
    of ontology/cases/ that declares the case (issue 25)."""
    import creative_py.case

    folder = tmp_path_factory.mktemp("ontology_cases")
    for shipped in creative_py.case.ONTOLOGY_CASES.glob("*.pl"):  # the shipped cases too
        (folder / shipped.name).symlink_to(shipped)
    (folder / "mini_onto.pl").write_text("case(mini).\ncase(other).\n")
    monkeypatch.setattr(creative_py.case, "ONTOLOGY_CASES", folder)


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


def _error(folder):
    """Return the error of reading ``folder``'s manifest, after its file prefix."""
    with pytest.raises(WorldFileError) as caught:
        read_manifest(folder)
    prefix = f"{folder / 'case.toml'}: "
    assert str(caught.value).startswith(prefix)
    return str(caught.value)[len(prefix):]


@pytest.mark.parametrize("old,new,message", [
    ('id = "mini"', 'id = "Mini"', "field 'id': must be a lower-case Prolog atom, got 'Mini'"),
    ('trial_budget = 3\n', 'trial_budget = 3\npaper_trials = 0\n',
     "field 'paper_trials': must be >= 1, got 0"),
    ('trial_budget = 3\n', 'trial_budget = 3\npaper_trials = 10001\n',
     "field 'paper_trials': must be <= 10000, got 10001"),
    ('trial_budget = 3\n', 'trial_budget = 10001\n',
     "field 'trial_budget': must be <= 10000, got 10001"),
    ('goal = ["at(box1, shelf1)"]', 'goal = []',
     "field 'goal': must be a non-empty list of literals written as text"),
    ('args = ["tool"]\n', 'args = ["tool", "hand"]\n',
     "field 'skill[0].args': must be a list of roles among tool, target, context, "
     "got ['tool', 'hand']"),
    ('args = ["tool"]\n', 'args = ["tool"]\noptions = 3\n',
     "field 'skill[0].options': must be a table"),
    ('pose = true\n', '', "field 'skill': exactly one skill must set pose = true, got 0 (none)"),
    ('args = ["tool"]\n', 'args = ["tool"]\npose = true\n',
     "field 'skill': exactly one skill must set pose = true, got 2 (grab, push)"),
    ('tool_action = true\n', '',
     "field 'skill': exactly one skill must set tool_action = true, got 0 (none)"),
    ('min = -0.1\nmax = 0.2', 'min = 0.3\nmax = 0.2',
     "field 'pose.param[0].max': must be >= min (0.3), got 0.2"),
    ('min = -0.1\n', 'min = -10.5\n', "field 'pose.param[0].min': must be >= -10.0, got -10.5"),
    ('min = -0.1\n', 'min = 10.5\n', "field 'pose.param[0].min': must be <= 10.0, got 10.5"),
    ('max = 0.2\n', 'max = -10.5\n', "field 'pose.param[0].max': must be >= -10.0, got -10.5"),
    ('max = 0.2\n', 'max = 10.5\n', "field 'pose.param[0].max': must be <= 10.0, got 10.5"),
    ('name = "easy"\n', 'name = "easy"\nset = 3\n',
     "field 'variant[0].set': must be a table of dotted scene keys and values"),
    ('name = "hard"\nharder = true\n', 'name = "easy"\nharder = true\n',
     "field 'variant': needs at least one [[variant]] with unique names, got ['easy', 'easy']"),
    ('name = "hard"\nharder = true\n', 'name = "hard"\n',
     "field 'variant': exactly one variant must be marked harder = true"),
    ('steps = ["grab", "push"]', 'steps = ["grab", "pull"]',
     "field 'demonstration.steps': must be a list of the case's skills (grab, push), "
     "got ['grab', 'pull']"),
    ('variant = "easy"', 'variant = "medium"',
     "field 'demonstration.variant': must be one of easy, hard, got 'medium'"),
    ('location = 2', 'location = 0', "field 'demonstration.location': must be >= 1, got 0"),
    ('dx = 0.05', 'dx = 0.5',
     "field 'demonstration.pose': demonstration.pose: dx must be within [-0.1, 0.2] m, "
     "got 0.5"),
    ('trial_budget = 3\n', 'trial_budget = 3\nbackend = "no_such_backend"\n',
     f"field 'backend': must be one of {BACKEND_NAMES}, got 'no_such_backend'"),
    ('trial_budget = 3\n', 'trial_budget = 3\nbackend = "PyBullet"\n',
     f"field 'backend': must be one of {BACKEND_NAMES}, got 'PyBullet' "
     "(did you mean 'pybullet'?)"),
    ('trial_budget = 3\n', 'trial_budget = 3\nbackend = 1\n',
     "field 'backend': must be a string, got 1"),
])
def test_manifest_errors_name_the_file_and_field(tmp_path, old, new, message):
    assert old in MINIMAL
    assert _error(_write(tmp_path, MINIMAL.replace(old, new, 1))) == message


def test_empty_arrays_of_skills_and_pose_parameters_are_refused(tmp_path):
    skills = MINIMAL[MINIMAL.index("[[skill]]"):MINIMAL.index("[pose]")]
    text = MINIMAL.replace(skills, "").replace("[roles]", "skill = []\n\n[roles]")
    assert _error(_write(tmp_path, text)) == "field 'skill': at least one [[skill]] is needed"
    params = MINIMAL[MINIMAL.index("[[pose.param]]"):MINIMAL.index("[[variant]]")]
    text = MINIMAL.replace(params, "").replace('term = "push_pose"\n',
                                               'term = "push_pose"\nparam = []\n')
    assert _error(_write(tmp_path, text, "no_params")) == (
        "field 'pose.param': at least one [[pose.param]] is needed")


def test_a_folder_without_a_manifest(tmp_path):
    with pytest.raises(WorldFileError) as caught:
        read_manifest(tmp_path)
    assert str(caught.value) == (f"{tmp_path / 'case.toml'}: file not found "
                                 f"(a case folder needs a case.toml)")


def test_bounds_equal_to_each_other_or_to_the_limits_are_kept(tmp_path):
    text = (MINIMAL.replace("min = -0.1\nmax = 0.2", "min = 0.05\nmax = 0.05")
            .replace("trial_budget = 3\n", "trial_budget = 10000\npaper_trials = 10000\n")
            + "[randomise.location.gap]\njitter = 1000.0\nmin = 0.5\nmax = 0.5\n"
            "[randomise.location.side]\njitter = 0\nmin = -1000.0\nmax = 1000.0\n")
    m = read_manifest(_write(tmp_path, text))
    assert (m.trial_budget, m.paper_trials) == (10000, 10000)
    assert m.pose_params == (PoseParam("dx", "m", 0.05, 0.05, ""),)
    assert m.location_jitter == (LocationJitter("gap", 1000.0, 0.5, 0.5),
                                 LocationJitter("side", 0.0, -1000.0, 1000.0))
    assert (m.catalogue_bounds, m.catalogue_value_bounds) == ((), ())
    text = MINIMAL.replace("min = -0.1\nmax = 0.2", "min = -10.0\nmax = 10.0")
    text += ("[randomise.catalogue.length]\nmin = -1000.0\nmax = 1000.0\n"
             "short = {min = 7, max = 7}\n")
    m = read_manifest(_write(tmp_path, text, "limits"))
    assert m.pose_params == (PoseParam("dx", "m", -10.0, 10.0, ""),)
    assert m.location_jitter == ()
    assert m.catalogue_bounds == (("length", -1000.0, 1000.0),)
    assert m.catalogue_value_bounds == (("length", "short", 7.0, 7.0),)


@pytest.mark.parametrize("table,old,new,message", [
    ("location.gap", "min = 0.0\n", "min = -1000.5\n", "min: must be >= -1000.0, got -1000.5"),
    ("location.gap", "min = 0.0\n", "min = 1000.5\n", "min: must be <= 1000.0, got 1000.5"),
    ("location.gap", "max = 0.04\n", "max = -1000.5\n",
     "max: must be >= -1000.0, got -1000.5"),
    ("location.gap", "max = 0.04\n", "max = 1000.5\n", "max: must be <= 1000.0, got 1000.5"),
    ("location.gap", "min = 0.0\nmax = 0.04", "min = 0.05\nmax = 0.04",
     "max: must be >= min (0.05), got 0.04"),
    ("location.gap", "jitter = 0.01\n", "jitter = -0.01\n", "jitter: must be >= 0.0, got -0.01"),
    ("location.gap", "jitter = 0.01\n", "jitter = 1000.5\n",
     "jitter: must be <= 1000.0, got 1000.5"),
    ("catalogue.length", "min = 0.1\n", "min = -1000.5\n",
     "min: must be >= -1000.0, got -1000.5"),
    ("catalogue.length", "min = 0.1\n", "min = 1000.5\n", "min: must be <= 1000.0, got 1000.5"),
    ("catalogue.width", "max = 0.03\n", "max = -1000.5\n",
     "max: must be >= -1000.0, got -1000.5"),
    ("catalogue.width", "max = 0.03\n", "max = 1000.5\n", "max: must be <= 1000.0, got 1000.5"),
    ("catalogue.length.long", "long = {min = 0.3, max = 0.5}", "long = {min = 0.6, max = 0.5}",
     "max: must be >= min (0.6), got 0.5"),
])
def test_randomise_errors_exact(tmp_path, table, old, new, message):
    assert old in FULL_EXTRA
    error = _error(_write(tmp_path, MINIMAL + FULL_EXTRA.replace(old, new, 1)))
    field, cause = message.split(": ", 1)
    assert error == f"field 'randomise.{table}.{field}': {cause}"


def test_a_randomise_table_with_only_locations_or_only_catalogue_bounds(tmp_path):
    locations, catalogue = FULL_EXTRA.split("[randomise.catalogue.length]")
    m = read_manifest(_write(tmp_path, MINIMAL + locations))
    assert m.location_jitter == (LocationJitter("gap", 0.01, 0.0, 0.04),
                                 LocationJitter("side", 0.0, -0.02, 0.02))
    assert (m.catalogue_bounds, m.catalogue_value_bounds) == ((), ())
    m = read_manifest(_write(tmp_path, MINIMAL + "[randomise.catalogue.length]" + catalogue,
                             "catalogue_only"))
    assert m.location_jitter == ()
    assert m.catalogue_bounds == (("length", 0.1, math.inf), ("width", -math.inf, 0.03))


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
    _write(tmp_path, 'title = "no id"\n', "c_world")
    _write(tmp_path, MINIMAL.replace('id = "mini"', 'id = "other"')
           .replace("trial_budget = 3", "trial_budget = 0"), "d_world")
    index = case_index(tmp_path)
    # issue 25: a duplicate id is no case at all (the sort order picked the one used)
    duplicate = (f"case 'mini' is declared by 2 folders: {tmp_path / 'a_world' / 'case.toml'}"
                 f" and {tmp_path / 'b_world' / 'case.toml'} (field 'id'; give each folder "
                 f"its own id)")
    assert index.folders == {"other": tmp_path / "d_world"}
    assert index.duplicates == {"mini": duplicate}
    assert sorted(index.broken) == [tmp_path / f"{x}_world" / "case.toml" for x in "abc"]
    assert index.broken[tmp_path / "a_world" / "case.toml"] == duplicate
    assert index.broken[tmp_path / "b_world" / "case.toml"] == duplicate
    with pytest.raises(WorldFileError) as refused:
        get_case("mini", tmp_path)
    assert str(refused.value) == duplicate
    assert set(load_cases(tmp_path, strict=False)) == set()
    with pytest.raises(WorldFileError):
        load_cases(tmp_path)
    assert sorted(broken_cases(tmp_path)) == [tmp_path / f"{x}_world" / "case.toml"
                                              for x in "abcd"]
    assert index.broken[tmp_path / "c_world" / "case.toml"] == (
        f"{tmp_path / 'c_world' / 'case.toml'}: field 'id': missing")
    assert broken_cases(tmp_path)[tmp_path / "d_world" / "case.toml"].startswith(
        f"{tmp_path / 'd_world' / 'case.toml'}: field 'trial_budget'")
    with pytest.raises(KeyError) as caught:
        get_case("nope", tmp_path)
    assert caught.value.args[0] == (
        f"unknown case 'nope'; known cases: other; {tmp_path / 'a_world' / 'case.toml'} does "
        f"not load; {tmp_path / 'b_world' / 'case.toml'} does not load; "
        f"{tmp_path / 'c_world' / 'case.toml'} does not load")


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
