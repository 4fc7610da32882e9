"""One trial of a ManiSkill case: ManiSkill's environment driven by the manifest's skills.

An episode resets ManiSkill's environment (:mod:`creative_py.backends.maniskill.env`) with the
location's seed, so the robot, the tool and the target (the actors ``tasks.toml``'s
``[env]`` names) start in ManiSkill's own seeded initial state; the tool is the catalogued (or created) object, built from its spec's
boxes. The skills run the primitives their manifest entries bind, each a few straight
moves of the end-effector pose controller (:mod:`creative_py.backends.maniskill.skills`).

Perception: the primitive facts come from the simulator's state, not from cameras
(``pose/5`` and ``size/4`` of the target from its actor's pose and ``[env]
target_half``; the held tool's ``tip_position/4``, ``tool_roll/2`` and ``tool_axis_y/2`` from
the tool actor's pose and its spec; ``reach_zone/4`` of the goal region from the robot
base's or the goal actor's pose and ``tasks.toml``'s radius; every object's catalogue
facts from its kind).

While the tool acts, the contact load on it is read from SAPIEN's contacts
(:mod:`creative_py.backends.maniskill.loads`), for the strength check of a created tool.

The goal verdict is ManiSkill's ``env.evaluate()["success"]`` and nothing else; the
Verdict records the target's distance to the goal region's centre in xy and the
``evaluate()`` entries ``[env] measures`` names (``cube_distance``, ...), and the arm's
fastest joint (``evaluate()`` of some tasks needs the robot static): where the judgement
is not what the distance says, its short note says why. Steps are ManiSkill control
steps (``env.step`` calls, 20 Hz), counted against the world's ``max_steps``; a skill
that runs out of them reports its motion ``out_of_time`` with the steps it needed, and
what that means for the trial is decided above the boundary, as for every backend
(:func:`creative_py.simulator.trial.trial_outcome`, in
:func:`creative_py.simulator.trial.run_trial`).
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from typing import Any, Iterator, Optional, Sequence

import numpy as np

from creative_py.backends.maniskill.skills import OPEN, Driver, grasp_handle
from creative_py.backends.maniskill.scene import World
from creative_py.simulator.types import (Fact, Observation, PoseTarget, SkillOutcome, Verdict,
                                         pose_numbers)

def tool_mass(item) -> float:
    """Return the tool's mass, kg: its spec's, else printed PLA's (created tools)."""
    from creative_py.kinds.parts import PLA_DENSITY

    mass = item.spec.mass
    return float(mass) if mass is not None else PLA_DENSITY * item.spec.volume()


def _yaw(q_wxyz: Sequence[float]) -> float:
    w, x, y, z = (float(v) for v in q_wxyz)
    return math.atan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def _rotate(q_wxyz, v):
    from scipy.spatial.transform import Rotation

    w, x, y, z = (float(a) for a in q_wxyz)
    return Rotation.from_quat([x, y, z, w]).apply(v)


