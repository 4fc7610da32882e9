"""How the simulator holds a tool: the handlings, chosen by a tool kind's ``HANDLING``.

A catalogued object's spec is its tool kind's (:mod:`creative_py.kinds`: one plug-in
module per kind); the spec says, as data, how it is held (``HANDLING``), and the
handlings registered in :data:`HANDLINGS` bring the motion: where the tool starts (the
``[tool_start]`` table of ``scene.toml``), the grasp, how the held tool is moved and
what the arm's proprioception says about it. Each handling's ``[tool_start]`` fields
and grasp options are its schema's (:mod:`creative_py.world.handlings`, by the same
names). :func:`catalogue_facts` is the one place that gives the catalogue facts of an
object (the spec's own).

A handling's methods take the running :class:`~creative_py.backends.pybullet.episode.Episode` as
``ep`` (typed ``Any``: the episode imports this module).

A *handled* tool (``HANDLING = "handle"``: hooks, sticks, paddles) is held by the butt
end of a handle along +x, the gripper along the handle; its *roll* is the rotation about
the handle axis, 0 with the side the spec calls ``roll_side`` (a hook's prong) down,
+pi/2 with it towards +y. The spec gives ``grip_offset``, ``grip_point``,
``handle_length``, ``handle_width``, ``roll_side``, ``has_head``, ``head_width``,
``working_point()`` and ``reach()``. A *top-gripped* tool (``"top"``: blocks) is gripped
from above, gripper down; its spec gives ``height`` and ``centre()``.
"""

from __future__ import annotations

import math
from typing import Any, Callable, Mapping

import numpy as np
import pybullet as pb

from creative_py.mesh.spec import Box
from creative_py.backends.pybullet.arm import gripper_down, gripper_forward, quat_angle
from creative_py.backends.pybullet.bodies import Surface, frame_pose, load_tool_urdf, spawn_parts, spawn_spec
from creative_py.backends.pybullet.core import Pose
from creative_py.simulator.types import Fact, SkillOutcome
from creative_py.world import handlings
from creative_py.world.handlings import Handling


IDENTITY = (0.0, 0.0, 0.0, 1.0)


# ---------------------------------------------------------- handled-tool geometry
def prong_centre(spec: Any) -> tuple[float, float, float]:
    """Return the handled tool's working point (a hook's prong centre, a stick's tip),
    tool frame, metres."""
    return spec.working_point()


def prong_reach(spec: Any) -> float:
    """Return how far the handled tool reaches from the handle axis, metres."""
    return spec.reach()


def tool_orientation(spec: Any, roll: float) -> tuple[float, float, float, float]:
    """Return the world orientation of the tool frame, handle along +x, at ``roll`` (rad)."""
    side = spec.roll_side
    return tuple(pb.getQuaternionFromEuler((roll - side * math.pi / 2, 0.0, 0.0)))


def tool_in_gripper(spec: Any) -> Pose:
    """Return the tool frame's pose in the ``right_gripper`` frame (the known grasp)."""
    g_pos, g_quat = (0.0, 0.0, 0.0), gripper_forward(0.0)
    t_quat = tool_orientation(spec, 0.0)
    inv = pb.invertTransform(g_pos, g_quat)
    _, rel = pb.multiplyTransforms(inv[0], inv[1], (0, 0, 0), t_quat)
    # The grip point (grip_offset, 0, 0) of the tool sits at the gripper's origin.
    offset = pb.multiplyTransforms((0, 0, 0), rel, (-spec.grip_offset, 0, 0), IDENTITY)[0]
    return tuple(offset), tuple(rel)


def roll_of(spec: Any, quat) -> float:
    """Return the tool roll (rad, 0 = prong down) of a tool-frame orientation."""
    side = spec.roll_side
    m = np.asarray(pb.getMatrixFromQuaternion(quat)).reshape(3, 3)
    d = side * m[:, 1]
    return math.atan2(float(d[1]), float(-d[2]))


