"""The pybullet backend's episode: one scene of a case's world, driven skill by skill.

Every case is driven the same way, by the skill names of its manifest
(``worlds/<folder>/case.toml``)::

    from creative_py.bridge import Engine
    from creative_py.case import get_case
    from creative_py.learning.poses import pose_resolver   # the engine's pose solution
    from creative_py.backends.pybullet import load_world, open_episode

    world = load_world(get_case("hook"))
    poses = pose_resolver(Engine.instance(), world.manifest)
    with open_episode(world, "standard", 1, "hook_a2", seed=0, pose_target=poses) as ep:
        ep.run_skill("pick_up")                      # SkillOutcome
        ep.run_skill("position_tool", pose=(0.03, 0.0, 0.0))
        ep.run_skill("pull")
        ep.verdict().holds                           # the physics oracle
        ep.observe()                                 # Observation(facts, frames, truth)

An episode builds the scene in a fresh :class:`~creative_py.backends.pybullet.core.Sim`: the bodies of
``scene.toml`` with the variant's and the location's values, the tool where its kind
starts, the arm at its start posture. A skill runs the primitive its manifest entry
binds (:mod:`creative_py.backends.pybullet.primitives`); the pose skill's world target comes from
``pose_target``, a :data:`PoseTarget` the caller gives (the engine's pose solution),
applied to what the robot perceives at that moment. :meth:`Episode.verdict` is what
the oracle (:mod:`creative_py.world.oracles`) measures. A trial (the
manifest's skills in order, the oracle asked, the outcome labelled) is run above the
boundary, as every backend's: :func:`creative_py.simulator.trial.run_trial`. Nothing
here looks at tool properties.

Perception: the objects of ``[[perception.object]]`` come from the cameras through
:mod:`creative_py.perception`; a held tool is known by proprioception (forward
kinematics and the grasp); bodies report their fixed geometry and sensors.
"""

from __future__ import annotations

from contextlib import contextmanager
from pathlib import Path
from typing import Any, Iterator, Sequence

import numpy as np
import pybullet as pb

from creative_py.backends.pybullet.loads import ToolLoad, ToolLoadMonitor
from creative_py.backends.pybullet.recorder import Recorder
from creative_py.world.read import (World, object_name, resolve_options, resolve_start,
                                   oracle_words)
from creative_py.records.trial import more_strikes
from creative_py.simulator.types import (Fact, Observation, PoseTarget, SkillOutcome, Verdict,
                                         pose_numbers)
from creative_py.world_files import PhysicsSettings, WorldFileError

@contextmanager
def open_episode(world: World, variant: str, location: int, tool: str, seed: int = 0,
                 gui: bool = False, images_dir: Path | None = None,
                 pose_target: PoseTarget | None = None, *,
                 robot: bool = True, record: "Recorder | None" = None) -> Iterator["Episode"]:
    """Build the scene and yield an :class:`Episode`; close it on exit.

    Parameters
    ----------
    world : World
        From :func:`creative_py.backends.pybullet.load_world`.
    variant : str
        A variant of the manifest (its ``set`` values change the scene).
    location : int
        1-based index of the predefined target location (``world.locations``).
    tool : str
        The catalogued object used as a tool; unknown names raise listing the others.
    seed : int
        Seeds every random choice (sensor noise); same seed, same result.
    gui : bool
        Show the pybullet GUI if a display exists.
    images_dir : Path or None
        Save camera snapshots there.
    pose_target : callable or None
        ``(facts, tool, pose) -> target``: the world target of a pose
        (:data:`PoseTarget`). None for an episode that puts no tool at a pose (only the
        scene's physics, perception, picking up); a pose skill then raises ValueError.
    robot : bool
        Build the world's robot (default); without it only by-hand placing and the scene's own
        physics run (for tests of the physics alone).
    record : Recorder or None
        Keep the scene's poses for a video clip (:mod:`creative_py.backends.pybullet.recorder`), from
        the built scene on; render them with ``record.render()`` before the episode
        closes. Recording only reads the physics.
    """
    ep = Episode(world, variant, location, tool, seed, gui,
                 None if images_dir is None else Path(images_dir), pose_target, robot=robot,
                 record=record)
    try:
        yield ep
    finally:
        ep.close()


