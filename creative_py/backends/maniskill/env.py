"""A ManiSkill3 task with its tool built from a catalogued spec.

The environment is ManiSkill's own task class, named by the world's ``tasks.toml``
(``[env] task``, e.g. a tabletop task with a tool), subclassed only where the case's data
enters: the tool actor the world file names (``[env] tool``, the actor's name in
ManiSkill's scene) is built with ManiSkill's actor builder from the boxes of a tool
kind's spec (:meth:`creative_py.kinds.parts.KindSpec.parts`: handle and prong of a
hook-like tool, the handle alone of a stick; the same boxes for a catalogued and a
created tool), and a variant may move the target (``[env] target``) farther along +x
(``cube_dx``, metres; the goal actor ``[env] goal``, when there is one, moves with it).
Everything else is ManiSkill's: the robot, the table, the target, the seeded initial
state of ``reset(seed=...)`` (the tool's and the target's draws are those of the stock
task; the tool is then laid on the table at its own height, its far end where the stock
tool has its own) and the success check :meth:`evaluate`.

The tool's boxes replace the stock tool's shapes when the task builds it: the task's
scene-loading code runs unchanged (the actors are made in the same order), and the
builder of the actor with the tool's name is given the spec's boxes in place of its own.

Runs on the CPU backend (``sim_backend="cpu"``) with one environment. SAPIEN needs a
Vulkan device even without rendering: :func:`vulkan_ready` points ``VK_ICD_FILENAMES``
at Mesa's lavapipe when the variable is unset.
"""

from __future__ import annotations

import glob
import logging
import os
from typing import Any

ENV_PREFIX = "Creative"
"""The subclass of ManiSkill's task ``T`` is registered as ``Creative`` + ``T``."""

LAVAPIPE_GLOB = "/usr/share/vulkan/icd.d/lvp_icd*.json"
"""Where Debian's ``mesa-vulkan-drivers`` puts lavapipe's ICD file."""


def vulkan_ready() -> None:
    """Select Mesa's CPU Vulkan driver (lavapipe) unless ``VK_ICD_FILENAMES`` is set."""
    if os.environ.get("VK_ICD_FILENAMES"):
        return
    found = sorted(glob.glob(LAVAPIPE_GLOB))
    if found:
        os.environ["VK_ICD_FILENAMES"] = found[0]


_REGISTERED: dict[str, Any] = {}


def task_ids() -> list[str]:
    """Return the ids of ManiSkill's registered tasks (imports ManiSkill)."""
    vulkan_ready()
    import mani_skill.envs  # noqa: F401  (registers the tasks)
    from mani_skill.utils.registration import REGISTERED_ENVS

    return sorted(k for k in REGISTERED_ENVS if not k.startswith(ENV_PREFIX))


def env_id(task: str) -> str:
    """Return the id the subclass of ManiSkill's ``task`` is registered under."""
    return ENV_PREFIX + task


def env_class(task: str):
    """Return the registered subclass of ManiSkill's task ``task`` (imported and
    registered on first use, so importing this module loads no simulator)."""
    if task in _REGISTERED:
        return _REGISTERED[task]
    spec = _stock_task(task)
    from mani_skill.utils.registration import register_env

    name = "Catalogue" + spec.cls.__name__
    cls = type(name, (CatalogueTask, spec.cls), {"__qualname__": name,
                                                 "__doc__": CatalogueTask.__doc__})
    register_env(env_id(task), max_episode_steps=spec.max_episode_steps)(cls)
    _REGISTERED[task] = cls
    return cls


def _stock_task(task: str):
    """Return ManiSkill's registration of its task ``task`` (its class and episode
    length), importing ManiSkill quietened; KeyError if it has no such task."""
    vulkan_ready()
    import mani_skill.envs  # noqa: F401  (registers the tasks)
    from mani_skill import logger as maniskill_logger
    from mani_skill.utils.registration import REGISTERED_ENVS

    # ManiSkill warns at every environment it builds that no initial pose was set for the
    # builders (the episode's initialisation sets them) and that CUDA is missing (the CPU
    # backend is meant): a run printed 7 such lines a trial. Its errors still show.
    maniskill_logger.setLevel(logging.ERROR)
    if task not in REGISTERED_ENVS:
        raise KeyError(task)
    return REGISTERED_ENVS[task]


