"""The trainer: who sets each episode's scene up, asked over ROS 2.

Every trial of a case starts from a scene: a variant of the task, a target location
and the tool on its stand (a catalogued one or a tool the learner created during the
run). In the pybullet backend the learner builds it; on a real arm a person (or a
reset script) puts the objects back. The learner asks for it on the profile's
``[trainer] request_topic`` and waits for the answer on ``done_topic``, both
``std_msgs/String`` carrying one JSON object:

request (learner -> trainer)::

    {"id": "3f2a...-7", "case": "hook", "variant": "standard", "location": 1,
     "tool": "hook_a2", "created": null}

    created: null for a catalogued tool, else the created tool:
      {"spec": {<the tool kind's spec fields, with "kind">}, "urdf": "/abs/path.urdf"}

answer (trainer -> learner)::

    {"id": "3f2a...-7", "ok": true, "error": ""}

The answer repeats the request's id; ``ok`` false with ``error`` (one line) when the
scene cannot be set up (an unknown tool, another case). The learner then waits for
fresh poses of every tracked object before the episode starts.

:class:`SceneKeeper` is the stand-in's side: it rebuilds its pybullet scene for a
request in its physics loop (:func:`creative_py.backends.ros.standin.serve`).
:func:`scene_request` makes a request's JSON. Needs no ROS to import.
"""

from __future__ import annotations

import json
import queue
from contextlib import ExitStack
from pathlib import Path
from typing import Any, Optional

REQUEST_KEYS = ("id", "case", "variant", "location", "tool", "created")
"""The fields of a scene request."""


def spec_to_dict(spec: Any) -> dict[str, Any]:
    """Return a tool kind's spec as JSON-ready fields (with ``kind``), what
    :func:`creative_py.kinds.spec_from_dict` reads back."""
    out: dict[str, Any] = {}
    for name in spec.__dataclass_fields__:
        value = getattr(spec, name)
        out[name] = list(value) if isinstance(value, tuple) else value
    return out


def scene_request(request_id: str, case: str, variant: str, location: int, tool: str,
                  spec: Any = None, urdf: Optional[Path] = None) -> str:
    """Return the JSON of a scene request; ``spec`` (and ``urdf``) for a created tool."""
    created = None
    if spec is not None:
        created = {"spec": spec_to_dict(spec),
                   "urdf": None if urdf is None else str(Path(urdf).resolve())}
    return json.dumps({"id": request_id, "case": case, "variant": variant,
                       "location": int(location), "tool": tool, "created": created})


class SceneKeeper:
    """The stand-in's scenes: the open pybullet episode and the requests for the next.

    Parameters
    ----------
    world : creative_py.world.read.World
        The case's world as its files say (created tools are added per request).
    open_episode : callable
        The backend that builds a scene, ``open_episode(world, variant, location, tool)``
        (a context manager yielding the episode): the stand-in gives the pybullet
        backend's (:func:`creative_py.backends.pybullet.open_episode`).
    """

    def __init__(self, world: Any, open_episode: Any) -> None:
        self.world = world
        self._open_episode = open_episode
        self.requests: "queue.Queue[str]" = queue.Queue()
        self._stack: Optional[ExitStack] = None
        self.episode: Any = None

    def open(self, variant: str, location: int, tool: str, world: Any = None) -> Any:
        """Build the scene (closing the one before); return its episode."""
        w = self.world if world is None else world
        stack = ExitStack()
        try:
            episode = stack.enter_context(self._open_episode(w, variant, location, tool))
        except BaseException:
            stack.close()
            raise
        self.close()
        self._stack, self.episode = stack, episode
        return episode

    def apply(self, text: str) -> tuple[Optional[str], Optional[str], Any]:
        """Build the scene a request's JSON asks for.

        Returns ``(id, error, episode)``: ``error`` None and the new episode when it
        was built, else one line saying why (the old scene stays); ``id`` None for a
        message that is no request at all.
        """
        from creative_py.kinds import spec_from_dict

        try:
            req = json.loads(text)
        except json.JSONDecodeError as exc:
            return None, f"not JSON: {exc.msg}", None
        if not isinstance(req, dict) or not isinstance(req.get("id"), str):
            return None, "not a scene request (no text field 'id')", None
        rid = req["id"]
        missing = [k for k in REQUEST_KEYS if k not in req]
        if missing:
            return rid, f"field {missing[0]!r} is missing", None
        m = self.world.manifest
        if req["case"] != m.id:
            return rid, f"field 'case': the stand-in runs case {m.id!r}, not {req['case']!r}", None
        world = self.world
        try:
            created = req["created"]
            if created is not None:
                spec = spec_from_dict(dict(created["spec"]), source="scene request")
                urdf = created.get("urdf")
                world = world.with_tool(spec, None if urdf is None else Path(urdf))
            if req["variant"] not in m.variant_names:
                raise ValueError(f"field 'variant': {req['variant']!r} is not a variant of "
                                 f"{m.id} ({', '.join(m.variant_names)})")
            if req["location"] not in world.locations:
                raise ValueError(f"field 'location': {req['location']!r} is not a location "
                                 f"of {m.id}")
            world.item(req["tool"])
            episode = self.open(req["variant"], int(req["location"]), req["tool"], world)
        except (KeyError, TypeError, ValueError, OSError) as exc:
            msg = exc.args[0] if isinstance(exc, KeyError) and exc.args else exc
            return rid, " ".join(str(msg).split()), None
        return rid, None, episode

    def close(self) -> None:
        """Close the open scene (idempotent)."""
        if self._stack is not None:
            self._stack.close()
        self._stack, self.episode = None, None
