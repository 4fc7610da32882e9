"""Every import statement of ``creative_py``, read from the source, and the graphs they make.

Every statement counts, also one inside a function or under ``if TYPE_CHECKING`` (a lazy
import hides a dependency from Python, not from a reader). Importing ``a.b.c`` runs the
package ``a.b`` first; that implicit edge is not counted, the written ones are.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
PACKAGE = ROOT / "creative_py"


@dataclass(frozen=True)
class ImportStatement:
    """One name an import statement imports: ``module`` (at ``path``:``line``) imports
    ``target`` (an absolute dotted name: a module of ``creative_py`` when the statement
    names one, else what it names, e.g. ``pybullet`` or ``matplotlib.figure``)."""

    module: str
    path: Path
    line: int
    target: str


def module_name(path: Path) -> str:
    """Return the dotted module name of a source file of ``creative_py``."""
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def modules() -> dict[str, Path]:
    """Return ``module -> source file`` of every module of ``creative_py``."""
    return {module_name(p): p for p in sorted(PACKAGE.rglob("*.py"))}


def import_statements(files: dict[str, Path] | None = None) -> list[ImportStatement]:
    """Return every name imported by every import statement of ``files`` (default: all
    of ``creative_py``), relative imports made absolute."""
    files = modules() if files is None else files
    found: list[ImportStatement] = []
    for name, path in files.items():
        is_package = path.name == "__init__.py"
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    anchor = name.split(".")
                    anchor = anchor if is_package else anchor[:-1]
                    anchor = anchor[:len(anchor) - node.level + 1]
                    base = ".".join(anchor + ([base] if base else []))
                # ``from pkg import sub`` imports the submodule; ``from mod import name``
                # the module.
                targets = [f"{base}.{a.name}" if f"{base}.{a.name}" in files else base
                           for a in node.names]
            found.extend(ImportStatement(name, path, node.lineno, t) for t in targets)
    return found


def import_graph() -> dict[str, set[str]]:
    """Return ``module -> modules of creative_py it imports`` from the source."""
    files = modules()
    graph: dict[str, set[str]] = {m: set() for m in files}
    for s in import_statements(files):
        if s.target in files and s.target != s.module:
            graph[s.module].add(s.target)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Return one cycle per strongly connected component with more than one node."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                found.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found
