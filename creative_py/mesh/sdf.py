"""SDF text for a tool: one model with one link in the spec's tool frame (metres, kg)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from xml.sax.saxutils import escape, quoteattr

from creative_py.mesh.link import Shape, ToolLink, format_number, format_vector, inertia_entries

SDF_VERSION = "1.6"


def _geometry(shape: Shape, mesh_uri: Callable[[str], str] = str) -> str:
    if shape.kind == "box":
        return f"<box><size>{format_vector(shape.size)}</size></box>"
    if shape.kind == "cylinder":
        return (f"<cylinder><radius>{format_number(shape.radius)}</radius>"
                f"<length>{format_number(shape.length)}</length></cylinder>")
    return f"<mesh><uri>{escape(mesh_uri(shape.mesh_file))}</uri><scale>1 1 1</scale></mesh>"


def sdf_text(link: ToolLink, *, mesh_uri: Callable[[str], str] = str,
             visuals: Sequence[Shape] | None = None) -> str:
    """Return the SDF document of a tool link.

    The model and link poses are the identity (the tool frame); the inertial pose is the
    centre of mass, with the full inertia tensor about it. Mesh URIs are file names
    relative to the SDF file, or ``mesh_uri(file name)`` (e.g. a ``model://`` URI).
    ``visuals`` replaces the link's shapes as visual geometry (default: the collision
    shapes).
    """
    m = link.mass
    colour = format_vector(link.rgba)
    lines = [
        '<?xml version="1.0"?>',
        f"<!-- CREATIVE-py tool {link.name}, written by creative_py.mesh: lengths in metres,",
        "     mass in kg, inertia in kg m^2 about the centre of mass. -->",
        f'<sdf version="{SDF_VERSION}">',
        f"  <model name={quoteattr(link.name)}>",
        "    <static>false</static>",
        "    <pose>0 0 0 0 0 0</pose>",
        f"    <link name={quoteattr(link.name)}>",
        "      <pose>0 0 0 0 0 0</pose>",
        "      <inertial>",
        f"        <pose>{format_vector(m.center_of_mass)} 0 0 0</pose>",
        f"        <mass>{format_number(m.mass)}</mass>",
        "        <inertia>" + "".join(f"<{k}>{v}</{k}>" for k, v in inertia_entries(m).items())
        + "</inertia>",
        "      </inertial>",
    ]
    shapes = {"collision": link.shapes,
              "visual": link.shapes if visuals is None else tuple(visuals)}
    for element in ("collision", "visual"):
        for i, shape in enumerate(shapes[element]):
            lines += [
                f'      <{element} name="{element}{i}">',
                f"        <pose>{format_vector(shape.xyz)} {format_vector(shape.rpy)}</pose>",
                f"        <geometry>{_geometry(shape, mesh_uri)}</geometry>",
            ]
            if element == "visual":
                lines.append(f"        <material><ambient>{colour}</ambient>"
                             f"<diffuse>{colour}</diffuse></material>")
            lines.append(f"      </{element}>")
    lines += ["    </link>", "  </model>", "</sdf>", ""]
    return "\n".join(lines)
