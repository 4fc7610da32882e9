"""Read world files: TOML tables checked field by field, errors naming file and field.

Every world folder (``worlds/<case>/``) holds the same five files, listed in
:data:`WORLD_FILES`. This module only knows how to read TOML safely; what the fields
mean belongs to their readers (:mod:`creative_py.world.read` for a scene a backend
builds, the ManiSkill backend's for a ManiSkill task).

A :class:`Fields` reader wraps one TOML table. Each accessor names the file and the
dotted field path in its error, and :meth:`Fields.done` rejects fields nobody asked
for (a typo) with a did-you-mean suggestion::

    f = Fields(load_toml(path), source=path)
    dt = f.float("time_step", minimum=1e-5)
    f.done()
"""

from __future__ import annotations

import difflib
import math
import tomllib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

WORLD_FILES = ("scene.toml", "physics.toml", "objects.toml", "tasks.toml", "case.toml")
"""The file names every world folder holds."""

WORLDS_ROOT = Path(__file__).resolve().parent.parent / "worlds"
"""The folder holding the shipped worlds (one folder per case)."""


class WorldFileError(ValueError):
    """A world file is missing, unreadable, or has a missing, mistyped or unknown field."""


class OptionError(ValueError):
    """An option of a table (a skill's ``options``, the ``[oracle]``) that cannot work:
    the option's name and the cause. The loader turns it into a
    :class:`WorldFileError` naming the file and the field."""

    def __init__(self, option: str, cause: str) -> None:
        super().__init__(f"{option}: {cause}")
        self.option = option
        self.cause = cause


def shown(value: Any) -> str:
    """Return ``value`` as an error line shows it: a number by ``%g``, a list or tuple
    in brackets, anything else by its repr (``[0.9, 'x']``)."""
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(shown(v) for v in value) + "]"
    if isinstance(value, float):
        return f"{value:g}"
    return repr(value)


_MISSING = object()


def world_file(world_dir: Path, name: str) -> Path:
    """Return the path of one of the :data:`WORLD_FILES` in ``world_dir``; raise if absent."""
    if name not in WORLD_FILES:
        raise ValueError(f"{name!r} is not a world file; expected one of {', '.join(WORLD_FILES)}")
    path = Path(world_dir) / name
    if not path.is_file():
        raise WorldFileError(f"{path}: file not found (a world folder must hold "
                             f"{', '.join(WORLD_FILES)})")
    return path


def load_toml(path: Path) -> dict:
    """Return the parsed TOML document at ``path``; errors name the file and the line."""
    path = Path(path)
    try:
        with path.open("rb") as fh:
            return tomllib.load(fh)
    except FileNotFoundError:
        raise WorldFileError(f"{path}: file not found") from None
    except tomllib.TOMLDecodeError as exc:
        raise WorldFileError(f"{path}: not valid TOML: {exc}") from None


