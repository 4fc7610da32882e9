"""Measure perception error and render time; record them in bench/results/perception.json.

Scenes: the hook world's table, riser, tube (top wall without a visual) and 3 cm cube at
each of its four predefined locations, seen by the world's ``[[camera]]``; and wedges,
a box and a cylinder at several placements on a floor seen by a downward and a side
camera. Each placement is estimated without noise and with the world's
``[perception]`` depth noise over several seeds. Ground truth comes from pybullet and is
used only here, to measure the error.

The scenes are built from ``worlds/hook_tube/scene.toml`` and ``tasks.toml`` (standard
tube, the four ``[[location]]`` tables) with the simulator's own body
builders (:mod:`creative_py.sim.bodies`); ``worlds/wedge_door/scene.toml`` supplies the
wedge cameras when it exists, otherwise a downward camera 1.6 m above the floor and a
side camera 0.5 m up are used.

    .venv/bin/python bench/perception_error.py [--seeds 5] [--out bench/results/perception.json]
"""

from __future__ import annotations

import argparse
import json
import logging
import math
import platform
import statistics
import time
import tomllib
from pathlib import Path

import numpy as np
import pybullet as pb

from creative_py.mesh.spec import BlockSpec, Box
from creative_py.perception import NoiseModel, estimate_objects
from creative_py.sim.bodies import Surface, frame_pose, set_frame_pose, spawn_parts, spawn_spec, yaw_of
from creative_py.sim.camera import CameraSpec, cameras_from_tables, capture
from creative_py.sim.core import Sim
from creative_py.world import PhysicsSettings

ROOT = Path(__file__).resolve().parents[1]
log = logging.getLogger("bench.perception")

CUBE = BlockSpec("cube1", "box", 0.03, 0.03, 0.03, mass=0.05)
WEDGE_OBJECTS = [
    BlockSpec("wedge_a1", "triangular_prism", 0.15, 0.05, 0.03),
    BlockSpec("wedge_a2", "triangular_prism", 0.10, 0.05, 0.03),
    BlockSpec("wedge_a3", "triangular_prism", 0.06, 0.05, 0.03),
    BlockSpec("wedge_b1", "triangular_prism", 0.04, 0.06, 0.03),
    BlockSpec("box_a1", "box", 0.08, 0.05, 0.03),
    BlockSpec("cylinder_b1", "cylinder", 0.06, 0.06, 0.04),
]
SYMMETRY_PERIOD = {"none": 2 * math.pi, "pi": math.pi, "half_pi": math.pi / 2, "round": None}


def angle_diff(a: float, b: float, period: float) -> float:
    """Return a - b wrapped into (-period/2, period/2], radians."""
    return (a - b + period / 2) % period - period / 2


def truth_of(sim: Sim, body: int, spec: BlockSpec) -> tuple[float, float, float, float]:
    """Return the true box centre (x, y, z) and heading of an upright block, world frame."""
    (x, y, z), quat = frame_pose(sim, body)
    return x, y, z + spec.height / 2, yaw_of(quat)


def errors(est, truth, spec: BlockSpec) -> dict:
    """Return the position (mm), height (mm), heading (deg) and size (mm) errors."""
    x, y, z, yaw = truth
    period = SYMMETRY_PERIOD[est.symmetry]
    size = (spec.length, spec.width, spec.height)
    return {
        "xy_mm": 1000 * math.hypot(est.x - x, est.y - y),
        "z_mm": 1000 * (est.z - z),
        "yaw_deg": None if period is None else abs(math.degrees(angle_diff(est.yaw, yaw, period))),
        "size_mm": [1000 * (a - b) for a, b in zip(est.size, size)],
        "symmetry": est.symmetry,
        "n_points": est.n_points,
        "cameras": list(est.cameras),
    }


