"""A case's simulated world: the manifest, the catalogue of tools and the scene files.

:func:`load_world` reads ``worlds/<folder>/`` (or a copy of it) for a
:class:`~creative_py.case.CaseManifest`; :meth:`World.with_tool` adds a created tool.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any

from creative_py.case import CaseManifest


@dataclass(frozen=True)
class World:
    """Everything the simulator needs to build a case's scenes.

    Attributes
    ----------
    manifest : CaseManifest
        The case (roles, skills, pose parameters, variants, demonstration).
    impl : object
        The scene description read from the world folder.
    """

    manifest: CaseManifest
    impl: Any

    @property
    def directory(self) -> Path:
        """Return the world folder the scene was read from."""
        return Path(self.impl.directory)

    @property
    def catalogue(self) -> dict[str, Any]:
        """Return the candidate tools, ``name -> spec`` (HookSpec, BlockSpec ...)."""
        if hasattr(self.impl, "tools"):
            return dict(self.impl.tools)
        return {n: item.spec for n, item in self.impl.objects.items()}

    @property
    def locations(self) -> tuple[int, ...]:
        """Return the 1-based indices of the target's predefined locations."""
        n = len(self.impl.locations) if hasattr(self.impl, "locations") else 1
        return tuple(range(1, n + 1))

    def with_tool(self, spec: Any, urdf: Path | None = None) -> "World":
        """Return this world with one more available tool (a created one).

        Its catalogue facts, grasp and skills come from ``spec``; its body from ``urdf``
        (written by :mod:`creative_py.mesh`, link frame = tool frame) when given,
        otherwise from the spec's parts.
        """
        if urdf is not None and not Path(urdf).is_file():
            raise FileNotFoundError(f"{urdf}: tool URDF not found")
        impl = self.impl
        if hasattr(impl, "tools"):
            from creative_py.sim.hook_tube import with_tool

            return replace(self, impl=with_tool(impl, spec, urdf))
        template = next(iter(impl.objects.values()))
        item = replace(template, spec=spec, set="created",
                       urdf=None if urdf is None else Path(urdf))
        return replace(self, impl=replace(impl, objects={**impl.objects, spec.name: item}))

    def listing(self) -> dict[str, Any]:
        """Return JSON-ready data: objects (spec fields, set), locations, variants,
        the default pose and the demonstration."""
        from creative_py.sim.cases import CASES

        m = self.manifest
        legacy = CASES[m.id].listing(self.impl)
        return {
            "case": m.id,
            "objects": legacy["objects"],
            "locations": legacy["locations"],
            "variants": {v.name: {"description": v.description, "harder": v.harder,
                                  "set": dict(v.set)} for v in m.variants},
            "default_pose": dict(zip(m.pose_names, m.demonstration.pose)),
            "demonstration": {"tool": m.demonstration.tool,
                              "variant": m.demonstration.variant,
                              "location": m.demonstration.location,
                              "steps": list(m.demonstration.steps),
                              "pose": dict(zip(m.pose_names, m.demonstration.pose))},
        }

    def impl_open(self, variant, location, tool, seed, gui, images_dir):
        """Return a new scene episode of the underlying world (close it when done)."""
        from creative_py.sim.cases import CASES

        self.manifest.variant(variant)
        return CASES[self.manifest.id].open_episode(self.impl, variant, location, tool, seed,
                                                    gui, images_dir)


def load_world(manifest: CaseManifest, world_dir: Path | None = None) -> World:
    """Return the world of ``manifest`` read from ``world_dir`` (default: its folder).

    Errors name the world file and the field (:class:`creative_py.world.WorldFileError`).
    """
    from creative_py.sim.cases import CASES

    d = Path(world_dir) if world_dir is not None else Path(manifest.folder)
    return World(manifest, CASES[manifest.id].load_world(d))
