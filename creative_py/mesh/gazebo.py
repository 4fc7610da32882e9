"""A tool as a Gazebo model folder and as a ROS description package.

:func:`write_sim_models` writes, inside a tool's folder (``tools/<name>/``):

=========================================  ==============================================
``gazebo/<name>/model.config``             Gazebo's model metadata: name, version, the SDF
``gazebo/<name>/model.sdf``                the tool's link (SDF 1.6); mesh URIs
                                           ``model://<name>/meshes/<file>``
``gazebo/<name>/meshes/``                  the meshes the SDF uses (metres)
``ros/<name>_description/package.xml``     a ROS 2 package (format 3, ament_cmake)
``ros/<name>_description/CMakeLists.txt``  installs ``urdf/`` and ``meshes/`` to
                                           ``share/<name>_description``
``ros/<name>_description/urdf/<name>.urdf``  the URDF, mesh file names
                                           ``package://<name>_description/meshes/<file>``
``ros/<name>_description/meshes/``         the meshes the URDF uses (metres)
=========================================  ==============================================

The link is the one of ``<name>.urdf`` and ``<name>.sdf`` (:func:`creative_py.mesh.link.tool_link`):
the same mass, inertia and collision shapes (primitives, and the convex hulls of a
wedge as OBJ files), so a tool behaves in Gazebo as in pybullet. The visual geometry
is the printable solid itself, ``meshes/<name>.stl`` in metres (the union of the parts
that ``<name>.stl`` holds in millimetres), so every model has a mesh to show.

Use: ``GZ_SIM_RESOURCE_PATH=tools/<name>/gazebo`` (``GAZEBO_MODEL_PATH`` for Gazebo
classic), then ``<include><uri>model://<name></uri></include>`` in a world; copy
``ros/<name>_description`` into a colcon workspace's ``src/``, build, and
``$(find-pkg-share <name>_description)/urdf/<name>.urdf`` resolves its meshes.
"""

from __future__ import annotations

from pathlib import Path
from xml.sax.saxutils import escape

import trimesh

from creative_py.mesh.link import Shape, hull_meshes, tool_link
from creative_py.mesh.sdf import SDF_VERSION, sdf_text
from creative_py.mesh.solid import MassProperties
from creative_py.mesh.spec import KindSpec
from creative_py.mesh.urdf import urdf_text

GAZEBO_DIR = "gazebo"
"""Folder of the tool's Gazebo model (a resource path entry: it holds ``<name>/``)."""

ROS_DIR = "ros"
"""Folder of the tool's ROS package."""

MESH_DIR = "meshes"

MODEL_VERSION = "1.0"


def gazebo_model_dir(tool_dir: Path | str, name: str) -> Path:
    """Return the Gazebo model folder of the tool ``name`` in its tool folder."""
    return Path(tool_dir) / GAZEBO_DIR / name


def ros_package_name(name: str) -> str:
    """Return the ROS package name of a tool (``<name>_description``).

    A tool's name is a Prolog atom of lower-case letters, digits and underscores that
    starts with a letter, which is also a valid ROS package name.
    """
    return f"{name}_description"


def ros_package_dir(tool_dir: Path | str, name: str) -> Path:
    """Return the ROS package folder of the tool ``name`` in its tool folder."""
    return Path(tool_dir) / ROS_DIR / ros_package_name(name)


def sim_model_paths(tool_dir: Path | str, spec: KindSpec) -> tuple[Path, ...]:
    """Return every file :func:`write_sim_models` writes for ``spec`` in ``tool_dir``."""
    name = spec.name
    meshes = [f"{name}.stl", *sorted(hull_meshes(spec))]
    model = gazebo_model_dir(tool_dir, name)
    pkg = ros_package_dir(tool_dir, name)
    return (model / "model.config", model / "model.sdf",
            *(model / MESH_DIR / m for m in meshes),
            pkg / "package.xml", pkg / "CMakeLists.txt", pkg / "urdf" / f"{name}.urdf",
            *(pkg / MESH_DIR / m for m in meshes))


