"""``creative robots`` and ``creative cases``: what there is to run, listed and checked."""

from __future__ import annotations

import json
from typing import Optional

import typer

from creative_py.cli.errors import stdout_to_stderr


def robots(
    names: Optional[list[str]] = typer.Argument(None, help="Profiles to check: names under "
                                                "robots/ or .toml paths (default: every "
                                                "shipped profile)."),
) -> None:
    """List the robot profiles, each with a one-line check: the URDF loads, the joints
    and links are found, the home posture is reachable (docs/robots.md).

    Exit 2 if a profile fails its check (each failure is one line naming the file and
    the field)."""
    from creative_py.case import DEFAULT_BACKEND
    from creative_py.robots import profile_names
    from creative_py.simulator.loader import backend as load_backend
    from creative_py.world_files import WorldFileError

    physics = load_backend(DEFAULT_BACKEND)
    specs = names or profile_names()
    width = max(len(str(s)) for s in specs)
    failed = 0
    for spec in specs:
        try:
            with stdout_to_stderr():
                line = physics.check_profile(spec)
        except (WorldFileError, FileNotFoundError) as exc:
            failed += 1
            line = f"FAILED: {exc}"
        typer.echo(f"{str(spec):<{width}} {line}")
    if failed:
        raise typer.Exit(2)


def cases(as_json: bool = typer.Option(False, "--json", help="Print the cases as JSON.")) -> None:
    """List the cases: id, world folder, variants (the harder one marked) and trial budget.

    A case folder whose manifest does not load is listed as broken with its error line;
    the other cases still load and run.
    """
    from creative_py.case import broken_cases, load_cases

    found = load_cases(strict=False)
    broken = broken_cases()
    listing = [m.listing() for m in found.values()]
    if as_json:
        listing += [{"id": None, "manifest": str(path), "broken": error}
                    for path, error in broken.items()]
        typer.echo(json.dumps(listing, indent=2))
        return
    width = max([len("broken")] + [len(c["id"]) for c in listing])  # the longest id's
    for c in listing:
        variants = ", ".join(v["name"] + (" (harder)" if v["harder"] else "")
                             for v in c["variants"])
        typer.echo(f"{c['id']:<{width}} {c['title']}\n{'':<{width}} world {c['world']}; "
                   f"variants {variants}; trial budget {c['trial_budget']}")
    for error in dict.fromkeys(broken.values()):  # a duplicate id: one line, both folders
        typer.echo(f"{'broken':<{width}} {error}")
