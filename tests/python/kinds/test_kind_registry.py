"""The tool kinds are plug-ins: one module per ``ontology/kinds/<kind>.pl``, one registry.

The registry is the ontology's folder; each kind module is pure (it imports only
``creative_py.kinds`` and the standard library), and no code outside ``creative_py/kinds``
names a spec class, so a new kind needs no other Python edit.
"""

from __future__ import annotations

import ast
import importlib.util
import re
from pathlib import Path

import pytest

import creative_py.kinds as kinds
from creative_py.kinds import kind_module, kind_names, kind_of, spec_classes, spec_from_dict
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec

ROOT = Path(__file__).resolve().parents[3]
KIND_MODULES = sorted(p.stem for p in (ROOT / "creative_py" / "kinds").glob("*.py")
                      if p.stem not in ("__init__", "parts"))


def test_every_ontology_kind_file_has_its_module_and_no_module_lacks_a_file():
    names = kind_names()
    assert {"hook_like", "block"} <= set(names)
    assert list(names) == KIND_MODULES
    for name in names:
        assert kind_module(name).__name__ == f"creative_py.kinds.{name}"


def test_the_classes_of_a_kind_are_classes_of_its_ontology_file():
    for name in kind_names():
        text = (ROOT / "ontology" / "kinds" / f"{name}.pl").read_text()
        for cls in kind_module(name).CLASSES:
            assert re.search(rf"^subclass_of\({cls},", text, re.M), (name, cls)


def test_the_registry_maps_ontology_classes_to_spec_classes():
    classes = spec_classes()
    assert classes["hook"] is HookSpec and classes["stick"] is HookSpec
    assert classes["block"] is BlockSpec
    assert "hook_like" not in classes  # the kind's name is no class of a tool
    stick = spec_from_dict({"kind": "stick", "name": "s1", "handle_length": 0.3})
    assert stick.kind == "stick" and stick.is_stick and kind_of(stick) == "hook_like"
    assert kind_of(BlockSpec("b1", "box", 0.05, 0.05, 0.05)) == "block"


def test_an_unknown_class_is_refused_naming_the_known_ones():
    with pytest.raises(ValueError, match=r"field 'kind' must be one of .*block.*hook.*stick"):
        spec_from_dict({"kind": "spoon", "name": "x1"}, source="objects.toml")
    with pytest.raises(KeyError, match="no tool kind 'spoon'"):
        kind_module("spoon")


def test_an_ontology_kind_without_a_module_is_named(tmp_path, monkeypatch):
    (tmp_path / "spoon.pl").write_text("subclass_of(spoon, tool).\n")
    monkeypatch.setattr(kinds, "KINDS_DIR", tmp_path)
    kind_names.cache_clear()
    kind_module.cache_clear()
    try:
        with pytest.raises(ImportError, match=r"spoon\.pl: the tool kind has no plug-in "
                                              r"module creative_py/kinds/spoon\.py"):
            kind_module("spoon")
    finally:
        kind_names.cache_clear()
        kind_module.cache_clear()


def _imports(path: Path) -> set[str]:
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            out |= {a.name for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            out.add(node.module or "")
    return out


def test_the_kinds_package_is_pure():
    allowed = {"__future__", "dataclasses", "itertools", "math", "typing", "importlib", "functools",
               "pathlib", "types", "creative_py.kinds", "creative_py.kinds.parts"}
    for path in sorted((ROOT / "creative_py" / "kinds").glob("*.py")):
        assert _imports(path) <= allowed, (path.name, _imports(path) - allowed)


def _code_lines():
    spec = importlib.util.spec_from_file_location(
        "case_names", ROOT / "tests" / "python" / "architecture" / "test_case_names.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.python_code_lines


def test_no_code_outside_the_kinds_names_a_spec_class():
    """Comments and docstrings aside: the mesh writers, the simulator and the learning
    loop ask a spec, they do not test its type."""
    code_lines = _code_lines()
    names = {cls.__name__ for cls in spec_classes().values()}
    pattern = re.compile(r"\b(" + "|".join(sorted(names)) + r")\b")
    found = []
    for path in sorted((ROOT / "creative_py").rglob("*.py")):
        if path.parent.name == "kinds":
            continue
        for n, code in code_lines(path.read_text()).items():
            if pattern.search(code):
                found.append(f"{path.relative_to(ROOT)}:{n}: {code}")
    assert found == []


# -- what every kind must be (a new kind is checked here, no line of this file changes)
_ABSTRACT = ("parts", "catalogue_facts", "feature_dimensions", "scad", "load_model")


@pytest.mark.parametrize("name", kind_names())
def test_every_kind_s_spec_keeps_the_contract(name):
    """Each class a kind's ``CLASSES`` names is a frozen :class:`KindSpec` dataclass that
    answers every question the mesh writers, the simulator and the strength check ask,
    held by a registered handling, drawn on a known plane, its catalogue facts backed by
    its own fields."""
    import dataclasses

    from creative_py.backends.pybullet.tools import HANDLINGS
    from creative_py.kinds.parts import KindSpec

    module = kind_module(name)
    assert module.CLASSES, name
    for cls, spec in module.CLASSES.items():
        assert issubclass(spec, KindSpec) and dataclasses.is_dataclass(spec), (name, cls)
        assert spec.__dataclass_params__.frozen, (name, cls)
        for method in _ABSTRACT:
            assert getattr(spec, method) is not getattr(KindSpec, method), (name, method)
        assert spec.HANDLING in HANDLINGS, (name, spec.HANDLING)
        assert spec.DRAWING_PLANE in ("top", "side"), (name, spec.DRAWING_PLANE)
        assert len(spec.RGBA) == 4 and all(0.0 <= c <= 1.0 for c in spec.RGBA)
        own = {f.name for f in dataclasses.fields(spec)}
        assert {"name", "kind"} <= own
        assert set(spec.FACT_FIELDS.values()) <= own, (name, spec.FACT_FIELDS)
        assert callable(getattr(spec, "from_fields", None)), name


def _shipped_tools() -> dict[str, list]:
    """Return kind -> the specs of every catalogued tool of the shipped worlds."""
    from creative_py.case import read_manifest
    from creative_py.simulator.catalogue import read_catalogue

    out: dict[str, list] = {}
    for folder in sorted(p.parent for p in (ROOT / "worlds").glob("*/case.toml")):
        table = read_manifest(folder).tools_table
        for item in read_catalogue(folder / "objects.toml", table, lambda spec: None).values():
            out.setdefault(kind_of(item.spec), []).append(item.spec)
    return out


@pytest.mark.parametrize("name", kind_names())
def test_every_kind_s_volume_is_its_solid_s(name):
    """A spec's ``volume()`` (a created tool's mass is PLA times it, and the STL check
    holds the STL to it within 0.1 %) equals the volume of the solid its parts make,
    overlaps counted once, for every catalogued tool of the kind in the shipped worlds
    (within 0.1 %: a cylinder's solid is a polygon of facets)."""
    from creative_py.mesh.solid import tool_mesh
    from creative_py.mesh.tolerances import STL_VOLUME_RTOL

    specs = _shipped_tools().get(name, [])
    if not specs:
        pytest.skip(f"no shipped world catalogues a tool of the kind {name}")
    for spec in specs:
        assert spec.volume() == pytest.approx(tool_mesh(spec).volume, rel=STL_VOLUME_RTOL), \
            spec.name
