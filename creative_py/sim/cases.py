"""The registry of cases: name -> an object implementing :class:`creative_py.sim.trial.Case`.

Add a case by importing its class and adding one entry.
"""

from __future__ import annotations

from creative_py.sim.hook_tube import HookTubeCase
from creative_py.sim.trial import Case
from creative_py.sim.wedge_door import WedgeDoorCase

CASES: dict[str, Case] = {
    "hook": HookTubeCase(),
    "wedge": WedgeDoorCase(),
}
