"""The layers of ``creative_py``: which package may import which, as the design page says.

The rule is data in one place, the tables of section 3 of ``docs/architecture.md``
(read here, so the page cannot drift from the rule): a row per package (or top-level
module) of ``creative_py`` and the packages it may import, and a row per third-party
engine and the one package that imports it. A row may also name one module inside a
package (``backends.ros.twin``): what it allows, that module alone may import besides
its package's row (a narrow, stated exception, never a package's). Every import statement counts, a lazy one
inside a function too (``_imports.py``); imports inside one package are free.
"""

from __future__ import annotations

import re
from pathlib import Path

from _imports import PACKAGE, ROOT, ImportStatement, cycles, import_statements, modules

from creative_py.simulator import backend_packages

DOC = ROOT / "docs" / "architecture.md"
SECTION = "## 3. The layers"
WHERE = "docs/architecture.md section 3"


def section(text: str) -> str:
    """Return the text of the layers section of the design page."""
    start = text.index(SECTION)
    end = text.find("\n## ", start + len(SECTION))
    return text[start:] if end < 0 else text[start:end]


def table(text: str, header: str) -> list[tuple[list[str], list[str]]]:
    """Return the rows of the Markdown table whose header row starts ``| header |``:
    the backquoted names of the first column and of the second."""
    lines = text.splitlines()
    at = next((i for i, line in enumerate(lines)
               if line.replace(" ", "").startswith(f"|{header.replace(' ', '')}|")), None)
    if at is None:
        raise AssertionError(f"{WHERE} has no table headed '| {header} |'")
    rows = []
    for line in lines[at + 2:]:
        if not line.startswith("|"):
            break
        cells = line.strip().strip("|").split("|")
        first, second = cells[0], "|".join(cells[1:])
        rows.append((re.findall(r"`([A-Za-z0-9_.]+)`", first),
                     re.findall(r"`([A-Za-z0-9_.]+)`", second.split("(")[0])))
    return rows


def layer_rules(text: str) -> dict[str, set[str]]:
    """Return ``package -> packages it may import`` from the page's layer table."""
    rules: dict[str, set[str]] = {}
    for names, allowed in table(section(text), "package | may import"):
        for name in names:
            if name in rules:
                raise AssertionError(f"{WHERE}: package {name} has two rows")
            rules[name] = set(allowed)
    return rules


def library_owners(text: str) -> dict[str, str]:
    """Return ``third-party library -> the one package that imports it`` from the page."""
    owners: dict[str, str] = {}
    for libraries, owner in table(section(text), "library | imported only by"):
        if len(owner) != 1:
            raise AssertionError(f"{WHERE}: {libraries} need one owner, got {owner}")
        owners.update({lib: owner[0] for lib in libraries})
    return owners


def package_of(module: str) -> str:
    """Return the package (or top-level module) of ``creative_py`` a module belongs to;
    ``""`` for the package root ``creative_py`` itself."""
    parts = module.split(".")
    if len(parts) > 2 and parts[1] == "backends":
        return f"backends.{parts[2]}"  # each backend is a package of its own
    return parts[1] if len(parts) > 1 else ""


def packages(names) -> set[str]:
    """Return the packages and top-level modules of ``creative_py`` among module names."""
    return {package_of(m) for m in names} - {""}


def where(s: ImportStatement) -> str:
    return f"{s.path.relative_to(ROOT)}:{s.line}"


def own_name(module: str) -> str:
    """Return a module's name as a row of the table names it (``creative_py.`` left off)."""
    return module.split(".", 1)[1] if "." in module else ""


def module_rows(rules: dict[str, set[str]], on_disk: set[str]) -> set[str]:
    """Return the rows of the table that name one module inside a package, not a package
    (``on_disk``: the packages and top-level modules of ``creative_py``)."""
    return {name for name in rules if name not in on_disk
            and package_of(f"creative_py.{name}") != name}


def unnamed_packages(rules: dict[str, set[str]], on_disk: set[str],
                     known: set[str] = frozenset()) -> list[str]:
    """Return an error per package of ``creative_py`` without a row, per name in the
    table that is no package of ``creative_py``, and per module row (``known``: the
    module names of ``creative_py``) that names no module or whose package has no row."""
    errors = [f"creative_py/{p} has no row in the layer table of {WHERE}: add one saying "
              "which packages it may import, and add it to the rows of the packages that "
              "import it" for p in sorted(on_disk - set(rules))]
    narrow = module_rows(rules, on_disk)
    named = (set(rules) - narrow) | {p for allowed in rules.values() for p in allowed}
    errors += [f"the layer table of {WHERE} names {p}, which is no package or top-level "
               "module of creative_py" for p in sorted(named - on_disk)]
    errors += [f"the layer table of {WHERE} has a row for the module {m}, which is no "
               "module of creative_py inside a package with a row of its own"
               for m in sorted(narrow) if f"creative_py.{m}" not in known
               or package_of(f"creative_py.{m}") not in rules]
    return errors


