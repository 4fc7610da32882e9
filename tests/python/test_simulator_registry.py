"""The simulator boundary's registry: a manifest's ``backend`` picks the module that runs
its world, and every way that can go wrong is one line naming the file.

A tiny backend defined here, registered under a test name, proves the dispatch (the
learning loop's task facts come from whichever backend the manifest names); it is a
test of the registry only. The pybullet backend itself is tested by ``tests/python/backends/pybullet``
and by every learning test. Every installed backend is checked against the protocol's
signatures (:func:`signature_mismatches`); one whose packages are missing is skipped
with the error that names them.
"""

from __future__ import annotations

import inspect
import sys
import types
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from typer.testing import CliRunner

from creative_py.backends import BACKENDS, DEFAULT_BACKEND, BackendEntry
from creative_py.case import read_manifest
from creative_py.cli import app
from creative_py.simulator import (Backend, BackendError, BackendUnavailable, Episode,
                                   Observation, UnknownBackend, World, backend, backend_for,
                                   backend_packages)
from creative_py.world_files import WorldFileError

NAMES = ", ".join(sorted(BACKENDS))
"""The registry's backends as the errors list them (a new backend changes no line)."""
NOT_A_BACKEND = "no_such_backend"

MANIFEST = """\
id = "regcase"
title = "A case for the registry"
ontology = "regcase"
trial_budget = 2
goal = ["at(box1, shelf1)"]
{backend}
[roles]
tools = "tool"
target = "box1"
context = "shelf1"

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
location = 1
steps = ["push"]
[demonstration.pose]
dx = 0.05
"""


@pytest.fixture(autouse=True)
def _ontology_file(tmp_path_factory, monkeypatch):
    """The ontology file the manifest names: a manifest's ``ontology`` must be a file of
    ontology/cases/ that declares the case (issue 25)."""
    import creative_py.case

    folder = tmp_path_factory.mktemp("ontology_cases")
    for shipped in creative_py.case.ONTOLOGY_CASES.glob("*.pl"):  # the shipped cases too
        (folder / shipped.name).symlink_to(shipped)
    (folder / "regcase.pl").write_text("case(regcase).\n")
    monkeypatch.setattr(creative_py.case, "ONTOLOGY_CASES", folder)


def _folder(tmp_path, backend_line: str):
    folder = tmp_path / "regcase"
    folder.mkdir()
    (folder / "case.toml").write_text(MANIFEST.format(backend=backend_line))
    return folder


@dataclass(frozen=True)
class _FakeWorld:
    manifest: object
    catalogue: dict = field(default_factory=lambda: {"stick1": None})
    locations: tuple = (1,)
    variation: str = ""


def _fake_backend_module(calls: list) -> types.ModuleType:
    """A backend whose episodes observe one fact naming the backend and the scene."""
    module = types.ModuleType("creative_test_fake_backend")

    def load_world(manifest):
        calls.append(("load_world", manifest.id))
        return _FakeWorld(manifest)

    @contextmanager
    def open_episode(world, variant, location, tool, seed=0, gui=False, images_dir=None,
                     pose_target=None, *, robot=True, record=None):
        calls.append(("open_episode", variant, location, tool, robot))
        yield types.SimpleNamespace(
            observe=lambda cameras=True: Observation(
                facts=(("fake_scene", variant, location, tool),)))

    module.load_world = load_world
    module.open_episode = open_episode
    return module


@pytest.fixture
def fake(monkeypatch):
    """Register the fake backend as ``fake_test``; return the calls it receives."""
    calls: list = []
    monkeypatch.setitem(sys.modules, "creative_test_fake_backend", _fake_backend_module(calls))
    monkeypatch.setitem(BACKENDS, "fake_test", BackendEntry("creative_test_fake_backend"))
    return calls


def test_a_manifest_without_a_backend_runs_in_pybullet(tmp_path):
    import creative_py.backends.pybullet

    m = read_manifest(_folder(tmp_path, ""))
    assert m.backend == DEFAULT_BACKEND == "pybullet"
    assert backend_for(m) is creative_py.backends.pybullet
    assert backend() is creative_py.backends.pybullet
    # The pybullet package has every function of the protocol.
    members = {n for n in vars(Backend) if not n.startswith("_")}
    assert members == {"load_world", "open_episode", "tool_rests", "display_reachable",
                       "recorder"}
    assert all(callable(getattr(creative_py.backends.pybullet, n)) for n in members)


