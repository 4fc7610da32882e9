"""Measure perception error and render time; record them in bench/results/perception.json.

Hook: every variant and cube location of ``worlds/hook_tube``, built by the world's own
loader (:mod:`creative_py.sim.hook_tube`), seen by its downward camera. Wedge: the stage
and the two cameras of ``worlds/wedge_door/scene.toml`` with each object of its
``objects.toml`` at random placements (the door left out). Each view is estimated
without noise and with the world's ``[perception]`` depth noise over several seeds.
Ground truth comes from pybullet and is used only here, to measure the error.

    .venv/bin/python bench/perception_error.py [--seeds 5] [--placements 5] [--out ...]
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

from creative_py.mesh.spec import BlockSpec, Box, spec_from_dict
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


def run_hook(seeds: int) -> dict:
    """Measure the cube's perception error in the hook world's episodes.

    Every variant and location of ``worlds/hook_tube`` is built by the world's own loader
    (Baxter, table, riser, tube, the cube settled for 60 steps); the cube is seen as it
    lies (yaw 0) and turned by a random yaw in place. The estimate is called as the
    episode calls it (known cube height), without and with the world's depth noise.
    """
    from creative_py.sim.hook_tube import load_hook_world, open_hook_episode

    world = load_hook_world()
    name = world.cube.name
    spec = BlockSpec(name, "box", world.cube.size, world.cube.size, world.cube.size)
    tool = world.demonstration.tool
    rows: dict[str, list] = {"noise_free": [], "noisy": []}
    rng_yaw = np.random.default_rng(0)
    for variant in world.variants:
        for location in range(1, len(world.locations) + 1):
            ep = open_hook_episode(world, variant, location, tool, seed=0)
            try:
                pos, _ = frame_pose(ep.sim, ep.cube_body)
                for yaw in (None, float(rng_yaw.uniform(-0.6, 0.6))):
                    if yaw is not None:
                        set_frame_pose(ep.sim, ep.cube_body,
                                       (pos, pb.getQuaternionFromEuler((0, 0, yaw))))
                    truth = ep.truth()[name]
                    frames = [capture(ep.sim.client, c) for c in world.cameras]
                    bodies, known = {name: ep.cube_body}, {name: world.cube.size}
                    base = {"variant": variant, "location": location, "true_yaw": truth[3]}
                    est = estimate_objects(frames, bodies, heights=known)
                    rows["noise_free"].append({**base, **errors(est[name], truth, spec)})
                    for seed in range(seeds):
                        est = estimate_objects(frames, bodies, world.noise,
                                               np.random.default_rng(seed), heights=known)
                        rows["noisy"].append({**base, "seed": seed,
                                              **errors(est[name], truth, spec)})
            finally:
                ep.close()
    cam = world.cameras[0]
    return {"scene": "worlds/hook_tube via creative_py.sim.hook_tube (every variant and location)",
            "cameras": [c.name for c in world.cameras], "resolution": [cam.width, cam.height],
            "noise": {"depth_sigma_m": world.noise.depth_sigma_m, "dropout": world.noise.dropout},
            "noise_free": summarise(rows["noise_free"]), "noisy": summarise(rows["noisy"]),
            "rows": rows}


def wedge_objects() -> list[BlockSpec]:
    """Return the block specs of ``worlds/wedge_door/objects.toml``."""
    path = ROOT / "worlds/wedge_door/objects.toml"
    specs = []
    for table in tomllib.loads(path.read_text())["object"]:
        table = {k: v for k, v in table.items() if k not in ("set", "slot", "friction")}
        specs.append(spec_from_dict(table, source=str(path)))
    return specs


def run_wedge(seeds: int, placements: int) -> dict:
    """Measure block errors at random placements in the wedge zone of the door world.

    The stage (the floor the door stands on) and the two cameras come from
    ``worlds/wedge_door/scene.toml`` and the objects from its ``objects.toml``; the door
    itself is left out (it would only hide objects behind it). Each object is placed at
    random in a 0.4 m square around the downward camera's target with a random heading.
    """
    path = ROOT / "worlds/wedge_door/scene.toml"
    scene = tomllib.loads(path.read_text())
    cameras = list(cameras_from_tables(scene["camera"], str(path)))
    noise = NoiseModel.from_dict(scene.get("perception", {}), str(path))
    stage = scene["stage"]
    floor_z = stage["top_z"]
    rows: dict[str, list] = {"noise_free": [], "noisy": [], "top_only": []}
    rng = np.random.default_rng(1)
    cx, cy = cameras[0].target[0], cameras[0].target[1]
    objects = wedge_objects()
    with Sim(PhysicsSettings()) as sim:
        sx, sy = stage["size"]
        spawn_parts(sim, [Box((0, 0, 0), (sx, sy, stage["thickness"]))],
                    ((*stage["centre"], floor_z - stage["thickness"] / 2), (0, 0, 0, 1)), 0.0,
                    Surface(stage["friction"], (0.5, 0.5, 0.5, 1.0)))
        for spec in objects:
            body = spawn_spec(sim, spec, ((cx, cy, floor_z), (0, 0, 0, 1)),
                              Surface(1.0, (0.9, 0.6, 0.1, 1.0)))
            for _ in range(placements):
                x, y = cx + rng.uniform(-0.2, 0.2), cy + rng.uniform(-0.2, 0.2)
                yaw = float(rng.uniform(-math.pi, math.pi))
                set_frame_pose(sim, body, ((x, y, floor_z), pb.getQuaternionFromEuler((0, 0, yaw))))
                truth = truth_of(sim, body, spec)
                frames = [capture(sim.client, c) for c in cameras]
                bodies, sup = {spec.name: body}, {spec.name: floor_z}
                base = {"object": spec.name, "shape": spec.shape}
                est = estimate_objects(frames, bodies, support_z=sup)[spec.name]
                rows["noise_free"].append({**base, **errors(est, truth, spec)})
                est = estimate_objects(frames[:1], bodies, support_z=sup)[spec.name]
                rows["top_only"].append({**base, **errors(est, truth, spec)})
                for seed in range(seeds):
                    est = estimate_objects(frames, bodies, noise, np.random.default_rng(seed),
                                           support_z=sup)[spec.name]
                    rows["noisy"].append({**base, "seed": seed, **errors(est, truth, spec)})
            pb.removeBody(body, physicsClientId=sim.client)
    wedges = {k: [r for r in v if r["shape"] == "triangular_prism"] for k, v in rows.items()}
    tip_wrong = sum(1 for v in wedges.values() for r in v if r["yaw_deg"] > 90)
    return {"scene": "worlds/wedge_door/scene.toml stage and cameras, objects.toml objects, "
                     "no door",
            "cameras": [c.name for c in cameras], "resolution": [cameras[0].width, cameras[0].height],
            "noise": {"depth_sigma_m": noise.depth_sigma_m, "dropout": noise.dropout},
            "objects": [s.name for s in objects], "placements_per_object": placements,
            "tip_direction_wrong": tip_wrong,
            "all_objects": {k: summarise(v) for k, v in rows.items()},
            "wedges_only": {k: summarise(v) for k, v in wedges.items()},
            "rows": rows}


def render_times(repeats: int) -> dict:
    """Return ms per frame of the hook world's camera at three resolutions (CPU renderer).

    The scene is a hook episode (Baxter without visuals, table, tube, cube, tool).
    """
    from creative_py.sim.hook_tube import load_hook_world, open_hook_episode

    world = load_hook_world()
    cam = world.cameras[0]
    out = {}
    ep = open_hook_episode(world, "standard", 1, world.demonstration.tool)
    try:
        for w, h in ((160, 120), (320, 240), (640, 480)):
            spec = CameraSpec(cam.name, cam.eye, cam.target, cam.up, cam.fov_deg, w, h,
                              cam.near, cam.far)
            capture(ep.sim.client, spec)
            times = [capture(ep.sim.client, spec).render_time_s for _ in range(repeats)]
            frame = capture(ep.sim.client, spec)
            t0 = time.perf_counter()
            estimate_objects([frame], {world.cube.name: ep.cube_body},
                             heights={world.cube.name: world.cube.size})
            out[f"{w}x{h}"] = {"render_ms_median": 1000 * statistics.median(times),
                               "render_ms_worst": 1000 * max(times),
                               "estimate_ms": 1000 * (time.perf_counter() - t0)}
    finally:
        ep.close()
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