class Episode:
    """One scene of a case in its own simulator, driven skill by skill by name.

    Attributes a primitive uses: ``sim``, ``robot`` (None without one), ``spec`` and
    ``kind`` of the tool, ``item`` (its catalogue entry), ``tool_body``, ``grasp`` (the
    tool frame in the gripper frame), ``held``, ``bodies`` (name -> scene body),
    ``watch`` (bodies whose blow-up ends a motion), ``state`` (what a skill leaves for
    the next, e.g. the tool's attitude) and ``records`` (what an oracle reads).
    ``render_time_s`` is the wall time the cameras' frames took (s), ``tool_load`` the
    :class:`~creative_py.simulator.load.ToolLoad` of the last tool action.
    """

    render_time_s: float = 0.0

    def __init__(self, world: World, variant: str, location: int, tool: str, seed: int = 0,
                 gui: bool = False, images_dir: Path | None = None,
                 pose_target: PoseTarget | None = None, *, robot: bool = True,
                 record: "Recorder | None" = None) -> None:
        from creative_py.backends.pybullet.core import Sim
        from creative_py.backends.pybullet.scene import make_bodies
        from creative_py.backends.pybullet.tools import tool_kind

        m = world.manifest
        self.world, self.manifest = world, m
        self.variant, self.location = variant, location
        self.item = world.item(tool)
        self.spec = self.item.spec
        self.kind = tool_kind(self.spec)
        self.ns = world.namespace(variant, location, tool)
        self.bodies = make_bodies(world.scene.bodies, self.ns)
        self.target_name, self.context_name = m.target, m.context
        self.pose_target = pose_target
        self.rng = np.random.default_rng(seed)
        self.images_dir = images_dir
        self.render_time_s = 0.0
        self._shots = 0
        self._last_skill = ""  # the skill run last: names the snapshots taken after it
        self.held = False
        self.grasp = self.kind.initial_grasp(self.spec)
        self.state: dict[str, Any] = {}
        self.records: dict[str, Any] = {}
        self.tool_load = ToolLoad()
        self.supports: dict[str, int] = {}
        """Bodies a tool's handling built to rest it on (name -> body: ``pedestal``)."""
        self.robot = None
        self.robot_parked = False
        self.with_robot = robot
        self._time_before = 0.0
        self._steps_at_switch = 0
        self.sim = Sim(world.physics["arm"], gui=gui)
        try:
            if self.sim.gui and world.scene.video is not None:
                cam = world.scene.video.camera  # the GUI shows what the clips show
                self.sim.look_at(cam.eye, cam.target)
            self._build()
            if record is not None:
                robot = self.robot
                record.attach(self.sim.client, None if robot is None else robot.body,
                              None if robot is None or world.scene.robot.visuals
                              else robot.urdf)
                self.sim.recorder = record
        except BaseException:
            self.close()
            raise

    # ------------------------------------------------------------ scene building
    def _build(self) -> None:
        from creative_py.backends.pybullet.arm import Arm, ArmConfig, base_pose

        w = self.world
        for body in self.bodies.values():
            body.build(self.sim)
        self.tool_body = self.kind.spawn(self, resolve_start(w, self.ns))
        from creative_py.backends.pybullet.bodies import frame_pose

        self.tool_spawn_z = frame_pose(self.sim, self.tool_body)[0][2]
        self.perceived = []
        for p in w.scene.perceived:
            name = object_name(self.manifest, p.name, self.spec.name)
            support = None if p.support_z is None else self.ns.evaluate(p.support_z, name)
            self.perceived.append((name, support))
        self.watch = [self.body_id(n) for n, _ in self.perceived]
        if self.with_robot:
            rs = w.scene.robot
            base = None if rs.base is None else base_pose(rs.profile, *rs.base)
            self.robot = Arm(self.sim, rs.profile, ArmConfig(
                visuals=rs.visuals, speed=rs.speed, turn_speed=rs.turn_speed,
                steps_per_waypoint=rs.steps_per_waypoint), base=base)
            self.robot.reset_posture(self._start_posture())
        self.run(w.scene.settle_time)
        if self.robot is not None:
            # Where the robot's own links strike a body the scene says they must keep
            # clear of ([robot] keep_clear; a skill's ``struck``).
            self.robot.watch_strikes({self.bodies[n].id: n for n in w.scene.robot.keep_clear})
        # Where the tracked objects start (an oracle measures how far they moved).
        self.start_centres = {n: self.true_centre(n) for n, _ in self.perceived}
        # And every movable body's (a reward counting bodies nobody tracks reads them).
        self.body_starts = {n: b.centre(self.sim) for n, b in self.bodies.items()
                            if b.dynamic}

    def _pose_of(self, table: dict[str, Any]):
        from creative_py.backends.pybullet.arm import GRIPPER_ATTITUDES

        pos = self.ns.evaluate(table["position"], "robot.start.position")
        angle = self.ns.evaluate(table["angle"], "robot.start.angle")
        return (tuple(pos), GRIPPER_ATTITUDES[table["gripper"]](angle))

    def _start_posture(self) -> list[float]:
        """Return the arm's start posture (searched once per scene geometry, then cached)."""
        rs = self.world.scene.robot
        home = self._pose_of(rs.start)
        via = None if rs.via is None else self._pose_of(rs.via)
        key = (via, home)
        cache = self.world.postures
        if key in cache:
            return cache[key]  # the same numbers the search below gives
        seeds = ()
        if via is not None:
            # The via search (40 restarts) is done once per via target, not once per
            # start pose (which moves with the tool's reach), unless the robot is heavy.
            # The robot was just built at the ready posture, so the answer is the same.
            via_key = ("via", via)
            if self.robot.light and via_key in cache:
                q_via = cache[via_key]
            else:
                q_via = self.robot.solve_ik_global(via)
                if self.robot.light:
                    cache[via_key] = q_via
            seeds = [q_via] if q_via else ()
        q = self.robot.solve_ik_global(home, keep=rs.keep, seeds=seeds)
        if q is None:
            raise WorldFileError(f"{self.world.directory / 'scene.toml'}: field "
                                 f"'robot.start': the arm cannot reach {list(home[0])}")
        cache[key] = q
        return q

    def body_id(self, name: str) -> int:
        """Return the pybullet body of the tool or of a scene body ``name``."""
        if name == self.spec.name:
            return self.tool_body
        if name in self.bodies:
            return self.bodies[name].id
        raise KeyError(f"no object {name!r} in the scene")

    # ------------------------------------------------------------------ helpers
    @property
    def tool(self) -> str:
        """Return the tool's name."""
        return self.spec.name

    @property
    def context_body(self):
        """Return the scene body of the case's context object."""
        return self.bodies[self.context_name]

    def object_name(self, name: str) -> str:
        """Return the object a role (``tool``, ``target``, ``context``) or a name denotes."""
        return object_name(self.manifest, name, self.spec.name)

    def need_robot(self, what: str) -> None:
        """Raise if the episode has no robot (built without, or parked)."""
        if self.robot is None or self.robot_parked:
            raise RuntimeError(f"{what}: this episode has no robot (built with robot=False, "
                               "or the robot was parked for a joint's release)")

    def use_physics(self, profile: str) -> None:
        """Switch to the ``rest`` or ``arm`` physics (time step, iterations), keeping time."""
        physics: PhysicsSettings = self.world.physics[profile]
        if physics == self.sim.physics:
            return
        self._time_before = self.sim_time()
        self._steps_at_switch = self.sim.steps
        self.sim.physics = physics
        self.sim.configure()

    def run(self, seconds: float) -> None:
        """Advance the physics by ``seconds`` at the current time step."""
        self.sim.step(int(round(seconds / self.sim.physics.time_step)))

    def park_robot(self) -> None:
        """Take the idle robot out of the physics (it must stand clear of what moves)."""
        if self.robot is None or self.robot_parked:
            return
        pb.removeBody(self.robot.body, physicsClientId=self.sim.client)
        self.robot.close()
        self.robot_parked = True

    def tool_pose(self):
        """Return the held tool's frame pose by proprioception (FK + the grasp)."""
        g = self.robot.gripper_pose()
        pos, quat = pb.multiplyTransforms(g[0], g[1], *self.grasp)
        return tuple(pos), tuple(quat)

    def gripper_for_tool_at(self, x: float, y: float, z: float, yaw: float):
        """Return the gripper pose that puts the held tool's frame at (x, y, z), heading yaw."""
        obj_q = pb.getQuaternionFromEuler((0, 0, yaw))
        inv = pb.invertTransform(*self.grasp)
        pos, quat = pb.multiplyTransforms((x, y, z), obj_q, inv[0], inv[1])
        return tuple(pos), tuple(quat)

    def perceived_top(self, name: str) -> float | None:
        """Return the top (m) of ``name`` as last perceived by :meth:`run_skill`, or None."""
        facts = self.state.get("facts", ())
        pose = next((f for f in facts if f[0] == "pose" and f[1] == name), None)
        size = next((f for f in facts if f[0] == "size" and f[1] == name), None)
        if pose is None or size is None:
            return None
        return pose[4] + size[4] / 2

    # ------------------------------------------------------------------- skills
    def run_skill(self, name: str, pose: Sequence[float] | None = None,
                  **options: Any) -> SkillOutcome:
        """Run the manifest's skill ``name`` (with the ``pose`` numbers for the pose skill).

        ``options`` override the skill's primitive options of ``case.toml`` for this
        call (e.g. ``by_hand=True`` for the trainer's placing). Returns how it ended; a
        reason names the skill. Raises ValueError for missing or non-finite pose
        numbers, KeyError for a skill the manifest does not have.
        """
        binding = self.manifest.skill(name)
        skill = self.world.skills[name]
        if binding.pose:
            pose = pose_numbers(name, pose, self.manifest.pose_names)
        monitor = ToolLoadMonitor(self) if binding.tool_action else None
        if monitor is not None:
            # The largest contact force on the tool while it acts (sim/loads.py).
            monitor.start()
        if self.robot is not None:
            self.robot.take_strikes()  # from this skill on
        try:
            res = self.run_primitive(skill.primitive, pose, **{**skill.options, **options})
        finally:
            self._last_skill = name
            if monitor is not None:
                self.tool_load = monitor.stop()
        struck = self._struck()
        if not res.ok:
            stop = res.stop
            if stop is not None and "touching_ids" in stop.measures:
                stop = self._name_touching(stop)
            return SkillOutcome(res.status, f"{name}: {res.reason}", stop, struck)
        if struck is not None:
            return SkillOutcome("ok", f"{name}: {struck.detail}", struck=struck)
        return res

    def _struck(self) -> Verdict | None:
        """Return the strikes of the robot's own links on scene bodies during the
        skill just run (:meth:`~creative_py.backends.pybullet.arm.Arm.take_strikes`)
        as a verdict, or None: the largest normal force (N) against none, the
        strongest strike in words (which link struck which body, where, how hard),
        every strike in ``measures["struck"]`` and the pairs in
        ``measures["touching"]``."""
        if self.robot is None:
            return None
        strikes = self.robot.take_strikes()
        if not strikes:
            return None
        top = strikes[0]
        x, y, z = top["point"]
        detail = (f"the robot's {top['link']} struck {top['body']} at ({x:.3f}, {y:.3f}, "
                  f"{z:.3f}) m with {top['force_n']:.0f} N" + more_strikes(strikes)
                  + ": the arm, not the tool, met the scene")
        touching = sorted({f"{s['link']} against {s['body']}" for s in strikes})
        keep_clear = ", ".join(self.world.scene.robot.keep_clear)
        return Verdict("robot strike force", top["force_n"], 0.0, "N", "<=", False,
                       threshold_name=f"robot links strike none of {keep_clear}",
                       detail=detail, measures={"struck": strikes, "touching": touching})

    def _name_touching(self, stop: Verdict) -> Verdict:
        """Return a guard's verdict with the bodies it saw touching named (scene
        bodies, the tool, ``robot``), and them said in its detail."""
        from dataclasses import replace

        names = {b.id: n for n, b in self.bodies.items()}
        names.update({body: n for n, body in self.supports.items()})
        names[self.tool_body] = self.spec.name
        if self.robot is not None and not self.robot_parked:
            names[self.robot.body] = "robot"
        measures = dict(stop.measures)
        pairs = sorted({f"{names.get(a, f'body{a}')} against {names.get(b, f'body{b}')}"
                        for a, b in measures.pop("touching_ids")})
        measures["touching"] = pairs
        detail = ("touching: " + ", ".join(pairs)) if pairs else "touching nothing"
        return replace(stop, measures=measures,
                       detail="; ".join(t for t in (stop.detail, detail) if t))

    def run_primitive(self, primitive: str, pose: Sequence[float] | None = None,
                      **options: Any) -> SkillOutcome:
        """Run a primitive with ``options`` (raw: numbers or scene expressions).

        A primitive that takes a world target gets it from :attr:`pose_target` applied
        to what the robot perceives now; its ``perceive`` option says whether the
        cameras are used for that (a target relative to a tracked object) or only the
        scene's own facts (a target relative to a hinge, no rendering, no noise drawn).
        """
        from creative_py.backends.pybullet.primitives import primitive as lookup
        from creative_py.world.skills import REQUIRED

        prim = lookup(primitive)
        unknown = sorted(set(options) - set(prim.options))
        if unknown:
            raise ValueError(f"primitive {primitive}: unknown options {unknown}; options: "
                             f"{', '.join(prim.options)}")
        defaults = {k: v for k, v in prim.options.items() if v is not REQUIRED}
        opts = resolve_options({**defaults, **options}, self.ns, f"primitive {primitive}")
        target: tuple = ()
        if prim.target:
            if prim.needs_held_tool(opts) and not self.held:
                return SkillOutcome("blocked", "no tool is held (pick it up first)")
            if self.pose_target is None:
                raise ValueError(f"primitive {primitive} needs the world target of a pose, "
                                 "but the episode has no pose resolver: pass pose_target "
                                 "to open_episode")
            facts = list(self.observe(cameras=opts.get("perceive", True)).facts)
            self.state["facts"] = facts
            target = tuple(self.pose_target(facts, self.spec.name, tuple(pose)))
            if not target:
                seen = {f[1] for f in facts if f[0] == "pose"}
                missing = [n for n, _ in self.perceived if n not in seen]
                why = (f"the camera does not see {', '.join(missing)}" if missing
                       else "the pose has no world target in this state")
                return SkillOutcome("unreachable", why)
            if target[0] != prim.target:
                raise ValueError(f"{primitive} needs a {prim.target}(...) target, the "
                                 f"pose solution gave {target[0]}(...)")
        return prim.run(self, opts, target)

    # ---------------------------------------------------------------- perception
    def _frames(self) -> tuple:
        from creative_py.backends.pybullet.camera import capture_frames

        step = f"after_{self._last_skill}" if self._last_skill else "start"
        frames = capture_frames(self.sim.client, self.world.scene.cameras, self.images_dir,
                                self._shots, step)
        self.render_time_s += sum(f.render_time_s for f in frames)
        self._shots += self.images_dir is not None
        return frames

    def _estimates(self):
        from creative_py.perception import estimate_objects

        if not self.perceived:
            return {}, ()
        frames = self._frames()
        bodies, support, heights = {}, {}, {}
        for name, support_z in self.perceived:
            bodies[name] = self.body_id(name)
            held = self.held and name == self.spec.name
            if support_z is not None and not held:
                support[name] = support_z
            h = (self.kind.height(self.spec) if name == self.spec.name
                 else self.bodies[name].height)
            if h is not None:
                heights[name] = h
        est = estimate_objects(frames, bodies, self.world.scene.noise, self.rng,
                               support_z=support, heights=heights)
        return est, frames

    def observe(self, cameras: bool = True) -> Observation:
        """Return the facts the robot perceives now, the frames and the ground truth.

        Facts: the tracked objects' ``pose/5`` and ``size/4`` (cameras, unless
        ``cameras`` is false: then nothing is rendered and no noise drawn), ``held/1`` and
        the tool kind's proprioception, every scene body's facts, the oracle's fact
        while the goal holds, and the catalogue of every available object.
        """
        from creative_py.perception import facts_from_estimates
        from creative_py.backends.pybullet.tools import catalogue_facts

        est, frames = self._estimates() if cameras else ({}, ())
        facts: list[Fact] = list(facts_from_estimates(est))
        if self.held:
            facts.append(("held", self.spec.name))
            facts += self.kind.proprioception(self)
        for body in self.bodies.values():
            facts += body.facts(self.sim)
        fact = self.world.oracle.options.get("fact")
        if fact and self.verdict().holds:
            subject = self.world.oracle.oracle.subject
            facts.append((fact, self.object_name(self.world.oracle.options[subject])))
        for item in self.world.items.values():
            facts += catalogue_facts(item.spec)
        return Observation(facts=tuple(facts), frames=frames, truth=self.truth())

    def true_centre(self, name: str) -> tuple[float, float, float, float]:
        """Return the true ``(x, y, z, yaw)`` of an object's centre (oracles, reports)."""
        from creative_py.backends.pybullet.bodies import frame_pose, yaw_of

        if name == self.spec.name:
            pos, quat = frame_pose(self.sim, self.tool_body)
            centre = pb.multiplyTransforms(pos, quat, self.kind.centre(self.spec),
                                           (0, 0, 0, 1))[0]
            return (*centre, yaw_of(quat))
        return self.bodies[name].centre(self.sim)

    def linear_velocity(self, name: str) -> tuple[float, float, float]:
        """Return the true linear velocity of an object's base (m/s, world frame)."""
        v, _ = pb.getBaseVelocity(self.body_id(name), physicsClientId=self.sim.client)
        return tuple(float(c) for c in v)

    def joint_angle(self, name: str) -> float | None:
        """Return the angle (rad) of a jointed body's joint from its sensor (a door's: 0
        is closed), or None for a body without one."""
        angle = getattr(self.bodies.get(name), "angle", None)
        return float(angle(self.sim)) if callable(angle) else None

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ground-truth ``name -> (x, y, z, yaw)`` of the tracked objects and the
        tool (its frame), for error reports only."""
        out = {n: self.true_centre(n) for n, _ in self.perceived}
        if self.spec.name not in out:
            from creative_py.backends.pybullet.bodies import frame_pose, yaw_of

            pos, quat = frame_pose(self.sim, self.tool_body)
            out[self.spec.name] = (*pos, yaw_of(quat))
        return {k: tuple(float(v) for v in p) for k, p in out.items()}

    # ------------------------------------------------------------------- oracle
    def verdict(self) -> Verdict:
        """Return the oracle's measured verdict on the simulated state: whether the goal
        holds, the quantity measured and the threshold it was judged by
        (:mod:`creative_py.world.oracles`)."""
        from dataclasses import replace

        spec = self.world.oracle
        opts = resolve_options(spec.options, self.ns, "oracle", words=oracle_words(self.world))
        kind = spec.oracle
        verdict = kind.judge(self, opts)
        if kind.threshold and not verdict.threshold_name:
            raw = spec.options.get(kind.threshold)
            verdict = replace(verdict, threshold_name=(
                raw if isinstance(raw, str) else kind.threshold))
        return verdict

    def sim_time(self) -> float:
        """Return the simulated time so far, seconds (across time-step changes)."""
        return (self._time_before
                + (self.sim.steps - self._steps_at_switch) * self.sim.physics.time_step)

    @property
    def steps(self) -> int:
        """Return the physics steps taken so far."""
        return self.sim.steps

    def measured_load(self) -> tuple[float, dict[str, Any] | None]:
        """Return the contact load on the tool during the last tool action: the largest
        summed normal force over one physics step (N) and the load as data
        (:meth:`~creative_py.simulator.load.ToolLoad.to_dict`)."""
        return self.tool_load.max_force_n, self.tool_load.to_dict()

    def close(self) -> None:
        """Release the simulator (idempotent)."""
        robot = getattr(self, "robot", None)
        if robot is not None and not self.robot_parked:
            robot.close()
        self.sim.close()


def tool_rests(world: World, tool: str, seconds: float = 2.0) -> bool:
    """Return whether ``tool`` lies still where the world puts it.

    The scene of the demonstration's variant and location is built without the robot
    and settled, then ``seconds`` more of physics run; the tool rests unless it dropped
    more than :data:`creative_py.backends.pybullet.primitives.FELL_M` below where it was spawned
    (off its stand: a drawn hook with a heavy prong on a short or thin handle tips
    over, and a trial with it would be ``invalid``).
    """
    from creative_py.backends.pybullet.bodies import frame_pose
    from creative_py.backends.pybullet.primitives import FELL_M

    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, tool, robot=False) as ep:
        ep.run(seconds)
        drop = ep.tool_spawn_z - frame_pose(ep.sim, ep.tool_body)[0][2]
    return drop <= FELL_M
