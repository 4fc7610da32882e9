"""The load the physics puts on a tool: the task's contact force during the tool action.

While the manifest's tool action runs (``tool_action = true`` in ``case.toml``: the
pull, the door's release), a :class:`ToolLoadMonitor` reads, after every physics step,
the contact points between the tool and the case's *target* (the object the tool acts
on: ``[roles] target`` of ``case.toml``, the cube a hook pulls, the door a wedge holds)
and sums their normal forces. That is the load the task puts on the tool; what else the
tool brushes against on the way (the table under a tool dragged along it, a tube's
wall) is named in :attr:`ToolLoad.other_bodies` but not counted: a tool resting on the
table 1 mm from the grasp is no load on its handle. The monitor keeps the step with
the largest sum and where on the tool that force acted: the contact points' centroid
weighted by their normal forces, in the tool's own frame (the spec's frame: the handle
along +x from its butt end; a block's base centred on the origin), with the grasp in
the same frame, so that the strength check's lever arm runs from the grasp.

One step's force is a poor measure of the load: a contact that opens or closes in a
step (the door meeting the wedge) gives a spike an order of magnitude above the force
that then holds (the door on the created wedge: a 1,791 N spike, 436 N for the rest of
the action), and a hook pulling a cube meets it in one-step pulses. So the robust force
beside the peak is the one every backend gives
(:mod:`creative_py.simulator.load`): the 95th percentile of the force averaged over
each 0.1 s of the action, over the windows with contact. The strength check of a
created tool (:mod:`creative_py.fabrication.strength`) reads the figures; nothing here
decides an outcome.

Units: newtons, metres, seconds, the tool frame unless a name says ``world``.
"""

from __future__ import annotations

from dataclasses import asdict
from typing import Any

import numpy as np
import pybullet as pb

from creative_py.backends.pybullet.bodies import frame_pose
from creative_py.simulator.load import (LOAD_WINDOW_S, ROBUST_PERCENTILE, ToolLoad,
                                        robust_force, samples_per_window)

__all__ = ["LOAD_WINDOW_S", "ROBUST_PERCENTILE", "ToolLoad", "ToolLoadMonitor",
           "contact_wrench"]


class ToolLoadMonitor:
    """Watch the tool's contacts with the target after every physics step of an
    episode's tool action.

    Parameters
    ----------
    ep : Episode
        The episode (its ``sim``, ``tool_body``, ``held``, ``grasp``, ``bodies`` and
        ``target_name``: the case's target role).

    Use :meth:`start` before the action and :meth:`stop` after it; :attr:`load` holds
    the result. The monitor only reads the simulation, so the physics is unchanged.
    """

    def __init__(self, ep: Any) -> None:
        self.ep = ep
        self.load = ToolLoad()
        self._steps = 0
        self._sums: list[float] = []
        self._impulse = 0.0
        self._names = {b.id: name for name, b in ep.bodies.items()}
        self.target = ep.body_id(ep.target_name)
        # A target made of bodies of its own (a scatter's cubes) is all of them.
        members = getattr(ep.bodies.get(ep.target_name), "members", None)
        self.targets = {self.target} | ({b.id for b in members().values()}
                                        if callable(members) else set())
        self._others: set[str] = set()

    def start(self) -> None:
        """Begin watching (a step callback of the episode's simulator)."""
        self.ep.sim.after_step.append(self._after_step)

    def stop(self) -> ToolLoad:
        """Stop watching; return the load seen."""
        if self._after_step in self.ep.sim.after_step:
            self.ep.sim.after_step.remove(self._after_step)
        dt = self.ep.sim.physics.time_step
        self.load = ToolLoad(**{**asdict(self.load), "steps": self._steps,
                                "robust_force_n": robust_force(
                                    self._sums, samples_per_window(1.0 / dt)),
                                "contact_steps": sum(f > 0 for f in self._sums),
                                "impulse_ns": self._impulse,
                                "other_bodies": tuple(sorted(self._others)),
                                "window_s": LOAD_WINDOW_S})
        return self.load

    def _after_step(self) -> None:
        self._steps += 1
        ep = self.ep
        every = pb.getContactPoints(bodyA=ep.tool_body, physicsClientId=ep.sim.client)
        cps = [cp for cp in every if cp[2] in self.targets]
        self._others.update(self._names.get(cp[2], f"body{cp[2]}") for cp in every
                            if cp[2] not in self.targets and cp[2] in self._names)
        total = float(sum(cp[9] for cp in cps))
        self._sums.append(total)
        if not total > 0.0:
            return
        self._impulse += total * ep.sim.physics.time_step
        if not total > self.load.max_force_n:
            return
        pos, quat = frame_pose(ep.sim, ep.tool_body)
        inv_pos, inv_quat = pb.invertTransform(pos, quat)
        rot = np.asarray(pb.getMatrixFromQuaternion(inv_quat)).reshape(3, 3)
        points = np.array([cp[5] for cp in cps], dtype=float)
        weights = np.array([cp[9] for cp in cps], dtype=float)
        world_point = (weights[:, None] * points).sum(axis=0) / total
        force = np.zeros(3)
        for cp in cps:
            # contactNormalOnB points from B to A: the force on A (the tool).
            force += cp[9] * np.asarray(cp[7]) + cp[10] * np.asarray(cp[11]) \
                + cp[12] * np.asarray(cp[13])
        point = pb.multiplyTransforms(inv_pos, inv_quat, tuple(world_point), (0, 0, 0, 1))[0]
        grasp = None
        if ep.held and ep.robot is not None and not ep.robot_parked:
            # The gripper frame in the tool frame: the inverse of the grasp.
            grasp = tuple(float(v) for v in pb.invertTransform(*ep.grasp)[0])
        self.load = ToolLoad(
            max_force_n=total, point=tuple(float(v) for v in point),
            force=tuple(float(v) for v in rot @ force), grasp_point=grasp,
            contacts=len(cps), bodies=(ep.target_name,), step=ep.sim.steps,
            steps=self._steps)


def contact_wrench(sim: Any, body: int, about: Any) -> tuple[tuple[float, float, float],
                                                            tuple[float, float, float]]:
    """Return the net contact force on ``body`` after the last step and its torque
    about the point ``about`` (world frame, N and N m): normal and friction forces of
    every contact point whose body A is ``body`` (what a force/torque sensor between the
    gripper and a held tool measures, tared: without the tool's weight). The stand-in
    robot publishes it as a wrist sensor would (:mod:`creative_py.backends.ros.standin`)."""
    force, torque = np.zeros(3), np.zeros(3)
    origin = np.asarray(about, dtype=float)
    for cp in pb.getContactPoints(bodyA=body, physicsClientId=sim.client):
        f = (cp[9] * np.asarray(cp[7]) + cp[10] * np.asarray(cp[11])
             + cp[12] * np.asarray(cp[13]))
        force += f
        torque += np.cross(np.asarray(cp[5]) - origin, f)
    return tuple(float(v) for v in force), tuple(float(v) for v in torque)

