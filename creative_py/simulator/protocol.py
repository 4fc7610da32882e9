"""What the learning loop needs of a simulator: the :class:`Backend`, its :class:`World`
and its :class:`Episode`, as :class:`typing.Protocol` classes.

The protocols hold exactly what ``creative_py/learning/`` (and the command line's
``creative trial``) use of a simulator, no more. What is not a simulator's is not
here: an object's catalogue facts are its tool kind's
(:meth:`creative_py.kinds.parts.KindSpec.catalogue_facts`), the same whatever the
physics, and every backend's episode must report exactly those.

A backend is a module (or any object) with the :class:`Backend` functions; its worlds
and episodes have the attributes and methods of :class:`World` and :class:`Episode`.
The pybullet backend (:mod:`creative_py.backends.pybullet`) is the reference: its behaviour is what
each docstring says.

Units, as everywhere in the project: metres, radians (degrees only where a name says
``_deg``), seconds, newtons, kilograms; the world frame has z up, the target's
locations are numbered from 1.
"""

from __future__ import annotations

from pathlib import Path
from typing import (TYPE_CHECKING, Any, Callable, ContextManager, Mapping, Optional,
                    Protocol, Sequence, Sized)

from creative_py.simulator.types import Observation, PoseTarget, SkillOutcome, TrialResult

if TYPE_CHECKING:
    from creative_py.case import CaseManifest

VerdictCallback = Callable[[str, str, Optional[dict]], None]
"""``verdict(outcome, reason, measured)``: what :meth:`Backend.run_trial` calls once
the physics has given the outcome, still inside the episode (``measured`` is the
result's ``verdict`` data)."""


class ClipCamera(Protocol):
    """The camera of a world's video clips (pybullet: :class:`creative_py.backends.pybullet.recorder.
    VideoSpec`); the learning loop reads only its frame rate."""

    @property
    def fps(self) -> float:
        """Frames per second of simulated time (> 0)."""


class ClipRecorder(Protocol):
    """Keeps one trial's poses for a clip while the trial runs; renders them after the
    verdict (pybullet: :class:`creative_py.backends.pybullet.recorder.Recorder`).

    Recording only reads the physics: a trial with a recorder has the outcome it has
    without one. The episode it is given to (``record=``) feeds it.
    """

    @property
    def snapshots(self) -> Sized:
        """The snapshots kept so far (one per frame of the clip)."""

    def render_then(self, use: Callable[[list, list[float]], None], background: bool = True,
                    nice: int = 0) -> Optional[int]:
        """Render the frames (RGB ``uint8`` arrays, H x W x 3) and call ``use(frames,
        times)`` with them and their simulated times (s).

        With ``background`` (where the system can fork) do it in a child process,
        scheduled ``nice`` lower, and return the child's pid (it exits 0 once ``use``
        returned, 1 if anything raised); otherwise do it here and return None. Called
        inside the trial's episode, after the verdict.
        """


class CatalogueEntry(Protocol):
    """One available object of a :class:`World` (a catalogued or a created tool)."""

    @property
    def spec(self) -> Any:
        """The object's tool-kind spec (:class:`creative_py.kinds.parts.KindSpec`)."""

    @property
    def outside_ranges(self) -> bool:
        """Whether its ``objects.toml`` table says some number lies outside every
        qualitative range of the ontology on purpose."""


