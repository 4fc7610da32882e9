"""Sweeps: many independent runs (cases x strategies x seeds x world seeds) on Ray.

``--prior`` gives every run a prior (transfer, ``creative run --prior``); ``{world}``
in it stands for the run's world seed, so each world's run starts from the prior
case's run of the same world.

``creative sweep hook wedge --strategies paper,informative --seeds 0-19 --world-seeds
0-19`` runs every combination as its own run (:func:`creative_py.learning.run.run_case`)
in its own run folder under the sweep's folder, as Ray tasks: a local Ray instance
using every core by default (``num_cpus``), or an existing Ray cluster (``address``).
Each Ray worker process runs its tasks one after another, with its one Prolog engine,
as ``serial`` does in this process (each run builds its world and version space from
nothing, and both give the same trials); ``fresh_workers`` gives every run a process
of its own instead (``max_calls=1``), which costs each run the start of Python,
pybullet and the engine, about 5 s. ``serial`` runs the same runs one after another in
this process, without Ray (the baseline of the speed-up).

The sweep writes, in its folder:

``sweep.csv``
    one row per run (:data:`COLUMNS`): case, strategy, seed, world seed, status
    (``ok`` or ``crashed``, with the error line), trials to learn, creation trials,
    evaluation successes of the learned model and of the created tool, h_g, wall time,
    the run folder.
``sweep.png``
    trials to learn per case and strategy (box and points), with the paper's counts
    (the manifest's ``paper_trials``) and the information bound
    (``info_bound_trials`` of the runs' summaries, when they have it) marked.
``sweep.json``
    the sweep's options and its wall time.

Progress: one line per finished run on stderr, with the runs done and left. A run
that crashes is recorded as such; the sweep goes on.
"""

from __future__ import annotations

import csv
import json
import math
import re
import signal
import statistics
import sys
import threading
import time
import traceback
from contextlib import contextmanager
from dataclasses import asdict, dataclass, field
from datetime import datetime, timezone
from pathlib import Path
from typing import Any, Callable, Iterator, Optional, Sequence

from creative_py.records.summary import Outcomes, RunSummary, UsePhase, as_summary

COLUMNS = ("case", "strategy", "seed", "world_seed", "status", "error", "trials_to_learn",
           "use_converged", "creation_trials", "creation_skipped_trial", "eval_successes",
           "eval_trials", "created_eval_successes", "created_eval_trials", "hg",
           "vs_count_initial", "info_bound_trials", "wall_time_s", "run_dir")
"""The columns of ``sweep.csv``, in order."""


@dataclass(frozen=True)
class RunSpec:
    """One run of a sweep."""

    case: str
    strategy: str
    seed: int
    world_seed: Optional[int]

    @property
    def name(self) -> str:
        """Return the run folder's name."""
        w = "files" if self.world_seed is None else f"w{self.world_seed}"
        return f"{self.case}-{self.strategy}-s{self.seed}-{w}"


@dataclass(frozen=True)
class SweepOptions:
    """The run options every run of a sweep shares (see
    :class:`creative_py.learning.options.RunOptions`); a sweep saves no video clip unless
    ``video`` says so."""

    phase: str = "all"
    max_trials: Optional[int] = None
    consecutive: int = 2
    eval_trials: int = 4
    create_eval_trials: int = 5
    video: str = "none"
    robot: Optional[str] = None
    """``--robot`` of every run (a robot profile); None: each case's robot."""
    prior: Optional[str] = None
    """``--prior`` of every run (transfer): a run folder or ``model.pl``, in which
    ``{world}`` and ``{seed}`` stand for the run's world seed and seed (each world its
    own prior: ``runs/hook-informative-s0-w{world}``); None: no prior."""


def prior_for(spec: "RunSpec", prior: Optional[str]) -> Optional[str]:
    """Return the ``--prior`` of run ``spec``: ``prior`` with ``{world}`` and
    ``{seed}`` replaced by its world seed and seed (``{world}`` of a run on the world
    files is ``files``)."""
    if prior is None:
        return None
    world = "files" if spec.world_seed is None else str(spec.world_seed)
    return prior.replace("{world}", world).replace("{seed}", str(spec.seed))