def _model_config(name: str) -> str:
    return "\n".join([
        '<?xml version="1.0"?>',
        "<model>",
        f"  <name>{escape(name)}</name>",
        f"  <version>{MODEL_VERSION}</version>",
        f'  <sdf version="{SDF_VERSION}">model.sdf</sdf>',
        "  <author><name>CREATIVE-py</name></author>",
        f"  <description>Tool {escape(name)} designed and sized by CREATIVE-py: one rigid "
        "link, metres and kilograms; visual: the printable solid, collision: the "
        "link's primitives and convex hulls.</description>",
        "</model>",
        "",
    ])


def _package_xml(package: str, name: str) -> str:
    return "\n".join([
        '<?xml version="1.0"?>',
        '<package format="3">',
        f"  <name>{package}</name>",
        "  <version>1.0.0</version>",
        f"  <description>URDF and meshes of the tool {escape(name)}, designed and sized "
        "by CREATIVE-py.</description>",
        '  <maintainer email="creative-py@example.org">CREATIVE-py contributors</maintainer>',
        "  <license>MIT</license>",
        "  <buildtool_depend>ament_cmake</buildtool_depend>",
        "  <export>",
        "    <build_type>ament_cmake</build_type>",
        "  </export>",
        "</package>",
        "",
    ])


def _cmakelists(package: str) -> str:
    return "\n".join([
        "cmake_minimum_required(VERSION 3.8)",
        f"project({package} NONE)",
        "find_package(ament_cmake REQUIRED)",
        "install(DIRECTORY urdf meshes DESTINATION share/${PROJECT_NAME})",
        "ament_package()",
        "",
    ])


def _write_meshes(folder: Path, visual_name: str, visual: trimesh.Trimesh,
                  hulls: dict[str, trimesh.Trimesh]) -> None:
    folder.mkdir(parents=True)
    (folder / visual_name).write_bytes(visual.export(file_type="stl"))
    for file_name, hull in hulls.items():
        (folder / file_name).write_text(hull.export(file_type="obj", include_normals=False),
                                        encoding="utf-8")


def write_sim_models(spec: KindSpec, mass: MassProperties, mesh: trimesh.Trimesh,
                     tool_dir: Path) -> dict[str, str]:
    """Write the tool's Gazebo model folder and ROS package inside ``tool_dir``.

    Parameters
    ----------
    spec : KindSpec
        The tool.
    mass : MassProperties
        Its mass properties (those of its URDF and SDF).
    mesh : trimesh.Trimesh
        The printable solid in metres, tool frame (the visual geometry).
    tool_dir : Path
        The tool's folder (during :func:`creative_py.mesh.export.write_tool_files`, the
        temporary folder that becomes it, so the whole folder stays atomic).

    Returns
    -------
    dict
        ``{"gazebo_model": "gazebo/<name>", "ros_package": "ros/<name>_description"}``,
        relative to ``tool_dir``.
    """
    name = spec.name
    link = tool_link(spec, mass)
    hulls = hull_meshes(spec)
    visual_name = f"{name}.stl"
    visuals = (Shape("mesh", (0.0, 0.0, 0.0), mesh_file=visual_name),)

    model = gazebo_model_dir(tool_dir, name)
    _write_meshes(model / MESH_DIR, visual_name, mesh, hulls)
    (model / "model.config").write_text(_model_config(name), encoding="utf-8")
    (model / "model.sdf").write_text(
        sdf_text(link, mesh_uri=lambda f: f"model://{name}/{MESH_DIR}/{f}", visuals=visuals),
        encoding="utf-8")

    package = ros_package_name(name)
    pkg = ros_package_dir(tool_dir, name)
    _write_meshes(pkg / MESH_DIR, visual_name, mesh, hulls)
    (pkg / "urdf").mkdir()
    (pkg / "urdf" / f"{name}.urdf").write_text(
        urdf_text(link, mesh_uri=lambda f: f"package://{package}/{MESH_DIR}/{f}",
                  visuals=visuals),
        encoding="utf-8")
    (pkg / "package.xml").write_text(_package_xml(package, name), encoding="utf-8")
    (pkg / "CMakeLists.txt").write_text(_cmakelists(package), encoding="utf-8")
    return {"gazebo_model": f"{GAZEBO_DIR}/{name}", "ros_package": f"{ROS_DIR}/{package}"}