class World(Protocol):
    """A case's world as a backend loaded it: the manifest, the available objects, the
    target's locations; immutable (the ``with_`` methods return a new world).
    """

    @property
    def manifest(self) -> CaseManifest:
        """The case (roles, skills, pose parameters, variants, demonstration)."""

    @property
    def catalogue(self) -> Mapping[str, Any]:
        """``name -> spec`` of every available object, in the catalogue's order."""

    @property
    def items(self) -> Mapping[str, CatalogueEntry]:
        """``name -> entry`` of every available object (same names and order as
        :attr:`catalogue`)."""

    @property
    def locations(self) -> tuple[int, ...]:
        """The 1-based indices of the target's predefined locations, in order."""

    @property
    def variation(self) -> str:
        """Empty for the world as its files say; ``world seed N`` for a drawn one
        (:meth:`Backend.apply_drawn`). Part of every cache key that depends on the
        world's numbers."""

    @property
    def video(self) -> Optional[ClipCamera]:
        """The camera of the trial clips, or None when the world has none (no clip is
        then recorded)."""

    def with_tool(self, spec: Any, urdf: Optional[Path] = None) -> "World":
        """Return this world with one more available object, a created tool: its
        catalogue facts, grasp and skills from ``spec`` (its kind), its body from
        ``urdf`` (link frame = tool frame, written by :mod:`creative_py.mesh`) when
        given, else from the spec's parts; the friction of the catalogue's first
        object (the same printed material). Raise FileNotFoundError for a missing
        ``urdf``."""

    def with_spec(self, name: str, spec: Any) -> "World":
        """Return this world with the available object ``name`` given the spec ``spec``
        (a drawn one: same kind and name, other numbers), its place in the catalogue,
        its table's scene values and its friction kept."""

    def listing(self) -> dict[str, Any]:
        """Return JSON-ready data (``creative trial --list``): ``case``, ``objects``
        (spec fields, ``set``, ``friction``), ``locations``, ``variants``,
        ``default_pose``, ``demonstration``."""


class Episode(Protocol):
    """One scene of a case (a variant, a target location, a tool), driven skill by
    skill by the names of the manifest's ``[[skill]]`` tables."""

    def run_skill(self, name: str, pose: Optional[Sequence[float]] = None) -> SkillOutcome:
        """Run the manifest's skill ``name`` (the primitive it binds, with its options)
        and return how it ended: ``ok``, ``blocked`` (a guard stopped a motion),
        ``unreachable`` (no arm posture) or ``invalid`` (a physics blow-up, or a skill
        that cannot run in this state).

        The pose skill (``pose = true``) needs ``pose``, the numbers of the manifest's
        ``[[pose.param]]`` in their order and units; its world target comes from the
        episode's ``pose_target`` (:data:`creative_py.simulator.types.PoseTarget`)
        applied to what the robot perceives at that moment. Raise KeyError for a skill
        the manifest does not have, ValueError for a pose skill without ``pose`` or
        without a ``pose_target``.
        """

    def observe(self, cameras: bool = True) -> Observation:
        """Return what the robot perceives now: primitive facts (``pose``, sizes,
        proprioception of a held tool, the scene's fixed facts and the catalogue of
        every available object; world frame, metres, radians), the camera frames behind
        them and the ground truth (for error reports only). Without ``cameras`` the
        tracked objects' facts come from the ground truth."""

    def goal_reached(self) -> bool:
        """Return whether the world's success oracle judges the goal reached in the
        simulated state now (the physics is the oracle)."""