NUMBERS_MAX = 10000
"""The most numbers ``--seeds`` or ``--world-seeds`` may give (each is a run or more)."""

RUNS_MAX = 10000
"""The most runs one sweep may plan (cases x strategies x seeds x world seeds)."""

NUMBER_MAX = 2 ** 63 - 1
"""The largest seed or world seed: a 64-bit signed integer (as ``creative run --seed``)."""


def parse_ints(text: str, option: str, most: int = NUMBERS_MAX) -> list[int]:
    """Parse ``"0-19"``, ``"3"`` or ``"0,2,5-7"`` into whole numbers >= 0.

    The count of numbers is bounded by ``most`` before any list is built (a range
    ``0-1000000000`` is refused at once, not allocated), and each number by
    :data:`NUMBER_MAX`.

    Raises
    ------
    ValueError
        Naming ``option`` and the cause (``--seeds 5-2: the range 5-2 is empty``).
    """
    bounds: list[tuple[int, int]] = []
    count = 0
    for part in str(text).split(","):
        part = part.strip()
        m = re.fullmatch(r"(\d{1,19})(?:-(\d{1,19}))?", part)
        if not m:
            if re.fullmatch(r"\d+(?:-\d+)?", part):
                raise ValueError(f"{option}: {part[:40]}: a number is larger than "
                                 f"{NUMBER_MAX}")
            raise ValueError(f"{option} {text}: {part!r} is not a whole number >= 0 or "
                             f"a range A-B")
        a = int(m.group(1))
        b = int(m.group(2)) if m.group(2) is not None else a
        if max(a, b) > NUMBER_MAX:
            raise ValueError(f"{option} {text}: {max(a, b)} is larger than {NUMBER_MAX}")
        if b < a:
            raise ValueError(f"{option} {text}: the range {part} is empty (end before start)")
        count += b - a + 1
        bounds.append((a, b))
    if count > most:
        raise ValueError(f"{option} {text}: {count} numbers, at most {most} in one sweep")
    out = [n for a, b in bounds for n in range(a, b + 1)]
    if len(set(out)) != len(out):
        raise ValueError(f"{option} {text}: a number is given twice")
    return out


def parse_strategies(text: str) -> list[str]:
    """Parse ``"paper,informative"``; raise ValueError naming an unknown strategy."""
    from creative_py.learning.strategies import UnknownStrategy, strategy_named

    names = [s.strip() for s in str(text).split(",") if s.strip()]
    if not names:
        raise ValueError("--strategies: no strategy given")
    for s in names:
        try:
            strategy_named(s)
        except UnknownStrategy as exc:
            raise ValueError(f"--strategies: {exc}") from None
    if len(set(names)) != len(names):
        raise ValueError(f"--strategies {text}: a strategy is given twice")
    return names


def plan_runs(cases: Sequence[str], strategies: Sequence[str], seeds: Sequence[int],
              world_seeds: Sequence[Optional[int]]) -> list[RunSpec]:
    """Return every combination, case-major; raise ValueError for an unknown case or
    one given twice (as :func:`parse_ints` and :func:`parse_strategies` refuse a
    number or a strategy given twice)."""
    from creative_py.case import get_case

    if not cases:
        raise ValueError("sweep: no case given")
    twice = next((c for i, c in enumerate(cases) if c in cases[:i]), None)
    if twice is not None:  # every run of it would run twice, in the same folder name
        raise ValueError(f"sweep: case {twice!r} is given twice")
    total = len(cases) * len(strategies) * len(seeds) * len(world_seeds)
    if total > RUNS_MAX:
        raise ValueError(f"sweep: {len(cases)} case(s) x {len(strategies)} strateg"
                         f"{'y' if len(strategies) == 1 else 'ies'} x {len(seeds)} seed(s) x "
                         f"{len(world_seeds)} world seed(s) are {total} runs, at most "
                         f"{RUNS_MAX} in one sweep")
    for c in cases:
        try:
            get_case(c)
        except KeyError as exc:
            raise ValueError(str(exc).strip("'\"")) from None
    return [RunSpec(c, s, seed, w) for c in cases for s in strategies for w in world_seeds
            for seed in seeds]


