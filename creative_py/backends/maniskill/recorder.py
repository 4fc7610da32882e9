"""Clips of a ManiSkill trial: ManiSkill's state dicts kept while it runs, rendered after
the verdict.

A :class:`Recorder` rides along an episode (``open_episode(..., record=Recorder(camera))``).
While the trial runs it only *reads* the physics: every ``1 / fps`` seconds of simulated
time (control steps at ManiSkill's 20 Hz) it keeps ``env.get_state_dict()`` (the poses
and velocities of the cube, the tool and the arm's joints, copied tensors; about
0.3 ms). Nothing is rendered during the trial.

After the verdict, :meth:`Recorder.render` sets each kept state back with
``env.set_state_dict`` and renders ManiSkill's human render camera (placed by the
world's ``[video]`` table), one frame per state, then sets the trial's final state
back: the physics does not run again, and what was judged (the outcome, the final
poses, the steps) was taken before. SAPIEN renders through Vulkan (lavapipe on this
machine, :func:`creative_py.backends.maniskill.env.vulkan_ready`), whose first frame in a process
costs seconds (the shaders are compiled once, and kept while an environment that
used them lives: the last clip's is kept, :data:`_WARM`); later frames cost about
0.05-0.15 s at 320x240.

The frames are rendered in this process even when the caller asks for the background
(:meth:`Recorder.render_then`): a forked copy of a process whose Vulkan device and
renderer threads are live cannot render (the threads do not survive the fork), and
building a new environment in a child would pay the first frame's seconds for every
clip.

The ``[video]`` table of a ManiSkill world's ``tasks.toml`` places the camera::

    [video]
    eye = [0.25, -1.15, 0.95]     # world frame, metres (the task's arm base at x -0.615)
    target = [-0.3, 0.0, 0.05]
    fov_deg = 55.0                # vertical field of view
    width = 320
    height = 240
    fps = 5.0                     # frames per second of simulated time
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from creative_py.world_files import Fields, WorldFileError


@dataclass(frozen=True)
class VideoCamera:
    """The fixed camera of a ManiSkill world's clips and their frame rate (a
    :class:`creative_py.simulator.ClipCamera`).

    Attributes
    ----------
    eye, target : tuple of float
        Where the camera is and what it looks at (world frame, metres; z up).
    fov_deg : float
        Vertical field of view, degrees.
    width, height : int
        Frame size, pixels.
    fps : float
        Frames per second of simulated time, in (0, 20] (ManiSkill's control rate: a
        state is kept after a control step).
    near, far : float
        Clipping planes, metres.
    """

    eye: tuple[float, float, float]
    target: tuple[float, float, float]
    fov_deg: float = 55.0
    width: int = 320
    height: int = 240
    fps: float = 5.0
    near: float = 0.01
    far: float = 10.0

    @classmethod
    def from_fields(cls, f: Fields) -> "VideoCamera":
        """Read the ``[video]`` table ``f`` (errors name the file and the field)."""
        eye = f.vec("eye", 3, minimum=-10.0, maximum=10.0)
        target = f.vec("target", 3, minimum=-10.0, maximum=10.0)
        if math.dist(eye, target) < 1e-3:
            raise f.error("target", "must differ from 'eye'")
        fov = f.float("fov_deg", 55.0, minimum=5.0, maximum=120.0)
        width = f.int("width", 320, minimum=16, maximum=1920)
        height = f.int("height", 240, minimum=16, maximum=1080)
        fps = f.float("fps", 5.0, minimum=0.1, maximum=20.0)
        near = f.float("near", 0.01, minimum=1e-3, maximum=1.0)
        far = f.float("far", 10.0, minimum=0.1, maximum=100.0)
        if far <= near:
            raise f.error("far", f"must exceed 'near' ({near}), got {far}")
        f.done()
        return cls(eye, target, fov, width, height, fps, near, far)

    def camera_config(self) -> dict[str, Any]:
        """Return ManiSkill's ``human_render_camera_configs`` for this camera (imports
        ManiSkill)."""
        from mani_skill.utils import sapien_utils

        return {"pose": sapien_utils.look_at(list(self.eye), list(self.target)),
                "width": self.width, "height": self.height,
                "fov": math.radians(self.fov_deg), "near": self.near, "far": self.far}


def read_video(f: Fields) -> Optional[VideoCamera]:
    """Return the camera of the ``[video]`` table of ``f`` (a world file), or None
    when the file has none."""
    if not f.has("video"):
        return None
    try:
        return VideoCamera.from_fields(f.table("video"))
    except ValueError as exc:
        if isinstance(exc, WorldFileError):
            raise
        raise WorldFileError(f"{f.source}: [video]: {exc}") from None


_WARM: list[Any] = []
"""The environment of the last clip rendered in this process, kept alive: SAPIEN drops
its compiled render pipelines with the last environment that used them, and the next
clip's first frame then costs seconds again (18 s instead of 0.15 s here)."""


