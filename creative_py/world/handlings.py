"""The handlings' schemas: how a tool kind's ``HANDLING`` says its tool starts and is grasped.

A catalogued object's spec (:mod:`creative_py.kinds`) names, as data, how it is held
(``HANDLING``). Each handling of :data:`HANDLINGS` lists the fields of ``scene.toml``'s
``[tool_start]`` table it reads (``start_fields``: ``name -> default``, None for
required) and the options of the ``grasp`` primitive it takes (``grasp_options``:
``name -> default``, the union of which is the ``grasp`` skill's options,
:data:`creative_py.world.skills.SKILLS`). A backend brings the motion
(the pybullet backend's :mod:`creative_py.backends.pybullet.tools`: the spawn, the grasp,
how the held tool is moved, what the arm feels of it), keyed by the same names.

A *handled* tool (``"handle"``: hooks, sticks, paddles) starts lying head-flat on a
pedestal: the butt end at ``position`` on the pedestal's top, at ``roll``; the pedestal
is ``pedestal_width`` wide, stands on ``pedestal_base_z`` and runs under the bare handle.
Its grasp approaches the butt end along +x from ``approach`` m behind it and lifts the
tool to ``lift_to``. A *top-gripped* tool (``"top"``: blocks) starts with its frame's
(x, y) and the support's top z at ``position``, heading ``yaw`` (rad), coloured by its
object set (``colours``); its grasp comes down from ``carry_z`` and grips it
``clearance`` above its top, the gripper at ``gripper_yaw``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Mapping


@dataclass(frozen=True)
class Handling:
    """One way of holding a tool: its name (a spec's ``HANDLING``), the ``[tool_start]``
    fields it reads (``name -> default``, None for required) and the options of the
    ``grasp`` primitive it takes (``name -> default``)."""

    name: str
    start_fields: Mapping[str, Any]
    grasp_options: Mapping[str, Any]


HANDLINGS: dict[str, Handling] = {h.name: h for h in (
    Handling("handle",
             start_fields={"position": None, "roll": None, "pedestal_width": None,
                           "pedestal_base_z": None, "pedestal_friction": 0.8,
                           "colour": (0.95, 0.8, 0.1, 1.0)},
             grasp_options={"approach": 0.10, "free_speed": 0.35, "speed": 0.20,
                            "lift_to": None}),
    Handling("top",
             start_fields={"position": None, "yaw": 0.0, "colours": {}},
             grasp_options={"carry_z": None, "clearance": 0.004, "gripper_yaw": 0.0}),
)}
"""The handlings by the ``HANDLING`` name a tool kind's spec gives."""


def handling(spec: Any) -> Handling:
    """Return the handling of ``spec``; raise :class:`TypeError` naming the registered
    handlings."""
    name = getattr(spec, "HANDLING", None)
    if name not in HANDLINGS:
        raise TypeError(f"{getattr(spec, 'name', spec)!r}: no handling {name!r} in the "
                        f"simulator; handlings: {', '.join(HANDLINGS)}")
    return HANDLINGS[name]


def quantities(spec: Any) -> dict[str, float]:
    """Return the tool's named sizes (m) that scene expressions may use
    (``tool.<q>``): the spec's own."""
    return spec.quantities()