def summarise(rows: list[dict]) -> dict:
    """Return mean and worst of each error over ``rows``."""
    xy = [r["xy_mm"] for r in rows]
    z = [abs(r["z_mm"]) for r in rows]
    yaw = [r["yaw_deg"] for r in rows if r["yaw_deg"] is not None]
    size = [abs(v) for r in rows for v in r["size_mm"]]
    return {"n": len(rows),
            "xy_mm_mean": statistics.fmean(xy), "xy_mm_worst": max(xy),
            "z_mm_mean": statistics.fmean(z), "z_mm_worst": max(z),
            "yaw_deg_mean": statistics.fmean(yaw) if yaw else None,
            "yaw_deg_worst": max(yaw) if yaw else None,
            "size_mm_mean": statistics.fmean(size), "size_mm_worst": max(size)}


def hook_scene(sim: Sim, scene: dict, length: float) -> tuple[int, float]:
    """Build table, riser and a tube ``length`` m long; return (tube body, tube floor z)."""
    t, r, tube = scene["table"], scene["riser"], scene["tube"]
    grey = Surface(0.5, (0.55, 0.55, 0.6, 1.0))
    spawn_parts(sim, [Box((t["near_edge_x"] + t["depth"] / 2, t["center_y"], t["top_z"] - t["thickness"] / 2),
                          (t["depth"], t["width"], t["thickness"]))], ((0, 0, 0), (0, 0, 0, 1)), 0.0, grey)
    riser_x0 = tube["mouth_x"] - r["front"]
    riser_len = tube["mouth_x"] + length - riser_x0
    spawn_parts(sim, [Box((riser_x0 + riser_len / 2, tube["axis_y"], t["top_z"] + r["height"] / 2),
                          (riser_len, r["width"], r["height"]))], ((0, 0, 0), (0, 0, 0, 1)), 0.0, grey)
    w, iw, ih = tube["wall"], tube["inner_width"], tube["inner_height"]
    z0 = t["top_z"] + r["height"]
    x0, y0, cx = tube["mouth_x"], tube["axis_y"], tube["mouth_x"] + length / 2
    ow, oh = iw + 2 * w, ih + 2 * w
    walls = [Box((cx, y0, z0 + w / 2), (length, ow, w)),                      # floor
             Box((cx, y0 - iw / 2 - w / 2, z0 + oh / 2), (length, w, oh)),     # right side
             Box((cx, y0 + iw / 2 + w / 2, z0 + oh / 2), (length, w, oh)),     # left side
             Box((x0 + length - w / 2, y0, z0 + oh / 2), (w, ow, oh)),         # far end
             Box((cx, y0, z0 + oh - w / 2), (length, ow, w))]                  # top: clear
    body = spawn_parts(sim, walls, ((0, 0, 0), (0, 0, 0, 1)), 0.0,
                       Surface(0.3, (0.3, 0.5, 0.8, 1.0)), hidden=[4])
    return body, z0 + w


def run_hook(seeds: int) -> dict:
    """Measure the cube's perception error at the hook world's four locations."""
    path = ROOT / "worlds/hook_tube/scene.toml"
    scene = tomllib.loads(path.read_text())
    cameras = cameras_from_tables(scene["camera"], str(path))
    noise = NoiseModel.from_dict(scene.get("perception", {}), str(path))
    tasks = tomllib.loads((ROOT / "worlds/hook_tube/tasks.toml").read_text())
    length = tasks["variant"]["standard"]["tube_length"]
    tube = scene["tube"]
    with Sim(PhysicsSettings()) as sim:
        tube_body, floor_z = hook_scene(sim, scene, length)
        far_inner = tube["mouth_x"] + length - tube["wall"]
        cube = spawn_spec(sim, CUBE, ((far_inner - 0.1, tube["axis_y"], floor_z), (0, 0, 0, 1)),
                          Surface(0.5, (0.85, 0.1, 0.1, 1.0)))
        rows = {"noise_free": [], "noisy": []}
        rng_yaw = np.random.default_rng(0)
        for i, loc in enumerate(tasks["location"]):
            x = far_inner - loc["back_gap"] - CUBE.length / 2
            y = tube["axis_y"] + loc["lateral"]
            for yaw in (0.0, float(rng_yaw.uniform(-0.4, 0.4))):
                set_frame_pose(sim, cube, ((x, y, floor_z), pb.getQuaternionFromEuler((0, 0, yaw))))
                truth = truth_of(sim, cube, CUBE)
                frames = [capture(sim.client, c) for c in cameras]
                est = estimate_objects(frames, {"cube1": cube}, support_z={"cube1": floor_z})
                rows["noise_free"].append({"location": i + 1, "yaw": yaw,
                                           **errors(est["cube1"], truth, CUBE)})
                for seed in range(seeds):
                    est = estimate_objects(frames, {"cube1": cube}, noise,
                                           np.random.default_rng(seed),
                                           support_z={"cube1": floor_z})
                    rows["noisy"].append({"location": i + 1, "yaw": yaw, "seed": seed,
                                          **errors(est["cube1"], truth, CUBE)})
        del tube_body
    return {"scene": "worlds/hook_tube/scene.toml geometry (standard tube), built with sim.bodies",
            "cameras": [c.name for c in cameras], "resolution": [cameras[0].width, cameras[0].height],
            "noise": {"depth_sigma_m": noise.depth_sigma_m, "dropout": noise.dropout},
            "noise_free": summarise(rows["noise_free"]), "noisy": summarise(rows["noisy"]),
            "rows": rows}


