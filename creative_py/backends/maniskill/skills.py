"""The skill primitives of the ManiSkill backend, driven by ManiSkill's end-effector
pose controller (``pd_ee_pose``: an absolute TCP pose in the robot's base frame and a
gripper command, one action per control step at 20 Hz).

A primitive is a short sequence of straight TCP moves, each split into control steps
of at most ``step_m`` metres; every ``env.step`` is counted (:attr:`Driver.steps`).
No motion planner is used (ManiSkill's bundled solution's planner, mplib, crashed on
this machine). Where the tool and cube are comes from the simulator's state: the
caller passes the numbers (see :mod:`creative_py.backends.maniskill.episode`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence

import numpy as np

OPEN, CLOSED = 1.0, -1.0
"""The gripper commands (normalised: 1 opens to 0.04 m a finger, -1 closes past 0)."""


def down_rotvec(yaw: float) -> np.ndarray:
    """Return the axis-angle vector of the TCP pointing down, turned ``yaw`` about z
    (yaw 0: the fingers close along the world's y axis)."""
    from scipy.spatial.transform import Rotation

    r = Rotation.from_euler("z", yaw) * Rotation.from_euler("x", math.pi)
    return r.as_rotvec()


@dataclass
class Driver:
    """Moves the arm's TCP in straight lines through ManiSkill's pose controller.

    Attributes
    ----------
    env : gymnasium.Env
        The ManiSkill environment (``pd_ee_pose``).
    base : numpy.ndarray
        The robot base's world position (the controller's frame is the base's).
    step_m : float
        The largest TCP move of one control step, metres.
    steps : int
        Control steps taken since the episode's reset.
    max_steps : int
        The episode's step budget; a move that would exceed it stops (``out of steps``).
    short : int
        The control steps the move that ran out of the budget still needed (0 while
        none ran out).
    """

    env: Any
    step_m: float = 0.03
    max_steps: int = 100
    steps: int = 0
    short: int = 0
    gripper: float = OPEN
    yaw: float = 0.0
    on_step: Optional[Callable[[], None]] = None
    """Called after every control step (the tool action's load monitor), or None."""
    on_record: Optional[Callable[[], None]] = None
    """Called after every control step (a clip's recorder, which only reads), or None."""

    def __post_init__(self) -> None:
        u = self.env.unwrapped
        self.base = u.agent.robot.pose.p[0].numpy().astype(float)

    def tcp(self) -> np.ndarray:
        """Return the TCP's world position, metres."""
        return self.env.unwrapped.agent.tcp.pose.p[0].numpy().astype(float)

    def _act(self, target: np.ndarray) -> None:
        action = np.concatenate([target - self.base, down_rotvec(self.yaw), [self.gripper]])
        self.env.step(action.astype(np.float32))
        self.steps += 1
        if self.on_step is not None:
            self.on_step()
        if self.on_record is not None:
            self.on_record()

    def move(self, target: Sequence[float], settle: int = 1,
             step_m: float | None = None) -> bool:
        """Move the TCP to ``target`` (world, metres) in straight steps of at most
        ``step_m`` (default :attr:`step_m`), then hold it for ``settle`` steps; return
        False when the step budget ran out first."""
        target = np.asarray(target, dtype=float)
        start = self.tcp()
        n = max(1, int(math.ceil(np.linalg.norm(target - start) / (step_m or self.step_m))))
        for i in range(1, n + settle + 1):
            if self.steps >= self.max_steps:
                self.short = n + settle + 1 - i
                return False
            self._act(start + (target - start) * min(1.0, i / n))
        return True

    def set_gripper(self, command: float, steps: int = 4) -> bool:
        """Open (1) or close (-1) the gripper holding the TCP where it is."""
        self.gripper = command
        here = self.tcp()
        for i in range(steps):
            if self.steps >= self.max_steps:
                self.short = steps - i
                return False
            self._act(here)
        return True


def grasp_handle(d: Driver, grip: Sequence[float], approach: float = 0.08,
                 step_m: float | None = None) -> bool:
    """Open, come down over the grip point ``grip`` (world, metres), close; moves of at
    most ``step_m`` a control step (default :attr:`Driver.step_m`)."""
    g = np.asarray(grip, dtype=float)
    return (d.set_gripper(OPEN, 1) and d.move(g + [0, 0, approach], step_m=step_m)
            and d.move(g, settle=4, step_m=step_m) and d.set_gripper(CLOSED, 5))
