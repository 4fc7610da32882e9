"""Frames of a trial for a video clip, without touching the trial's physics.

A :class:`Recorder` rides along an episode (``open_episode(..., record=Recorder(spec))``).
While the physics runs it only *reads* the scene: every ``1 / fps`` seconds of simulated
time it keeps the base pose and joint positions of every body and the world pose of
every link of the robot (a few pybullet queries, well under a millisecond). Nothing is
rendered and nothing is added to the physics during the trial, so recording cannot
change an outcome.

After the trial's verdict, :meth:`Recorder.render` puts every body back where a
snapshot saw it and renders the video camera with the CPU renderer, one frame per
snapshot; :meth:`Recorder.render_then` does it in a forked copy of the process, so
that the physics client of the run is never moved and the run goes on meanwhile. The robot is loaded without visual meshes (they cost 1.2 s per scene and a
slow renderer), so the frames show a stand-in drawn from its collision shapes:
cylinders, boxes and spheres, created only for the rendering. Whether a trial is worth
rendering is decided once its outcome is known, so the cheap part (snapshots) runs for
every trial and the expensive part (rendering) only for the clips that are kept.

The ``[video]`` table of a world's ``scene.toml`` places the camera
(:class:`~creative_py.world.cameras.VideoSpec`).
"""

from __future__ import annotations

import math
import os
import sys
import time
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np
import pybullet as pb

from creative_py.backends.pybullet.camera import projection_matrix, view_matrix
from creative_py.world.cameras import VideoSpec

PROXY_RGBA = (0.55, 0.58, 0.62, 1.0)
"""Colour of the robot's stand-in shapes."""

MIN_PROXY_SIZE = 0.005

MESHES = False
"""Whether collision meshes (a torso and pedestal, say) join the stand-in: off, as
they render speckled and more than double the time of a frame."""
"""Collision shapes smaller than this (m) are left out of the stand-in."""


@dataclass(frozen=True)
class _Shape:
    link: int
    geometry: int
    dims: tuple[float, ...]
    pos: tuple[float, float, float]
    orn: tuple[float, float, float, float]
    mesh: str


@dataclass
class _Snapshot:
    time_s: float
    bodies: dict[int, tuple[tuple, tuple, list[float]]]
    links: dict[int, tuple[tuple, tuple]]


