"""The options of a run (:class:`RunOptions`) and the ``run.json`` a resumed run reads
them from (:func:`read_run_json`)."""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict, dataclass, fields
from pathlib import Path
from typing import Any, Optional

from creative_py.learning.clips import VIDEO_MODES
from creative_py.learning.strategies import strategy_named


PHASES = ("use", "create", "all")


@dataclass(frozen=True)


class RunOptions:
    """Options of one run.

    Parameters
    ----------
    seed : int
        Seed of the physics and sensor noise.
    phase : {"use", "create", "all"}
        ``use``: demonstration and tool-use learning only; ``create`` and ``all``: then
        tool creation on the harder variant.
    max_trials : int or None
        N of Algorithm 1, at least 1 (default: the case manifest's ``trial_budget``).
    consecutive : int
        K of Algorithm 1: consecutive successes needed once nothing is left to test.
    eval_trials : int
        Evaluation trials of the learned model after tool-use learning (planner's own
        tool and pose choice), over the predefined locations.
    create_eval_trials : int
        Evaluation trials of a successful created tool (paper: 5).
    video : {"key", "all", "none"}
        Which trials are saved as MP4 clips in ``videos/``
        (:mod:`creative_py.learning.clips`): ``key`` the demonstration, the first
        success, every creation trial and the first trial of each failure reason;
        ``all`` every trial; ``none`` no clip.
    gui : bool
        Show the trials in pybullet's GUI (needs a display).
    strategy : str
        How tool-use learning chooses its experiments: a name of
        :data:`creative_py.learning.strategies.STRATEGIES` (``paper``, ``informative``,
        ``random``); another raises
        :class:`~creative_py.learning.strategies.UnknownStrategy`.
    world_seed : int or None
        None: the world as its files say; N: a world drawn from the case's manifest
        (:func:`creative_py.simulator.randomise.draw_world`: the catalogue's numbers inside their
        own qualitative ranges, its order shuffled, the locations jittered), the same
        for the same N.
    catalogue_first : bool or None
        Before manufacturing a tool for the harder task, try in the physics the
        catalogued objects the generalised model admits
        (:meth:`creative_py.learning.creation.ToolCreator._try_catalogue`); a tool is
        made only when none succeeds. None: on, except under the paper's strategy
        (whose Algorithm 2 makes a tool at once, as the parity fixtures record).
    demonstrate_creation : bool
        When a catalogued object solved the harder task, still create a tool afterwards
        as a demonstration of Algorithm 2 (``make hook`` does).
    prior : str or None
        Transfer: a run folder (or its ``model.pl``) of another case whose learned model
        the version space starts from, where the ontology maps its literals
        (:mod:`creative_py.learning.prior`); None: learn from the demonstration alone.
    backend : str or None
        A simulator backend (:data:`creative_py.backend_registry.BACKENDS`) instead of the one
        the case's manifest names (``--backend ros``: the arm over ROS 2); None: the
        manifest's.
    robot : str or None
        The robot profile (a name under ``robots/`` or a ``.toml`` path) the arm is
        built from; None: the case's robot (a new run records the one it used).
        The run's manifest carries it to the backend (``CaseManifest.robot``).
    """

    seed: int = 0
    phase: str = "all"
    max_trials: Optional[int] = None
    consecutive: int = 2
    eval_trials: int = 4
    create_eval_trials: int = 5
    video: str = "key"
    gui: bool = False
    strategy: str = "informative"
    world_seed: Optional[int] = None
    catalogue_first: Optional[bool] = None
    demonstrate_creation: bool = False
    prior: Optional[str] = None
    backend: Optional[str] = None
    robot: Optional[str] = None

    def recorded(self) -> dict[str, Any]:
        """The options by name as ``run.json`` and ``summary.json`` record them:
        ``prior``, ``backend`` and ``robot`` only when set (runs recorded before they
        existed write back the same)."""
        out = asdict(self)
        for name in ("prior", "backend", "robot"):
            if out[name] is None:
                del out[name]
        return out

    @property
    def tries_catalogue(self) -> bool:
        """Whether tool creation tries the catalogued objects first (``catalogue_first``,
        None meaning what the strategy says: on, except under the paper's)."""
        if self.catalogue_first is None:
            return strategy_named(self.strategy).catalogue_first
        return self.catalogue_first

    def __post_init__(self) -> None:
        checks = [("seed", self.seed, 0), ("max_trials", self.max_trials, 1),
                  ("consecutive", self.consecutive, 1), ("eval_trials", self.eval_trials, 0),
                  ("create_eval_trials", self.create_eval_trials, 0),
                  ("world_seed", self.world_seed, 0)]
        for name, value, least in checks:
            if value is None and name in ("max_trials", "world_seed"):
                continue
            if isinstance(value, bool) or not isinstance(value, int) or value < least:
                raise ValueError(f"option {name} must be a whole number >= {least}, "
                                 f"got {value!r}")
        if self.phase not in PHASES:
            raise ValueError(f"option phase must be one of {', '.join(PHASES)}, "
                             f"got {self.phase!r}")
        if self.video not in VIDEO_MODES:
            raise ValueError(f"option video must be one of {', '.join(VIDEO_MODES)}, "
                             f"got {self.video!r}")
        if not isinstance(self.gui, bool):
            raise ValueError(f"option gui must be true or false, got {self.gui!r}")
        if self.catalogue_first is not None and not isinstance(self.catalogue_first, bool):
            raise ValueError(f"option catalogue_first must be true, false or unset, got "
                             f"{self.catalogue_first!r}")
        if not isinstance(self.demonstrate_creation, bool):
            raise ValueError(f"option demonstrate_creation must be true or false, got "
                             f"{self.demonstrate_creation!r}")
        if self.prior is not None and (not isinstance(self.prior, str) or not self.prior):
            raise ValueError(f"option prior must be a path (a run folder or model.pl), "
                             f"got {self.prior!r}")
        for name in ("backend", "robot"):
            value = getattr(self, name)
            if value is not None and (not isinstance(value, str) or not value):
                raise ValueError(f"option {name} must be a name, got {value!r}")
        strategy_named(self.strategy)


