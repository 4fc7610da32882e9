"""Measure perception error and render time; record them in bench/results/perception.json.

Hook: every variant and cube location of ``worlds/hook_tube``, built by the world's own
loader (:mod:`creative_py.sim.hook_tube`), seen by its downward camera. Wedge: every object
of ``worlds/wedge_door`` in an episode of that world (:mod:`creative_py.sim.wedge_door`),
put at door-relative placements and seen by its downward and side cameras. Each view is estimated
without noise and with the world's ``[perception]`` depth noise over several seeds.
Ground truth comes from pybullet and is used only here, to measure the error.

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
from pathlib import Path

import numpy as np
import pybullet as pb

from creative_py.mesh.spec import BlockSpec
from creative_py.perception import estimate_objects
from creative_py.sim.bodies import frame_pose, set_frame_pose
from creative_py.sim.camera import CameraSpec, capture

ROOT = Path(__file__).resolve().parents[1]
log = logging.getLogger("bench.perception")

SYMMETRY_PERIOD = {"none": 2 * math.pi, "pi": math.pi, "half_pi": math.pi / 2, "round": None}


def angle_diff(a: float, b: float, period: float) -> float:
    """Return a - b wrapped into (-period/2, period/2], radians."""
    return (a - b + period / 2) % period - period / 2


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


WEDGE_POSES = [(0.55, 0.02, 0.0), (0.45, 0.05, 0.25), (0.65, 0.10, -0.25), (0.35, 0.0, 0.0),
               (0.60, 0.30, 0.1), (0.50, 0.05, math.pi), (0.40, 0.15, -0.3)]
"""Door-relative placements (r m, gap m, yaw rad) like those the experiments ask for."""


def run_wedge(seeds: int) -> dict:
    """Measure object errors at door-relative placements in the wedge world's episodes.

    Each object of ``worlds/wedge_door`` gets its own episode (stage, door held open,
    Baxter parked at its retreat pose) built by the world's loader; the object is put on
    the stage at each of :data:`WEDGE_POSES` (converted with the world's own
    ``place_from_pose``) and seen by both cameras, by the downward camera alone, and with
    the world's depth noise. The estimate is called as the episode calls it (support at
    the stage top, known height).
    """
    from creative_py.sim.wedge_door import WedgePose, load_wedge_world, open_wedge_episode, place_from_pose

    world = load_wedge_world()
    top_z = world.stage.top_z
    rows: dict[str, list] = {"noise_free": [], "noisy": [], "top_only": []}
    for name, item in world.objects.items():
        spec = item.spec
        ep = open_wedge_episode(world, world.default_variant, 1, name, seed=0)
        try:
            angle = ep.door_angle()
            for pose in WEDGE_POSES:
                x, y, yaw = place_from_pose(world.door, angle, spec.length, WedgePose(*pose))
                set_frame_pose(ep.sim, ep.body, ((x, y, top_z), pb.getQuaternionFromEuler((0, 0, yaw))))
                truth = ep.truth()[name]
                frames = [capture(ep.sim.client, c) for c in world.cameras]
                bodies, sup, known = {name: ep.body}, {name: top_z}, {name: spec.height}
                base = {"object": name, "shape": spec.shape, "pose": list(pose)}
                est = estimate_objects(frames, bodies, support_z=sup, heights=known)
                if name not in est:
                    rows["noise_free"].append({**base, "unseen": True})
                    continue
                rows["noise_free"].append({**base, **errors(est[name], truth, spec)})
                est = estimate_objects(frames[:1], bodies, support_z=sup, heights=known)
                if name in est:
                    rows["top_only"].append({**base, **errors(est[name], truth, spec)})
                for seed in range(seeds):
                    est = estimate_objects(frames, bodies, world.noise, np.random.default_rng(seed),
                                           support_z=sup, heights=known)
                    rows["noisy"].append({**base, "seed": seed, **errors(est[name], truth, spec)})
        finally:
            ep.close()
    unseen = [r for r in rows["noise_free"] if r.get("unseen")]
    rows = {k: [r for r in v if not r.get("unseen")] for k, v in rows.items()}
    wedges = {k: [r for r in v if r["shape"] == "triangular_prism"] for k, v in rows.items()}
    tip_wrong = sum(1 for v in wedges.values() for r in v if r["yaw_deg"] > 90)
    cam = world.cameras[0]
    return {"scene": "worlds/wedge_door via creative_py.sim.wedge_door (door open, Baxter parked)",
            "cameras": [c.name for c in world.cameras], "resolution": [cam.width, cam.height],
            "noise": {"depth_sigma_m": world.noise.depth_sigma_m, "dropout": world.noise.dropout},
            "objects": list(world.objects), "poses": WEDGE_POSES,
            "unseen": unseen, "tip_direction_wrong": tip_wrong,
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
    parser.add_argument("--repeats", type=int, default=10)
    parser.add_argument("--out", type=Path, default=ROOT / "bench/results/perception.json")
    args = parser.parse_args()
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    t0 = time.perf_counter()
    result = {"hook": run_hook(args.seeds), "wedge": run_wedge(args.seeds),
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