class Episode:
    """One ManiSkill episode of a case: a variant, a location (seed), a tool.

    Attributes
    ----------
    env : gymnasium.Env
        ManiSkill's environment (``pd_ee_pose``, CPU backend).
    driver : Driver
        The end-effector moves, with the control steps counted.
    held : bool
        Whether the robot holds the tool.
    render_time_s : float
        Always 0.0: the facts come from the simulator's state, no camera renders.
    """

    render_time_s: float = 0.0

    def __init__(self, world: World, variant: str, location: int, tool: str, seed: int = 0,
                 pose_target: Optional[PoseTarget] = None, robot: bool = True,
                 record=None) -> None:
        from creative_py.backends.maniskill.env import make_env

        m = world.manifest
        self.world, self.manifest = world, m
        self.variant, self.location = variant, location
        self.item = world.item(tool)
        self.spec = self.item.spec
        self.target_name, self.context_name = m.target, m.context
        self.pose_target = pose_target
        self.seed = seed
        self.reset_seed = world.seed(location)
        m.variant(variant)
        te = world.env
        self.env = make_env(te.task, te.tool, te.target, te.goal, self.spec.parts(),
                            tool_mass(self.item), self.item.friction,
                            world.cube_dx(variant), world.max_steps,
                            render=record is not None,
                            camera=None if record is None else record.camera.camera_config())
        self.env.reset(seed=self.reset_seed)
        u = self.env.unwrapped
        self.u = u
        self.driver = Driver(self.env, max_steps=world.max_steps)
        self.record = record
        if record is not None:  # keeps the states from the reset on; reads only
            record.attach(self.env, self.sim_time)
            self.driver.on_record = record.tick
        self.held = False
        self.grasp_offset = np.zeros(3)
        self.grasp_z = 0.0
        self.state: dict[str, Any] = {}
        self.tool_load: Optional[dict[str, Any]] = None
        self.with_robot = robot

    # ----------------------------------------------------------------- state
    @property
    def tool_actor(self):
        """Return the tool's actor (ManiSkill's scene, the name ``[env] tool`` gives)."""
        return self.u.scene.actors[self.world.env.tool]

    @property
    def target_actor(self):
        """Return the target's actor (the name ``[env] target`` gives)."""
        return self.u.scene.actors[self.world.env.target]

    def zone_centre(self) -> np.ndarray:
        """Return the goal region's centre, world metres: the robot base's position or
        the goal actor's (``[zone] centre``)."""
        if self.world.zone_centre == "robot":
            return self._p(self.u.agent.robot)
        return self._p(self.u.scene.actors[self.world.zone_centre])

    def _p(self, actor) -> np.ndarray:
        return actor.pose.p[0].numpy().astype(float)

    def _q(self, actor) -> np.ndarray:
        return actor.pose.q[0].numpy().astype(float)

    def tool_point(self, local: Sequence[float]) -> np.ndarray:
        """Return a point of the tool frame (its spec's frame) in the world, m."""
        tool = self.tool_actor
        return self._p(tool) + _rotate(self._q(tool), local)

    def prong_centre(self) -> np.ndarray:
        """Return the world position of the prong's centre (the handle's tip for a stick)."""
        parts = self.spec.parts()
        local = parts[1].center if len(parts) > 1 else (self.spec.handle_length, 0.0, 0.0)
        return self.tool_point(local)

    @property
    def steps(self) -> int:
        """Return the ManiSkill control steps taken so far."""
        return self.driver.steps

    def sim_time(self) -> float:
        """Return the simulated time, s (control steps at ManiSkill's control rate)."""
        return self.steps / float(self.u.control_freq)

    def measured_load(self) -> tuple[float, Optional[dict[str, Any]]]:
        """Return the contact load on the tool during the last tool action: its
        largest summed normal force over one control step (N) and the load's data
        (:mod:`creative_py.backends.maniskill.loads`; None when none was measured)."""
        return (self.tool_load or {}).get("max_force_n", 0.0), self.tool_load

    # ---------------------------------------------------------------- skills
    def run_skill(self, name: str, pose: Optional[Sequence[float]] = None,
                  **options: Any) -> SkillOutcome:
        """Run the manifest's skill ``name`` (the primitive it binds, with its options)."""
        binding = self.manifest.skill(name)
        primitive, opts = self.world.skills[name]
        opts = {**opts, **options}
        if binding.pose:
            pose = pose_numbers(name, pose, self.manifest.pose_names)
        monitor = None
        if binding.tool_action:
            from creative_py.backends.maniskill.loads import LoadMonitor

            monitor = LoadMonitor(self)  # the contact load on the tool while it acts
            self.driver.on_step = monitor.sample
        try:
            res = getattr(self, "_" + primitive)(opts, pose)
        finally:
            if monitor is not None:
                self.driver.on_step = None
                self.tool_load = monitor.result()
        if not res.ok:
            return SkillOutcome(res.status, f"{name}: {res.reason}", res.stop)
        return res

    def _out_of_steps(self) -> SkillOutcome:
        """Return the ``out_of_time`` outcome of a move the episode's step budget cut
        short, with what it needed: the steps taken and the rest of that move (at
        least: the moves after it are not counted) against the budget."""
        budget, needed = self.world.max_steps, self.steps + self.driver.short
        stop = Verdict("control steps needed at least", needed, budget, "steps", "<=", False,
                       "[episode] max_steps",
                       detail=f"{self.steps} taken and {self.driver.short} more for the move "
                              "that ran out; the moves after it not counted",
                       measures={"steps_taken": self.steps, "move_left": self.driver.short})
        return SkillOutcome("out_of_time", f"the episode's {budget} control steps ran out",
                            stop)

    def _grasp(self, opts, pose) -> SkillOutcome:
        grip = self.tool_point(self.spec.grip_point)
        step = float(opts["step_m"])
        if not grasp_handle(self.driver, grip, opts["approach"], step):
            return self._out_of_steps()
        self.held = True
        self.grasp_offset = self.driver.tcp() - self._p(self.tool_actor)
        self.grasp_z = self.driver.tcp()[2]
        d = self.driver
        if not d.move(d.tcp() * [1, 1, 0] + [0, 0, float(opts["lift_to"])], step_m=step):
            return self._out_of_steps()
        return SkillOutcome("ok")

    def _place_at_pose(self, opts, pose) -> SkillOutcome:
        if not self.held:
            return SkillOutcome("blocked", "no tool is held (pick it up first)")
        if self.pose_target is None:
            raise ValueError("place_at_pose needs the world target of a pose, but the "
                             "episode has no pose resolver: pass pose_target")
        facts = list(self.observe().facts)
        self.state["facts"] = facts
        target = tuple(self.pose_target(facts, self.spec.name, tuple(pose)))
        if not target:
            return SkillOutcome("unreachable", "the pose has no world target in this state")
        if target[0] != "place":
            raise ValueError(f"place_at_pose needs a place(...) target, got {target[0]}(...)")
        _, x, y, _heading = target
        d = self.driver
        prong_x = self.spec.parts()[1].center[0] if len(self.spec.parts()) > 1 \
            else self.spec.handle_length
        tcp = np.array([x - prong_x, y, 0.0]) + self.grasp_offset
        tcp[2] = self.grasp_z
        carry = float(opts["carry_z"])
        # Lowered beside the target, away from the prong's side, then slid sideways
        # into place: the drooping tool is levelled by the table, not on the cube.
        side = -1.0 if getattr(self.spec, "hook_side", "left") == "right" else 1.0
        beside = tcp - [0.0, side * float(opts["side_clear"]), 0.0]
        step = float(opts["step_m"])
        ok = (d.move(d.tcp() * [1, 1, 0] + [0, 0, carry], step_m=step)
              and d.move(beside * [1, 1, 0] + [0, 0, carry], step_m=step)
              and d.move(beside, settle=int(opts["settle_steps"]), step_m=step)
              and (float(opts["side_clear"]) == 0.0  # lowered in place: no slide
                   or d.move(tcp, settle=int(opts["settle_steps"]),
                             step_m=float(opts["slide_step_m"]))))
        self.state["place_tcp"] = tcp
        return SkillOutcome("ok") if ok else self._out_of_steps()

    def _pull_to_radius(self, opts, pose) -> SkillOutcome:
        """Draw the held tool straight towards the robot base (in xy, at the grasp's
        height) until its prong's centre is ``radius`` metres from the base, then lift
        it ``lift_by`` metres off the table (the tool is no longer in use)."""
        if not self.held:
            return SkillOutcome("blocked", "no tool is held (pick it up first)")
        d = self.driver
        base = self._p(self.u.agent.robot)
        tip = self.prong_centre()
        out = (tip - base) * [1, 1, 0]
        dist = float(np.linalg.norm(out))
        travel = max(0.0, dist - float(opts["radius"]))
        end = d.tcp() - out / max(dist, 1e-9) * travel
        end[2] = self.grasp_z
        ok = (d.move(end, settle=int(opts["settle_steps"]), step_m=float(opts["step_m"]))
              and d.move(d.tcp() + [0.0, 0.0, float(opts["lift_by"])], settle=0))
        return SkillOutcome("ok") if ok else self._out_of_steps()

    def _push_to_zone(self, opts, pose) -> SkillOutcome:
        """Push the held tool straight along the direction from the target to the goal
        region's centre (in xy, at the grasp's height) by the target's distance to that
        centre plus ``beyond`` metres, then hold it still for ``settle_steps`` (where the
        tool meets the target, and so where the target stops, is the pose's business)."""
        if not self.held:
            return SkillOutcome("blocked", "no tool is held (pick it up first)")
        d = self.driver
        out = (self.zone_centre() - self._p(self.target_actor)) * [1, 1, 0]
        dist = float(np.linalg.norm(out))
        travel = dist + float(opts["beyond"])
        end = d.tcp() + out / max(dist, 1e-9) * travel
        end[2] = self.grasp_z
        ok = d.move(end, settle=int(opts["settle_steps"]), step_m=float(opts["step_m"]))
        return SkillOutcome("ok") if ok else self._out_of_steps()

    # ------------------------------------------------------------ perception
    def observe(self, cameras: bool = True) -> Observation:
        """Return the primitive facts from the simulator's state (see the module
        docstring; ``cameras`` changes nothing: no camera is used)."""
        cube = self._p(self.target_actor)
        cube_yaw = _yaw(self._q(self.target_actor))
        side = 2 * self.world.env.target_half
        facts: list[Fact] = [("pose", self.target_name, *map(float, cube), cube_yaw),
                             ("size", self.target_name, side, side, side)]
        base = self.zone_centre()
        facts.append(("reach_zone", self.context_name, float(base[0]), float(base[1]),
                      float(self.world.zone_radius)))
        if self.held:
            tip = self.prong_centre()
            axis = self.tool_point((0.0, 0.0, 0.0))
            facts += [("held", self.spec.name),
                      ("tip_position", self.spec.name, *map(float, tip)),
                      ("tool_roll", self.spec.name, 0.0),
                      ("tool_axis_y", self.spec.name, float(axis[1]))]
        for item in self.world.items.values():
            facts += item.spec.catalogue_facts()
        return Observation(facts=tuple(facts), truth=self.truth())

    def truth(self) -> dict[str, tuple[float, float, float, float]]:
        """Return ``name -> (x, y, z, yaw)`` of the target and the tool (its frame)."""
        out = {}
        for name, actor in ((self.target_name, self.target_actor),
                            (self.spec.name, self.tool_actor)):
            p = self._p(actor)
            out[name] = (float(p[0]), float(p[1]), float(p[2]), _yaw(self._q(actor)))
        return out

    # ---------------------------------------------------------------- oracle
    def verdict(self) -> Verdict:
        """Return ManiSkill's verdict: ``evaluate()["success"]``, with the target's xy
        distance to the goal region's centre (the robot base or the goal actor) against
        the region's radius, and the ``evaluate()`` entries ``[env] measures`` names."""
        info = self.u.evaluate()
        success = bool(info["success"][0])
        cube = self._p(self.target_actor)
        if self.world.zone_centre == "robot":
            centre, about = self._p(self.u.agent.robot.get_links()[0]), "the robot base"
        else:
            centre, about = self.zone_centre(), f"the centre of {self.world.zone_centre}"
        dist = float(np.linalg.norm(cube[:2] - centre[:2]))
        measures: dict[str, Any] = {"evaluate_success": success}
        for name in self.world.env.measures:
            value = info[name]
            value = value.reshape(-1)[0] if hasattr(value, "reshape") else value
            measures[name] = bool(value) if getattr(value, "dtype", None) is not None \
                and str(value.dtype).endswith("bool") else float(value)
        measures["control_steps"] = self.steps
        # the arm's fastest joint (the fingers left out), as ManiSkill's is_static reads it
        qvel = self.u.agent.robot.get_qvel()[0, :-2].numpy()
        speed = float(np.max(np.abs(qvel))) if qvel.size else 0.0
        measures["arm_joint_speed_rad_s"] = round(speed, 4)
        radius = float(self.world.zone_radius)
        note = ""
        if (dist < radius) != success:
            # the distance alone would say otherwise: say what else evaluate() judged
            note = (f"ManiSkill evaluate() success {success}, the arm's joints at up to "
                    f"{speed:.2f} rad/s")
        return Verdict(f"{self.target_name} distance to {about} in xy", dist,
                       radius, "m", "<", success,
                       f"ManiSkill {self.world.env.task} evaluate()",
                       detail=f"ManiSkill evaluate() success={success}", measures=measures,
                       note=note)

    def close(self) -> None:
        """Close ManiSkill's environment."""
        env = getattr(self, "env", None)
        if env is not None:
            env.close()
            self.env = None


@contextmanager
def open_episode(world: World, variant: str, location: int, tool: str, seed: int = 0,
                 gui: bool = False, images_dir=None, pose_target: Optional[PoseTarget] = None,
                 *, robot: bool = True, record=None) -> Iterator[Episode]:
    """Build ManiSkill's scene for the location's seed and yield an :class:`Episode`;
    with ``record`` (:class:`creative_py.backends.maniskill.recorder.Recorder`) the environment
    has the clip's camera and the recorder keeps its states from the reset on."""
    if gui:
        raise ValueError("the ManiSkill backend has no window here (no display)")
    ep = Episode(world, variant, location, tool, seed, pose_target, robot, record)
    try:
        yield ep
    finally:
        ep.close()


def tool_rests(world: World, tool: str) -> bool:
    """Return whether ``tool`` lies still on the table: the demonstration's scene,
    then ten control steps holding the robot still; rests unless it dropped 1 cm."""
    demo = world.manifest.demonstration
    with open_episode(world, demo.variant, demo.location, tool) as ep:
        z0 = ep._p(ep.tool_actor)[2]
        ep.driver.set_gripper(OPEN, 10)
        return z0 - ep._p(ep.tool_actor)[2] <= 0.01