def test_the_manifest_s_backend_runs_the_learning_loop_s_episodes(tmp_path, fake):
    from creative_py.simulator.trial import task_facts

    m = read_manifest(_folder(tmp_path, 'backend = "fake_test"'))
    assert m.backend == "fake_test"
    world = backend_for(m).load_world(m)
    assert task_facts(world, "hard", 1) == [("fake_scene", "hard", 1, "stick1")]
    assert fake == [("load_world", "regcase"), ("open_episode", "hard", 1, "stick1", False)]


def test_an_unknown_backend_is_a_field_error_of_the_manifest(tmp_path):
    folder = _folder(tmp_path, f'backend = "{NOT_A_BACKEND}"')
    with pytest.raises(WorldFileError) as caught:
        read_manifest(folder)
    assert str(caught.value) == (f"{folder / 'case.toml'}: field 'backend': must be one of "
                                 f"{NAMES}, got '{NOT_A_BACKEND}'")
    with pytest.raises(UnknownBackend) as caught:
        backend(NOT_A_BACKEND, folder / "case.toml")
    assert str(caught.value) == (f"{folder / 'case.toml'}: field 'backend': unknown simulator "
                                 f"backend '{NOT_A_BACKEND}'; backends: {NAMES}")
    with pytest.raises(UnknownBackend, match=f"^unknown simulator backend '{NOT_A_BACKEND}'; "):
        backend(NOT_A_BACKEND)


def test_a_backend_that_is_not_installed_says_what_installs_it(tmp_path, monkeypatch):
    monkeypatch.syspath_prepend(str(tmp_path))
    (tmp_path / "creative_test_needs_lib.py").write_text("import creative_test_absent_lib\n")
    monkeypatch.setitem(BACKENDS, "needs_lib", BackendEntry("creative_test_needs_lib",
                                                           extra="needs_lib",
                                                           setup="make setup-needs-lib"))
    monkeypatch.setitem(BACKENDS, "core_gone", BackendEntry("creative_test_gone_backend"))
    with pytest.raises(BackendUnavailable) as caught:
        backend("needs_lib", "w/case.toml")
    assert str(caught.value) == (
        "w/case.toml: field 'backend': the simulator backend 'needs_lib' needs the module "
        "creative_test_absent_lib, which is not installed: make setup-needs-lib (the extra "
        "'.[needs_lib]')")
    with pytest.raises(BackendUnavailable) as caught:
        backend("core_gone")
    assert str(caught.value) == (
        "the simulator backend 'core_gone' needs the module creative_test_gone_backend, "
        "which is not installed: make setup")


def test_a_broken_import_inside_the_project_is_not_taken_for_a_missing_install(
        tmp_path, monkeypatch):
    monkeypatch.syspath_prepend(str(tmp_path))
    (tmp_path / "creative_test_buggy_backend.py").write_text(
        "import creative_py.no_such_module\n")
    monkeypatch.setitem(BACKENDS, "buggy", BackendEntry("creative_test_buggy_backend"))
    with pytest.raises(ModuleNotFoundError, match="creative_py.no_such_module"):
        backend("buggy")


def test_the_command_line_refuses_a_bad_backend_in_one_line(tmp_path, monkeypatch):
    runner = CliRunner()
    folder = _folder(tmp_path, f'backend = "{NOT_A_BACKEND}"')
    result = runner.invoke(app, ["trial", "regcase", "--world", str(folder), "--tool", "t"])
    assert result.exit_code == 2
    assert result.output.strip() == (f"error: {folder / 'case.toml'}: field 'backend': must "
                                     f"be one of {NAMES}, got '{NOT_A_BACKEND}'")
    monkeypatch.setitem(BACKENDS, "core_gone", BackendEntry("creative_test_gone_backend"))
    (folder / "case.toml").write_text(MANIFEST.format(backend='backend = "core_gone"'))
    result = runner.invoke(app, ["trial", "regcase", "--world", str(folder), "--tool", "t"])
    assert result.exit_code == 2
    assert result.output.strip() == (
        f"error: {folder / 'case.toml'}: field 'backend': the simulator backend 'core_gone' "
        "needs the module creative_test_gone_backend, which is not installed: make setup")