def _copy(state: Any) -> Any:
    """Return a deep copy of a ManiSkill state dict (tensors cloned)."""
    if isinstance(state, dict):
        return {k: _copy(v) for k, v in state.items()}
    clone = getattr(state, "clone", None)
    return clone() if clone is not None else state


class Recorder:
    """Keeps a ManiSkill trial's states at ``fps`` of simulated time; renders them on
    demand (a :class:`creative_py.simulator.ClipRecorder`).

    Parameters
    ----------
    camera : VideoCamera
        The camera and the frame rate.

    Use: pass it to :func:`~creative_py.backends.maniskill.episode.open_episode`, which builds
    the environment with the camera, attaches the recorder after the reset and calls
    :meth:`tick` after every control step; after the verdict, inside the episode, call
    :meth:`render`. ``snapshot_time_s``, ``render_time_s`` and ``first_frame_s`` say
    what each part cost (wall time).
    """

    def __init__(self, camera: VideoCamera) -> None:
        self.camera = camera
        self.period = 1.0 / camera.fps
        self.env: Any = None
        self.clock: Callable[[], float] = lambda: 0.0
        self.snapshots: list[tuple[float, dict]] = []
        self._next = 0.0
        self.finished = False
        self.rendered = False
        self.frames: list[np.ndarray] = []
        """The frames of the last :meth:`render`."""
        self.snapshot_time_s = 0.0
        self.render_time_s = 0.0
        self.first_frame_s = 0.0
        """Wall time of the first frame rendered (the process's first: seconds)."""

    @property
    def fps(self) -> float:
        """Return the frame rate, frames per second of simulated time."""
        return self.camera.fps

    # ----------------------------------------------------------------- recording
    def attach(self, env: Any, clock: Callable[[], float]) -> None:
        """Start recording ``env`` (ManiSkill's environment, built with this camera)
        whose simulated time (s) ``clock()`` says; keep the first state."""
        self.env = env
        self.clock = clock
        self.snapshot()

    def tick(self) -> None:
        """Keep the state if a frame's time has come (called after each control step)."""
        if not self.finished and self.clock() + 1e-9 >= self._next:
            self.snapshot()

    def snapshot(self) -> None:
        """Keep the environment's state now (``get_state_dict``: read only)."""
        t0 = time.perf_counter()
        self.snapshots.append((float(self.clock()),
                               _copy(self.env.unwrapped.get_state_dict())))
        self._next = len(self.snapshots) * self.period
        self.snapshot_time_s += time.perf_counter() - t0

    def finish(self) -> None:
        """Keep the last state (once): the scene as the trial left it."""
        if not self.finished:
            self.snapshot()
            self.finished = True

    @property
    def times(self) -> list[float]:
        """Return the simulated time (s) of each snapshot, one per frame."""
        return [t for t, _ in self.snapshots]

    # ----------------------------------------------------------------- rendering
    def render(self) -> list[np.ndarray]:
        """Render one RGB frame (``uint8``, H x W x 3) per kept state, after a last one
        (:meth:`finish`), and set the final state back.

        Call it after the trial's verdict and before the episode closes (the physics
        must not run afterwards). Raises RuntimeError if called twice.
        """
        if self.rendered:
            raise RuntimeError("Recorder.render: the frames were rendered already")
        self.finish()
        self.rendered = True
        u = self.env.unwrapped
        t0 = time.perf_counter()
        frames = []
        try:
            for i, (_, state) in enumerate(self.snapshots):
                u.set_state_dict(state)
                t = time.perf_counter()
                image = u.render_rgb_array()
                if i == 0:
                    self.first_frame_s = time.perf_counter() - t
                image = image[0] if image.ndim == 4 else image
                frames.append(np.ascontiguousarray(image.cpu().numpy()[..., :3],
                                                   dtype=np.uint8))
        finally:
            u.set_state_dict(self.snapshots[-1][1])  # the state the trial ended in
        self.render_time_s += time.perf_counter() - t0
        _WARM[:] = [u]
        self.frames = frames
        return frames

    def render_then(self, use: Callable[[list[np.ndarray], list[float]], None],
                    background: bool = True, nice: int = 0) -> Optional[int]:
        """Render the frames (:meth:`render`) and call ``use(frames, times)`` here; return
        None. ``background`` and ``nice`` are accepted and not used: a fork of this
        process cannot render (see the module docstring)."""
        del background, nice
        use(self.render(), self.times)
        return None
