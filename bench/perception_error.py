"""Measure perception error and render time; record them in bench/results/perception.json.

For every case (``worlds/*/case.toml``), every variant and location is built by the
generic simulator (:mod:`creative_py.backends.pybullet`) and each object its cameras track
(``[[perception.object]]`` of ``scene.toml``) is measured: a scene body as it lies and
turned by a random yaw in place; a tracked tool, for every catalogued tool, put by hand
at the demonstration's pose and at poses around it (when the pose skill can be done
by hand). Each view is estimated as the episode estimates it (support and known
height), without noise, with the first camera alone, and with the world's
``[perception]`` depth noise over several seeds. Ground truth comes from pybullet and
is used only here, to measure the error.

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
from recording import add_output_options, write_figures

from creative_py.perception import estimate_objects
from creative_py.backends.pybullet.bodies import frame_pose, set_frame_pose
from creative_py.backends.pybullet.camera import capture
from creative_py.world.cameras import CameraSpec

ROOT = Path(__file__).resolve().parents[1]
log = logging.getLogger("bench.perception")

SYMMETRY_PERIOD = {"none": 2 * math.pi, "pi": math.pi, "half_pi": math.pi / 2, "round": None}


def angle_diff(a: float, b: float, period: float) -> float:
    """Return a - b wrapped into (-period/2, period/2], radians."""
    return (a - b + period / 2) % period - period / 2


def errors(est, truth, size: tuple[float, float, float]) -> dict:
    """Return the position (mm), height (mm), heading (deg) and size (mm) errors.

    ``size`` is the object's true extents along its own x, y, z (m).
    """
    x, y, z, yaw = truth
    period = SYMMETRY_PERIOD[est.symmetry]
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


def _true_size(ep, name: str) -> tuple[float, float, float] | None:
    """Return the object's true extents (m) along its own axes, or None if unknown."""
    if name == ep.spec.name:
        spec = ep.spec
        if all(hasattr(spec, a) for a in ("length", "width", "height")):
            return (spec.length, spec.width, spec.height)
        return None
    size = getattr(ep.bodies[name], "size", None)
    return None if size is None else tuple(size)


def _views(ep, world, name: str, size, seeds: int, base: dict, rows: dict) -> None:
    """Estimate ``name`` in the current scene as the episode does; append the errors."""
    support = {n: z for n, z in ep.perceived if z is not None and n == name}
    height = ep.kind.height(ep.spec) if name == ep.spec.name else ep.bodies[name].height
    known = {} if height is None else {name: height}
    bodies = {name: ep.body_id(name)}
    truth = ep.truth()[name]
    cams = world.scene.cameras
    frames = [capture(ep.sim.client, c) for c in cams]
    est = estimate_objects(frames, bodies, support_z=support, heights=known)
    if name not in est:
        rows["unseen"].append(base)
        return
    rows["noise_free"].append({**base, **errors(est[name], truth, size)})
    if len(frames) > 1:
        est = estimate_objects(frames[:1], bodies, support_z=support, heights=known)
        if name in est:
            rows["top_only"].append({**base, **errors(est[name], truth, size)})
    for seed in range(seeds):
        est = estimate_objects(frames, bodies, world.scene.noise, np.random.default_rng(seed),
                               support_z=support, heights=known)
        if name in est:
            rows["noisy"].append({**base, "seed": seed, **errors(est[name], truth, size)})


def _poses_around(manifest, n: int, rng) -> list[tuple[float, ...]]:
    """Return the demonstration's pose and ``n`` poses around it (15 % of each range)."""
    demo = manifest.demonstration.pose
    out = [tuple(demo)]
    for _ in range(n):
        pose = []
        for p, v in zip(manifest.pose_params, demo):
            span = 0.15 * (p.max - p.min)
            pose.append(float(min(p.max, max(p.min, v + rng.uniform(-span, span)))))
        out.append(tuple(pose))
    return out


