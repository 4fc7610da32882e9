"""The ManiSkill3 backend: a ManiSkill tabletop task with a tool (the one a world's
``tasks.toml`` names: ``PullCubeTool-v1``, ``PokeCube-v1``) on SAPIEN's CPU backend, with
ManiSkill's own arm, table and target, the case's tools built with ManiSkill's actor
builder in place of the task's own, and ManiSkill's ``evaluate()["success"]`` as the
only goal verdict.

The one home of ``mani_skill``, ``sapien``, ``torch`` and ``gymnasium`` in the project
(installed by ``pip install -e '.[maniskill]'`` / ``make setup-maniskill``). It
implements :class:`creative_py.simulator.Backend`:

``env``       the task's subclass (tool from a spec's boxes, target moved by a variant)
``skills``    straight end-effector moves through ManiSkill's ``pd_ee_pose`` controller
``world``     the world folder (catalogue, ManiSkill seeds as locations, step budget)
``episode``   one episode: skills, perception from the simulator's state, the verdict
              (a trial is run above the boundary: :mod:`creative_py.simulator.trial`;
              randomised worlds are refused: the locations are ManiSkill's seeds)
``recorder``  a trial's clip: its states kept while it runs, rendered after the verdict
"""

from __future__ import annotations

import importlib.util
from typing import Optional

for _package in ("mani_skill", "sapien", "torch", "gymnasium"):
    # Imported when an episode is built (they take seconds to load); missing, the
    # backend is not installed, which the registry reports with what installs it.
    if importlib.util.find_spec(_package) is None:
        raise ModuleNotFoundError(f"No module named {_package!r}", name=_package)

from creative_py.backends.maniskill.episode import Episode, open_episode, tool_rests
from creative_py.backends.maniskill.recorder import Recorder, VideoCamera
from creative_py.backends.maniskill.scene import World, load_world


def display_reachable() -> Optional[str]:
    """Return why no window can open: this backend runs without a viewer."""
    return "the maniskill backend runs without a window (SAPIEN's viewer is not used)"


def recorder(camera: VideoCamera) -> Recorder:
    """Return a new, empty recorder of one trial's clip for ``camera`` (a world's
    ``video``, the ``[video]`` table of its ``tasks.toml``)."""
    return Recorder(camera)


__all__ = ["Episode", "Recorder", "VideoCamera", "World", "display_reachable", "load_world",
           "open_episode", "recorder", "tool_rests"]
