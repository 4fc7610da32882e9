"""Slice a printable piece to G-code with PrusaSlicer's command line.

::

    prusa-slicer --export-gcode --load profiles/generic_pla_0.4.ini --dont-arrange \
        --output part.gcode part.stl

The profile (:data:`PROFILE`, kept in this package) is a generic 0.4 mm nozzle PLA
printer whose bed is the default build volume; another build volume and the filament's
density (:data:`creative_py.mesh.spec.PLA_DENSITY`, the one density of the project) are
passed on the command line. The piece's STL is already in its print placement
(:mod:`creative_py.mesh.split`), so the slicer keeps it where it lies
(``--dont-arrange``). The print time and the filament used come from the G-code's
closing comments (``; estimated printing time (normal mode) = 1h 2m 3s``,
``; filament used [g] = 3.21``).

The slicer runs on one CPU and without address-space randomisation
(:func:`_deterministic`): PrusaSlicer 2.5 orders some toolpaths (which island or
perimeter comes next, where a travel retracts) by the order its worker threads finish
and by the addresses of its objects in memory, so the same STL gave G-code that differed
in a few moves and a print time that differed by 1-2 s from one run to the next
(measured: 5 slicings of one piece, 4 different files, 7630-7632 s). Pinned to one CPU
with the addresses fixed, and given the same arguments and environment whatever the
run folder (the piece is sliced in the slicer's private folder under its own name, with
only ``HOME``, ``LC_ALL`` and ``PATH`` set), the same STL gives the same G-code, byte for
byte but the date line (the memory layout also follows the length of the arguments and
environment: the same piece at another path gave 7631 s against 7633 s before).

A piece the slicer rejects is an error, not a warning: a non-zero exit, no G-code, no
estimate, or a print outside the bed (PrusaSlicer 2.5's command line slices an object
lying off the bed without complaint, so the G-code's moves and layers are checked
against the build volume) raises :class:`SliceError`.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from creative_py.mesh.spec import PLA_DENSITY
from creative_py.mesh.tolerances import FIT_MARGIN, MM_PER_M

if TYPE_CHECKING:
    from creative_py.mesh.printability import PrintSettings
# This module stays light (no numpy, no trimesh at import): the command line imports
# SliceError for its one-line errors.

PROFILE = Path(__file__).resolve().parent / "profiles" / "generic_pla_0.4.ini"
"""The PrusaSlicer profile of a generic 0.4 mm nozzle PLA printer (package data)."""

SLICER = "prusa-slicer"
"""The slicer's executable (Debian package ``prusa-slicer``, 2.5)."""

SLICE_TIMEOUT_S = 300.0
"""Longest one piece may take to slice, seconds."""

_TIME = re.compile(r"^; estimated printing time \(normal mode\) = (.+)$", re.M)
_FILAMENT = {unit: re.compile(rf"^; filament used \[{re.escape(unit)}\] = ([0-9.]+)$", re.M)
             for unit in ("mm", "cm3", "g")}
_DURATION = re.compile(r"(\d+)([dhms])")
_SECONDS = {"d": 86400, "h": 3600, "m": 60, "s": 1}
_CLOSING_CHARS = 200_000
_MOVE_XY = re.compile(r"^G[01] X(-?[0-9.]+) Y(-?[0-9.]+)", re.M)
_LAYER_Z = re.compile(r"^;Z:([0-9.]+)$", re.M)


class SliceError(RuntimeError):
    """The slicer rejected a piece (or is missing); the message names the piece."""


@dataclass(frozen=True)
class SliceResult:
    """One piece's G-code and the slicer's estimates.

    Attributes
    ----------
    gcode : pathlib.Path
        The G-code file.
    print_time_s : float
        Estimated printing time (normal mode), seconds.
    filament_mm, filament_cm3, filament_g : float
        Filament used: length (mm), volume (cm^3), mass (g).
    extrusion_bounds_mm : tuple of float
        Smallest and largest x and y of the nozzle's moves and z of the layers
        (x0, y0, z0, x1, y1, z1), mm.
    wall_time_s : float
        Wall time of the slicer's run, seconds.
    """

    gcode: Path
    print_time_s: float
    filament_mm: float
    filament_cm3: float
    filament_g: float
    extrusion_bounds_mm: tuple[float, float, float, float, float, float]
    wall_time_s: float

    def as_dict(self) -> dict:
        """Return the figures for a JSON file (the G-code by file name)."""
        return {"gcode": self.gcode.name, "print_time_s": self.print_time_s,
                "print_time": format_duration(self.print_time_s),
                "filament_mm": self.filament_mm, "filament_cm3": self.filament_cm3,
                "filament_g": self.filament_g,
                "extrusion_bounds_mm": list(self.extrusion_bounds_mm),
                "slice_wall_time_s": round(self.wall_time_s, 3)}