def test_the_backend_packages_are_the_registry_s():
    """One package per registry entry, named after the module the entry loads (the
    layer table has a row for each; a new backend adds its entry and its row)."""
    import creative_py.backends

    folder = Path(creative_py.backends.__file__).parent
    packages = {f"backends.{d.name}" for d in folder.iterdir() if (d / "__init__.py").is_file()}
    assert backend_packages() == packages       # every backend folder is registered
    assert {"backends.pybullet", "backends.maniskill", "backends.ros"} <= packages


@pytest.mark.parametrize("name", sorted(BACKENDS))
def test_every_registry_entry_names_a_backend_package_and_its_installer(name):
    entry = BACKENDS[name]
    assert name.isidentifier() and name == name.lower()
    assert entry.module.startswith(f"creative_py.backends.{name}")
    assert entry.setup.startswith("make setup")
    assert (entry.extra == "") == (entry.setup == "make setup")


def test_a_missing_maniskill_says_the_make_target_that_installs_it(monkeypatch):
    import builtins

    real = builtins.__import__

    def without_mani_skill(name, *args, **kwargs):
        if name.split(".")[0] == "mani_skill" or name == "creative_py.backends.maniskill":
            raise ModuleNotFoundError(f"No module named {name!r}", name="mani_skill")
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", without_mani_skill)
    monkeypatch.setattr("importlib.import_module",
                        lambda name: without_mani_skill(name))
    with pytest.raises(BackendUnavailable) as caught:
        backend("maniskill", "w/case.toml")
    assert str(caught.value) == (
        "w/case.toml: field 'backend': the simulator backend 'maniskill' needs the module "
        "mani_skill, which is not installed: make setup-maniskill (the extra "
        "'.[maniskill]')")


def _members(protocol) -> list[str]:
    return sorted(n for n in vars(protocol) if not n.startswith("_"))


def signature_mismatches(protocol, implementation) -> list[str]:
    """Return what ``implementation`` (a backend module, a class) lacks of ``protocol``'s
    methods: a missing method, or a parameter the protocol passes that it does not take
    the same way (by position or keyword, with a default where the protocol has one).
    Extra parameters with defaults are the implementation's own."""
    errors = []
    for name in _members(protocol):
        want = getattr(protocol, name)
        if isinstance(want, property):
            if not hasattr(implementation, name):
                errors.append(f"{name}: missing")
            continue
        have = getattr(implementation, name, None)
        if not callable(have):
            errors.append(f"{name}: missing")
            continue
        wanted = list(inspect.signature(want).parameters.values())[1:]  # self
        params = inspect.signature(have).parameters
        if inspect.isclass(implementation):
            params = dict(list(params.items())[1:])
        for p in wanted:
            got = params.get(p.name)
            if got is None or got.kind != p.kind:
                errors.append(f"{name}: parameter {p.name} ({p.kind.description}) missing")
            elif p.default is not p.empty and got.default is got.empty:
                errors.append(f"{name}: parameter {p.name} needs a default")
        extra = [q for q in params.values() if q.name not in {p.name for p in wanted}
                 and q.default is q.empty and q.kind not in (q.VAR_POSITIONAL, q.VAR_KEYWORD)]
        errors += [f"{name}: parameter {q.name} the protocol does not pass" for q in extra]
    return errors


def test_the_checker_finds_a_missing_method_and_a_mismatched_parameter():
    def module_of_protocol(name: str) -> types.ModuleType:
        module = types.ModuleType(name)
        for n in _members(Backend):
            setattr(module, n, getattr(Backend, n).__get__(module))  # the same signatures
        return module

    assert signature_mismatches(Backend, module_of_protocol("good_backend")) == []
    bad = module_of_protocol("bad_backend")
    del bad.recorder
    bad.tool_rests = lambda world, name: True
    bad.load_world = lambda manifest, strict: None
    assert signature_mismatches(Backend, bad) == [
        "load_world: parameter strict the protocol does not pass",
        "recorder: missing",
        "tool_rests: parameter tool (positional or keyword) missing",
        "tool_rests: parameter name the protocol does not pass"]


