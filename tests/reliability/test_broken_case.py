"""One broken ``case.toml`` under ``worlds/`` affects only its own case.

Cases are found by their manifest's ``id`` alone; a case's manifest is read whole only
when that case is asked for, and ``creative cases`` lists a folder that does not load as
broken, with its error line, beside the cases that do.
"""

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from creative_py.case import broken_cases, case_index, get_case, load_cases
from creative_py.world_files import WORLDS_ROOT, WorldFileError

from test_bad_input import BANNER, _tree_copy


@pytest.fixture()
def worlds(tmp_path) -> Path:
    """A copy of the shipped worlds with two broken manifests beside them."""
    root = tmp_path / "worlds"
    shutil.copytree(WORLDS_ROOT, root, ignore=shutil.ignore_patterns("__pycache__"))
    (root / "not_toml").mkdir()
    (root / "not_toml" / "case.toml").write_text("id = 'oops\n")
    typo = root / "typo_case"
    shutil.copytree(root / "rake_shelf", typo)
    text = (typo / "case.toml").read_text().replace('id = "rake"', 'id = "rake2"')
    (typo / "case.toml").write_text(text.replace("trial_budget", "trial_budgte", 1))
    return root


def test_a_broken_manifest_leaves_every_other_case_loadable(worlds):
    assert get_case("hook", worlds).id == "hook"
    assert get_case("wedge", worlds).trial_budget == 9
    assert sorted(load_cases(worlds, strict=False)) == sorted(load_cases())


def test_the_broken_manifests_are_listed_with_their_error_line(worlds):
    broken = broken_cases(worlds)
    assert sorted(p.parent.name for p in broken) == ["not_toml", "typo_case"]
    assert "not valid TOML" in broken[worlds / "not_toml" / "case.toml"]
    assert "trial_budget" in broken[worlds / "typo_case" / "case.toml"]
    assert case_index(worlds).folders["rake2"] == worlds / "typo_case"


def test_the_broken_case_itself_is_refused_with_its_file_and_field(worlds):
    with pytest.raises(WorldFileError, match=r"typo_case/case.toml.*trial_budget"):
        get_case("rake2", worlds)
    with pytest.raises(WorldFileError):
        load_cases(worlds)  # strict: the first broken manifest is an error


def test_an_unknown_case_names_the_folders_that_do_not_load(worlds):
    with pytest.raises(KeyError, match=r"unknown case 'nope'.*not_toml/case.toml does not load"):
        get_case("nope", worlds)


def test_creative_cases_lists_a_broken_case_and_the_others(tmp_path):
    import os

    copy = _tree_copy(tmp_path)
    (copy / "worlds" / "broken_one").mkdir()
    (copy / "worlds" / "broken_one" / "case.toml").write_text("id = [\n")
    env = {**os.environ, "PYTHONPATH": str(copy)}
    proc = subprocess.run([sys.executable, "-m", "creative_py.cli", "cases", "--json"],
                          capture_output=True, text=True, timeout=60, env=env, cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr
    listing = json.loads(proc.stdout)
    assert sorted(c["id"] for c in listing if c["id"]) == sorted(load_cases())
    [broken] = [c for c in listing if c["id"] is None]
    assert broken["manifest"].endswith("broken_one/case.toml")
    assert "not valid TOML" in broken["broken"]
    text = subprocess.run([sys.executable, "-m", "creative_py.cli", "cases"],
                          capture_output=True, text=True, timeout=60, env=env, cwd=tmp_path)
    width = max(len(c["id"]) for c in listing if c["id"])    # the longest id's (issue 25)
    assert [line for line in text.stdout.splitlines() if line.startswith("broken")] == [
        f"{'broken':<{width}} {broken['broken']}"]
    assert BANNER not in text.stdout