def grasp_slip(ep: Any) -> tuple[float, float]:
    """Return how far the held tool has slipped in the grasp: (angle rad, offset m).

    Compares the tool body's own frame (simulator state) with where the grasp holds
    it, the gripper's pose times the grasp frame (:attr:`Episode.grasp`). pybullet's
    fixed grasp constraint is soft against contacts with static bodies: a jammed tool
    twists in the hand while the gripper follows its commands.
    """
    want = ep.tool_pose()
    have = frame_pose(ep.sim, ep.tool_body)
    return quat_angle(want[1], have[1]), math.dist(want[0], have[0])


# ---------------------------------------------------------------------- handlings
class ToolKind:
    """How the simulator holds one family of tools (subclass per handling).

    ``START_FIELDS`` lists the fields of ``[tool_start]`` the handling reads (``name ->
    default``, None for required); ``GRASP_OPTIONS`` the options of the ``grasp``
    primitive (``name -> default``): both its schema's (``SCHEMA``, a
    :class:`~creative_py.world.handlings.Handling`). What a tool is (its catalogue facts, sizes, the
    fields a randomised world redraws) its spec says (:class:`creative_py.kinds.parts.KindSpec`).
    """

    SCHEMA: Handling
    START_FIELDS: Mapping[str, Any] = {}
    GRASP_OPTIONS: Mapping[str, Any] = {}

    def catalogue_facts(self, spec: Any) -> list[Fact]:
        """Return the catalogue facts of ``spec`` (metres, degrees)."""
        return spec.catalogue_facts()

    def spawn(self, ep: Any, start: Mapping[str, Any]) -> int:
        """Create the tool where it starts (and any support it needs); return its body."""
        raise NotImplementedError

    def initial_grasp(self, spec: Any) -> Pose | None:
        """Return the tool frame in the gripper frame if known before grasping."""
        return None

    def grasp(self, ep: Any, opts: Mapping[str, Any]) -> SkillOutcome:
        """Grasp the tool where it lies and lift it."""
        raise NotImplementedError

    def attitude(self, ep: Any) -> float:
        """Return the held tool's attitude angle (rad) that :meth:`move` keeps."""
        raise NotImplementedError

    def move(self, ep: Any, pos, attitude: float, speed: float | None,
             guard: Callable[[], SkillOutcome | None] | None = None) -> SkillOutcome:
        """Move the gripper to ``pos`` (m) holding the tool at ``attitude`` (rad).

        ``guard`` is run after every guarded step of the motion; an outcome it returns
        ends the move (:meth:`creative_py.backends.pybullet.arm.Arm.move_to`).
        """
        raise NotImplementedError

    def working_point(self, ep: Any) -> tuple[float, float, float]:
        """Return the world point of the tool that does the work (proprioception)."""
        return ep.tool_pose()[0]

    def proprioception(self, ep: Any) -> list[Fact]:
        """Return what the arm feels of the held tool, after ``held/1``."""
        return []

    def height(self, spec: Any) -> float | None:
        """Return the tool's known height (m), for perception; None if unknown."""
        return None

    def centre(self, spec: Any) -> tuple[float, float, float]:
        """Return the point of the tool frame reported as its true position (m)."""
        return (0.0, 0.0, 0.0)


