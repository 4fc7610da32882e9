"""The ``creative`` command line.

``creative trial CASE ...`` runs one physical trial in pybullet and prints its result
(JSON with ``--json``); ``creative trial CASE --list`` prints the case's objects,
locations, variants and default pose as JSON. The command is generic over the cases
registered in :data:`creative_py.sim.cases.CASES`.
"""

from __future__ import annotations

import json
import logging
import os
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, Optional

import typer

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="CREATIVE: learn to use tools from one demonstration, and create new ones.")


@app.callback()
def main(verbose: bool = typer.Option(False, "--verbose", "-v", help="Log progress.")) -> None:
    """CREATIVE in Python and Prolog (Wicaksono & Sammut, IJECE 2020)."""
    logging.basicConfig(level=logging.INFO if verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")


@contextmanager
def _stdout_to_stderr() -> Iterator[None]:
    """Send what C libraries print to stdout (pybullet's banner and URDF warnings) to
    stderr, so that stdout carries only the command's output (e.g. one JSON line)."""
    sys.stdout.flush()
    saved = os.dup(1)
    try:
        os.dup2(2, 1)
        yield
    finally:
        sys.stdout.flush()
        os.dup2(saved, 1)
        os.close(saved)


def _fail(message: str) -> None:
    typer.echo(f"error: {message}", err=True)
    raise typer.Exit(code=2)


@app.command()
def trial(
    case: str = typer.Argument(..., help="The case: hook or wedge."),
    tool: Optional[str] = typer.Option(None, "--tool", "--object", "-t",
                                       help="The object used as a tool (--object is a synonym)."),
    location: int = typer.Option(1, "--location", "-l", help="Predefined target location, 1-based."),
    variant: Optional[str] = typer.Option(None, "--variant",
                                          help="Task variant (hook: standard, long_tube); "
                                               "default: the demonstration's."),
    pose: Optional[str] = typer.Option(None, "--pose",
                                       help="Pose numbers relative to the target, comma "
                                            "separated (hook: DX,DY,ROLL in m, m, rad); "
                                            "default: the demonstration's."),
    seed: int = typer.Option(0, "--seed", help="Seed of every random choice (sensor noise)."),
    as_json: bool = typer.Option(False, "--json", help="Print the result as one JSON line."),
    save_images: Optional[Path] = typer.Option(None, "--save-images",
                                               help="Save camera snapshots in this folder."),
    gui: bool = typer.Option(False, "--gui", help="Show the pybullet GUI (needs a display)."),
    world: Optional[Path] = typer.Option(None, "--world", help="World folder (default: the "
                                         "shipped worlds/<case>)."),
    list_: bool = typer.Option(False, "--list", help="Print objects, locations, variants "
                               "and the default pose as JSON, and exit."),
) -> None:
    """Run one physical trial and report its outcome (success, failure, blocked,
    unreachable or invalid)."""
    with _stdout_to_stderr():
        lines = _trial(case, tool, location, variant, pose, seed, as_json, save_images, gui,
                       world, list_)
    for line in lines:
        typer.echo(line)


def _trial(case, tool, location, variant, pose, seed, as_json, save_images, gui, world,
           list_) -> list[str]:
    out: list[str] = []
    from creative_py.sim.cases import CASES
    from creative_py.sim.trial import get_case, list_case, load_case_world, run_trial
    from creative_py.world import WorldFileError

    if case not in CASES:
        _fail(f"unknown case {case!r}; known cases: {', '.join(sorted(CASES))}")
    try:
        w = load_case_world(case, world)
    except WorldFileError as exc:
        _fail(str(exc))
    if list_:
        return [json.dumps(list_case(case, w), indent=2, sort_keys=True)]
    c = get_case(case)
    listing = list_case(case, w)
    objects = list(listing["objects"])
    demo = listing.get("demonstration", {})
    if tool is None:
        _fail(f"--{c.object_option} is required; available: {', '.join(objects)}")
    if tool not in objects:
        _fail(f"unknown {c.object_option} {tool!r}; available: {', '.join(objects)}")
    variants = list(listing["variants"])
    variant = variant or demo.get("variant") or variants[0]
    if variant not in variants:
        _fail(f"unknown variant {variant!r}; variants: {', '.join(variants)}")
    n_loc = len(listing["locations"])
    if not 1 <= location <= n_loc:
        _fail(f"--location must lie in 1..{n_loc}, got {location}")
    parsed = None
    if pose is not None:
        try:
            parsed = c.parse_pose(pose)
        except ValueError as exc:
            _fail(str(exc))
    result = run_trial(case, w, tool, variant, location, pose=parsed, seed=seed,
                       images_dir=save_images, gui=gui)
    if as_json:
        return [result.to_json()]
    p = ", ".join(f"{v:g}" for v in result.pose)
    out.append(f"{case} trial: {tool} at location {location} ({variant}), pose ({p}) -> "
               f"{result.outcome}" + (f": {result.reason}" if result.reason else ""))
    out.append(f"  {result.steps} steps, {result.sim_time_s:.2f} s simulated, "
               f"{result.wall_time_s:.2f} s wall ({result.render_time_s:.2f} s rendering)")
    for name, truth in sorted(result.true_final.items()):
        seen = (result.perceived_final or {}).get(name)
        seen_txt = ("perceived (" + ", ".join(f"{v:.3f}" for v in seen) + ")"
                    if seen is not None else "not perceived")
        out.append(f"  {name}: true (" + ", ".join(f"{v:.3f}" for v in truth) + f"), {seen_txt}")
    return out


if __name__ == "__main__":  # pragma: no cover
    app()
