"""What the layers above need of a simulator: the :class:`Backend`, its :class:`World`
and its :class:`Episode`, as :class:`typing.Protocol` classes.

The protocols hold exactly what the layers above the boundary use of a simulator (the
trial loop of :mod:`creative_py.simulator.trial`, the world sampler of
:mod:`creative_py.simulator.randomise`, ``creative_py/learning/`` and the command line's
``creative trial``), no more: a backend builds scenes, runs skills, observes and
measures; running a trial, labelling its outcome and drawing randomised worlds happen
above it, once for every backend. What is not a simulator's is not
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

from creative_py.simulator.types import Observation, PoseTarget, SkillOutcome, Verdict

if TYPE_CHECKING:
    from creative_py.case import CaseManifest

VerdictCallback = Callable[[str, str, Optional[dict]], None]
"""``verdict(outcome, reason, measured)``: what :func:`creative_py.simulator.trial.run_trial`
calls once the physics has given the outcome, still inside the episode (``measured`` is
the result's ``verdict`` data)."""


class ClipCamera(Protocol):
    """The camera of a world's video clips (pybullet: :class:`creative_py.world.cameras.VideoSpec`);
    the learning loop reads only its frame rate."""

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

    def render(self) -> list:
        """Render the frames here and now and return them (RGB ``uint8`` arrays, H x W x
        3, one per snapshot): what the trial loop does with a recorder no verdict
        callback took. Called inside the trial's episode, after the verdict; the
        physics must not run afterwards."""


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
        (:func:`creative_py.simulator.randomise.apply_drawn`). Part of every cache key
        that depends on the world's numbers."""

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

    def with_catalogue(self, order: Sequence[str],
                       numbers: Mapping[str, Mapping[str, float]]) -> "World":
        """Return this world with its available objects in ``order`` (a permutation of
        their names) and the spec fields ``numbers[name]`` (``field -> value``, metres,
        radians) set on their specs, everything else kept (a drawn world's catalogue,
        :func:`creative_py.simulator.randomise.apply_drawn`;
        :class:`~creative_py.simulator.catalogue.CatalogueWorld` has it)."""

    def location_values(self, location: int) -> Mapping[str, Any]:
        """Return the scene values that location ``location`` sets (``key -> value``,
        the ``set`` table of its ``[[location]]``, or of a drawn world's), what the
        world sampler jitters. Raise ValueError naming the case's ``case.toml`` when
        this backend's locations are no scene values (it draws no randomised worlds:
        ManiSkill's locations are seeded initial states)."""

    def scene_value(self, key: str, variant: str, location: int, tool: str) -> float:
        """Return the scene value ``key`` (a name of :meth:`location_values`' tables)
        as the episode of ``variant``, ``location`` and ``tool`` resolves it (the
        scene's value, overridden by the variant's and the location's ``set``), in the
        world's units."""

    def with_locations(self, tables: Sequence[Mapping[str, Any]],
                       variation: str) -> "World":
        """Return this world with location ``i``'s scene values ``tables[i - 1]`` (one
        per location, the keys of :meth:`location_values`) and :attr:`variation`
        ``variation``; every scene value of every variant and location is checked
        again (:class:`~creative_py.world_files.WorldFileError` or ValueError naming
        the field). ValueError as :meth:`location_values` for a backend without
        drawn worlds."""


class Episode(Protocol):
    """One scene of a case (a variant, a target location, a tool), driven skill by
    skill by the names of the manifest's ``[[skill]]`` tables.

    What the trial loop (:mod:`creative_py.simulator.trial`) and the learning loop use
    of a scene: run a skill, observe, measure, the true poses, the simulated time and
    steps, the load on the tool. An episode decides no trial's outcome: a skill reports
    how its motion ended, the oracle what it measured; the loop labels the trial.
    """

    def run_skill(self, name: str, pose: Optional[Sequence[float]] = None,
                  **options: Any) -> SkillOutcome:
        """Run the manifest's skill ``name`` (the primitive it binds, with its options)
        and return how its motion ended: ``ok``, ``blocked`` (a guard stopped a
        motion; ``stop`` says what it measured), ``out_of_time`` (the episode's step
        or time budget ran out before the motion's end; ``stop`` says what it needed
        against the budget), ``unreachable`` (no arm posture) or
        ``invalid`` (a physics blow-up, or a skill that cannot run in this state); the
        reason names the skill.

        The pose skill (``pose = true``) needs ``pose``, the numbers of the manifest's
        ``[[pose.param]]`` in their order and units; its world target comes from the
        episode's ``pose_target`` (:data:`creative_py.simulator.types.PoseTarget`)
        applied to what the robot perceives at that moment. ``options`` override the
        skill's primitive options for this call (the trainer's placing: ``by_hand=True``
        on the pose skill puts the tool at the pose without the arm; a backend whose
        primitive has no such option ignores it). Raise KeyError for a skill the
        manifest does not have, ValueError for a pose skill without ``pose`` or
        without a ``pose_target``.
        """

    def observe(self, cameras: bool = True) -> Observation:
        """Return what the robot perceives now: primitive facts (``pose``, sizes,
        proprioception of a held tool, the scene's fixed facts and the catalogue of
        every available object; world frame, metres, radians), the camera frames behind
        them (empty without cameras) and the ground truth (for error reports only).
        Without ``cameras`` the tracked objects' facts come from the ground truth."""

    def verdict(self) -> Verdict:
        """Return what the case's oracle measures in the simulated state now: the
        quantity, its value and threshold in the world's units, and whether the goal
        holds (``holds``). Raise ValueError or ArithmeticError when the state has
        nothing finite to measure (a blow-up):
        :class:`~creative_py.simulator.types.NonFiniteState` (a ValueError) for a
        non-finite number read from the state, which makes the trial ``invalid`` where
        the oracle is asked (:func:`creative_py.simulator.trial.judge`)."""

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return the ground truth ``name -> (x, y, z, yaw)`` (m, rad, world frame) of
        the tracked objects and the tool (its frame): the trial's final poses, for
        reports; a non-finite number makes the trial ``invalid``."""

    def sim_time(self) -> float:
        """Return the simulated time since the scene was built, seconds."""

    @property
    def steps(self) -> int:
        """The simulator's steps taken so far (pybullet: physics steps; ManiSkill:
        control steps)."""

    @property
    def render_time_s(self) -> float:
        """The wall time spent rendering the cameras' frames so far, seconds (0.0 for a
        backend that perceives without cameras)."""

    def measured_load(self) -> tuple[float, Optional[dict[str, Any]]]:
        """Return the contact load on the tool during the last tool action (the skill
        with ``tool_action = true``): the largest sum of the normal forces of its
        contacts over one step, newtons, and where and how it acted as JSON-ready data
        (:meth:`creative_py.simulator.load.ToolLoad.to_dict`'s fields:
        ``max_force_n``, ``point`` and ``force`` in the tool frame, ``grasp_point``,
        ``bodies``, ``robust_force_n``, ...; None when none was measured). Asked only
        once the tool action started."""


class Backend(Protocol):
    """A simulator backend: what the layers above the boundary call to build a case's
    world and its scenes (module-level functions; :mod:`creative_py.backends.pybullet` is
    the pybullet one). A trial is run by :func:`creative_py.simulator.trial.run_trial`
    and a randomised world drawn by :mod:`creative_py.simulator.randomise`, both through
    these functions and the :class:`World` and :class:`Episode` members."""

    def load_world(self, manifest: CaseManifest) -> World:
        """Read the manifest's world folder and return its :class:`World`, every value
        of every variant and location checked; raise
        :class:`creative_py.world_files.WorldFileError` naming the file and the field.
        A backend that builds an arm of a robot profile builds ``manifest.robot``'s (a
        run's manifest carries ``--robot``'s there): the choice travels in no other
        way."""

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

    def tool_rests(self, world: World, tool: str) -> bool:
        """Return whether the available object ``tool`` lies still where the world
        puts it: the demonstration's scene built without the robot, settled, then
        two seconds more of physics; it rests unless it dropped off its stand (a trial
        with it would be ``invalid``). The world sampler's ``keeps`` asks it of every
        drawn object (:func:`creative_py.learning.run.draw_catalogue_world`)."""

    def display_reachable(self) -> Optional[str]:
        """Return None when the simulator's window (``gui=True``) can open on this
        machine's display, else why not, in words (checked before any folder or
        physics: a simulator may abort the process on a display it cannot open)."""

    def recorder(self, camera: ClipCamera) -> ClipRecorder:
        """Return a new, empty recorder of one trial's clip for ``camera`` (a world's
        :attr:`World.video`)."""
