"""The backend loader: from a manifest's ``backend = "<name>"`` to the module.

The names and modules are the registry :data:`creative_py.backend_registry.BACKENDS` (beside
the backends, importing none; the manifest reader refuses an unknown name); a backend's module is
imported only when a case names it, so a machine without a backend's optional
dependencies runs every other case.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import TYPE_CHECKING, Optional, cast

from creative_py.backend_registry import BACKENDS, DEFAULT_BACKEND
from creative_py.world_files import WorldFileError

if TYPE_CHECKING:
    from creative_py.case import CaseManifest
    from creative_py.simulator.protocol import Backend


class BackendError(WorldFileError):
    """A manifest names a backend that is unknown or cannot run here."""


class UnknownBackend(BackendError):
    """No backend of that name is registered (:data:`creative_py.backend_registry.BACKENDS`)."""


class BackendUnavailable(BackendError):
    """A known backend whose module or optional dependencies are not installed."""


def backend(name: str = DEFAULT_BACKEND, where: Optional[Path | str] = None) -> "Backend":
    """Return the backend registered as ``name``, importing its module on first use.

    Parameters
    ----------
    name : str
        A name of :data:`creative_py.backend_registry.BACKENDS` (``pybullet``, ``maniskill``).
    where : Path or str or None
        The file that named it (a ``case.toml``), for the error messages.

    Raises
    ------
    UnknownBackend
        ``name`` is not registered (the message lists the registered names).
    BackendUnavailable
        Its module, or a package it needs, is not installed (the message says which
        and what installs it). An import error inside an installed backend is a
        bug and is raised as it is.
    """
    prefix = f"{where}: field 'backend': " if where is not None else ""
    entry = BACKENDS.get(name)
    if entry is None:
        raise UnknownBackend(f"{prefix}unknown simulator backend {name!r}; backends: "
                             f"{', '.join(sorted(BACKENDS))}")
    try:
        module = importlib.import_module(entry.module)
    except ModuleNotFoundError as exc:
        missing = exc.name or ""
        if missing.split(".")[0] == "creative_py" and missing != entry.module:
            raise  # another module of this project is missing: a bug, not an installation
        install = entry.setup + (f" (the extra '.[{entry.extra}]')" if entry.extra else "")
        raise BackendUnavailable(f"{prefix}the simulator backend {name!r} needs the "
                                 f"module {missing}, which is not installed: {install}"
                                 ) from None
    return cast("Backend", module)


def backend_for(manifest: "CaseManifest") -> "Backend":
    """Return the backend the case's manifest names (``backend``, default
    ``pybullet``); errors name its ``case.toml``, as :func:`backend` says."""
    return backend(manifest.backend, Path(manifest.folder) / "case.toml")


def backend_packages() -> set[str]:
    """Return the packages of ``creative_py`` that are backends (``backends.pybullet``,
    ``backends.maniskill``): what the learning loop must never import."""
    return {".".join(entry.module.split(".")[1:3]) for entry in BACKENDS.values()
            if entry.module.startswith("creative_py.")}
