"""The load ManiSkill's physics puts on the tool while it acts (the pull).

After every control step of the tool action, :class:`LoadMonitor` reads SAPIEN's
contacts of the tool's actor with anything but the robot (the cube, the table) and
sums their normal forces, the contact impulse of the last physics step divided by that
step's length (ManiSkill runs 5 physics steps of 0.01 s per control step, so one
sample in 5). It keeps the sample with the largest sum, where on the tool it acted
(the force-weighted centroid, tool frame) and the grasp point (the TCP in the tool
frame), and the 95th percentile of the samples with contact: the same fields as the
pybullet backend's ``ToolLoad.to_dict()``, which the strength check of a created tool
reads. Nothing here decides an outcome.

Units: newtons, metres, newton seconds; the tool frame unless a name says world.
"""

from __future__ import annotations

from typing import Any, Optional

import numpy as np

ROBUST_PERCENTILE = 95.0
"""The percentile of the per-sample summed normal force that ``robust_force_n`` is."""


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
        self.robot_names = {link.name for link in u.agent.robot.get_links()}
        self.dt = 1.0 / float(u.sim_freq)
        self.samples: list[float] = []
        self.best: Optional[dict[str, Any]] = None

    def sample(self) -> None:
        """Read the tool's contacts now and keep the sum of their normal forces."""
        ep = self.ep
        total, weighted, vector, points, touched = 0.0, np.zeros(3), np.zeros(3), 0, set()
        for contact in self.scene.get_contacts():
            names = [b.entity.name for b in contact.bodies]
            if self.tool_name not in names:
                continue
            other = names[1] if names[0] == self.tool_name else names[0]
            if other in self.robot_names:
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
                touched.add(other.split("_", 1)[-1])
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
                         "contacts": points, "bodies": sorted(touched),
                         "step": ep.steps}

    def result(self) -> Optional[dict[str, Any]]:
        """Return the load as JSON-ready data (the pybullet ``ToolLoad.to_dict`` fields),
        with zeros when the tool touched nothing."""
        contact = [s for s in self.samples if s > 0]
        best = self.best or {"max_force_n": 0.0, "point": None, "force": None,
                             "grasp_point": None, "contacts": 0, "bodies": [], "step": 0}
        return {**best, "steps": len(self.samples),
                "robust_force_n": float(np.percentile(contact, ROBUST_PERCENTILE))
                if contact else 0.0,
                "contact_steps": len(contact),
                "impulse_ns": float(sum(contact) / self.ep.u.control_freq)}