def forbidden_imports(statements: list[ImportStatement], rules: dict[str, set[str]],
                      known: set[str]) -> list[str]:
    """Return ``file:line: ...`` for each import between packages its row does not allow
    (its package's row, and its own module row if it has one); ``known`` are the module
    names of ``creative_py``."""
    errors = []
    for s in statements:
        if s.target not in known:
            continue  # not a module of creative_py
        src, dst = package_of(s.module), package_of(s.target)
        own = own_name(s.module)
        allowed = rules.get(src, set()) | (rules.get(own, set()) if own != src else set())
        if src == "" and dst != "":
            errors.append(f"{where(s)}: the package root imports {s.target}; importing "
                          "creative_py must start nothing")
        elif dst not in ("", src) and src in rules and dst not in allowed:
            names = ", ".join(sorted(allowed)) or "nothing of creative_py"
            who = src if own == src or own not in rules else own
            errors.append(f"{where(s)}: {who} imports {s.target}, but {who} may import only "
                          f"{names} ({WHERE})")
    return errors


def misplaced_libraries(statements: list[ImportStatement], owners: dict[str, str]) -> list[str]:
    """Return ``file:line: ...`` for each import of a third-party engine outside its home."""
    return [f"{where(s)}: {package_of(s.module)} imports {s.target.split('.')[0]}, which only "
            f"{owners[s.target.split('.')[0]]} may import ({WHERE})"
            for s in statements
            if s.target.split(".")[0] in owners
            and package_of(s.module) != owners[s.target.split(".")[0]]]


def package_graph(statements: list[ImportStatement], known: set[str]) -> dict[str, set[str]]:
    """Return ``package -> packages of creative_py it imports`` (the root left out)."""
    graph: dict[str, set[str]] = {p: set() for p in packages(known)}
    for s in statements:
        src, dst = package_of(s.module), package_of(s.target)
        if s.target in known and "" not in (src, dst) and src != dst:
            graph[src].add(dst)
    return graph


# ----------------------------------------------------------------------- the checker


def _statement(module: str, target: str) -> ImportStatement:
    return ImportStatement(module, PACKAGE / "x.py", 7, target)


PAGE = """# Design

## 3. The layers

| package | may import |
|---|---|
| `top` | `low`, `leaf` |
| `low` | `leaf` (the leaf's reader) |
| `leaf` | nothing |
| `leaf.gate` | `low` (one module of leaf, and no other, may) |

| library | imported only by |
|---|---|
| `pyswip` | `low` |

## 4. Next
"""


def test_the_checker_reads_the_tables_of_the_layers_section() -> None:
    assert layer_rules(PAGE) == {"top": {"low", "leaf"}, "low": {"leaf"}, "leaf": set(),
                                 "leaf.gate": {"low"}}
    assert library_owners(PAGE) == {"pyswip": "low"}


def test_the_checker_finds_a_forbidden_import_a_missing_row_and_a_misplaced_library() -> None:
    rules = layer_rules(PAGE)
    known = {"creative_py", "creative_py.top", "creative_py.low.a", "creative_py.low.b",
             "creative_py.leaf", "creative_py.new.x", "creative_py.leaf.gate",
             "creative_py.leaf.other"}
    ok = [_statement("creative_py.top", "creative_py.low.a"),
          _statement("creative_py.low.a", "creative_py.low.b"),
          _statement("creative_py.low.b", "creative_py.leaf"),
          _statement("creative_py.low.b", "creative_py"),
          _statement("creative_py.leaf", "numpy")]
    assert forbidden_imports(ok, rules, known) == []
    bad = _statement("creative_py.leaf", "creative_py.low.a")
    assert forbidden_imports(ok + [bad], rules, known) == [
        f"creative_py/x.py:7: leaf imports creative_py.low.a, but leaf may import only "
        f"nothing of creative_py ({WHERE})"]
    # A module row is narrow: that module may, the rest of its package may not.
    gate = _statement("creative_py.leaf.gate", "creative_py.low.a")
    other = _statement("creative_py.leaf.other", "creative_py.low.a")
    assert forbidden_imports([gate], rules, known) == []
    assert forbidden_imports([other], rules, known) == [
        f"creative_py/x.py:7: leaf imports creative_py.low.a, but leaf may import only "
        f"nothing of creative_py ({WHERE})"]
    root = _statement("creative_py", "creative_py.leaf")
    assert "the package root imports" in forbidden_imports([root], rules, known)[0]
    assert unnamed_packages(rules, packages(known), known) == [
        f"creative_py/new has no row in the layer table of {WHERE}: add one saying which "
        "packages it may import, and add it to the rows of the packages that import it"]
    assert "has a row for the module leaf.gate" in unnamed_packages(
        rules, packages(known), known - {"creative_py.leaf.gate"})[-1]
    assert "names leaf, which is no package" in unnamed_packages(rules, {"top", "low"})[0]
    lib = _statement("creative_py.top", "pyswip.core")
    assert misplaced_libraries([lib], library_owners(PAGE)) == [
        f"creative_py/x.py:7: top imports pyswip, which only low may import ({WHERE})"]
    assert cycles(package_graph(ok + [bad], known)) == [["leaf", "low"]]