def wedge_cameras() -> tuple[list[CameraSpec], str]:
    """Return the wedge world's cameras, or the stand-in pair if it has none yet."""
    path = ROOT / "worlds/wedge_door/scene.toml"
    if path.is_file():
        scene = tomllib.loads(path.read_text())
        if scene.get("camera"):
            return list(cameras_from_tables(scene["camera"], str(path))), str(path.relative_to(ROOT))
    return [CameraSpec("top", eye=(0.4, 0.3, 1.6), target=(0.4, 0.3, 0.0), up=(1.0, 0.0, 0.0),
                       fov_deg=45.0, width=320, height=240, near=0.1, far=4.0),
            CameraSpec("side", eye=(1.4, -0.6, 0.5), target=(0.4, 0.3, 0.0), up=(0.0, 0.0, 1.0),
                       fov_deg=45.0, width=320, height=240, near=0.1, far=4.0)], "stand-in cameras"


def run_wedge(seeds: int, placements: int) -> dict:
    """Measure block errors at random placements in view of the wedge cameras."""
    cameras, source = wedge_cameras()
    noise = NoiseModel(depth_sigma_m=0.0005)
    rows = {"noise_free": [], "noisy": [], "top_only": []}
    rng = np.random.default_rng(1)
    cx, cy = cameras[0].target[0], cameras[0].target[1]
    with Sim(PhysicsSettings()) as sim:
        floor = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE, physicsClientId=sim.client),
                                   -1, physicsClientId=sim.client)
        del floor
        for spec in WEDGE_OBJECTS:
            body = spawn_spec(sim, spec, ((cx, cy, 0.0), (0, 0, 0, 1)), Surface(1.0, (0.9, 0.6, 0.1, 1.0)))
            for _ in range(placements):
                x, y = cx + rng.uniform(-0.3, 0.3), cy + rng.uniform(-0.3, 0.3)
                yaw = float(rng.uniform(-math.pi, math.pi))
                set_frame_pose(sim, body, ((x, y, 0.0), pb.getQuaternionFromEuler((0, 0, yaw))))
                truth = truth_of(sim, body, spec)
                frames = [capture(sim.client, c) for c in cameras]
                bodies, sup = {spec.name: body}, {spec.name: 0.0}
                est = estimate_objects(frames, bodies, support_z=sup)[spec.name]
                base = {"object": spec.name, "shape": spec.shape}
                rows["noise_free"].append({**base, **errors(est, truth, spec)})
                est = estimate_objects(frames[:1], bodies, support_z=sup)[spec.name]
                rows["top_only"].append({**base, **errors(est, truth, spec)})
                for seed in range(seeds):
                    est = estimate_objects(frames, bodies, noise, np.random.default_rng(seed),
                                           support_z=sup)[spec.name]
                    rows["noisy"].append({**base, "seed": seed, **errors(est, truth, spec)})
            pb.removeBody(body, physicsClientId=sim.client)
    wedges = {k: [r for r in v if r["shape"] == "triangular_prism"] for k, v in rows.items()}
    tip_wrong = sum(1 for v in rows.values() for r in v
                    if r["shape"] == "triangular_prism" and r["yaw_deg"] > 90)
    return {"cameras": [c.name for c in cameras], "camera_source": source,
            "resolution": [cameras[0].width, cameras[0].height],
            "noise": {"depth_sigma_m": noise.depth_sigma_m, "dropout": noise.dropout},
            "objects": [s.name for s in WEDGE_OBJECTS], "placements_per_object": placements,
            "tip_direction_wrong": tip_wrong,
            "all_objects": {k: summarise(v) for k, v in rows.items()},
            "wedges_only": {k: summarise(v) for k, v in wedges.items()},
            "rows": rows}