def run_one(spec: RunSpec, runs_dir: str, options: SweepOptions) -> dict[str, Any]:
    """Run one run of a sweep in this process and return its row of ``sweep.csv``.

    Never raises: a run that fails is a row with status ``crashed`` and the error's
    last line.
    """
    from creative_py.learning.options import RunOptions
    from creative_py.learning.run import run_case

    t0 = time.perf_counter()
    row: dict[str, Any] = {k: "" for k in COLUMNS}
    row.update(case=spec.case, strategy=spec.strategy, seed=spec.seed,
               world_seed="" if spec.world_seed is None else spec.world_seed)
    try:
        fields = asdict(options)
        fields["prior"] = prior_for(spec, options.prior)
        opts = RunOptions(seed=spec.seed, strategy=spec.strategy, world_seed=spec.world_seed,
                          **fields)
        folder = run_case(spec.case, Path(runs_dir), opts, run_name=spec.name)
        summary = RunSummary.read(folder.path)
        row.update(status="ok", run_dir=str(folder.path), **summary_row(summary))
    except BaseException as exc:  # noqa: BLE001 - a crashed run is a row, not the end
        if isinstance(exc, (KeyboardInterrupt, _Signalled)):
            raise
        lines = [ln for ln in traceback.format_exception_only(type(exc), exc)
                 if ln.strip()]
        row.update(status="crashed", error=" ".join(lines[-1].split()) if lines else repr(exc))
    row["wall_time_s"] = round(time.perf_counter() - t0, 2)
    return row


def summary_row(summary: "RunSummary | dict[str, Any]") -> dict[str, Any]:
    """Return the ``sweep.csv`` figures of one run's summary (a dict is read as
    ``summary.json``); a figure the summary lacks is empty."""
    s = as_summary(summary)
    use = s.use or UsePhase()
    ev = s.eval or Outcomes()
    create = s.create if s.create is not None and s.create.to_dict() else None
    created_eval = create.eval if create is not None else []
    return {
        "trials_to_learn": _cell(use.trials),
        "use_converged": _cell(use.converged),
        "creation_trials": _cell(create.trials if create else None),
        "creation_skipped_trial": _cell(create.predicted_failure_skipped if create
                                        else None),
        "eval_successes": _cell(ev.successes),
        "eval_trials": _cell(ev.trials),
        "created_eval_successes": (sum(o == "success" for o in created_eval)
                                   if create else ""),
        "created_eval_trials": len(created_eval) if create else "",
        "hg": _cell(s.hypotheses.hg if s.hypotheses else None),
        "vs_count_initial": _cell(s.vs_count_initial),
        "info_bound_trials": _cell(s.info_bound_trials),
    }


def _cell(value: Any) -> Any:
    """A figure of ``sweep.csv``: empty for one the summary lacks."""
    return "" if value is None else value


STOP_EXIT_CODES = {signal.SIGINT: 130, signal.SIGTERM: 143}
"""The exit code of ``creative sweep`` stopped by a signal (128 + its number)."""


class SweepStopped(Exception):
    """A sweep stopped by SIGTERM or SIGINT (Ctrl-C): the runs finished so far are
    in the folder's ``sweep.csv``; Ray (when used) has been shut down."""

    def __init__(self, signum: int, folder: Path, done: int, total: int) -> None:
        name = signal.Signals(signum).name
        super().__init__(f"sweep stopped by {name} after {done} of {total} runs; the "
                         f"finished ones are in {folder / 'sweep.csv'}")
        self.signum, self.folder, self.done, self.total = signum, folder, done, total

    @property
    def exit_code(self) -> int:
        """Return the command's exit code (:data:`STOP_EXIT_CODES`)."""
        return STOP_EXIT_CODES.get(self.signum, 128 + self.signum)


