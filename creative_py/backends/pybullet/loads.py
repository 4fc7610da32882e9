"""The load the physics puts on a tool: the contact force during the tool action.

While the manifest's tool action runs (``tool_action = true`` in ``case.toml``: the
pull, the door's release), a :class:`ToolLoadMonitor` reads, after every physics step,
every contact point whose body A is the tool (``getContactPoints(bodyA=tool)``) and sums
their normal forces. It keeps the step with the largest sum and where on the tool that
force acted: the contact points' centroid weighted by their normal forces, in the
tool's own frame (the spec's frame: the handle along +x from its butt end; a block's
base centred on the origin).

One step's peak is a poor measure of the load: a contact that opens or closes in a
step (the door meeting the wedge) gives a spike an order of magnitude above the force
that then holds (a wedge: a 3,557 N spike, a few hundred newtons for the rest of the
action), and the spike changes with the time step. So the monitor also keeps every
step's sum and gives a robust force beside the peak: the :data:`ROBUST_PERCENTILE`
th percentile of the sums over the steps with contact, the load the tool bears for
all but the briefest part of the action. The strength check of a created tool
(:mod:`creative_py.fabrication.strength`) reads the figures; nothing here decides an
outcome.

Units: newtons, metres, the tool frame unless a name says ``world``.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import Any, Optional

import numpy as np
import pybullet as pb

from creative_py.backends.pybullet.bodies import frame_pose

ROBUST_PERCENTILE = 95.0
"""The percentile of the per-step summed normal force (over the steps with contact)
that :attr:`ToolLoad.robust_force_n` is."""


@dataclass(frozen=True)
class ToolLoad:
    """The largest contact load on a tool during its action.

    Attributes
    ----------
    max_force_n : float
        The largest sum over one physics step of the normal forces of the tool's
        contacts, newtons (0.0 when the tool touched nothing).
    point : tuple of float or None
        Where it acted: the contacts' centroid weighted by normal force, tool frame,
        metres (None without contact).
    force : tuple of float or None
        The summed contact force vector of that step (normal and friction), tool frame,
        newtons.
    grasp_point : tuple of float or None
        The gripper frame's origin in the tool frame at that step, metres (None when the
        tool was not held: a placed block).
    contacts : int
        Contact points of that step.
    bodies : tuple of str
        The names of the bodies it touched then, sorted.
    step : int
        The physics step (of the episode) at which it happened.
    steps : int
        The physics steps watched (the length of the tool action).
    robust_force_n : float
        The :data:`ROBUST_PERCENTILE` th percentile of the per-step summed normal force
        over the steps with contact, newtons (0.0 without contact): the force the
        strength check uses, the peak being a contact spike.
    contact_steps : int
        The steps with contact.
    impulse_ns : float
        The summed normal force integrated over the action, newton seconds.
    """

    max_force_n: float = 0.0
    point: Optional[tuple[float, float, float]] = None
    force: Optional[tuple[float, float, float]] = None
    grasp_point: Optional[tuple[float, float, float]] = None
    contacts: int = 0
    bodies: tuple[str, ...] = ()
    step: int = 0
    steps: int = 0
    robust_force_n: float = 0.0
    contact_steps: int = 0
    impulse_ns: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        """Return the load as JSON-ready data (tuples become lists, floats rounded)."""
        d = asdict(self)
        for k in ("point", "force", "grasp_point"):
            if d[k] is not None:
                d[k] = [round(float(v), 6) for v in d[k]]
        for k in ("max_force_n", "robust_force_n", "impulse_ns"):
            d[k] = round(float(d[k]), 6)
        d["bodies"] = list(d["bodies"])
        return d

    @classmethod
    def from_dict(cls, data: Optional[dict[str, Any]]) -> "ToolLoad":
        """Return the load :meth:`to_dict` wrote (an empty load for None)."""
        if not data:
            return cls()
        def vec(v):
            return None if v is None else tuple(float(x) for x in v)
        return cls(float(data.get("max_force_n", 0.0)), vec(data.get("point")),
                   vec(data.get("force")), vec(data.get("grasp_point")),
                   int(data.get("contacts", 0)), tuple(data.get("bodies", ())),
                   int(data.get("step", 0)), int(data.get("steps", 0)),
                   float(data.get("robust_force_n", data.get("max_force_n", 0.0))),
                   int(data.get("contact_steps", 0)), float(data.get("impulse_ns", 0.0)))


class ToolLoadMonitor:
    """Watch the tool's contacts after every physics step of an episode's tool action.

    Parameters
    ----------
    ep : Episode
        The episode (its ``sim``, ``tool_body``, ``held``, ``grasp`` and ``bodies``).

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

    def start(self) -> None:
        """Begin watching (a step callback of the episode's simulator)."""
        self.ep.sim.after_step.append(self._after_step)

    def stop(self) -> ToolLoad:
        """Stop watching; return the load seen."""
        if self._after_step in self.ep.sim.after_step:
            self.ep.sim.after_step.remove(self._after_step)
        robust = (float(np.percentile(self._sums, ROBUST_PERCENTILE)) if self._sums
                  else 0.0)
        self.load = ToolLoad(**{**asdict(self.load), "steps": self._steps,
                                "robust_force_n": robust,
                                "contact_steps": len(self._sums),
                                "impulse_ns": self._impulse})
        return self.load

    def _after_step(self) -> None:
        self._steps += 1
        ep = self.ep
        cps = pb.getContactPoints(bodyA=ep.tool_body, physicsClientId=ep.sim.client)
        if not cps:
            return
        total = float(sum(cp[9] for cp in cps))
        self._sums.append(total)
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
            contacts=len(cps),
            bodies=tuple(sorted({self._names.get(cp[2], f"body{cp[2]}") for cp in cps})),
            step=ep.sim.steps, steps=self._steps)


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