class CatalogueTask:
    """ManiSkill's task whose tool actor is built from ``tool_parts`` and whose
    target starts ``cube_dx`` farther along +x (0: the stock task).

    The overrides of a stock task's class, which :func:`env_class` puts first in the
    bases of its subclass (so ``super()`` is the stock task); imports ManiSkill, SAPIEN
    and torch only when called."""

    def __init__(self, *args, tool_actor="", target_actor="", goal_actor="",
                 tool_parts=(), tool_mass=0.5, tool_friction=None, cube_dx=0.0,
                 **kwargs):
        self.tool_actor, self.target_actor = tool_actor, target_actor
        self.goal_actor = goal_actor
        self.tool_parts = tuple(tool_parts)
        self.tool_mass = float(tool_mass)
        self.tool_friction = tool_friction
        self.cube_dx = float(cube_dx)
        self.stock_far = 0.0
        super().__init__(*args, **kwargs)

    def actor(self, name: str):
        """Return the scene's actor called ``name``."""
        return self.scene.actors[name]

    def _tool_boxes(self, builder) -> None:
        """Give ``builder`` (the stock tool's) the spec's boxes in place of its own,
        keeping how far the stock tool's shapes reach along +x."""
        import sapien

        self.stock_far = max(float(r.pose.p[0]) + float(r.scale[0])
                             for r in builder.collision_records if r.type == "box")
        builder.collision_records.clear()
        builder.visual_records.clear()
        mat = sapien.render.RenderMaterial()
        mat.set_base_color([1, 0, 0, 1])
        volume = sum(p.size[0] * p.size[1] * p.size[2] for p in self.tool_parts)
        density = self.tool_mass / volume
        phys = None
        if self.tool_friction is not None:
            f = float(self.tool_friction)
            phys = sapien.pysapien.physx.PhysxMaterial(f, f, 0.0)
        for part in self.tool_parts:
            q = sapien.Pose(q=_yaw_quat_wxyz(part.yaw)).q
            pose = sapien.Pose(list(part.center), q)
            half = [s / 2 for s in part.size]
            builder.add_box_collision(pose, half, density=density, material=phys)
            builder.add_box_visual(pose, half, material=mat)

    def _load_scene(self, options):
        if not self.tool_parts:
            return super()._load_scene(options)
        scene = self.scene
        create = scene.create_actor_builder
        env = self

        def create_actor_builder(*a, **k):
            builder = create(*a, **k)
            build = builder.build

            def build_tool(name, *ba, **bk):
                if name == env.tool_actor:
                    env._tool_boxes(builder)
                return build(name, *ba, **bk)

            builder.build = build_tool
            return builder

        scene.create_actor_builder = create_actor_builder
        try:
            return super()._load_scene(options)
        finally:
            del scene.create_actor_builder

    def _initialize_episode(self, env_idx, options):
        super()._initialize_episode(env_idx, options)
        if not self.tool_parts and self.cube_dx == 0.0:
            return
        import torch

        with torch.device(self.device):
            if self.tool_parts:
                self._lay_tool()
            self._move_target()

    def _lay_tool(self) -> None:
        """Lay the tool on the table at its own height, its far end where the stock
        tool has its own."""
        from mani_skill.utils.structs import Pose

        actor = self.actor(self.tool_actor)
        tool = actor.pose
        p = tool.p.clone()
        # the tool frame on the handle's axis, its lowest face on the table
        p[..., 2] = -min(part.center[2] - part.size[2] / 2 for part in self.tool_parts)
        # its far end where the stock tool has its own (a longer handle reaches back
        # towards the robot, not into the target's region)
        far = max(part.center[0] + part.size[0] / 2 for part in self.tool_parts)
        p[..., 0] -= max(0.0, far - self.stock_far)
        actor.set_pose(Pose.create_from_pq(p=p, q=tool.q))

    def _move_target(self) -> None:
        """Move the target (and the goal, when there is one) ``cube_dx`` along +x; the
        target is set again even where it stays (as it always was)."""
        from mani_skill.utils.structs import Pose

        for name in (self.target_actor, self.goal_actor):
            if name and (name == self.target_actor or self.cube_dx != 0.0):
                moved = self.actor(name)
                c = moved.pose.p.clone()
                c[..., 0] += self.cube_dx
                moved.set_pose(Pose.create_from_pq(p=c, q=moved.pose.q))


def _yaw_quat_wxyz(yaw: float) -> list[float]:
    """Return the quaternion ``w, x, y, z`` (SAPIEN's order) of a turn ``yaw`` about z."""
    import math

    return [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]


def make_env(task: str, tool_actor: str, target_actor: str, goal_actor: str = "",
             parts=(), mass: float = 0.5, friction: float | None = None,
             cube_dx: float = 0.0, max_steps: int = 100, render: bool = False,
             camera: dict | None = None):
    """Return a gymnasium environment of ManiSkill's ``task`` on the CPU backend, state
    observations, ManiSkill's end-effector pose controller (``pd_ee_pose``).

    Parameters
    ----------
    task : str
        ManiSkill's task id.
    tool_actor, target_actor, goal_actor : str
        The names of the task's tool, target and goal actors in its scene (the goal's
        may be empty: the task has none).
    parts : sequence of Box
        The tool's boxes in its frame (metres); empty: ManiSkill's own tool.
    mass : float
        The tool's mass, kg (spread over the boxes by volume).
    friction : float or None
        The tool's friction (static = dynamic); None: SAPIEN's default material.
    cube_dx : float
        How much farther along +x the target (and the goal actor) start than ManiSkill
        draws them, metres.
    max_steps : int
        The episode's step limit (control steps at the task's control rate).
    render : bool
        Build the human render camera (``rgb_array``) for clips.
    camera : dict or None
        ManiSkill's ``human_render_camera_configs`` (pose, size, field of view) of that
        camera (:meth:`creative_py.backends.maniskill.recorder.VideoCamera.camera_config`); None:
        the task's own.
    """
    import gymnasium as gym

    env_class(task)
    return gym.make(env_id(task), obs_mode="state", control_mode="pd_ee_pose",
                    sim_backend="cpu", render_mode="rgb_array" if render else None,
                    max_episode_steps=max_steps, tool_actor=tool_actor,
                    target_actor=target_actor, goal_actor=goal_actor, tool_parts=parts,
                    tool_mass=mass, tool_friction=friction, cube_dx=cube_dx,
                    **({"human_render_camera_configs": camera} if camera else {}))