def render_times(repeats: int) -> dict:
    """Return ms per frame of the hook world's camera at three resolutions (CPU renderer)."""
    path = ROOT / "worlds/hook_tube/scene.toml"
    scene = tomllib.loads(path.read_text())
    table = dict(scene["camera"][0])
    out = {}
    with Sim(PhysicsSettings()) as sim:
        _, floor_z = hook_scene(sim, scene, 0.30)
        cube = spawn_spec(sim, CUBE, ((1.1, scene["tube"]["axis_y"], floor_z), (0, 0, 0, 1)))
        for w, h in ((160, 120), (320, 240), (640, 480)):
            spec = CameraSpec.from_dict({**table, "width": w, "height": h}, str(path))
            capture(sim.client, spec)
            times = [capture(sim.client, spec).render_time_s for _ in range(repeats)]
            t0 = time.perf_counter()
            frame = capture(sim.client, spec)
            estimate_objects([frame], {"cube1": cube}, support_z={"cube1": floor_z})
            est_ms = 1000 * (time.perf_counter() - t0 - frame.render_time_s)
            out[f"{w}x{h}"] = {"render_ms_median": 1000 * statistics.median(times),
                               "render_ms_worst": 1000 * max(times),
                               "estimate_ms": est_ms}
    return out


def main() -> None:
    """Run the measurements and write the JSON file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--placements", type=int, default=5)
    parser.add_argument("--repeats", type=int, default=10)
    parser.add_argument("--out", type=Path, default=ROOT / "bench/results/perception.json")
    args = parser.parse_args()
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    t0 = time.perf_counter()
    result = {"hook": run_hook(args.seeds), "wedge": run_wedge(args.seeds, args.placements),
              "render": render_times(args.repeats),
              "machine": {"python": platform.python_version(), "processor": platform.machine(),
                          "pybullet": pb.getAPIVersion()},
              "wall_time_s": 0.0}
    result["wall_time_s"] = time.perf_counter() - t0
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=1) + "\n")
    h, w = result["hook"], result["wedge"]
    log.info("hook cube, noise-free: %.2f mm mean, %.2f mm worst, %.2f deg worst",
             h["noise_free"]["xy_mm_mean"], h["noise_free"]["xy_mm_worst"],
             h["noise_free"]["yaw_deg_worst"])
    log.info("hook cube, noisy: %.2f mm mean, %.2f mm worst, %.2f deg worst",
             h["noisy"]["xy_mm_mean"], h["noisy"]["xy_mm_worst"], h["noisy"]["yaw_deg_worst"])
    for k, v in w["all_objects"].items():
        log.info("wedge scene, %s: %.2f mm mean, %.2f mm worst, %.2f deg worst", k,
                 v["xy_mm_mean"], v["xy_mm_worst"], v["yaw_deg_worst"])
    log.info("wedge tip direction wrong: %d", w["tip_direction_wrong"])
    for k, v in result["render"].items():
        log.info("render %s: %.1f ms median", k, v["render_ms_median"])
    log.info("wrote %s in %.1f s", args.out, result["wall_time_s"])


if __name__ == "__main__":
    main()