def run_case(manifest, seeds: int) -> dict:
    """Measure every tracked object of one case's world (see the module docstring)."""
    from creative_py.bridge import Engine
    from creative_py.learning.poses import pose_resolver
    from creative_py.backends.pybullet import load_world, open_episode
    from creative_py.backends.pybullet.primitives import PRIMITIVES

    world = load_world(manifest)
    poses = pose_resolver(Engine.instance(), manifest)
    pose_skill = next(s for s in manifest.skills if s.pose)
    by_hand = "by_hand" in PRIMITIVES[world.skills[pose_skill.name].primitive].options
    tracks_tool = any(p.name == "tool" for p in world.scene.perceived)
    tools = list(world.catalogue) if tracks_tool else [manifest.demonstration.tool]
    rng = np.random.default_rng(0)
    rows: dict[str, list] = {"noise_free": [], "noisy": [], "top_only": [], "unseen": []}
    for variant in manifest.variant_names:
        for location in world.locations:
            for tool in tools:
                with open_episode(world, variant, location, tool, seed=0,
                                  robot=not by_hand, pose_target=poses) as ep:
                    for name, _ in ep.perceived:
                        size = _true_size(ep, name)
                        if size is None:
                            continue
                        base = {"variant": variant, "location": location, "object": name}
                        if name == ep.spec.name:
                            if not by_hand:
                                _views(ep, world, name, size, seeds, base, rows)
                                continue
                            for pose in _poses_around(manifest, 4, rng):
                                if ep.run_skill(pose_skill.name, pose, by_hand=True).ok:
                                    _views(ep, world, name, size, seeds,
                                           {**base, "pose": list(pose)}, rows)
                            continue
                        _views(ep, world, name, size, seeds, base, rows)
                        body = ep.body_id(name)
                        pos, _ = frame_pose(ep.sim, body)
                        yaw = float(rng.uniform(-0.6, 0.6))
                        set_frame_pose(ep.sim, body, (pos, pb.getQuaternionFromEuler((0, 0, yaw))))
                        _views(ep, world, name, size, seeds, {**base, "turned": yaw}, rows)
    cam = world.scene.cameras[0]
    noise = world.scene.noise
    return {"world": str(world.directory.name), "cameras": [c.name for c in world.scene.cameras],
            "resolution": [cam.width, cam.height],
            "noise": {"depth_sigma_m": noise.depth_sigma_m, "dropout": noise.dropout},
            "unseen": rows.pop("unseen"),
            "tip_direction_wrong": sum(1 for v in rows.values() for r in v
                                       if r["yaw_deg"] is not None and r["yaw_deg"] > 90),
            **{k: summarise(v) for k, v in rows.items() if v}, "rows": rows}


def render_times(repeats: int) -> dict:
    """Return ms per frame of the first case's first camera at three resolutions.

    The scene is that case's demonstration scene (Baxter without visuals); the
    estimate time is for every tracked object in a 320 x 240 view.
    """
    from creative_py.case import load_cases
    from creative_py.backends.pybullet import load_world, open_episode

    manifest = load_cases()[sorted(load_cases())[0]]
    world = load_world(manifest)
    cam = world.scene.cameras[0]
    demo = manifest.demonstration
    out = {"case": manifest.id}
    with open_episode(world, demo.variant, demo.location, demo.tool) as ep:
        for w, h in ((160, 120), (320, 240), (640, 480)):
            spec = CameraSpec(cam.name, cam.eye, cam.target, cam.up, cam.fov_deg, w, h,
                              cam.near, cam.far)
            capture(ep.sim.client, spec)
            times = [capture(ep.sim.client, spec).render_time_s for _ in range(repeats)]
            frame = capture(ep.sim.client, spec)
            t0 = time.perf_counter()
            estimate_objects([frame], {n: ep.body_id(n) for n, _ in ep.perceived})
            out[f"{w}x{h}"] = {"render_ms_median": 1000 * statistics.median(times),
                               "render_ms_worst": 1000 * max(times),
                               "estimate_ms": 1000 * (time.perf_counter() - t0)}
    return out


def main() -> None:
    """Run the measurements and write the JSON file."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=5,
                        help="sensor-noise seeds per case (default 5)")
    parser.add_argument("--repeats", type=int, default=10,
                        help="renders per image size for the render times (default 10)")
    add_output_options(parser, "perception.json", "the pose errors and render times (JSON)")
    args = parser.parse_args()
    logging.basicConfig(level=logging.INFO, format="%(message)s")
    from creative_py.case import load_cases

    t0 = time.perf_counter()
    result = {cid: run_case(m, args.seeds) for cid, m in sorted(load_cases().items())}
    result["render"] = render_times(args.repeats)
    result["machine"] = {"python": platform.python_version(), "processor": platform.machine(),
                         "pybullet": pb.getAPIVersion()}
    result["wall_time_s"] = time.perf_counter() - t0
    for cid, r in result.items():
        if not isinstance(r, dict) or "noise_free" not in r:
            continue
        for k in ("noise_free", "top_only", "noisy"):
            if k in r:
                v = r[k]
                log.info("%s, %s: position error %.2f mm mean, %.2f mm worst; yaw error "
                         "%s deg worst", cid, k,
                         v["xy_mm_mean"], v["xy_mm_worst"], v["yaw_deg_worst"])
        log.info("%s: tip direction wrong %d times, objects unseen %d", cid,
                 r["tip_direction_wrong"],
                 len(r["unseen"]))
    for k, v in result["render"].items():
        if isinstance(v, dict):
            log.info("render %s: %.1f ms median", k, v["render_ms_median"])
    log.info("measured in %.1f s", result["wall_time_s"])
    write_figures(args, "perception.json", result)


if __name__ == "__main__":
    main()
