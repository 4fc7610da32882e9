"""URDF text for a tool: one link in the spec's tool frame (metres, kilograms)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from xml.sax.saxutils import quoteattr

from creative_py.mesh.link import Shape, ToolLink, format_number, format_vector, inertia_entries


def _geometry(shape: Shape, mesh_uri: Callable[[str], str] = str) -> str:
    if shape.kind == "box":
        return f'<box size="{format_vector(shape.size)}"/>'
    if shape.kind == "cylinder":
        return (f'<cylinder radius="{format_number(shape.radius)}" '
                f'length="{format_number(shape.length)}"/>')
    return f'<mesh filename={quoteattr(mesh_uri(shape.mesh_file))} scale="1 1 1"/>'


def urdf_text(link: ToolLink, *, mesh_uri: Callable[[str], str] = str,
              visuals: Sequence[Shape] | None = None) -> str:
    """Return the URDF document of a tool link.

    Mesh file names are relative to the URDF file, or ``mesh_uri(file name)`` (e.g. a
    ``package://`` URI); ``visuals`` replaces the link's shapes as visual geometry
    (default: the collision shapes).

    The link origin is the tool frame; the inertial origin is the centre of mass with
    the full inertia tensor about it (axes of the tool frame). pybullet reads the tensor
    only with ``flags=URDF_USE_INERTIA_FROM_FILE``; without it pybullet recomputes the
    inertia from the collision shapes.
    """
    m = link.mass
    inertia = " ".join(f'{k}="{v}"' for k, v in inertia_entries(m).items())
    colour = format_vector(link.rgba)
    lines = [
        '<?xml version="1.0"?>',
        f"<!-- CREATIVE-py tool {link.name}, written by creative_py.mesh: lengths in metres,",
        "     mass in kg, inertia in kg m^2 about the centre of mass. -->",
        f"<robot name={quoteattr(link.name)}>",
        f'  <material name="{link.name}_colour"><color rgba="{colour}"/></material>',
        f"  <link name={quoteattr(link.name)}>",
        "    <inertial>",
        f'      <origin xyz="{format_vector(m.center_of_mass)}" rpy="0 0 0"/>',
        f'      <mass value="{format_number(m.mass)}"/>',
        f"      <inertia {inertia}/>",
        "    </inertial>",
    ]
    shapes = {"collision": link.shapes,
              "visual": link.shapes if visuals is None else tuple(visuals)}
    for element in ("visual", "collision"):
        for i, shape in enumerate(shapes[element]):
            lines += [
                f'    <{element} name="{element}{i}">',
                f'      <origin xyz="{format_vector(shape.xyz)}" rpy="{format_vector(shape.rpy)}"/>',
                f"      <geometry>{_geometry(shape, mesh_uri)}</geometry>",
            ]
            if element == "visual":
                lines.append(f'      <material name="{link.name}_colour"/>')
            lines.append(f"    </{element}>")
    lines += ["  </link>", "</robot>", ""]
    return "\n".join(lines)
