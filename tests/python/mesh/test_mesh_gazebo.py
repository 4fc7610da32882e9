"""The Gazebo model folder and the ROS package of a tool, read by Gazebo's own parser.

The parser is libsdformat, from the system packages (Debian's ``libsdformat-dev``,
sdformat 12, which ``make setup`` installs): the PyPI wheel ``sdformat14-py-bindings``
installs but does not import on Debian 12, whose packages lack the
``libsdformat14.so.14`` and ``libgz-math7.so.7`` it links to. ``sdf_check.cpp`` (beside
this file) is compiled once against it; it loads a file as Gazebo does and prints the
errors, the models, the links and every mesh URI with the file it resolves to.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import trimesh

from creative_py.mesh.gazebo import gazebo_model_dir, ros_package_dir, ros_package_name

SOURCE = Path(__file__).with_name("sdf_check.cpp")
PKG = "sdformat12"


@pytest.fixture(scope="session")
def sdf_check() -> Path:
    """Return the checker's executable, compiled once per source into the venv."""
    digest = hashlib.sha256(SOURCE.read_bytes()).hexdigest()[:12]
    exe = Path(sys.prefix) / "var" / f"sdf_check-{digest}"
    if exe.is_file():
        return exe
    if shutil.which("g++") is None or shutil.which("pkg-config") is None:
        pytest.fail("the libsdformat check needs g++ and pkg-config (make setup installs them)")
    flags = subprocess.run(["pkg-config", "--cflags", "--libs", PKG], capture_output=True,
                           text=True)
    if flags.returncode != 0:
        pytest.fail(f"libsdformat is missing ({flags.stderr.strip()}): "
                    "apt-get install libsdformat-dev (make setup does)")
    exe.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=exe.parent, prefix=".sdf_check.")
    os.close(fd)
    subprocess.run(["g++", "-O1", "-o", tmp, str(SOURCE), *flags.stdout.split()],
                   check=True, timeout=600)
    os.replace(tmp, exe)       # atomic: parallel workers may compile it at once
    return exe


def load(checker: Path, path: Path, **uri_paths: Path) -> dict:
    """Load ``path`` with libsdformat; return its errors, models, links and meshes.

    ``uri_paths`` maps a URI scheme's name (``model``) to the folder searched for it.
    """
    args = [str(checker), str(path)] + [f"{k}://={v}" for k, v in uri_paths.items()]
    out = subprocess.run(args, check=True, capture_output=True, text=True, timeout=60)
    got: dict = {"error": [], "model": [], "link": [], "mesh": [], "world": []}
    for line in out.stdout.splitlines():
        kind, *fields = line.split("\t")
        if kind == "errors":
            got["count"] = int(fields[0])
        else:
            got[kind].append(fields)
    return got


def test_the_gazebo_model_loads_without_errors_and_its_meshes_resolve(
        written, kind, sdf_check):
    files = written[kind]
    name = files.spec.name
    model = gazebo_model_dir(files.directory, name)

    got = load(sdf_check, model / "model.sdf", model=model.parent)

    assert got["count"] == 0 and got["error"] == []
    assert got["model"] == [[name]]
    ((link, mass),) = got["link"]
    assert link == name and float(mass) == pytest.approx(files.mass.mass, rel=1e-6)
    visuals = [m for m in got["mesh"] if m[0] == "visual"]
    assert [uri for _, uri, _ in visuals] == [f"model://{name}/meshes/{name}.stl"]
    for _, uri, resolved in got["mesh"]:
        assert uri.startswith(f"model://{name}/meshes/")
        assert Path(resolved) == model / "meshes" / uri.rsplit("/", 1)[1]
        assert Path(resolved).is_file()
    collisions = [uri.rsplit("/", 1)[1] for e, uri, _ in got["mesh"] if e == "collision"]
    assert collisions == [p.name for p in files.meshes]      # the wedge's hulls


def test_a_world_includes_the_model_by_its_uri(written, sdf_check, tmp_path):
    """Gazebo finds the model as a resource path entry: model.config names model.sdf."""
    for kind in ("hook_right", "prism"):
        files = written[kind]
        name = files.spec.name
        world = tmp_path / f"{kind}.world"
        world.write_text(f'<?xml version="1.0"?><sdf version="1.6"><world name="w">'
                         f"<include><uri>model://{name}</uri></include></world></sdf>")

        got = load(sdf_check, world, model=gazebo_model_dir(files.directory, name).parent)

        assert got["count"] == 0 and got["world"] == [["w"]] and got["model"] == [[name]]
        config = ET.parse(gazebo_model_dir(files.directory, name) / "model.config").getroot()
        assert config.findtext("name") == name
        assert config.find("sdf").text == "model.sdf"


def test_the_ros_package_s_urdf_loads_and_names_its_meshes_by_package(
        written, kind, sdf_check):
    files = written[kind]
    name = files.spec.name
    package = ros_package_dir(files.directory, name)
    urdf = package / "urdf" / f"{name}.urdf"
    filenames = [m.get("filename") for m in ET.parse(urdf).getroot().iter("mesh")]
    assert filenames and all(f.startswith(f"package://{ros_package_name(name)}/meshes/")
                             for f in filenames)

    # libsdformat converts the URDF and reads package:// as model:// (as Gazebo does).
    got = load(sdf_check, urdf, model=package.parent)

    assert got["count"] == 0 and got["model"] == [[name]]
    assert float(got["link"][0][1]) == pytest.approx(files.mass.mass, rel=1e-6)
    assert got["mesh"] and all(Path(resolved).is_file() and package in Path(resolved).parents
                               for _, _, resolved in got["mesh"])
    manifest = ET.parse(package / "package.xml").getroot()
    assert manifest.get("format") == "3" and manifest.findtext("name") == package.name
    assert "install(DIRECTORY urdf meshes" in (package / "CMakeLists.txt").read_text()


def test_the_visual_mesh_is_the_printable_solid_in_metres(written, kind):
    files = written[kind]
    name = files.spec.name
    stl_mm = trimesh.load_mesh(files.stl)
    for folder in (gazebo_model_dir(files.directory, name), ros_package_dir(files.directory, name)):
        visual = trimesh.load_mesh(folder / "meshes" / f"{name}.stl")
        np.testing.assert_allclose(visual.bounds * 1000, stl_mm.bounds, atol=1e-6)
        assert visual.volume == pytest.approx(files.mass.volume, rel=1e-6)