class Recorder:
    """Keeps the scene's poses at ``fps`` of simulated time; renders them on demand.

    Parameters
    ----------
    spec : VideoSpec
        The camera and the frame rate.

    Use: pass it to :func:`~creative_py.backends.pybullet.episode.open_episode` (the episode attaches
    it to its simulator, which feeds it every physics step); after the trial, inside
    the episode, call :meth:`render`. ``snapshot_time_s`` and ``render_time_s`` say
    what each part cost (wall time).
    """

    def __init__(self, spec: VideoSpec) -> None:
        self.spec = spec
        self.period = 1.0 / spec.fps
        self.client = -1
        self.robot = -1
        self.shapes: list[_Shape] = []
        self._links: list[int] = []
        self.snapshots: list[_Snapshot] = []
        self.sim_time_s = 0.0
        self._next = 0.0
        self.snapshot_time_s = 0.0
        self.render_time_s = 0.0
        self.rendered = False
        self.finished = False
        self.frames: list[np.ndarray] = []
        """The frames of the last :meth:`render`."""

    # ----------------------------------------------------------------- recording
    def attach(self, client: int, robot: int | None = None,
               stand_in: Path | None = None) -> None:
        """Start recording the scene of physics client ``client`` and take the first
        snapshot.

        ``robot`` is the robot's body (or None); ``stand_in``, the URDF of a robot
        loaded without visual meshes, whose collision shapes then draw it.
        """
        self.client = client
        self.robot = -1 if robot is None else robot
        if robot is not None and stand_in is not None:
            self.shapes = urdf_shapes(client, robot, stand_in)
        self._links = sorted({s.link for s in self.shapes if s.link >= 0})
        if robot is not None and self.shapes:
            self._base_inertial = pb.getDynamicsInfo(robot, -1, physicsClientId=client)[3:5]
        self.snapshot()

    def tick(self, dt: float) -> None:
        """Advance the recorder's clock by one physics step of ``dt`` seconds."""
        self.sim_time_s += dt
        if self.sim_time_s + 1e-9 >= self._next and not self.finished:
            self.snapshot()

    def snapshot(self) -> None:
        """Keep the poses of every body now (read-only queries)."""
        t0 = time.perf_counter()
        c = self.client
        bodies: dict[int, tuple[tuple, tuple, list[float]]] = {}
        links: dict[int, tuple[tuple, tuple]] = {}
        for i in range(pb.getNumBodies(physicsClientId=c)):
            b = pb.getBodyUniqueId(i, physicsClientId=c)
            pos, orn = pb.getBasePositionAndOrientation(b, physicsClientId=c)
            if b == self.robot and self.shapes:
                # Drawn by its stand-in: the link frames as the last step left them.
                states = pb.getLinkStates(b, self._links, physicsClientId=c)
                links = {j: (tuple(s[4]), tuple(s[5])) for j, s in zip(self._links, states)}
                links[-1] = self._base_frame(b, pos, orn)
                bodies[b] = (tuple(pos), tuple(orn), [])
                continue
            n = pb.getNumJoints(b, physicsClientId=c)
            q = ([s[0] for s in pb.getJointStates(b, list(range(n)), physicsClientId=c)]
                 if n else [])
            bodies[b] = (tuple(pos), tuple(orn), q)
        if self.shapes and self.robot not in bodies and self.snapshots:
            links = self.snapshots[-1].links  # taken out of the physics: it stays put
        self.snapshots.append(_Snapshot(self.sim_time_s, bodies, links))
        self._next = len(self.snapshots) * self.period
        self.snapshot_time_s += time.perf_counter() - t0

    def _base_frame(self, body: int, pos, orn) -> tuple[tuple, tuple]:
        """Return the base link's frame from its centre-of-mass pose."""
        inv = pb.invertTransform(*self._base_inertial)
        p, q = pb.multiplyTransforms(pos, orn, inv[0], inv[1])
        return tuple(p), tuple(q)

    @property
    def times(self) -> list[float]:
        """Return the simulated time (s) of each snapshot, one per frame."""
        return [s.time_s for s in self.snapshots]

    @property
    def duration_s(self) -> float:
        """Return the simulated time recorded so far, seconds."""
        return self.sim_time_s

    # ----------------------------------------------------------------- rendering
    def render(self) -> list[np.ndarray]:
        """Render one RGB frame (uint8, HxWx3) per snapshot, after a last one (:meth:`finish`).

        Call it after the trial's verdict and before the episode closes: it moves the
        bodies to each snapshot's poses (and adds the robot's stand-in), so the
        physics must not run afterwards. Raises RuntimeError if called twice.
        """
        if self.rendered:
            raise RuntimeError("Recorder.render: the frames were rendered already")
        self.finish()
        self.rendered = True
        t0 = time.perf_counter()
        c = self.client
        cam = self.spec.camera
        view, proj = view_matrix(cam), projection_matrix(cam)
        proxies = self._build_proxies()
        frames = []
        for snap in self.snapshots:
            for b, (pos, orn, q) in snap.bodies.items():
                if b == self.robot and self.shapes:
                    continue  # drawn by its stand-in
                try:
                    pb.resetBasePositionAndOrientation(b, pos, orn, physicsClientId=c)
                    for j, v in enumerate(q):
                        pb.resetJointState(b, j, v, physicsClientId=c)
                except pb.error:
                    continue  # removed since (a parked robot)
            for link, body in proxies:
                pose = snap.links.get(link)
                pos, orn = pose if pose is not None else ((0.0, 0.0, -100.0), (0, 0, 0, 1))
                pb.resetBasePositionAndOrientation(body, pos, orn, physicsClientId=c)
            _, _, rgba, _, _ = pb.getCameraImage(
                cam.width, cam.height, viewMatrix=view, projectionMatrix=proj,
                renderer=pb.ER_TINY_RENDERER, flags=pb.ER_NO_SEGMENTATION_MASK,
                physicsClientId=c)
            frames.append(np.asarray(rgba, dtype=np.uint8)
                          .reshape(cam.height, cam.width, 4)[:, :, :3].copy())
        self.render_time_s += time.perf_counter() - t0
        self.frames = frames
        return frames

    def finish(self) -> None:
        """Take the last snapshot (once): the scene as the trial left it."""
        if not self.finished:
            self.snapshot()
            self.finished = True

    def render_then(self, use: Callable[[list[np.ndarray], list[float]], None],
                    background: bool = True, nice: int = 0) -> int | None:
        """Render the frames (:meth:`render`) and hand them with their times to ``use``.

        With ``background`` (and where the system can fork) this happens in a child
        process, a copy of this one taken now, so the run goes on while the clip is
        rendered and encoded on another core; the child exits 0 once ``use`` returned,
        1 if anything raised (one line on stderr). Returns the child's pid, or None
        when it ran here. The physics of this process is not touched either way in the
        background case; in the foreground one see :meth:`render`. ``nice`` lowers the
        child's scheduling priority by that much (``os.nice``), so that it takes the CPU
        the run leaves idle instead of slowing the run.
        """
        self.finish()
        if not (background and hasattr(os, "fork")):
            use(self.render(), self.times)
            return None
        sys.stdout.flush()
        sys.stderr.flush()
        pid = os.fork()
        if pid:
            self.rendered = True  # this process's copy is done with
            return pid
        code = 1
        try:
            if nice > 0:
                os.nice(nice)
            use(self.render(), self.times)
            code = 0
        except BaseException as exc:  # the child must never return into the run
            try:
                os.write(2, f"warning: video clip not written: "
                            f"{exc or type(exc).__name__}\n".encode())
            except OSError:
                pass
        finally:
            os._exit(code)

    def _build_proxies(self) -> list[tuple[int, int]]:
        """Create one visual-only body (no collision shape, no mass) per robot shape;
        return ``(link, body)`` pairs."""
        c = self.client
        out = []
        for s in self.shapes:
            kw: dict[str, Any] = dict(shapeType=s.geometry, rgbaColor=PROXY_RGBA,
                                      visualFramePosition=s.pos,
                                      visualFrameOrientation=s.orn, physicsClientId=c)
            if s.geometry == pb.GEOM_BOX:
                kw["halfExtents"] = [d / 2 for d in s.dims[:3]]
            elif s.geometry == pb.GEOM_SPHERE:
                kw["radius"] = s.dims[0]
            elif s.geometry in (pb.GEOM_CYLINDER, pb.GEOM_CAPSULE):
                kw["length"], kw["radius"] = s.dims[0], s.dims[1]
            else:
                kw["fileName"], kw["meshScale"] = s.mesh, list(s.dims[:3])
            vis = pb.createVisualShape(**kw)
            if vis >= 0:
                out.append((s.link, pb.createMultiBody(0, -1, vis, (0, 0, -100),
                                                       physicsClientId=c)))
        return out


