"""``creative make-tool``: a tool sized from a qualitative spec and written (URDF, SDF,
SCAD, STL, the printed pieces and their G-code), summarised in a few lines."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

from creative_py.cli.errors import fail, one_line_errors, stdout_to_stderr
from creative_py.cli.options import name_option, path_option, text_option

TOOL_NAME_MAX = 200
"""The longest ``make-tool --name``: its files' names add to it (``<name>_description``,
the writer's temporary ``.<name>.<random>.tmp``) and must stay within NAME_MAX."""

BUILD_VOLUME_MAX_MM = 10000.0
"""The largest side of ``--build-volume``, millimetres."""


def _print_settings(text: str):
    """Return the print settings of a ``--build-volume X,Y,Z`` (mm), or fail in one line."""
    from creative_py.mesh.printability import PrintSettings
    from creative_py.mesh.tolerances import MM_PER_M

    try:
        values = [float(v) for v in text.split(",")]
    except ValueError:
        values = []
    if len(values) != 3 or not all(0 < v <= BUILD_VOLUME_MAX_MM for v in values):
        fail(f"--build-volume {text!r}: expected three positive numbers of millimetres "
             f"X,Y,Z, each at most {BUILD_VOLUME_MAX_MM:g}, e.g. 250,210,210")
    return PrintSettings(build_volume=tuple(v / MM_PER_M for v in values))


def make_tool_cmd(
    case: str = typer.Argument(..., help="A case id (creative cases lists them)."),
    spec: str = typer.Argument(..., help="Qualitative spec in the case's vocabulary, e.g. "
                               "handle_length=long,hook_side=left (hook) or "
                               "shape=triangular_prism,block_length=long (wedge); a wrong "
                               "property lists the allowed ones."),
    name: str = typer.Option("new_tool", "--name", help="Tool name (a Prolog atom)."),
    out: str = typer.Option("tools", "--out", help="Folder for the tool's files."),
    variant: Optional[str] = typer.Option(None, "--variant", help="Task variant whose "
                                          "perceived geometry bounds the sizes (default: "
                                          "the demonstration's)."),
    context: Optional[str] = typer.Option(None, "--context", help="Extra task facts, e.g. "
                                          "'max_tool_length(0.5)'."),
    overwrite: bool = typer.Option(False, "--overwrite", help="Replace the tool's folder "
                                   "if it exists."),
    build_volume: Optional[str] = typer.Option(None, "--build-volume", help="The printer's "
                                               "build volume X,Y,Z in mm (default "
                                               "250,210,210); a larger tool is split into "
                                               "pieces that fit."),
    no_slice: bool = typer.Option(False, "--no-slice", help="Write the printed pieces' "
                                  "STL but do not slice them to G-code."),
) -> None:
    """Size a tool from a qualitative spec with CLP(R) and write URDF, SDF, SCAD, STL,
    the printed pieces (split to fit the build volume) and their G-code (PrusaSlicer)."""
    from creative_py.mesh.printability import PrintSettings

    variant, name = name_option("--variant", variant), name_option("--name", name)
    case, spec = text_option("CASE", case), text_option("SPEC", spec)
    context = text_option("--context", context)
    if len(name) > TOOL_NAME_MAX:
        fail(f"--name: at most {TOOL_NAME_MAX} characters (the tool's file names add to "
             f"it), got {len(name)}")
    # deepest: <out>/<name>/ros/<name>_description/meshes/<name>...
    out = path_option("--out", out, 3 * len(name.encode("utf-8", "surrogateescape")) + 64)
    if out.exists() and not out.is_dir():
        fail(f"--out {out}: not a folder")
    settings = PrintSettings() if build_volume is None else _print_settings(build_volume)
    files = _write_tool(case, spec, name, out, variant, context, overwrite, settings,
                        slice_=not no_slice)
    typer.echo(tool_summary(files.manifest))
    for p in files.paths():
        typer.echo(str(p))
    if no_slice:
        typer.echo(unsliced_warning(files.manifest), err=True)


def _write_tool(case: str, spec: str, name: str, out: Path, variant: Optional[str],
                context: Optional[str], overwrite: bool, settings, slice_: bool):
    """Size the tool ``spec`` describes in the engine and write its files under ``out``
    (G-code too if ``slice_``); return them, or fail in one line naming the cause."""
    from creative_py.bridge import Engine, PrologError
    from creative_py.fabrication.manufacture import (
        InfeasibleSpec, default_context, make_tool, parse_context, parse_spec, with_context,
    )
    from creative_py.mesh.slicer import require_slicer
    from creative_py.world_files import WorldFileError

    with one_line_errors():  # what the specific messages below do not cover
        if slice_:
            require_slicer()
        try:
            with stdout_to_stderr():
                engine = Engine.instance()
                lits = parse_spec(case, spec)
                extra = parse_context(engine, context) if context else []  # no scene yet
                ctx = with_context(default_context(case, variant), extra)
                return make_tool(engine, case, lits, ctx, name, out, picture=True,
                                 overwrite=overwrite, settings=settings, gcode=slice_)
        except FileExistsError as exc:
            fail(f"{exc.filename or out}: the tool's folder exists (--overwrite replaces it)")
        except (InfeasibleSpec, ValueError, WorldFileError) as exc:
            fail(str(exc))
        except PrologError as exc:
            if not context:
                raise
            shown = context if len(context) <= 80 else f"{context[:60]}...{context[-12:]}"
            fail(f"--context {shown!r}: the size model cannot use it: {exc.formal}")


def unsliced_warning(manifest: Path) -> str:
    """Return the one-line warning of a tool written with ``--no-slice``: that it cannot
    be printed (its print entry says why), or that no slicer has checked its pieces."""
    data = json.loads(Path(manifest).read_text())
    name, printed = data.get("name", "?"), data.get("print") or {}
    if not printed.get("printable", False):
        why = " ".join(str(printed.get("reason") or "no printable pieces").split())
        return f"warning: {name}: cannot be printed: {why}"
    pieces = len(printed.get("pieces") or [])
    return (f"warning: {name}: {pieces} printed piece(s) written but not sliced "
            f"(--no-slice): no slicer has checked them")


def tool_summary(manifest: Path) -> str:
    """Return a written tool in a few lines: its size, mass, printed pieces, print time
    and filament (from its JSON)."""
    from creative_py.report.table import print_text

    data = json.loads(Path(manifest).read_text())
    extent = (data.get("printability") or {}).get("extent")
    size = (" x ".join(f"{v * 1000:.1f}" for v in extent) + " mm"
            if isinstance(extent, list) else "?")
    mass = data.get("mass_kg")
    lines = [f"tool {data.get('name', '?')}: {size}, "
             f"{f'{mass * 1000:.1f} g' if isinstance(mass, (int, float)) else 'mass ?'}"]
    printed = data.get("print")
    if isinstance(printed, dict):
        lines.append(f"print: {print_text(printed)}")
    return "\n".join(lines)