class _Signalled(BaseException):
    """Raised by the sweep's SIGTERM handler (a BaseException, as KeyboardInterrupt:
    no run's ``except Exception`` takes it for a crash)."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


@contextmanager
def _stop_on_sigterm(raise_at_once: bool = True) -> Iterator[None]:
    """Stop the sweep on SIGTERM (on the main thread), replacing the handler
    ``ray.init`` installs (``sys.exit`` from a signal handler, and Ray's C++ handler
    printing a stack dump); restore the previous handler after.

    The signal is kept (:func:`_check_stop` raises :class:`_Signalled` after each run
    and, on Ray, every second); with ``raise_at_once`` (a serial sweep, whose run may
    take minutes) the handler also raises it at once. Not under Ray: an exception raised
    inside ``ray.wait``'s C code becomes a SystemError."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum: int, _frame: Any) -> None:
        _STOP["signum"] = signum   # kept: the exception may land where it is swallowed
        if raise_at_once:
            raise _Signalled(signum)

    _STOP.clear()
    previous = signal.signal(signal.SIGTERM, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


_STOP: dict[str, int] = {}
"""The signal that stopped the sweep, if one did (:func:`_stop_on_sigterm`)."""


def _check_stop() -> None:
    """Raise :class:`_Signalled` if a SIGTERM came (an import or a library that caught
    the handler's exception must not let the sweep go on)."""
    if "signum" in _STOP:
        raise _Signalled(_STOP["signum"])


@dataclass
class SweepResult:
    """What a sweep did: its folder, rows and wall time."""

    folder: Path
    rows: list[dict[str, Any]] = field(default_factory=list)
    wall_time_s: float = 0.0


RAY_CONNECT_TIMEOUT_S = 5.0
"""How long ``--address`` may take to accept a connection before the sweep is refused."""


def check_ray_address(address: str, timeout_s: float = RAY_CONNECT_TIMEOUT_S) -> None:
    """Raise ValueError unless something accepts a connection at ``address`` in time.

    ``address`` is Ray's ``host:port`` or ``ray://host:port``; ``auto`` (a cluster on
    this machine, which Ray finds itself) is not probed. Without the probe,
    ``ray.init`` waits for an address where nothing listens without end.
    """
    import socket

    if address == "auto":
        return
    host, sep, port = address.split("://", 1)[-1].rpartition(":")
    if not sep or not host or not port.isdigit() or not 0 < int(port) < 65536:
        raise ValueError(f"--address must be host:port or ray://host:port, got {address!r}")
    try:
        socket.create_connection((host, int(port)), timeout=timeout_s).close()
    except OSError as exc:
        why = "timed out" if isinstance(exc, TimeoutError) else (exc.strerror or str(exc))
        raise ValueError(f"--address {address}: no Ray cluster answers there "
                         f"({why} within {timeout_s:g} s)") from None


def run_sweep(runs: Sequence[RunSpec], out: Path, options: SweepOptions = SweepOptions(),
              address: Optional[str] = None, num_cpus: Optional[int] = None,
              serial: bool = False, progress: Optional[Callable[[str], None]] = None,
              name: Optional[str] = None, fresh_workers: bool = False) -> SweepResult:
    """Run every run of ``runs`` and write ``sweep.csv``, ``sweep.png``, ``sweep.json``.

    Parameters
    ----------
    runs : sequence of RunSpec
        From :func:`plan_runs`.
    out : Path
        The parent of the sweep's folder ``sweep-<UTC time>`` (or ``name``).
    address : str or None
        An existing Ray cluster (``ray.init(address=...)``); None starts a local one.
    num_cpus : int or None
        Cores of the local Ray instance (default: every core).
    serial : bool
        Run them one after another in this process, without Ray.
    fresh_workers : bool
        A fresh Ray worker process for every run (default: a worker runs several).
    progress : callable or None
        Receives one line per finished run.
    """
    say = progress or (lambda m: print(m, file=sys.stderr, flush=True))
    folder = new_sweep_folder(Path(out), name)
    runs_dir = folder / "runs"
    runs_dir.mkdir()
    result = SweepResult(folder)
    t0 = time.perf_counter()
    total = len(runs)

    def finished(row: dict[str, Any]) -> None:
        result.rows.append(row)
        say(_progress_line(row, len(result.rows), total))
        _write_csv(folder / "sweep.csv", result.rows)

    try:
        with _stop_on_sigterm(raise_at_once=serial):
            if serial:
                for spec in runs:
                    finished(run_one(spec, str(runs_dir), options))
                    _check_stop()
            else:
                _run_on_ray(runs, runs_dir, options, address, num_cpus, fresh_workers,
                            finished)
    except (_Signalled, KeyboardInterrupt) as exc:
        signum = exc.signum if isinstance(exc, _Signalled) else signal.SIGINT
        _write_csv(folder / "sweep.csv", result.rows)
        raise SweepStopped(signum, folder, len(result.rows), total) from None
    result.wall_time_s = round(time.perf_counter() - t0, 2)
    ray = None if serial else {"address": address, "num_cpus": num_cpus,
                               "fresh_workers": fresh_workers}
    _write_outputs(result, runs, options, ray, serial)
    return result


def _progress_line(row: dict[str, Any], done: int, total: int) -> str:
    """Return the line that says run ``row`` finished, the ``done``-th of ``total``."""
    what = (f"{row['trials_to_learn']} tool-use trials, {row['creation_trials'] or '-'} "
            f"creation trials" if row["status"] == "ok" else row["error"])
    return (f"[{done}/{total}, {total - done} left] {row['case']} {row['strategy']} "
            f"seed {row['seed']} world {'-' if row['world_seed'] == '' else row['world_seed']}: "
            f"{row['status']}, {what}, "
            f"{row['wall_time_s']} s")


def _write_outputs(result: SweepResult, runs: Sequence[RunSpec], options: SweepOptions,
                   ray: Optional[dict[str, Any]], serial: bool) -> None:
    """Write a finished sweep's ``sweep.csv`` (rows in the planned order), ``sweep.png``
    and ``sweep.json`` into its folder."""
    folder = result.folder
    _sort_as_planned(result.rows, runs)
    _write_csv(folder / "sweep.csv", result.rows)
    plot_sweep(result.rows, folder / "sweep.png")
    _write_sweep_json(folder / "sweep.json", runs, options, ray, serial, result)


def _sort_as_planned(rows: list[dict[str, Any]], runs: Sequence[RunSpec]) -> None:
    """Sort the rows of finished runs (in the order they finished) as ``runs`` plans them."""
    order = {spec: i for i, spec in enumerate(runs)}
    rows.sort(key=lambda r: order.get(RunSpec(
        r["case"], r["strategy"], int(r["seed"]),
        None if r["world_seed"] == "" else int(r["world_seed"])), 0))


def _write_sweep_json(path: Path, runs: Sequence[RunSpec], options: SweepOptions,
                      ray: Optional[dict[str, Any]], serial: bool, result: SweepResult) -> None:
    """Write ``sweep.json``: the planned runs, the options, how they ran (Ray's settings,
    or serial), the wall time (s) and the counts of runs that ended and that crashed."""
    path.write_text(json.dumps({
        "runs": [asdict(r) for r in runs], "options": asdict(options),
        "ray": ray, "serial": serial, "wall_time_s": result.wall_time_s,
        "ok": sum(r["status"] == "ok" for r in result.rows),
        "crashed": sum(r["status"] != "ok" for r in result.rows)}, indent=1) + "\n")


RAY_START_ATTEMPTS = 3
"""How often a local Ray instance is started before the sweep gives up: on a loaded
machine its raylet may miss the 30 s Ray allows it to register (``The current node
timed out during startup``), and a second start usually succeeds."""


def start_ray(init: dict[str, Any], local: bool = True,
              attempts: int = RAY_START_ATTEMPTS,
              say: Callable[[str], None] = lambda m: print(m, file=sys.stderr, flush=True)
              ) -> None:
    """``ray.init(**init)``; a local instance (``local``) that times out during its
    startup is shut down and started again, up to ``attempts`` times in all, saying so
    in one line each time. Any other error, and the last timeout, are raised."""
    import ray

    for attempt in range(1, attempts + 1):
        try:
            ray.init(**init)
            return
        except Exception as exc:  # noqa: BLE001 - Ray raises a bare Exception here
            if not local or attempt == attempts or "timed out during startup" not in str(exc):
                raise
            ray.shutdown()
            say(f"warning: the local Ray instance timed out during startup (attempt "
                f"{attempt} of {attempts}); starting it again")


def _run_on_ray(runs: Sequence[RunSpec], runs_dir: Path, options: SweepOptions,
                address: Optional[str], num_cpus: Optional[int], fresh_workers: bool,
                finished: Callable[[dict[str, Any]], None]) -> None:
    """Run ``runs`` as Ray tasks, calling ``finished`` with each row as it comes; Ray
    is shut down however this ends. SIGTERM keeps the sweep's handler
    (:func:`_stop_on_sigterm`), which ``ray.init`` would replace."""
    import ray

    init: dict[str, Any] = {"log_to_driver": False, "include_dashboard": False}
    if address:
        init["address"] = address
    elif num_cpus is not None:
        init["num_cpus"] = num_cpus
    ours = signal.getsignal(signal.SIGTERM)
    try:
        start_ray(init, local=not address)
    except SystemExit as exc:  # SIGTERM while ray.init's own handler was in place
        if exc.code == signal.SIGTERM:
            raise _Signalled(signal.SIGTERM) from None
        raise
    finally:
        signal.signal(signal.SIGTERM, ours)
    try:
        remote = ray.remote(num_cpus=1, max_calls=1 if fresh_workers else 0)(run_one)
        pending = {remote.remote(spec, str(runs_dir), options): spec for spec in runs}
        while pending:
            _check_stop()
            ready, _ = ray.wait(list(pending), num_returns=1, timeout=1.0)
            for ref in ready:
                spec = pending.pop(ref)
                try:
                    row = ray.get(ref)
                except Exception as exc:  # noqa: BLE001 - the worker itself died
                    row = {k: "" for k in COLUMNS}
                    row.update(case=spec.case, strategy=spec.strategy, seed=spec.seed,
                               world_seed="" if spec.world_seed is None
                               else spec.world_seed, status="crashed",
                               error=" ".join(str(exc).split())[:300])
                finished(row)
    finally:
        ray.shutdown()


def new_sweep_folder(out: Path, name: Optional[str] = None) -> Path:
    """Create and return the sweep's folder ``<out>/<name>`` (default
    ``sweep-<UTC time>``). Without ``name``, a sweep started in the same second as
    another gets ``sweep-<UTC time>-2`` (``-3``, ...): ``mkdir`` is the atomic test, so
    two sweeps never share a folder. A given ``name`` that exists is an error
    (FileExistsError)."""
    out.mkdir(parents=True, exist_ok=True)
    if name is not None:
        folder = out / name
        folder.mkdir()
        return folder
    base = f"sweep-{datetime.now(timezone.utc).strftime('%Y%m%d-%H%M%S')}"
    folder, n = out / base, 1
    while True:
        try:
            folder.mkdir()
            return folder
        except FileExistsError:
            n += 1
            folder = out / f"{base}-{n}"


def _write_csv(path: Path, rows: Sequence[dict[str, Any]]) -> None:
    tmp = path.with_suffix(".csv.tmp")
    with tmp.open("w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(COLUMNS))
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in COLUMNS})
    tmp.replace(path)


