"""``creative trial``: one physical trial in the case's backend, its outcome and what was
measured (or the case's objects, locations, variants and default pose with ``--list``)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

from creative_py.cli.errors import fail, one_line_errors, stdout_to_stderr
from creative_py.cli.options import (
    BACKEND_HELP, PROFILE_HELP, SEED_MAX, backend_override, case_manifest, check_counts,
    name_option, need_display, path_option,
)


def trial(
    case: str = typer.Argument(..., help="A case id (creative cases lists them)."),
    tool: Optional[str] = typer.Option(None, "--tool", "--object", "-t",
                                       help="The object used as a tool (--object is a synonym)."),
    location: int = typer.Option(1, "--location", "-l", help="Predefined target location, 1-based."),
    variant: Optional[str] = typer.Option(None, "--variant",
                                          help="Task variant; default: the demonstration's."),
    pose: Optional[str] = typer.Option(None, "--pose",
                                       help="Pose numbers relative to the target, comma "
                                            "separated, as the case manifest's [pose] names "
                                            "them (hook: DX,DY,ROLL in m, m, rad); default: "
                                            "the demonstration's."),
    seed: int = typer.Option(0, "--seed", help="Seed of every random choice (sensor noise)."),
    as_json: bool = typer.Option(False, "--json", help="Print the result as one JSON line."),
    save_images: Optional[str] = typer.Option(None, "--save-images",
                                               help="Save camera snapshots in this folder."),
    gui: bool = typer.Option(False, "--gui", help="Show the pybullet GUI (needs a display)."),
    world: Optional[str] = typer.Option(None, "--world", help="World folder (default: the "
                                        "shipped one of the case)."),
    list_: bool = typer.Option(False, "--list", help="Print objects, locations, variants "
                               "and the default pose as JSON, and exit."),
    backend: Optional[str] = typer.Option(None, "--backend", help=BACKEND_HELP),
    robot: Optional[str] = typer.Option(None, "--robot", "--robot-profile", help=PROFILE_HELP),
) -> None:
    """Run one physical trial and report its outcome (success, failure, blocked,
    unreachable or invalid)."""
    variant = name_option("--variant", variant)
    save_images = path_option("--save-images", save_images, 64)
    world = path_option("--world", world)
    backend_override(backend, robot)
    with one_line_errors(), stdout_to_stderr():
        lines = _trial_lines(case, tool, location, variant, pose, seed, as_json, save_images,
                             gui, world, list_, backend, robot)
    for line in lines:
        typer.echo(line)


def _trial_lines(case, tool, location, variant, pose, seed, as_json, save_images, gui, world,
                 list_, backend=None, robot=None) -> list[str]:
    """Run the trial the options describe (or list the world) and return what to print."""
    from creative_py.bridge import Engine
    from creative_py.learning.poses import pose_resolver
    from creative_py.simulator.trial import run_trial

    m = _trial_manifest(case, world, backend, robot)
    check_counts(("--seed", seed, 0, SEED_MAX))
    if save_images is not None and save_images.exists() and not save_images.is_dir():
        fail(f"--save-images {save_images}: not a folder")
    w = _loaded_world(m)
    if gui:
        need_display(m)
    if list_:
        return [json.dumps(w.listing(), indent=2, sort_keys=True)]
    variant, parsed = _trial_choices(m, w, tool, variant, location, pose)
    result = run_trial(w, tool, variant, location, pose=parsed, seed=seed,
                       images_dir=save_images, gui=gui,
                       pose_target=pose_resolver(Engine.instance(), m))
    if as_json:
        return [result.to_json()]
    return _result_lines(case, tool, location, variant, result)


def _trial_manifest(case: str, world: Optional[Path], backend: Optional[str],
                    robot: Optional[str]):
    """Return the manifest of ``case`` on ``--backend`` (if given) with the arm its
    backend builds (``--robot``, if given), or fail in one line."""
    m = case_manifest(case, world)
    if backend is not None and backend != m.backend:
        from dataclasses import replace

        m = replace(m, backend=backend)
    if robot is not None and m.robot is None:
        fail(f"--robot {robot}: the case {case} runs in the {m.backend!r} backend, which "
             "brings its own arm")
    if robot is not None:
        from dataclasses import replace

        m = replace(m, robot=robot)  # the backend builds this arm
    return m


def _loaded_world(m):
    """Return the world of manifest ``m`` loaded in its backend, or fail in one line."""
    from creative_py.simulator import backend_for
    from creative_py.world_files import WorldFileError

    try:
        physics = backend_for(m)
        return physics.load_world(m)
    except WorldFileError as exc:
        fail(str(exc))


def _trial_choices(m, w, tool: Optional[str], variant: Optional[str], location: int,
                   pose: Optional[str]):
    """Return the trial's variant (default: the demonstration's) and parsed pose (None:
    the demonstration's) after checking the tool, variant and location against world
    ``w``, or fail in one line naming what is wrong and what is available."""
    objects = list(w.catalogue)
    if tool is None:
        fail(f"--tool is required; available: {', '.join(objects)}")
    if tool not in objects:
        fail(f"unknown tool {tool!r}; available: {', '.join(objects)}")
    variant = variant or m.demonstration.variant
    if variant not in m.variant_names:
        fail(f"unknown variant {variant!r}; variants: {', '.join(m.variant_names)}")
    if location not in w.locations:
        fail(f"--location must lie in 1..{len(w.locations)}, got {location}")
    parsed = None
    if pose is not None:
        try:
            parsed = m.parse_pose(pose)
        except ValueError as exc:
            fail(str(exc))
    return variant, parsed


def _result_lines(case: str, tool: str, location: int, variant: str, result) -> list[str]:
    """Return a trial's result in words: the outcome and its reason, what was measured,
    the steps and times, each object's true and perceived final pose."""
    from creative_py.records.trial import verdict_words

    out: list[str] = []
    p = ", ".join(f"{v:g}" for v in result.pose)
    out.append(f"{case} trial: {tool} at location {location} ({variant}), pose ({p}) -> "
               f"{result.outcome}" + (f": {result.reason}" if result.reason else ""))
    if result.verdict:
        out.append(f"  measured: {verdict_words(result.verdict)}")
    out.append(f"  {result.steps} steps, {result.sim_time_s:.2f} s simulated, "
               f"{result.wall_time_s:.2f} s wall ({result.render_time_s:.2f} s rendering)")
    for name, truth in sorted(result.true_final.items()):
        seen = (result.perceived_final or {}).get(name)
        seen_txt = ("perceived (" + ", ".join(f"{v:.3f}" for v in seen) + ")"
                    if seen is not None else "not perceived")
        out.append(f"  {name}: true (" + ", ".join(f"{v:.3f}" for v in truth) + f"), {seen_txt}")
    return out
