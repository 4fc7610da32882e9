"""A case is data: the code names no case, world folder, scene object or catalogued object.

The names come from the data itself (every ``worlds/*/`` folder: its name, the case id
and roles of its ``case.toml``, every ``name`` of its ``scene.toml`` and
``objects.toml``), so a new case is checked as soon as its folder exists. Outside
``worlds/``, ``ontology/``, ``tests/`` and ``docs/`` no code line (comments and
docstrings aside) names a world folder, a scene object or a catalogued object; in
``prolog/`` and ``creative_py/learning/`` no code line names a case id either.
"""

from __future__ import annotations

import io
import re
import tokenize
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
SCANNED = ("creative_py", "prolog", "bench")
NO_CASE_IDS = ("prolog", "creative_py/learning")


def _names_in(data, out: set[str]) -> None:
    # Cameras are sensors, not scene objects ("top", "side").
    if isinstance(data, dict):
        for k, v in data.items():
            if k == "name" and isinstance(v, str):
                out.add(v)
            elif k != "camera":
                _names_in(v, out)
    elif isinstance(data, list):
        for v in data:
            _names_in(v, out)


def world_names() -> tuple[set[str], set[str]]:
    """Return (world folders with scene and catalogued objects, case ids) of ``worlds/``."""
    objects: set[str] = set()
    ids: set[str] = set()
    folders: set[str] = set()
    for case_toml in sorted((ROOT / "worlds").glob("*/case.toml")):
        folder = case_toml.parent
        folders.add(folder.name)
        manifest = tomllib.loads(case_toml.read_text())
        ids.add(manifest["id"])
        objects.update((manifest["roles"]["target"], manifest["roles"]["context"]))
        for f in ("scene.toml", "objects.toml"):
            if (folder / f).exists():
                _names_in(tomllib.loads((folder / f).read_text()), objects)
    return folders | objects, ids


def python_code_lines(text: str) -> dict[int, str]:
    """Return ``line -> code`` of Python source without comments and docstrings."""
    lines: dict[int, list[str]] = {}
    prev = tokenize.NEWLINE
    for tok in tokenize.generate_tokens(io.StringIO(text).readline):
        if tok.type == tokenize.COMMENT:
            continue
        if tok.type == tokenize.STRING and prev in (tokenize.NEWLINE, tokenize.NL,
                                                    tokenize.INDENT, tokenize.DEDENT):
            prev = tok.type  # a docstring (a string statement)
            continue
        if tok.type not in (tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT,
                            tokenize.ENDMARKER):
            for n in range(tok.start[0], tok.end[0] + 1):
                lines.setdefault(n, []).append(tok.string)
        prev = tok.type
    return {n: " ".join(parts) for n, parts in lines.items()}


def prolog_code_lines(text: str) -> dict[int, str]:
    """Return ``line -> code`` of Prolog source without comments."""
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    out = {}
    for n, line in enumerate(text.splitlines(), 1):
        code = re.sub(r"%.*", "", re.sub(r"0'%", "", line)).strip()
        if code:
            out[n] = code
    return out


def violations(names: set[str], roots: tuple[str, ...]) -> list[str]:
    """Return ``file:line: name`` for each code line under ``roots`` naming one of ``names``."""
    if not names:
        return []
    pattern = re.compile(r"(?<![A-Za-z0-9_])(" + "|".join(sorted(map(re.escape, names)))
                         + r")(?![A-Za-z0-9_])")
    found = []
    for root in roots:
        for path in sorted((ROOT / root).rglob("*")):
            if path.suffix == ".py":
                code = python_code_lines(path.read_text())
            elif path.suffix in (".pl", ".plt"):
                code = prolog_code_lines(path.read_text())
            else:
                continue
            for n, line in sorted(code.items()):
                for m in pattern.finditer(line):
                    found.append(f"{path.relative_to(ROOT)}:{n}: {m.group(1)}")
    return found


def test_the_scanner_reads_code_not_comments_or_docstrings():
    py = '"""cube1 here"""\nx = 1  # cube1\ny = "cube1"\n'
    assert list(python_code_lines(py).values()) == ["x = 1", 'y = "cube1"']
    pl = "% cube1\np(X) :- q(X). % cube1\n/* cube1\n */ r(cube1).\n"
    assert prolog_code_lines(pl) == {2: "p(X) :- q(X).", 4: "r(cube1)."}


def test_the_worlds_name_their_objects():
    objects, ids = world_names()
    assert {"hook", "wedge"} <= ids
    assert {"hook_tube", "cube1", "tube1", "hook_a2", "door1", "wedge_a2"} <= objects


def test_no_code_outside_the_data_names_a_world_scene_or_catalogued_object():
    objects, _ = world_names()
    assert violations(objects, SCANNED) == []


def test_no_engine_or_learning_code_names_a_case():
    _, ids = world_names()
    assert violations(ids, NO_CASE_IDS) == []
