"""ManiSkill3's ``PullCubeTool-v1`` with the L-tool built from a catalogued spec.

The environment is ManiSkill's own task class, subclassed only where the case's data
enters: the tool is built with ManiSkill's actor builder from the boxes of a tool
kind's spec (:meth:`creative_py.kinds.parts.KindSpec.parts`: handle and prong of a
hook-like tool, the same boxes for a catalogued and a created tool), and a variant may
move the cube farther from the robot (``cube_dx``, metres along +x). Everything else is
ManiSkill's: the Panda, the table, the cube, the seeded initial state of
``reset(seed=...)`` (the tool's and the cube's draws are those of the stock task; the
tool is then laid on the table at its own height) and the success check
:meth:`evaluate`.

Runs on the CPU backend (``sim_backend="cpu"``) with one environment. SAPIEN needs a
Vulkan device even without rendering: :func:`vulkan_ready` points ``VK_ICD_FILENAMES``
at Mesa's lavapipe when the variable is unset.
"""

from __future__ import annotations

import glob
import logging
import os
from typing import Any

ENV_ID = "CreativePullCubeTool-v1"
"""The id this subclass is registered under (ManiSkill's is ``PullCubeTool-v1``)."""

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


def env_class():
    """Return the registered subclass of ManiSkill's ``PullCubeToolEnv`` (imported and
    registered on first use, so importing this module loads no simulator)."""
    if "cls" in _REGISTERED:
        return _REGISTERED["cls"]
    vulkan_ready()
    import numpy as np
    import sapien
    import torch
    from mani_skill import logger as maniskill_logger
    from mani_skill.envs.tasks import PullCubeToolEnv
    from mani_skill.utils.registration import register_env
    from mani_skill.utils.structs import Pose

    # ManiSkill warns at every environment it builds that no initial pose was set for the
    # builders (the episode's initialisation sets them) and that CUDA is missing (the CPU
    # backend is meant): a run printed 7 such lines a trial. Its errors still show.
    maniskill_logger.setLevel(logging.ERROR)

    class CataloguePullCubeToolEnv(PullCubeToolEnv):
        """``PullCubeTool-v1`` whose L-tool is built from ``tool_parts`` and whose cube
        starts ``cube_dx`` farther along +x (0: the stock task)."""

        def __init__(self, *args, tool_parts=(), tool_mass=0.5, tool_friction=None,
                     cube_dx=0.0, **kwargs):
            self.tool_parts = tuple(tool_parts)
            self.tool_mass = float(tool_mass)
            self.tool_friction = tool_friction
            self.cube_dx = float(cube_dx)
            super().__init__(*args, **kwargs)

        def _build_l_shaped_tool(self, handle_length, hook_length, width, height):
            if not self.tool_parts:
                return super()._build_l_shaped_tool(handle_length, hook_length, width,
                                                    height)
            builder = self.scene.create_actor_builder()
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
            return builder.build(name="l_shape_tool")

        def _initialize_episode(self, env_idx, options):
            super()._initialize_episode(env_idx, options)
            if not self.tool_parts and self.cube_dx == 0.0:
                return
            with torch.device(self.device):
                tool = self.l_shape_tool.pose
                p = tool.p.clone()
                if self.tool_parts:
                    # the tool frame on the handle's axis, its lowest face on the table
                    p[..., 2] = -min(part.center[2] - part.size[2] / 2
                                     for part in self.tool_parts)
                    # its far end where ManiSkill's tool has its own (a longer handle
                    # reaches back towards the robot, not into the cube's region)
                    far = max(part.center[0] + part.size[0] / 2 for part in self.tool_parts)
                    p[..., 0] -= max(0.0, far - self.handle_length)
                self.l_shape_tool.set_pose(Pose.create_from_pq(p=p, q=tool.q))
                cube = self.cube.pose
                c = cube.p.clone()
                c[..., 0] += self.cube_dx
                self.cube.set_pose(Pose.create_from_pq(p=c, q=cube.q))

    register_env(ENV_ID, max_episode_steps=100)(CataloguePullCubeToolEnv)
    _REGISTERED["cls"] = CataloguePullCubeToolEnv
    del np
    return CataloguePullCubeToolEnv


def _yaw_quat_wxyz(yaw: float) -> list[float]:
    """Return the quaternion ``w, x, y, z`` (SAPIEN's order) of a turn ``yaw`` about z."""
    import math

    return [math.cos(yaw / 2), 0.0, 0.0, math.sin(yaw / 2)]


def make_env(parts=(), mass: float = 0.5, friction: float | None = None,
             cube_dx: float = 0.0, max_steps: int = 100, render: bool = False,
             camera: dict | None = None):
    """Return a gymnasium environment of the task on the CPU backend, state observations,
    ManiSkill's end-effector pose controller (``pd_ee_pose``).

    Parameters
    ----------
    parts : sequence of Box
        The tool's boxes in its frame (metres); empty: ManiSkill's own L-tool.
    mass : float
        The tool's mass, kg (spread over the boxes by volume).
    friction : float or None
        The tool's friction (static = dynamic); None: SAPIEN's default material.
    cube_dx : float
        How much farther along +x the cube starts than ManiSkill draws it, metres.
    max_steps : int
        The episode's step limit (ManiSkill's task: 100 control steps at 20 Hz).
    render : bool
        Build the human render camera (``rgb_array``) for clips.
    camera : dict or None
        ManiSkill's ``human_render_camera_configs`` (pose, size, field of view) of that
        camera (:meth:`creative_py.backends.maniskill.recorder.VideoCamera.camera_config`); None:
        the task's own.
    """
    import gymnasium as gym

    env_class()
    return gym.make(ENV_ID, obs_mode="state", control_mode="pd_ee_pose", sim_backend="cpu",
                    render_mode="rgb_array" if render else None,
                    max_episode_steps=max_steps, tool_parts=parts, tool_mass=mass,
                    tool_friction=friction, cube_dx=cube_dx,
                    **({"human_render_camera_configs": camera} if camera else {}))