def read_csv(path: Path) -> list[dict[str, str]]:
    """Return the rows of a ``sweep.csv``."""
    with Path(path).open(newline="") as fh:
        return list(csv.DictReader(fh))


def plot_sweep(rows: Sequence[dict[str, Any]], path: Path) -> Path:
    """Draw trials to learn per case and strategy (box and points) to ``path``.

    Under each group its learned models' evaluation successes (``model 78/80``). A
    solid red mark is the paper's count of the case (the manifest's
    ``paper_trials``), a dashed green one the information bound ceil(log2 N0)
    (median of the runs' ``info_bound_trials``), where known; crashed runs are
    counted under each group's label.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    cases = list(dict.fromkeys(r["case"] for r in rows))
    strategies = list(dict.fromkeys(r["strategy"] for r in rows))
    fig, ax = plt.subplots(figsize=(max(5.0, 1.1 * len(cases) * len(strategies) + 2), 4.2))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    positions, labels, data = [], [], []
    x = 0.0
    marked = {"paper": False, "bound": False}
    for ci, case in enumerate(cases):
        start = x
        for si, strategy in enumerate(strategies):
            group = [r for r in rows if r["case"] == case and r["strategy"] == strategy]
            label, ok = _sweep_group(case, strategy, group)
            positions.append(x)
            labels.append(label)
            data.append(ok)
            if ok:
                jitter = [x + 0.12 * math.sin(7.3 * i) for i in range(len(ok))]
                ax.scatter(jitter, ok, s=14, color=colours[si % len(colours)], alpha=0.8,
                           zorder=5)
            x += 1.0
        _mark_case(ax, case, rows, start, x - 1.0, marked)
        x += 0.6 if ci < len(cases) - 1 else 0.0
    nonempty = [(p, d) for p, d in zip(positions, data) if d]
    if nonempty:
        ax.boxplot([d for _, d in nonempty], positions=[p for p, _ in nonempty], widths=0.5,
                   showfliers=False, zorder=2)
    ax.set_xticks(positions)
    ax.set_xticklabels(labels, fontsize=8)
    ax.set_ylabel("tool-use trials to learn")
    ax.set_ylim(0, _highest_mark(rows, data, cases) * 1.15 + 1)
    n = len(rows)
    worlds = len({r["world_seed"] for r in rows})
    ax.set_title(f"CREATIVE-py sweep: {n} run{'s' if n != 1 else ''} over {worlds} "
                 f"world{'s' if worlds != 1 else ''}", fontsize=10)
    if not marked["bound"]:
        ax.plot([], [], " ", label="log2 bound: not in these runs' summaries")
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.18), ncol=2,
              frameon=False)
    ax.grid(axis="y", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return Path(path)


def _sweep_group(case: str, strategy: str,
                 group: Sequence[dict[str, Any]]) -> tuple[str, list[float]]:
    """Return the label of one case and strategy's runs (with its learned models'
    evaluation and its crashed runs) and the trials to learn of its runs that ended."""
    ok = [float(r["trials_to_learn"]) for r in group
          if r["status"] == "ok" and r["trials_to_learn"] not in ("", None)]
    crashed = len(group) - len(ok)
    ev = [(int(r["eval_successes"]), int(r["eval_trials"])) for r in group
          if r["status"] == "ok" and str(r.get("eval_trials", "")) not in ("", "0")]
    model = (f"\nmodel {sum(a for a, _ in ev)}/{sum(b for _, b in ev)}" if ev else "")
    return (f"{case}\n{strategy}{model}" + (f"\n({crashed} crashed)" if crashed else ""),
            ok)


def _mark_case(ax, case: str, rows: Sequence[dict[str, Any]], start: float, end: float,
               marked: dict[str, bool]) -> None:
    """Draw over the groups of ``case`` (x from ``start`` to ``end``) the paper's count
    and the median information bound, where known; label each kind of mark once
    (``marked`` says which are labelled already)."""
    from creative_py.case import get_case

    try:
        paper = get_case(case).paper_trials
    except KeyError:
        paper = None
    if paper is not None:
        ax.hlines(paper, start - 0.4, end + 0.4, colors="tab:red", linewidth=2,
                  label=None if marked["paper"] else "paper's count", zorder=4)
        marked["paper"] = True
    bounds = [float(r["info_bound_trials"]) for r in rows
              if r["case"] == case and r.get("info_bound_trials") not in ("", None)]
    if bounds:
        ax.hlines(statistics.median(bounds), start - 0.4, end + 0.4, colors="tab:green",
                  linestyles="dashed", linewidth=2,
                  label=None if marked["bound"] else "ceil(log2 N0) bound", zorder=4)
        marked["bound"] = True


def _highest_mark(rows: Sequence[dict[str, Any]], data: list[list[float]],
                  cases: list[str]) -> float:
    """Return the highest number the plot shows (at least 1): a run's trials, a bound,
    a paper's count."""
    from creative_py.case import get_case

    tops = [v for d in data for v in d] + [1.0]
    tops += [float(r["info_bound_trials"]) for r in rows
             if r.get("info_bound_trials") not in ("", None)]
    for case in cases:
        try:
            tops.append(float(get_case(case).paper_trials or 0))
        except KeyError:
            pass
    return max(tops)
