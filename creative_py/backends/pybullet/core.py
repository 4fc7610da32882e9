"""The simulator: one pybullet physics client owned by a :class:`Sim` object.

No module globals hold clients; every pybullet call passes ``physicsClientId``.
Poses are ``(point, quat)`` with points in metres (world frame) and quaternions
``(x, y, z, w)`` as pybullet has them.
"""

from __future__ import annotations

import logging
import math
import os
from contextlib import contextmanager
from typing import Iterator

import pybullet as pb

from creative_py.world_files import PhysicsSettings

log = logging.getLogger(__name__)

Point = tuple[float, float, float]
Quat = tuple[float, float, float, float]
Pose = tuple[Point, Quat]


def display_available() -> bool:
    """Return whether a GUI window can be opened (an X display is set)."""
    return bool(os.environ.get("DISPLAY"))


def display_reachable() -> str | None:
    """Return None when pybullet's GUI can open on ``$DISPLAY``, else why not.

    A set ``DISPLAY`` is not enough (pybullet aborts the process on a display it
    cannot open): the display is opened with Xlib (``XOpenDisplay``), or, without
    libX11, its socket is connected to.
    """
    import ctypes
    import ctypes.util
    import socket

    name = os.environ.get("DISPLAY")
    if not name:
        return "no display to open pybullet's GUI on (DISPLAY is not set)"
    lib = ctypes.util.find_library("X11")
    if lib:
        x11 = ctypes.CDLL(lib)
        x11.XOpenDisplay.restype = ctypes.c_void_p
        x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
        x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
        handle = x11.XOpenDisplay(name.encode())
        if not handle:
            return f"the display {name} cannot be opened (DISPLAY={name})"
        x11.XCloseDisplay(handle)
        return None
    host, _, rest = name.rpartition(":")
    try:
        number = int(rest.split(".")[0])
    except ValueError:
        return f"DISPLAY={name} is not a display name (host:number)"
    try:
        if host in ("", "unix"):
            with socket.socket(socket.AF_UNIX) as s:
                s.settimeout(2)
                s.connect(f"/tmp/.X11-unix/X{number}")
        else:
            socket.create_connection((host, 6000 + number), timeout=2).close()
    except OSError as exc:
        return f"the display {name} cannot be reached ({exc.strerror or exc})"
    return None