def urdf_shapes(client: int, body: int, urdf: Path) -> list[_Shape]:
    """Return the collision shapes of ``body`` as its URDF file writes them.

    pybullet reports a URDF cylinder as a convex mesh without its sizes, so the shapes
    are read from the file: per link its ``<collision>`` origins and geometry (box,
    cylinder, sphere, mesh), each placed in the link frame. Shapes smaller than
    :data:`MIN_PROXY_SIZE` are left out.
    """
    index = {pb.getBodyInfo(body, physicsClientId=client)[0].decode(): -1}
    for j in range(pb.getNumJoints(body, physicsClientId=client)):
        index[pb.getJointInfo(body, j, physicsClientId=client)[12].decode()] = j
    shapes = []
    for link in ET.parse(urdf).getroot().iter("link"):
        j = index.get(link.get("name"))
        if j is None:
            continue
        for col in link.iter("collision"):
            origin = col.find("origin")
            xyz = _floats(origin.get("xyz", "0 0 0") if origin is not None else "0 0 0")
            rpy = _floats(origin.get("rpy", "0 0 0") if origin is not None else "0 0 0")
            geo = col.find("geometry")
            g = next(iter(geo), None) if geo is not None else None
            if g is None:
                continue
            if g.tag == "box":
                dims = _floats(g.get("size"))
                size, kind, mesh = max(dims), pb.GEOM_BOX, ""
            elif g.tag == "cylinder":
                dims = (float(g.get("length")), float(g.get("radius")))
                size, kind, mesh = max(dims[0], 2 * dims[1]), pb.GEOM_CYLINDER, ""
            elif g.tag == "sphere":
                dims = (float(g.get("radius")),)
                size, kind, mesh = 2 * dims[0], pb.GEOM_SPHERE, ""
            elif g.tag == "mesh" and MESHES and Path(g.get("filename", "")).is_file():
                dims = _floats(g.get("scale", "1 1 1"))
                size, kind, mesh = math.inf, pb.GEOM_MESH, g.get("filename")
            else:
                continue
            if size < MIN_PROXY_SIZE:
                continue
            shapes.append(_Shape(j, kind, tuple(dims), tuple(xyz),
                                 tuple(pb.getQuaternionFromEuler(rpy)), mesh))
    return shapes


def _floats(text: str) -> tuple[float, ...]:
    return tuple(float(v) for v in text.split())
