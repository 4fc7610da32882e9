"""The world files are read once, above the backends (docs/architecture.md sections 1-3).

A world whose scene a backend builds (``scene.toml``, ``tasks.toml``, ``physics.toml``,
``objects.toml``) is read by :mod:`creative_py.world` for every backend that builds
one; the backends build what it describes and read no world file themselves. The one
exception is stated: a ManiSkill world's ``tasks.toml`` names a ManiSkill task and its
actors (a format only that backend runs), read by its ``scene.py``, whose catalogue is
read by the same :func:`creative_py.simulator.catalogue.read_catalogue`.
"""

from __future__ import annotations

import ast

from _imports import PACKAGE, module_name, modules

from creative_py.simulator import backend_packages

OWN_FORMAT = {"creative_py.backends.maniskill.scene"}
"""The backend modules that read a world format of their own (see the module doc)."""

LOADERS = {"load_toml", "world_file", "tomllib"}
"""What reading a world file takes (the TOML loader of world files, a file of a world)."""


def _backend_files() -> dict[str, object]:
    backends = {f"creative_py.{b}" for b in backend_packages()}
    return {m: p for m, p in modules().items()
            if any(m == b or m.startswith(b + ".") for b in backends)}


def test_no_backend_reads_a_world_file_but_the_one_with_a_format_of_its_own() -> None:
    # A broken build: put `load_toml(world_file(d, "scene.toml"))` back into a module of
    # backends/pybullet and this lists it.
    found = []
    for module, path in _backend_files().items():
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            name = (node.func.id if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                    else node.names[0].name if isinstance(node, ast.Import) else None)
            if name in LOADERS and module not in OWN_FORMAT:
                found.append(f"{path.relative_to(PACKAGE.parent)}:{node.lineno}: {name}")
    assert found == []


def test_no_backend_imports_another_backend_s_world() -> None:
    # The ROS 2 backend's twin is the pybullet backend's episode, but its World comes
    # from creative_py.world, not from the pybullet backend.
    backends = {f"creative_py.{b}" for b in backend_packages()}
    found = []
    for module, path in _backend_files().items():
        own = next(b for b in backends if module == b or module.startswith(b + "."))
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if not (isinstance(node, ast.ImportFrom) and node.module):
                continue
            other = next((b for b in backends - {own}
                          if node.module == b or node.module.startswith(b + ".")), None)
            names = {a.name for a in node.names}
            if other and names & {"load_world", "World", "world"}:
                found.append(f"{module}:{node.lineno}: {node.module} {sorted(names)}")
    assert found == []


def test_the_pybullet_backend_loads_its_world_with_the_one_reader() -> None:
    import creative_py.backends.pybullet as pybullet_backend
    from creative_py.world import read

    assert pybullet_backend.load_world is read.load_world
    assert pybullet_backend.World is read.World


def test_the_ros_backend_loads_its_world_with_the_one_reader() -> None:
    path = PACKAGE / "backends" / "ros" / "backend.py"
    tree = ast.parse(path.read_text(), str(path))
    assert module_name(path) == "creative_py.backends.ros.backend"
    assert any(isinstance(n, ast.ImportFrom) and n.module == "creative_py.world.read"
               and any(a.name == "load_world" for a in n.names) for n in ast.walk(tree))
