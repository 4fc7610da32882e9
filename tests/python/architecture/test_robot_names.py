"""An arm is data: no robot's name appears in ``creative_py``.

The names come from the data itself (every ``robots/*.toml`` profile's file name and
``name``, and the makers' names of the arms the profiles describe), so a profile added
later is checked as soon as it exists. Every file of ``creative_py`` is searched, code,
comments and docstrings alike, case-insensitively: what
``grep -rni "baxter\\|panda" creative_py`` would find, and more.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]


def robot_names() -> set[str]:
    """Return the shipped profiles' names (file stems and ``name`` fields)."""
    names = set()
    for path in (ROOT / "robots").glob("*.toml"):
        names.add(path.stem.lower())
        names.add(str(tomllib.loads(path.read_text())["name"]).lower())
    return names


def hits(names: set[str]) -> list[str]:
    """Return ``file:line: text`` of every line of ``creative_py`` naming a robot."""
    pattern = re.compile("|".join(re.escape(n) for n in sorted(names)), re.I)
    out = []
    for path in sorted((ROOT / "creative_py").rglob("*")):
        if not path.is_file() or path.suffix not in (".py", ".pl", ".toml", ".md", ".txt",
                                                     ".json", ".yaml", ".cfg"):
            continue
        for n, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            if pattern.search(line):
                out.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    return out


def test_the_shipped_profiles_include_the_two_issue_arms():
    assert {"baxter", "panda"} <= robot_names()


def test_no_robot_is_named_in_the_package():
    assert hits(robot_names() | {"baxter", "panda", "franka"}) == []


def test_the_search_finds_a_robot_name_where_there_is_one(tmp_path, monkeypatch):
    # The search itself can fail: point it at a tree with a name in a docstring.
    pkg = tmp_path / "creative_py"
    pkg.mkdir()
    (pkg / "x.py").write_text('"""Moves the Baxter."""\n')
    monkeypatch.setattr(__import__(__name__), "ROOT", tmp_path)
    assert hits({"baxter"}) == ['creative_py/x.py:1: """Moves the Baxter."""']