class HandleHeld(ToolKind):
    """Handled tools (hooks, sticks, paddles): a handle along +x from the butt end, maybe
    a head (prong, blade) at its end.

    The tool starts lying head-flat on a pedestal (``[tool_start]``: the butt end at
    ``position`` on the pedestal's top, ``roll``; the pedestal is ``pedestal_width``
    wide, stands on ``pedestal_base_z`` and runs under the bare handle).
    """

    SCHEMA = handlings.HANDLINGS["handle"]
    START_FIELDS = SCHEMA.start_fields
    GRASP_OPTIONS = SCHEMA.grasp_options

    def spawn(self, ep: Any, start: Mapping[str, Any]) -> int:
        spec, sim = ep.spec, ep.sim
        butt_x, axis_y, top_z = start["position"]
        x0 = butt_x + spec.grip_offset + 0.06
        x1 = butt_x + spec.handle_length - spec.head_width - 0.01
        if x1 - x0 < 0.03:
            x0 = x1 - 0.03
        base = start["pedestal_base_z"]
        stand_h = top_z - base
        ep.supports["pedestal"] = spawn_parts(
            sim, [Box((0, 0, 0), (x1 - x0, start["pedestal_width"], stand_h))],
            (((x0 + x1) / 2, axis_y, base + stand_h / 2), IDENTITY), 0.0,
            Surface(start["pedestal_friction"], (0.3, 0.3, 0.3, 1.0)))
        lying = ((butt_x, axis_y, top_z + spec.handle_width / 2 + 0.0005),
                 tool_orientation(spec, start["roll"]))
        if ep.item.urdf is not None:
            return load_tool_urdf(sim, ep.item.urdf, lying, ep.item.friction)
        return spawn_spec(sim, spec, lying, Surface(ep.item.friction, tuple(start["colour"])))

    def initial_grasp(self, spec: Any) -> Pose:
        return tool_in_gripper(spec)

    def attitude(self, ep: Any) -> float:
        """Return the held tool's roll (rad, 0 = prong down) by proprioception."""
        return roll_of(ep.spec, ep.tool_pose()[1])

    def move(self, ep: Any, pos, roll: float, speed: float | None,
             guard: Callable[[], SkillOutcome | None] | None = None) -> SkillOutcome:
        """Move the gripper (pointing +x) to ``pos`` while turning the tool to ``roll``.

        A big change of roll is split into pieces under 70 degrees, so that the
        orientation turns through the intermediate rolls (about the handle axis)
        instead of taking whichever way a half-turn slerp picks.
        """
        start_pos, start_quat = ep.robot.gripper_pose()
        start_roll = roll_of(ep.spec, pb.multiplyTransforms(start_pos, start_quat,
                                                            *ep.grasp)[1])
        n = max(1, math.ceil(abs(roll - start_roll) / math.radians(70)))
        for i in range(1, n + 1):
            t = i / n
            p = tuple(a + t * (b - a) for a, b in zip(start_pos, pos))
            r = start_roll + t * (roll - start_roll)
            res = ep.robot.move_to((p, gripper_forward(r)), speed=speed, watch=ep.watch,
                                   guard=guard)
            if not res.ok:
                return res
        return res

    def gripper_for_tool(self, ep: Any, tool_origin, roll: float):
        """Return the gripper position that puts the tool frame's origin at ``tool_origin``."""
        q = tool_orientation(ep.spec, roll)
        return tuple(pb.multiplyTransforms(tool_origin, q, ep.spec.grip_point, IDENTITY)[0])

    def grasp(self, ep: Any, opts: Mapping[str, Any]) -> SkillOutcome:
        """Approach the butt end along +x, close on the grip point, lift to ``lift_to``."""
        if ep.held:
            return SkillOutcome("ok", "already holding the tool")
        spec = ep.spec
        origin, quat = frame_pose(ep.sim, ep.tool_body)
        roll = roll_of(spec, quat)
        grip = pb.multiplyTransforms(origin, quat, spec.grip_point, IDENTITY)[0]
        pre = (grip[0] - opts["approach"], grip[1], grip[2])
        for target, speed in (((pre[0], pre[1], pre[2] + 0.05), opts["free_speed"]),
                              (pre, opts["speed"]), (grip, opts["speed"])):
            res = self.move(ep, target, roll, speed)
            if not res.ok:
                return res
        ep.robot.grasp(ep.tool_body, ep.grasp)
        ep.held = True
        return self.move(ep, (grip[0], grip[1], opts["lift_to"]), roll, opts["free_speed"])

    def working_point(self, ep: Any) -> tuple[float, float, float]:
        """Return the world position of the spec's working point (a hook's prong centre,
        a stick's tip)."""
        pos, quat = ep.tool_pose()
        return tuple(pb.multiplyTransforms(pos, quat, prong_centre(ep.spec), IDENTITY)[0])

    def proprioception(self, ep: Any) -> list[Fact]:
        """``tip_position/4`` (the prong's centre, m) and ``tool_roll/2`` (rad)."""
        n = ep.spec.name
        return [("tip_position", n, *self.working_point(ep)),
                ("tool_roll", n, self.attitude(ep))]


