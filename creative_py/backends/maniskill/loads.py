"""The load ManiSkill's physics puts on the tool while it acts (the pull).

After every control step of the tool action, :class:`LoadMonitor` reads SAPIEN's
contacts of the tool's actor with the case's target (``[roles] target``, ManiSkill's
actor ``[env] target``: the cube the tool pulls) and sums their normal forces, the
contact impulse of the last physics step divided by that step's length (ManiSkill runs
5 physics steps of 0.01 s per control step, so one sample in 5). What else the tool
touches (the table it is dragged along, 1 mm from the grasp) is named in
``other_bodies``, not counted: it is no load on the handle. It keeps the sample with
the largest sum, where on the tool it acted (the force-weighted centroid, tool frame)
and the grasp point (the TCP in the tool frame), and the robust force, the 95th
percentile of the force averaged over each ``LOAD_WINDOW_S`` (0.1 s) over the windows
with contact: the same fields and the same rule as the pybullet backend's
``ToolLoad.to_dict()`` (:mod:`creative_py.simulator.load`), which the strength
check of a created tool reads. Nothing here decides an outcome.

Units: newtons, metres, newton seconds; the tool frame unless a name says world.
"""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

from creative_py.simulator.load import LOAD_WINDOW_S, robust_force, samples_per_window


def _to_tool(tool_p: np.ndarray, tool_q_wxyz: np.ndarray, world: np.ndarray) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    w, x, y, z = (float(v) for v in tool_q_wxyz)
    return Rotation.from_quat([x, y, z, w]).inv().apply(np.asarray(world) - tool_p)


class LoadMonitor:
    """Samples the tool's contact load once per control step of an episode.

    Parameters
    ----------
    ep : Episode
        The ManiSkill episode (:class:`creative_py.backends.maniskill.episode.Episode`).
    """

    def __init__(self, ep: Any) -> None:
        self.ep = ep
        u = ep.u
        self.scene = u.scene.sub_scenes[0]
        self.tool_name = ep.tool_actor._objs[0].name
        self.target = ep.target_actor._objs[0].name
        self.target_role = ep.target_name
        self.robot_names = {link.name for link in u.agent.robot.get_links()}
        self.dt = 1.0 / float(u.sim_freq)
        self.samples: list[float] = []
        self.best: Optional[dict[str, Any]] = None
        self.others: set[str] = set()

    def sample(self) -> None:
        """Read the tool's contacts with the target now and keep the sum of their
        normal forces."""
        ep = self.ep
        total, weighted, vector, points = 0.0, np.zeros(3), np.zeros(3), 0
        for contact in self.scene.get_contacts():
            names = [b.entity.name for b in contact.bodies]
            if self.tool_name not in names:
                continue
            other = names[1] if names[0] == self.tool_name else names[0]
            if other in self.robot_names:
                continue
            if other != self.target:
                if any(float(np.linalg.norm(p.impulse)) > 0.0 for p in contact.points):
                    self.others.add(other.split("_", 1)[-1])
                continue
            for p in contact.points:
                # SAPIEN's impulse of the contact point over the last physics step (its
                # sign follows the order of the contact's two bodies)
                f = np.asarray(p.impulse, dtype=float) / self.dt
                n = abs(float(np.dot(f, np.asarray(p.normal, dtype=float))))
                if n <= 0.0:
                    continue
                total += n
                weighted += n * np.asarray(p.position, dtype=float)
                vector += f
                points += 1
        self.samples.append(total)
        if total > 0 and (self.best is None or total > self.best["max_force_n"]):
            tool = ep.tool_actor
            tp, tq = ep._p(tool), ep._q(tool)
            point = _to_tool(tp, tq, weighted / total)
            force = _to_tool(tp, tq, tp + vector)  # a direction: rotated only
            grasp = _to_tool(tp, tq, ep.driver.tcp()) if ep.held else None
            self.best = {"max_force_n": total, "point": [float(v) for v in point],
                         "force": [float(v) for v in force],
                         "grasp_point": None if grasp is None else [float(v) for v in grasp],
                         "contacts": points, "bodies": [self.target_role],
                         "step": ep.steps}

    def result(self) -> Optional[dict[str, Any]]:
        """Return the load as JSON-ready data (``creative_py.simulator.load.ToolLoad.to_dict``'s fields),
        with zeros when the tool touched nothing."""
        contact = [s for s in self.samples if s > 0]
        best = self.best or {"max_force_n": 0.0, "point": None, "force": None,
                             "grasp_point": None, "contacts": 0, "bodies": [], "step": 0}
        per_window = samples_per_window(float(self.ep.u.control_freq))
        return {**best, "steps": len(self.samples),
                "robust_force_n": robust_force(self.samples, per_window),
                "contact_steps": len(contact),
                "impulse_ns": float(sum(contact) / self.ep.u.control_freq),
                "other_bodies": sorted(self.others), "window_s": LOAD_WINDOW_S}
