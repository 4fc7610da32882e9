"""The module graph of ``creative_py`` has no import cycle.

Every import statement counts, also one inside a function (a lazy import hides a cycle
from Python, not from a reader); see ``_imports.py``. Which package may import which is
checked by ``test_layers.py``.
"""

from __future__ import annotations

from _imports import cycles, import_graph, import_statements


def test_the_cycle_finder_finds_a_cycle() -> None:
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_creative_py_has_no_import_cycle() -> None:
    graph = import_graph()
    assert "creative_py.bridge.terms" in graph
    assert cycles(graph) == []


def test_the_bridge_imports_only_the_standard_library_pyswip_and_itself() -> None:
    """``make test-narrow`` (numpy's vector dispatch narrowed) leaves out
    ``tests/python/bridge``: the Prolog facade computes no float with numpy, which holds
    while it imports nothing else."""
    import sys

    outside = sorted(f"{s.path.name}:{s.line}: {s.target}" for s in import_statements()
                     if s.module.split(".")[:2] == ["creative_py", "bridge"]
                     and s.target.split(".")[0] not in sys.stdlib_module_names
                     and s.target.split(".")[0] != "pyswip"
                     and s.target.split(".")[:2] != ["creative_py", "bridge"])
    assert outside == []