class Fields:
    """A checked view of one TOML table.

    Parameters
    ----------
    data : dict
        The table.
    source : str or Path
        The file the table comes from (named in every error).
    prefix : str
        Dotted path of this table inside the file (``""`` at top level).
    """

    def __init__(self, data: Any, source: str | Path, prefix: str = "") -> None:
        self.source = str(source)
        self.prefix = prefix
        if not isinstance(data, dict):
            raise WorldFileError(f"{self.source}: field {prefix or '<top>'!r} must be a table, "
                                 f"got {type(data).__name__}")
        self.data = data
        self._used: set[str] = set()

    def path(self, name: str) -> str:
        """Return the dotted path of field ``name``."""
        return f"{self.prefix}.{name}" if self.prefix else name

    def error(self, name: str, cause: str) -> WorldFileError:
        """Return an error naming the file, the field and the cause."""
        return WorldFileError(f"{self.source}: field {self.path(name)!r}: {cause}")

    def has(self, name: str) -> bool:
        """Return whether field ``name`` is present."""
        return name in self.data

    def raw(self, name: str, default: Any = _MISSING) -> Any:
        """Return the unchecked value of ``name`` (marking it used); raise if missing."""
        self._used.add(name)
        if name not in self.data:
            if default is _MISSING:
                spare = [k for k in self.data if k not in self._used]
                close = difflib.get_close_matches(name, spare, n=1, cutoff=0.6)
                hint = f" (is {close[0]!r} a typo for it?)" if close else ""
                raise self.error(name, "missing" + hint)
            return default
        return self.data[name]

    def float(self, name: str, default: Any = _MISSING, *, minimum: float | None = None,
              maximum: float | None = None) -> float:
        """Return a finite number (int or float in the file) within optional bounds."""
        value = self.raw(name, default)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.error(name, f"must be a number, got {value!r}")
        value = float(value)
        if not math.isfinite(value):
            raise self.error(name, f"must be finite, got {value!r}")
        if minimum is not None and value < minimum:
            raise self.error(name, f"must be >= {minimum}, got {value}")
        if maximum is not None and value > maximum:
            raise self.error(name, f"must be <= {maximum}, got {value}")
        return value

    def int(self, name: str, default: Any = _MISSING, *, minimum: int | None = None,
            maximum: int | None = None) -> int:
        """Return an integer within optional bounds (a whole float such as ``1e9`` is
        refused as not an integer)."""
        value = self.raw(name, default)
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(name, f"must be an integer, got {value!r}")
        if minimum is not None and value < minimum:
            raise self.error(name, f"must be >= {minimum}, got {value}")
        if maximum is not None and value > maximum:
            raise self.error(name, f"must be <= {maximum}, got {value}")
        return value

    def bool(self, name: str, default: Any = _MISSING) -> bool:
        """Return a boolean."""
        value = self.raw(name, default)
        if not isinstance(value, bool):
            raise self.error(name, f"must be true or false, got {value!r}")
        return value

    def str(self, name: str, default: Any = _MISSING, *,
            choices: tuple[str, ...] | None = None) -> str:
        """Return a string, optionally one of ``choices``."""
        value = self.raw(name, default)
        if not isinstance(value, str):
            raise self.error(name, f"must be a string, got {value!r}")
        if choices is not None and value not in choices:
            raise self.error(name, f"must be one of {', '.join(choices)}, got {value!r}"
                             + did_you_mean(value, choices))
        return value

    def vec(self, name: str, n: int, default: Any = _MISSING, *,
            minimum: float | None = None, maximum: float | None = None) -> tuple[float, ...]:
        """Return a list of ``n`` finite numbers as a tuple, each within optional bounds."""
        value = self.raw(name, default)
        if (not isinstance(value, (list, tuple)) or len(value) != n
                or any(isinstance(v, bool) or not isinstance(v, (int, float))
                       or not math.isfinite(v) for v in value)):
            raise self.error(name, f"must be a list of {n} numbers, got {value!r}")
        for v in value:
            if minimum is not None and v < minimum:
                raise self.error(name, f"every number must be >= {minimum}, got {v}")
            if maximum is not None and v > maximum:
                raise self.error(name, f"every number must be <= {maximum}, got {v}")
        return tuple(float(v) for v in value)

    def table(self, name: str, default: Any = _MISSING) -> "Fields":
        """Return the sub-table ``name`` as a :class:`Fields`."""
        value = self.raw(name, default)
        if not isinstance(value, dict):
            raise self.error(name, f"must be a table, got {type(value).__name__}")
        return Fields(value, self.source, self.path(name))

    def tables(self, name: str, default: Any = _MISSING) -> list["Fields"]:
        """Return the array of tables ``name`` (``[[name]]`` in TOML)."""
        value = self.raw(name, default)
        if not isinstance(value, list) or not all(isinstance(v, dict) for v in value):
            raise self.error(name, "must be an array of tables ([[...]])")
        return [Fields(v, self.source, f"{self.path(name)}[{i}]") for i, v in enumerate(value)]

    def done(self) -> None:
        """Raise if the table has fields no accessor asked for (typos), suggesting a fix."""
        unknown = sorted(set(self.data) - self._used)
        if unknown:
            name = unknown[0]
            raise self.error(name, "unknown field" + did_you_mean(name, sorted(self._used))
                             + f"; known fields: {', '.join(sorted(self._used))}")


def did_you_mean(word: str, options) -> str:
    """Return `` (did you mean 'X'?)`` for the option closest to ``word``, or ``""``."""
    close = difflib.get_close_matches(word, list(options), n=1, cutoff=0.6)
    return f" (did you mean {close[0]!r}?)" if close else ""


@dataclass(frozen=True)
class PhysicsSettings:
    """Physics settings of a world (``physics.toml``).

    Attributes
    ----------
    time_step : float
        Simulation time step, seconds.
    solver_iterations : int
        Constraint solver iterations per step.
    gravity : tuple of float
        Gravity vector in the world frame, m/s^2.
    """

    time_step: float = 1.0 / 240.0
    solver_iterations: int = 50
    gravity: tuple[float, float, float] = (0.0, 0.0, -9.81)


TIME_STEP_S = (1e-4, 0.05)
"""The bounds of a physics ``time_step``, seconds (10 kHz to 20 Hz)."""

SOLVER_ITERATIONS = (1, 1000)
"""The bounds of ``solver_iterations`` per physics step."""

GRAVITY_M_S2 = 100.0
"""The largest size of each component of ``gravity``, m/s^2 (about 10 g)."""


def read_physics(fields: Fields, gravity: tuple[float, float, float] | None = None
                 ) -> PhysicsSettings:
    """Return the :class:`PhysicsSettings` of a ``[physics]``-style table.

    ``time_step`` (s) must lie within :data:`TIME_STEP_S`, ``solver_iterations`` within
    :data:`SOLVER_ITERATIONS`, each component of ``gravity`` (m/s^2) within
    +-:data:`GRAVITY_M_S2`. With ``gravity`` given (an ``[arm]`` table), the table has
    no gravity of its own.
    """
    time_step = fields.float("time_step", minimum=TIME_STEP_S[0], maximum=TIME_STEP_S[1])
    iterations = fields.int("solver_iterations", minimum=SOLVER_ITERATIONS[0],
                            maximum=SOLVER_ITERATIONS[1])
    if gravity is None:
        gravity = fields.vec("gravity", 3, minimum=-GRAVITY_M_S2, maximum=GRAVITY_M_S2)
    return PhysicsSettings(time_step=time_step, solver_iterations=iterations,
                           gravity=gravity)