class TopGripped(ToolKind):
    """Blocks (prisms, boxes, cylinders): lying on their base, gripped from above.

    ``[tool_start]``: the block frame's (x, y) and the support's top z in ``position``,
    the heading ``yaw`` (rad); ``colours`` maps an object set to its RGBA colour.
    """

    SCHEMA = handlings.HANDLINGS["top"]
    START_FIELDS = SCHEMA.start_fields
    GRASP_OPTIONS = SCHEMA.grasp_options

    def spawn(self, ep: Any, start: Mapping[str, Any]) -> int:
        x, y, z = start["position"]
        pose = ((x, y, z + 0.0005), tuple(pb.getQuaternionFromEuler((0, 0, start["yaw"]))))
        item = ep.item
        if item.urdf is not None:
            return load_tool_urdf(ep.sim, item.urdf, pose, lateral_friction=item.friction)
        colour = tuple(start["colours"].get(item.set, (0.6, 0.6, 0.6, 1.0)))
        return spawn_spec(ep.sim, item.spec, pose, Surface(item.friction, colour))

    def attitude(self, ep: Any) -> float:
        """Return the gripper's yaw (rad)."""
        quat = ep.robot.gripper_pose()[1]
        return float(pb.getEulerFromQuaternion(quat)[2])

    def move(self, ep: Any, pos, yaw: float, speed: float | None,
             guard: Callable[[], SkillOutcome | None] | None = None) -> SkillOutcome:
        """Move the gripper, pointing down with its x axis at ``yaw``, to ``pos``."""
        return ep.robot.move_to((tuple(pos), gripper_down(yaw)), speed=speed, watch=ep.watch,
                                guard=guard)

    def grasp(self, ep: Any, opts: Mapping[str, Any]) -> SkillOutcome:
        """Come down on the block from ``carry_z`` (its base height when carried), grip
        it ``clearance`` above its top, and lift it back."""
        if ep.held:
            return SkillOutcome("ok", "already holding the object")
        height, yaw = ep.spec.height, opts["gripper_yaw"]
        base, _ = frame_pose(ep.sim, ep.tool_body)
        x, y = base[0], base[1]
        carry_z = opts["carry_z"] + height + opts["clearance"]
        for target in ((x, y, carry_z), (x, y, base[2] + height + opts["clearance"])):
            res = self.move(ep, target, yaw, None)
            if not res.ok:
                return res
        g = ep.robot.gripper_pose()
        obj = frame_pose(ep.sim, ep.tool_body)
        inv = pb.invertTransform(*g)
        rel = pb.multiplyTransforms(inv[0], inv[1], obj[0], obj[1])
        ep.grasp = (tuple(rel[0]), tuple(rel[1]))
        ep.robot.grasp(ep.tool_body, ep.grasp)
        ep.held = True
        return self.move(ep, (x, y, carry_z), yaw, None)

    def height(self, spec: Any) -> float:
        return spec.height

    def centre(self, spec: Any) -> tuple[float, float, float]:
        """Return the spec's centre (a block's box: (0, 0, height / 2)) in its frame."""
        return spec.centre()


HANDLINGS: dict[str, ToolKind] = {k.SCHEMA.name: k for k in (HandleHeld(), TopGripped())}
"""The handlings by the ``HANDLING`` name a tool kind's spec gives (the names of
:data:`creative_py.world.handlings.HANDLINGS`)."""


def tool_kind(spec: Any) -> ToolKind:
    """Return the handling of ``spec``; raise naming the registered handlings
    (:func:`creative_py.world.handlings.handling`)."""
    return HANDLINGS[handlings.handling(spec).name]


def catalogue_facts(spec: Any) -> list[Fact]:
    """Return the catalogue facts of any catalogued object, by its kind."""
    return spec.catalogue_facts()
