"""The simulator backends' registry (:data:`BACKENDS`: name -> package, optional
extra, set-up command), at the bottom of the layers and importing nothing: the manifest
reader (:mod:`creative_py.case`) refuses an unknown ``backend`` with it, the loader
(:mod:`creative_py.simulator.loader`) imports the package a manifest names. The
packages themselves live in :mod:`creative_py.backends`, which re-exports the registry.

``pybullet``   the reference: a robot profile's arm and a case's scene in pybullet
``maniskill``  ManiSkill3 on SAPIEN (optional: ``make setup-maniskill``)
``ros``        an arm over ROS 2, the pybullet stand-in or a lab's (optional:
               ``make setup-ros``; ``creative run CASE --backend ros``)
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class BackendEntry:
    """Where a simulator backend lives and what installs it.

    Attributes
    ----------
    module : str
        The module that implements :class:`creative_py.simulator.Backend` (imported
        only when a case names the backend).
    extra : str
        The optional dependencies of ``pyproject.toml`` that it needs
        (``pip install -e '.[<extra>]'``); empty for one the core dependencies install.
    setup : str
        The command that installs it in this project (``make setup-maniskill``: pip
        alone lacks the pinned CPU torch wheel and SAPIEN's Vulkan driver): what the
        error for a missing backend tells.
    """

    module: str
    extra: str = ""
    setup: str = "make setup"


BACKENDS: dict[str, BackendEntry] = {
    "pybullet": BackendEntry("creative_py.backends.pybullet"),
    "maniskill": BackendEntry("creative_py.backends.maniskill", extra="maniskill",
                              setup="make setup-maniskill"),
    "ros": BackendEntry("creative_py.backends.ros.backend", extra="ros",
                        setup="make setup-ros"),
}
"""The simulator backends a manifest's ``backend`` may name: the registry that
:func:`creative_py.simulator.loader.backend` reads. It lives below the layers that read
it and imports none of the backends, so that the manifest reader
(:mod:`creative_py.case`) can refuse an unknown name with the file and the field."""

DEFAULT_BACKEND = "pybullet"
"""The backend of a manifest that names none."""