RUN_JSON_KEYS = ("case", "options", "world", "drawn_world", "check")
"""The keys of a run folder's ``run.json`` (:func:`read_run_json`)."""


def run_json(case: str, options: RunOptions, world: Optional[Path],
             drawn: Optional[dict[str, Any]]) -> dict[str, Any]:
    """Return the ``run.json`` of a new run: its case, options, world folder and drawn
    world, and ``check``, the SHA-256 of those four (:func:`run_json_check`), by which a
    resume refuses a ``run.json`` edited after the run began."""
    meta = {"case": case, "options": options.recorded(),
            "world": str(world) if world else None, "drawn_world": drawn}
    return {**meta, "check": run_json_check(meta)}


def run_json_check(meta: dict[str, Any]) -> str:
    """Return the SHA-256 (hex) of a ``run.json``'s case, options, world and drawn world,
    as canonical JSON (sorted keys)."""
    body = {k: meta.get(k) for k in ("case", "options", "world", "drawn_world")}
    return hashlib.sha256(json.dumps(body, sort_keys=True).encode("utf-8")).hexdigest()


def read_run_json(run_dir: Path) -> tuple[str, RunOptions, Optional[Path],
                                          Optional[dict[str, Any]]]:
    """Return the case, options, world folder and drawn world of a run folder's
    ``run.json``, checked.

    A run recorded before there were strategies ran the paper's Algorithm 1, and one
    recorded before catalogued objects were tried first made a tool at once; other
    missing options take their defaults. A resumed run shows no GUI (the display it
    was started on may be gone). A ``run.json`` whose ``check`` is missing or does not
    match (:func:`run_json_check`) was edited after the run began and is refused, after
    its fields are checked.

    Raises
    ------
    ValueError
        One line naming ``run.json`` and the field: no ``run.json``, not JSON, not an
        object, a missing key, an unknown option or a bad option value, a
        ``drawn_world`` that is not an object, a ``check`` missing or not matching.
    """
    meta_path = Path(run_dir) / "run.json"
    if not meta_path.is_file():
        raise ValueError(f"{run_dir}: not a resumable run folder (no run.json)")
    meta = _run_json_object(meta_path)
    options = _recorded_options(meta_path, meta["options"])
    world = meta.get("world")
    if world is not None and not isinstance(world, str):
        raise ValueError(f"{meta_path}: field 'world' must be a folder or null, got "
                         f"{world!r}")
    drawn = meta.get("drawn_world")
    if drawn is not None and not isinstance(drawn, dict):
        raise ValueError(f"{meta_path}: field 'drawn_world' must be an object or null, "
                         f"got {type(drawn).__name__}")
    _check_unedited(meta_path, meta)
    return meta["case"], options, Path(world) if world else None, drawn