class Sim:
    """A pybullet physics client with a world's settings.

    Parameters
    ----------
    physics : PhysicsSettings
        Time step (s), solver iterations and gravity (m/s^2).
    gui : bool
        Open the GUI if a display exists; otherwise (and by default) DIRECT.

    Use as a context manager, or call :meth:`close`.
    """

    def __init__(self, physics: PhysicsSettings, gui: bool = False) -> None:
        self.physics = physics
        mode = pb.DIRECT
        if gui:
            if display_available():
                mode = pb.GUI
            else:
                log.warning("no display: running the simulator without a GUI")
        self.gui = mode == pb.GUI
        self.client = pb.connect(mode)
        if self.client < 0:
            raise RuntimeError("pybullet: could not connect a physics client")
        self.steps = 0
        self.after_step: list = []
        """Callables run after every physics step (e.g. a
        :class:`creative_py.backends.pybullet.loads.ToolLoadMonitor`); they only read the state."""
        self.recorder = None
        """A :class:`~creative_py.backends.pybullet.recorder.Recorder` fed after every step, or None."""
        self.configure()

    def configure(self) -> None:
        """(Re)apply the physics settings to the client."""
        c = self.client
        pb.setGravity(*self.physics.gravity, physicsClientId=c)
        pb.setPhysicsEngineParameter(fixedTimeStep=self.physics.time_step,
                                     numSolverIterations=self.physics.solver_iterations,
                                     deterministicOverlappingPairs=1,
                                     physicsClientId=c)
        if self.gui:
            pb.configureDebugVisualizer(pb.COV_ENABLE_GUI, 0, physicsClientId=c)

    def look_at(self, eye: Point, target: Point) -> None:
        """Point the GUI's camera from ``eye`` at ``target`` (world, m); no-op without GUI."""
        if not self.gui:
            return
        v = [e - t for e, t in zip(eye, target)]
        d = math.sqrt(sum(x * x for x in v))
        if d < 1e-9:
            return
        pb.resetDebugVisualizerCamera(
            cameraDistance=d, cameraYaw=math.degrees(math.atan2(v[0], -v[1])),
            cameraPitch=-math.degrees(math.asin(max(-1.0, min(1.0, v[2] / d)))),
            cameraTargetPosition=list(target), physicsClientId=self.client)

    @property
    def time(self) -> float:
        """Return the simulated time since the client started, seconds."""
        return self.steps * self.physics.time_step

    def step(self, n: int = 1) -> None:
        """Advance the physics by ``n`` time steps."""
        rec = self.recorder
        if not self.after_step and rec is None:
            for _ in range(n):
                pb.stepSimulation(physicsClientId=self.client)
            self.steps += n
            return
        dt = self.physics.time_step
        for _ in range(n):
            pb.stepSimulation(physicsClientId=self.client)
            self.steps += 1
            for callback in tuple(self.after_step):
                callback()
            if rec is not None:
                rec.tick(dt)

    def pose(self, body: int, link: int = -1) -> Pose:
        """Return the world pose of a body's base (link -1) or of one of its links."""
        if link < 0:
            pos, quat = pb.getBasePositionAndOrientation(body, physicsClientId=self.client)
        else:
            state = pb.getLinkState(body, link, computeForwardKinematics=True,
                                    physicsClientId=self.client)
            pos, quat = state[4], state[5]
        return tuple(pos), tuple(quat)

    def body_is_sane(self, body: int, bound: float = 20.0) -> bool:
        """Return whether a body's base pose is finite and within ``bound`` metres."""
        pos, quat = self.pose(body)
        return all(math.isfinite(v) for v in (*pos, *quat)) and max(abs(v) for v in pos) < bound

    def blow_up(self, body: int, max_speed: float = 5.0, bound: float = 20.0) -> str:
        """Return why ``body`` looks like a physics blow-up, or "" if it looks sane.

        A blow-up is a non-finite pose, a position beyond ``bound`` metres from the
        origin, or a linear speed above ``max_speed`` m/s.
        """
        if not self.body_is_sane(body, bound):
            return f"body {body} has a non-finite pose or left the scene (physics blow-up)"
        vel, _ = pb.getBaseVelocity(body, physicsClientId=self.client)
        speed = math.sqrt(sum(v * v for v in vel))
        if not math.isfinite(speed) or speed > max_speed:
            return f"body {body} moves at {speed:.1f} m/s (physics blow-up)"
        return ""

    def save_state(self) -> int:
        """Save the whole physics state in memory; return its id."""
        return pb.saveState(physicsClientId=self.client)

    def restore_state(self, state_id: int) -> None:
        """Restore a state saved with :meth:`save_state`."""
        pb.restoreState(stateId=state_id, physicsClientId=self.client)

    def remove_state(self, state_id: int) -> None:
        """Forget a saved state."""
        pb.removeState(state_id, physicsClientId=self.client)

    @contextmanager
    def saved(self) -> Iterator[int]:
        """Save the state on entry and restore it on exit (a try that leaves no trace)."""
        state = self.save_state()
        steps, recorder = self.steps, self.recorder
        self.recorder = None  # what is tried here is no part of the trial's clip
        try:
            yield state
        finally:
            self.restore_state(state)
            self.remove_state(state)
            self.steps, self.recorder = steps, recorder

    def close(self) -> None:
        """Disconnect the client (idempotent)."""
        if self.client >= 0:
            try:
                pb.disconnect(physicsClientId=self.client)
            finally:
                self.client = -1

    def __enter__(self) -> "Sim":
        return self

    def __exit__(self, *exc) -> None:
        self.close()