def require_slicer() -> str:
    """Return the slicer's path; raise :class:`SliceError` when it is not installed."""
    exe = shutil.which(SLICER)
    if exe is None:
        raise SliceError(f"the slicer {SLICER!r} is not installed, and every printed piece "
                         "is sliced (make setup installs it: apt-get install prusa-slicer)")
    return exe


def slice_piece(stl: Path | str, gcode: Path | str, settings: PrintSettings | None = None,
                profile: Path = PROFILE) -> SliceResult:
    """Slice one piece's STL (millimetres, in its print placement) to G-code.

    Parameters
    ----------
    stl : path
        The piece.
    gcode : path
        The G-code file to write.
    settings : PrintSettings or None
        The printer: its build volume becomes the slicer's bed and height, its nozzle
        the slicer's (default: ``PrintSettings()``).
    profile : path
        The PrusaSlicer profile (default :data:`PROFILE`).

    Raises
    ------
    SliceError
        The slicer is missing, exits non-zero, writes no G-code or no estimate, or
        prints outside the build volume.
    """
    stl, gcode = Path(stl), Path(gcode)
    settings = _settings(settings)
    exe = require_slicer()
    if not profile.is_file():
        raise SliceError(f"{profile}: slicer profile not found")
    with tempfile.TemporaryDirectory(prefix="creative-slicer-") as datadir:
        # A private data folder: the slicer reads and writes no user configuration. The
        # piece is sliced there under its own name, with a fixed environment: the
        # slicer's memory layout (and so its toolpath order, see the module) depends on
        # its arguments and environment, which then depend on the piece alone, not on
        # the run folder's path or the caller's variables.
        work = Path(datadir) / "piece"
        work.mkdir()
        try:
            shutil.copyfile(stl, work / stl.name)
        except OSError as exc:
            raise SliceError(f"{stl}: cannot be read ({exc.strerror or exc})") from None
        out = work / gcode.name
        cmd = _slicer_command(exe, datadir, profile, settings, out.name, stl.name)
        start = time.perf_counter()
        try:
            done = subprocess.run(cmd, capture_output=True, text=True,
                                  timeout=SLICE_TIMEOUT_S, cwd=work,
                                  env={"HOME": datadir, "LC_ALL": "C",
                                       "PATH": os.environ.get("PATH", os.defpath)},
                                  preexec_fn=_deterministic)
        except subprocess.TimeoutExpired:
            raise SliceError(f"{stl.name}: the slicer took longer than "
                             f"{SLICE_TIMEOUT_S:g} s") from None
        wall = time.perf_counter() - start
        if out.is_file():
            gcode.parent.mkdir(parents=True, exist_ok=True)
            shutil.move(str(out), str(gcode))
    if done.returncode != 0 or not gcode.is_file():
        message = " ".join((done.stderr or done.stdout).split()[-40:])
        raise SliceError(f"{stl.name}: the slicer rejected the piece (exit code "
                         f"{done.returncode}): {message or 'no G-code written'}")
    return _read_gcode(stl.name, gcode, settings, wall)


def _slicer_command(exe: str, datadir: str, profile: Path, settings: PrintSettings,
                    output: str, stl: str) -> list[str]:
    """Return the slicer's command line: its private ``datadir``, the ``profile``, the
    printer's bed, height and nozzle (mm) and PLA's density (g/cm^3), the piece ``stl``
    sliced where it lies to G-code ``output`` (names in the working folder)."""
    bx, by, bz = (v * MM_PER_M for v in settings.build_volume)
    nozzle = settings.nozzle_diameter * MM_PER_M
    return [exe, "--loglevel", "1", "--datadir", datadir, "--load", str(profile),
            "--bed-shape", f"0x0,{bx:g}x0,{bx:g}x{by:g},0x{by:g}",
            "--max-print-height", f"{bz:g}", "--nozzle-diameter", f"{nozzle:g}",
            "--filament-density", f"{PLA_DENSITY / 1000:g}",
            "--dont-arrange", "--export-gcode", "--output", output, stl]