@pytest.mark.parametrize("name", sorted(BACKENDS))
def test_every_installed_backend_has_the_protocol_s_functions(name):
    try:
        module = backend(name)
    except BackendError as exc:
        pytest.skip(str(exc))
    assert signature_mismatches(Backend, module) == []


def test_the_pybullet_world_and_episode_have_the_protocol_s_members():
    from creative_py.case import get_case
    from creative_py.backends.pybullet import Episode as PybulletEpisode

    world = backend("pybullet").load_world(get_case("hook"))
    assert signature_mismatches(World, world) == []
    assert signature_mismatches(Episode, PybulletEpisode) == []


@pytest.mark.parametrize("name", sorted(BACKENDS))
def test_every_installed_backend_s_world_and_episode_have_the_protocol_s_members(name):
    from creative_py.case import load_cases

    try:
        module = backend(name)
    except BackendError as exc:
        pytest.skip(str(exc))
    from creative_py.backends import DEFAULT_BACKEND

    assert signature_mismatches(Episode, module.Episode) == []
    # A backend that ships no case of its own (one that drives an arm over a world
    # described by the default backend's files) is checked on a default backend's case.
    cases = sorted(load_cases().items())
    manifest = next((m for _, m in cases if m.backend == name),
                    next(m for _, m in cases if m.backend == DEFAULT_BACKEND))
    assert signature_mismatches(World, module.load_world(manifest)) == []


@pytest.mark.parametrize("name", sorted(BACKENDS))
def test_every_installed_backend_reads_objects_toml_with_the_one_reader(name, tmp_path):
    """A backend's world holds the shared CatalogueItem of ``read_catalogue``
    (simulator/catalogue.py), and a table it cannot hold is refused on the ``kind``
    field in the reader's one line."""
    import shutil

    from creative_py.case import load_cases
    from creative_py.simulator.catalogue import CatalogueItem

    try:
        module = backend(name)
    except BackendError as exc:
        pytest.skip(str(exc))
    cases = sorted(load_cases().items())
    manifest = next((m for _, m in cases if m.backend == name), None)
    if manifest is None:
        pytest.skip(f"no shipped case runs on {name}")
    world = module.load_world(manifest)
    assert world.items and all(type(i) is CatalogueItem for i in world.items.values())
    folder = tmp_path / "world"
    shutil.copytree(manifest.folder, folder)
    objects = folder / "objects.toml"
    objects.write_text(objects.read_text() + f'\n[[{manifest.tools_table}]]\nname = "x1"\n'
                       'kind = "not_a_kind"\nset = "s"\n')
    with pytest.raises(WorldFileError, match=r"objects\.toml.*'kind'"):
        module.load_world(manifest, folder)


def test_the_one_reader_names_the_field_a_backend_cannot_hold(tmp_path):
    from creative_py.simulator.catalogue import read_catalogue

    path = tmp_path / "objects.toml"
    path.write_text('[[tool]]\nname = "s1"\nkind = "stick"\nset = "a"\nhandle_length = 0.3\n'
                    'friction = 0.7\n')
    items = read_catalogue(path, "tool", lambda spec: None)
    assert (items["s1"].set, items["s1"].friction, items["s1"].outside_ranges) == (
        "a", 0.7, False)
    with pytest.raises(WorldFileError) as caught:
        read_catalogue(path, "tool", lambda spec: f"cannot hold a {spec.kind}")
    assert str(caught.value) == f"{path}: field 'tool[0].kind': cannot hold a stick"
    path.write_text('[[tool]]\nname = "s1"\nkind = "stick"\nset = "a"\nfriction = 11.0\n')
    with pytest.raises(WorldFileError, match=r"field 'tool\[0\]\.friction': must be <= 10"):
        read_catalogue(path, "tool", lambda spec: None)