def _run_json_object(meta_path: Path) -> dict[str, Any]:
    """Return ``run.json`` read: a JSON object with its ``case`` (text) and ``options``;
    raise ValueError naming the file and what is wrong."""
    try:
        meta = json.loads(meta_path.read_text(encoding="utf-8"))
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise ValueError(f"{meta_path}: not JSON ({getattr(exc, 'msg', exc)})") from None
    if not isinstance(meta, dict):
        raise ValueError(f"{meta_path}: a JSON object with keys {', '.join(RUN_JSON_KEYS)} "
                         f"was expected, not a {type(meta).__name__}")
    for key in ("case", "options"):
        if key not in meta:
            raise ValueError(f"{meta_path}: field {key!r} is missing")
    if not isinstance(meta["case"], str):
        raise ValueError(f"{meta_path}: field 'case' must be text, got {meta['case']!r}")
    return meta


def _recorded_options(meta_path: Path, opts: Any) -> RunOptions:
    """Return the run's options from ``run.json``'s ``options`` (an older run's defaults
    where it has none; no GUI); raise ValueError naming the field that is wrong."""
    if not isinstance(opts, dict):
        raise ValueError(f"{meta_path}: field 'options' must be an object, got "
                         f"{type(opts).__name__}")
    if "robot_profile" in opts and "robot" not in opts:  # recorded before --robot
        opts = {("robot" if k == "robot_profile" else k): v for k, v in opts.items()}
    names = {f.name for f in fields(RunOptions)}
    unknown = sorted(set(opts) - names)
    if unknown:
        raise ValueError(f"{meta_path}: field 'options.{unknown[0]}' is not an option "
                         f"({', '.join(sorted(names))})")
    try:
        return RunOptions(**{"strategy": "paper", "catalogue_first": False,
                             **opts, "gui": False})
    except ValueError as exc:
        raise ValueError(f"{meta_path}: field 'options': {exc}") from None


def _check_unedited(meta_path: Path, meta: dict[str, Any]) -> None:
    """Raise ValueError unless ``run.json`` has its ``check`` and it matches the fields
    (:func:`run_json_check`): the file was not edited after the run began."""
    # Every run.json is written with its check (run_json), so a missing one was taken
    # out: without it an edited seed resumed and mixed two seeds' trials.
    if "check" not in meta:
        raise ValueError(f"{meta_path}: field 'check' is missing, so an edit of run.json "
                         "after the run began cannot be told; the run cannot be resumed "
                         "(start a new run)")
    if meta["check"] != run_json_check(meta):
        raise ValueError(f"{meta_path}: field 'check' does not match the case, options, "
                         "world and drawn world: run.json was changed after the run began; "
                         "the run cannot be resumed (start a new run for other options)")
