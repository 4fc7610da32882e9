"""Benchmark the manufacturing path per tool kind and record it in bench/results/mesh.json.

For the first catalogued tool of each class of each tool kind in the shipped worlds'
``objects.toml``: the time to build the manifold3d solid and its mass properties, to write
the URDF, SDF, OpenSCAD and STL files (no picture), to draw the picture, and to check the
files (OpenSCAD rendering included); medians over --repeats runs, milliseconds.

    .venv/bin/python bench/mesh_bench.py [--repeats 5] [--out bench/results/mesh.json]
"""

from __future__ import annotations

import argparse
import importlib.metadata
import json
import logging
import platform
import statistics
import tempfile
import time
from pathlib import Path

import trimesh
from recording import add_output_options, write_figures

from creative_py.case import read_manifest
from creative_py.kinds import kind_of
from creative_py.kinds.block import BlockSpec
from creative_py.mesh.check import check_tool_files
from creative_py.mesh.export import write_tool_files
from creative_py.mesh.printability import check_min_feature
from creative_py.mesh.solid import mass_properties, tool_mesh
from creative_py.simulator.catalogue import read_catalogue

ROOT = Path(__file__).resolve().parents[1]


CREATED = {"block/block/triangular_prism": BlockSpec("wedge_new", "triangular_prism", 0.15, 0.05,
                                                   0.03, tip_height=0.001, mass=None)}
"""A created tool of a class whose catalogued tools no printer takes: a wedge blunted as
the engine sizes one (its tip at least two nozzle widths high)."""


def catalogue_specs() -> tuple[dict[str, object], dict[str, str]]:
    """Return ``kind/class/name -> spec``, the first printable catalogued tool of each
    class (and block shape) of each tool kind in the shipped worlds' ``objects.toml``
    (the worlds in name order), so that every registered kind, a new one too, is
    measured as its worlds ship it; and ``kind/class -> why`` for a class none of whose
    catalogued tools a printer takes (the catalogue's wedges end in a sharp edge)."""
    out: dict[str, object] = {}
    refused: dict[str, str] = {}
    for folder in sorted(p.parent for p in ROOT.glob("worlds/*/case.toml")):
        table = read_manifest(folder).tools_table
        for item in read_catalogue(folder / "objects.toml", table, lambda spec: None).values():
            spec = item.spec
            key = "/".join(k for k in (kind_of(spec), spec.kind, getattr(spec, "shape", "")) if k)
            if any(label.startswith(key + " (") for label in out):
                continue
            try:
                check_min_feature(spec)
            except ValueError as exc:
                refused.setdefault(key, str(exc))
                continue
            refused.pop(key, None)
            out[f"{key} ({spec.name})"] = spec
    for key in refused:
        if key in CREATED:
            out[f"{key} ({CREATED[key].name}, created)"] = CREATED[key]
    return out, refused


def _ms(fn) -> tuple[float, object]:
    start = time.perf_counter()
    value = fn()
    return (time.perf_counter() - start) * 1000.0, value


def bench_kind(spec, repeats: int, root: Path) -> dict:
    """Return median timings (ms) and the check figures for one spec."""
    solid, files_ms, picture_ms, check_ms, scad_ms = [], [], [], [], []
    report = files = None
    for i in range(repeats):
        solid.append(_ms(lambda: mass_properties(spec, tool_mesh(spec)))[0])
        t, files = _ms(lambda: write_tool_files(spec, root / f"plain{i}", picture=False))
        files_ms.append(t)
        picture_ms.append(_ms(lambda: write_tool_files(spec, root / f"pic{i}"))[0] - t)
        t, report = _ms(lambda: check_tool_files(files))
        check_ms.append(t)
        scad_ms.append(report.scad_seconds * 1000.0)
    return {
        "solid_and_mass_ms": statistics.median(solid),
        "write_urdf_sdf_scad_stl_ms": statistics.median(files_ms),
        "picture_ms": statistics.median(picture_ms),
        "check_ms": statistics.median(check_ms),
        "openscad_render_ms": statistics.median(scad_ms),
        "stl_triangles": len(trimesh.load_mesh(files.stl).faces),
        "stl_volume_rel_err": report.stl_volume_rel_err,
        "scad_volume_rel_err": report.scad_volume_rel_err,
        "scad_mismatch_rel": report.scad_mismatch_rel,
        "fits_build_volume": report.fits_build_volume,
        "check_ok": report.ok,
    }


def main() -> None:
    """Run the benchmark and write the JSON results."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5,
                        help="runs of each step; the median counts (default 5)")
    add_output_options(parser, "mesh.json", "the median times of each step (JSON)")
    args = parser.parse_args()
    logging.basicConfig(level=logging.ERROR)
    with tempfile.TemporaryDirectory(prefix="mesh_bench_") as tmp:
        specs, refused = catalogue_specs()
        results = {label: bench_kind(spec, args.repeats, Path(tmp) / f"tool{i}")
                   for i, (label, spec) in enumerate(specs.items())}
    record = {
        "benchmark": "mesh: spec -> URDF, SDF, OpenSCAD, STL, PNG; check with OpenSCAD",
        "units": "milliseconds (medians); relative errors are fractions",
        "repeats": args.repeats,
        "machine": {"python": platform.python_version(), "processor": platform.machine(),
                    **{p: importlib.metadata.version(p)
                       for p in ("manifold3d", "trimesh", "matplotlib")}},
        "date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "kinds": results,
        "not_printable": refused,
    }
    width = max(map(len, results))
    print(f"median milliseconds of each step, {args.repeats} runs:")
    print(f"{'kind':{width}}  solid  files  picture  check  openscad  files check out")
    for kind, r in results.items():
        print(f"{kind:{width}}  {r['solid_and_mass_ms']:5.1f}  {r['write_urdf_sdf_scad_stl_ms']:5.1f}"
              f"  {r['picture_ms']:7.1f}  {r['check_ms']:5.1f}  {r['openscad_render_ms']:8.1f}"
              f"  {r['check_ok']}")
    for key, why in refused.items():
        print(f"{key}: no catalogued tool is printable ({why})")
    write_figures(args, "mesh.json", record, indent=2)


if __name__ == "__main__":
    main()
