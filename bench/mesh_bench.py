"""Benchmark the manufacturing path per tool kind and record it in bench/results/mesh.json.

For each kind: the time to build the manifold3d solid and its mass properties, to write
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

from creative_py.mesh.check import check_tool_files
from creative_py.mesh.export import write_tool_files
from creative_py.mesh.solid import mass_properties, tool_mesh
from creative_py.kinds.block import BlockSpec
from creative_py.kinds.hook_like import HookSpec

KINDS = {
    "hook_right": HookSpec("hook_right", 0.3, hook_side="right"),
    "hook_left": HookSpec("hook_left", 0.3, hook_side="left"),
    "hook_angled": HookSpec("hook_angled", 0.3, hook_side="right", hook_angle_deg=60.0),
    "hook_long_oversize": HookSpec("hook_long_oversize", 0.55),
    "stick": HookSpec("stick", 0.3, hook_side="none", hook_length=0.0),
    "prism": BlockSpec("prism", "triangular_prism", 0.15, 0.05, 0.03),
    "box": BlockSpec("box", "box", 0.04, 0.05, 0.03),
    "cylinder": BlockSpec("cylinder", "cylinder", 0.04, 0.04, 0.05),
}


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
        results = {kind: bench_kind(spec, args.repeats, Path(tmp) / kind)
                   for kind, spec in KINDS.items()}
    record = {
        "benchmark": "mesh: spec -> URDF, SDF, OpenSCAD, STL, PNG; check with OpenSCAD",
        "units": "milliseconds (medians); relative errors are fractions",
        "repeats": args.repeats,
        "machine": {"python": platform.python_version(), "processor": platform.machine(),
                    **{p: importlib.metadata.version(p)
                       for p in ("manifold3d", "trimesh", "matplotlib")}},
        "date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
        "kinds": results,
    }
    width = max(map(len, results))
    print(f"median milliseconds of each step, {args.repeats} runs:")
    print(f"{'kind':{width}}  solid  files  picture  check  openscad  files check out")
    for kind, r in results.items():
        print(f"{kind:{width}}  {r['solid_and_mass_ms']:5.1f}  {r['write_urdf_sdf_scad_stl_ms']:5.1f}"
              f"  {r['picture_ms']:7.1f}  {r['check_ms']:5.1f}  {r['openscad_render_ms']:8.1f}"
              f"  {r['check_ok']}")
    write_figures(args, "mesh.json", record, indent=2)


if __name__ == "__main__":
    main()