class Backend(Protocol):
    """A simulator backend: what the learning loop calls to build and run a case's
    world (module-level functions; :mod:`creative_py.backends.pybullet` is the pybullet one)."""

    def load_world(self, manifest: CaseManifest) -> World:
        """Read the manifest's world folder and return its :class:`World`, every value
        of every variant and location checked; raise
        :class:`creative_py.world_files.WorldFileError` naming the file and the field."""

    def open_episode(self, world: World, variant: str, location: int, tool: str,
                     seed: int = 0, gui: bool = False, images_dir: Optional[Path] = None,
                     pose_target: Optional[PoseTarget] = None, *, robot: bool = True,
                     record: Optional[ClipRecorder] = None) -> ContextManager[Episode]:
        """Return a context manager that builds the scene and yields an
        :class:`Episode`, and releases the simulator on exit.

        Parameters
        ----------
        world : World
            From :meth:`load_world` (or its ``with_`` and drawn variations).
        variant : str
            A variant of the manifest (its ``set`` values change the scene); KeyError
            listing the variants otherwise.
        location : int
            1-based index of the target's location (``world.locations``).
        tool : str
            The available object used as the tool; KeyError listing them otherwise.
        seed : int
            Seeds every random choice (sensor noise): same seed, same episode.
        gui : bool
            Show the simulator's window (a display is needed,
            :meth:`display_reachable`).
        images_dir : Path or None
            Save the cameras' snapshots there.
        pose_target : PoseTarget or None
            The pose skill's world target (the engine's pose solution); None for an
            episode that puts no tool at a pose.
        robot : bool
            Build the robot; without it the scene's objects are observed as they lie
            (the task's facts are the same, and the scene builds faster).
        record : ClipRecorder or None
            Keep the scene's poses for a clip, from the built scene on.
        """

    def run_trial(self, world: World, tool: str, variant: str, location: int,
                  pose: Optional[Sequence[float]] = None, seed: int = 0,
                  images_dir: Optional[Path] = None, gui: bool = False,
                  pose_target: Optional[PoseTarget] = None,
                  record: Optional[ClipRecorder] = None,
                  verdict: Optional[VerdictCallback] = None) -> TrialResult:
        """Run one trial: an episode (arguments as :meth:`open_episode`), every skill
        of the manifest in order with ``pose`` (None: the demonstration's) given to the
        pose skill, the facts observed just before the tool action, then the oracle.

        Return a :class:`~creative_py.simulator.types.TrialResult` whose ``outcome``
        (``success``, ``failure``, ``blocked``, ``unreachable``, ``invalid``) the
        simulated state alone decides, never the tool's properties: blocked before the
        tool action is ``blocked`` (with the facts observed where the motion stopped),
        blocked while the tool acts is ``success`` or ``failure`` by the goal.
        ``facts_before`` is what the learner labels; ``max_tool_force_n`` (N) and
        ``tool_load`` the largest summed normal force of the tool's contacts over one
        step of the tool action and where it acted (None before it starts);
        ``verdict`` what the oracle measured against its threshold (and a guard's
        measure of a stopped motion); ``seed`` the trial's; ``wall_time_s`` the wall
        time until the verdict. ``verdict(outcome, reason, measured)`` is called once
        the physics has given the outcome, inside the episode (where a kept trial's
        clip is rendered from ``record``); without it, ``record`` is rendered at the
        end.
        """

    def tool_rests(self, world: World, tool: str) -> bool:
        """Return whether the available object ``tool`` lies still where the world
        puts it: the demonstration's scene built without the robot, settled, then
        two seconds more of physics; it rests unless it dropped off its stand (a trial
        with it would be ``invalid``)."""

    def draw_world(self, world: World, seed: int,
                   ranges: Mapping[str, Mapping[str, tuple[float, float, str, str]]],
                   keeps: Optional[Callable[[str, Any], bool]] = None,
                   demonstrates: Optional[Callable[[dict], bool]] = None) -> dict[str, Any]:
        """Draw a randomised world of ``world`` for world seed ``seed`` and return it as
        JSON-ready data (``seed``, ``order``, ``objects``, ``locations``, ``redraws``:
        what ``run.json`` keeps and :meth:`apply_drawn` applies).

        Deterministic in ``seed``: the catalogue's order, each catalogued number inside
        its own qualitative range of ``ranges`` (``object -> {catalogue fact -> (low,
        high, bounds, value)}``, the engine's ``catalogue_ranges``, narrowed by the
        manifest's ``[randomise.catalogue]``; the demonstration's tool keeps its
        numbers), redrawn while ``keeps(name, spec)`` is false; each location's values
        within the manifest's ``[randomise]``; the demonstration's location redrawn
        while ``demonstrates(drawn)`` is false (ValueError naming the world seed when
        the attempts run out).
        """

    def apply_drawn(self, world: World, drawn: Mapping[str, Any]) -> World:
        """Return ``world`` with a drawn world's catalogue order, numbers and locations
        (:meth:`draw_world`'s data, or ``run.json``'s read back), its ``variation``
        ``world seed N``; the loader's checks run again, errors (ValueError) name the
        world seed."""

    def display_reachable(self) -> Optional[str]:
        """Return None when the simulator's window (``gui=True``) can open on this
        machine's display, else why not, in words (checked before any folder or
        physics: a simulator may abort the process on a display it cannot open)."""

    def recorder(self, camera: ClipCamera) -> ClipRecorder:
        """Return a new, empty recorder of one trial's clip for ``camera`` (a world's
        :attr:`World.video`)."""