_ADDR_NO_RANDOMIZE = 0x0040000
"""Linux's personality flag that turns address-space randomisation off (setarch -R)."""


def _deterministic() -> None:
    """In the slicer's process, before it starts: one CPU (the lowest this process may
    use) and no address-space randomisation, so that the same piece gives the same
    G-code and print time (see the module's docstring). Where the system has neither
    (not Linux), nothing changes."""
    if hasattr(os, "sched_setaffinity"):
        try:
            os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
        except OSError:
            pass
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        current = libc.personality(ctypes.c_ulong(0xFFFFFFFF))
        if current != -1:
            libc.personality(ctypes.c_ulong(current | _ADDR_NO_RANDOMIZE))
    except (OSError, AttributeError):
        pass


def read_gcode(gcode: Path | str, settings: PrintSettings | None = None, *,
               piece: str | None = None, wall_time_s: float = 0.0) -> SliceResult:
    """Return the estimates of a G-code file PrusaSlicer wrote, checked against the bed.

    Raises
    ------
    SliceError
        No print time or filament estimate, nothing extruded, or an extrusion outside
        ``settings.build_volume``.
    """
    gcode = Path(gcode)
    return _read_gcode(piece or gcode.name, gcode, _settings(settings), wall_time_s)


def _settings(settings: PrintSettings | None) -> PrintSettings:
    from creative_py.mesh.printability import PrintSettings

    return PrintSettings() if settings is None else settings


def _read_gcode(piece: str, gcode: Path, settings: PrintSettings, wall: float) -> SliceResult:
    text = gcode.read_text(encoding="utf-8", errors="replace")
    closing = text[-_CLOSING_CHARS:]  # the estimates and the settings close the file
    found = _TIME.search(closing)
    filament = {u: r.search(closing) for u, r in _FILAMENT.items()}
    if found is None or not all(filament.values()):
        raise SliceError(f"{piece}: {gcode.name} has no print time or filament estimate "
                         "(the slicer printed nothing?)")
    seconds = parse_duration(found.group(1))
    bounds = _extrusion_bounds(text)
    if bounds is None:
        raise SliceError(f"{piece}: {gcode.name} has no moves or layers")
    bed = [v * MM_PER_M for v in settings.build_volume]
    slack = FIT_MARGIN * MM_PER_M
    x0, y0, z0, x1, y1, z1 = bounds
    if x0 < -slack or y0 < -slack or x1 > bed[0] + slack or y1 > bed[1] + slack \
            or z1 > bed[2] + slack:
        raise SliceError(
            f"{piece}: the slicer prints outside the {bed[0]:g} x {bed[1]:g} x {bed[2]:g} "
            f"mm build volume (x {x0:.1f}..{x1:.1f}, y {y0:.1f}..{y1:.1f}, z up to "
            f"{z1:.1f} mm)")
    values = {u: float(m.group(1)) for u, m in filament.items()}
    return SliceResult(gcode, seconds, values["mm"], values["cm3"], values["g"],
                       bounds, wall)


def _extrusion_bounds(text: str) -> tuple[float, ...] | None:
    """Return the bounds of the print: x and y of every move in the plane (extrusions and
    travels: where the nozzle goes), z of every layer (``;Z:`` comments), mm."""
    import numpy as np

    xy = np.array(_MOVE_XY.findall(text), dtype=float).reshape(-1, 2)
    z = np.array(_LAYER_Z.findall(text), dtype=float)
    if not len(xy) or not len(z):
        return None
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    return (float(lo[0]), float(lo[1]), float(z.min()), float(hi[0]), float(hi[1]),
            float(z.max()))


def parse_duration(text: str) -> float:
    """Return the seconds of a PrusaSlicer duration such as ``"1d 2h 3m 4s"``.

    Raises
    ------
    ValueError
        The text holds no duration.
    """
    parts = _DURATION.findall(text)
    if not parts:
        raise ValueError(f"not a duration: {text!r}")
    return float(sum(int(n) * _SECONDS[u] for n, u in parts))


def format_duration(seconds: float) -> str:
    """Return seconds as ``"1h 02m 03s"``."""
    s = int(round(seconds))
    h, rest = divmod(s, 3600)
    m, s = divmod(rest, 60)
    return f"{h}h {m:02d}m {s:02d}s" if h else f"{m}m {s:02d}s"
