"""The ManiSkill3 backend: ManiSkill's ``PullCubeTool-v1`` on SAPIEN's CPU backend, with
ManiSkill's Panda, table and cube, the case's L-tools built with ManiSkill's actor
builder, and ManiSkill's ``evaluate()["success"]`` as the only goal verdict.

The one home of ``mani_skill``, ``sapien``, ``torch`` and ``gymnasium`` in the project
(installed by ``pip install -e '.[maniskill]'`` / ``make setup-maniskill``). It
implements :class:`creative_py.simulator.Backend`:

``env``       the environment subclass (tool from a spec's boxes, cube moved by a variant)
``skills``    straight end-effector moves through ManiSkill's ``pd_ee_pose`` controller
``world``     the world folder (catalogue, ManiSkill seeds as locations, step budget)
``episode``   one episode: skills, perception from the simulator's state, the verdict
``recorder``  a trial's clip: its states kept while it runs, rendered after the verdict
"""

from __future__ import annotations

import importlib.util
from typing import Any, Optional

for _package in ("mani_skill", "sapien", "torch", "gymnasium"):
    # Imported when an episode is built (they take seconds to load); missing, the
    # backend is not installed, which the registry reports with what installs it.
    if importlib.util.find_spec(_package) is None:
        raise ModuleNotFoundError(f"No module named {_package!r}", name=_package)

from creative_py.backends.maniskill.episode import Episode, open_episode, run_trial, tool_rests
from creative_py.backends.maniskill.recorder import Recorder, VideoCamera
from creative_py.backends.maniskill.scene import World, load_world


def draw_world(world, seed, ranges, keeps=None, demonstrates=None) -> dict[str, Any]:
    """Randomised worlds are not offered by this backend: ManiSkill's seeds already
    randomise the initial state (ValueError naming the backend)."""
    raise ValueError(f"{world.manifest.folder / 'case.toml'}: the maniskill backend draws "
                     "no randomised worlds (--world-seed); its locations are ManiSkill's "
                     "seeded initial states")


def apply_drawn(world, drawn) -> World:
    """See :func:`draw_world`: no drawn worlds on this backend (ValueError)."""
    return draw_world(world, drawn.get("seed", 0), {})


def display_reachable() -> Optional[str]:
    """Return why no window can open: this backend runs without a viewer."""
    return "the maniskill backend runs without a window (SAPIEN's viewer is not used)"


def recorder(camera: VideoCamera) -> Recorder:
    """Return a new, empty recorder of one trial's clip for ``camera`` (a world's
    ``video``, the ``[video]`` table of its ``tasks.toml``)."""
    return Recorder(camera)


__all__ = ["Episode", "Recorder", "VideoCamera", "World", "apply_drawn", "display_reachable",
           "draw_world", "load_world", "open_episode", "recorder", "run_trial", "tool_rests"]