# ----------------------------------------------------------------------- creative_py


def test_every_package_of_creative_py_has_a_row_in_the_layer_table() -> None:
    rules = layer_rules(DOC.read_text())
    on_disk = packages(modules())
    assert {"cli", "learning", "backends.pybullet", "simulator", "bridge", "records", "report"} <= on_disk
    # A registered backend's package has its row even in a checkout without it.
    errors = unnamed_packages(rules, on_disk | backend_packages(), set(modules()))
    assert errors == [], "\n".join(errors)


def test_the_layer_table_allows_no_cycle_between_packages() -> None:
    assert cycles(layer_rules(DOC.read_text())) == []


def test_no_package_imports_what_its_row_does_not_allow() -> None:
    rules = layer_rules(DOC.read_text())
    statements = import_statements()
    assert len(statements) > 100
    errors = forbidden_imports(statements, rules, set(modules()))
    assert errors == [], "\n".join(errors)


def test_creative_py_has_no_cycle_between_packages() -> None:
    known = set(modules())
    assert cycles(package_graph(import_statements(), known)) == []


def test_the_physics_asks_no_one() -> None:
    # Whatever the table says: every backend (and the boundary) gets the pose resolver
    # from its caller.
    known = set(modules())
    physics = backend_packages() | {"simulator"}
    assert [where(s) for s in import_statements()
            if package_of(s.module) in physics and s.target in known
            and package_of(s.target) in ("bridge", "learning")] == []


def test_each_third_party_engine_has_one_home() -> None:
    owners = library_owners(DOC.read_text())
    assert {"pyswip": "bridge", "pybullet": "backends.pybullet", "trimesh": "mesh"}.items() <= owners.items()
    errors = misplaced_libraries(import_statements(), owners)
    assert errors == [], "\n".join(errors)


def test_the_learning_loop_imports_no_simulator_backend() -> None:
    # Whatever the table says: learning (and the sweep and reports above or beside it)
    # reaches a physics through the boundary, creative_py.simulator, alone.
    backends = backend_packages()
    assert {"backends.pybullet", "backends.maniskill"} <= backends
    rules = layer_rules(DOC.read_text())
    loop = ("learning", "sweep", "report")
    assert [p for p in loop if rules[p] & backends] == []
    assert [where(s) for s in import_statements()
            if package_of(s.module) in loop and s.target.startswith("creative_py.")
            and package_of(s.target) in backends] == []


def test_no_backend_imports_another_but_the_two_modules_the_table_names() -> None:
    # Whatever the table says: a backend's package imports no other backend's, except the
    # ROS 2 backend's learner's model (twin.py: the pybullet backend's episode and
    # kinematics, whose physics never runs) and its stand-in (standin.py: the pybullet
    # backend's scene served behind an arm's interface, a process of its own).
    backends = backend_packages()
    known = set(modules())
    crossing = {s.module for s in import_statements()
                if package_of(s.module) in backends and s.target in known
                and package_of(s.target) in backends
                and package_of(s.target) != package_of(s.module)}
    assert crossing == {"creative_py.backends.ros.twin", "creative_py.backends.ros.standin"}
    rules = layer_rules(DOC.read_text())
    assert [p for p in backends if rules[p] & backends] == []
    assert {m for m, allowed in rules.items() if allowed & backends} == {
        "backends.ros.twin", "backends.ros.standin"}
