"""What every backend's world does with its catalogue, written once.

:func:`read_catalogue` is the one reader of a world's ``objects.toml`` for every
backend: each ``[[<table>]]`` a :class:`CatalogueItem` (the tool kind's spec, its set,
friction and ``outside_ranges``), each error one line naming the file and the field; a
backend says only which specs it can hold (``holds``). A backend's ``World`` (a frozen
dataclass with ``items``: ``name -> CatalogueItem``) subclasses :class:`CatalogueWorld`
and gets the protocol's ``catalogue``, ``item``, ``with_spec`` and ``with_catalogue``
from it.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any, Callable, Mapping, Optional, Sequence

from creative_py.kinds import spec_from_dict
from creative_py.world_files import Fields, WorldFileError, load_toml

FRICTION = (0.0, 10.0)
"""Bounds of a catalogued object's friction coefficient."""


@dataclass(frozen=True)
class CatalogueItem:
    """An available object: its spec (a tool kind's, which holds its mass: kg, None for
    a created tool, printed PLA), set name, friction and, for a created tool, the URDF
    file written for it."""

    spec: Any
    set: str
    friction: float = 0.5
    urdf: Optional[Path] = None
    outside_ranges: bool = False
    """Set by ``outside_ranges = true`` in objects.toml: the user knows a dimension lies
    outside the ontology's qualitative ranges (a run refuses such an object otherwise)."""


def read_catalogue(path: Path, table: str,
                   holds: Callable[[Any], Optional[str]]) -> dict[str, CatalogueItem]:
    """Return ``name -> CatalogueItem`` of the ``[[table]]`` tables of ``objects.toml``
    at ``path``, in the file's order.

    ``holds(spec)`` is the backend's word on a spec: None when it can hold it, else why
    not (the error of the object's ``kind`` field). Raises WorldFileError naming the
    file and the field: an unknown kind or a bad field of its spec, a friction outside
    :data:`FRICTION`, a name used twice, no table at all.
    """
    f = Fields(load_toml(path), path)
    items: dict[str, CatalogueItem] = {}
    for tf in f.tables(table):
        data = dict(tf.data)
        obj_set = tf.str("set")
        friction = tf.float("friction", 0.5, minimum=FRICTION[0], maximum=FRICTION[1])
        outside = tf.bool("outside_ranges", False)
        for k in ("set", "friction", "outside_ranges"):
            data.pop(k, None)
        try:
            spec = spec_from_dict(data, source=f"{path}: {tf.prefix}")
        except ValueError as exc:
            raise WorldFileError(str(exc)) from None
        why = holds(spec)
        if why is not None:
            raise tf.error("kind", why)
        if spec.name in items:
            raise tf.error("name", f"object name {spec.name!r} is used twice")
        items[spec.name] = CatalogueItem(spec, obj_set, friction, outside_ranges=outside)
    f.done()
    if not items:
        raise WorldFileError(f"{path}: field {table!r}: at least one [[{table}]] is needed")
    return items


class CatalogueWorld:
    """The catalogue half of :class:`creative_py.simulator.protocol.World`."""

    items: dict[str, Any]

    def listing(self) -> dict[str, Any]:
        """Return JSON-ready data (``creative trial CASE --list``): the objects (spec
        fields, set, friction, the URDF of a created tool), the locations (the world's
        own :meth:`location_listing`), the variants, the default pose and the
        demonstration."""
        m = self.manifest
        objects = {}
        for n, item in self.items.items():
            d = asdict(item.spec)
            d.update(set=item.set, friction=item.friction)
            if item.urdf is not None:
                d["urdf"] = str(item.urdf)
            objects[n] = d
        pose = dict(zip(m.pose_names, m.demonstration.pose))
        demo = m.demonstration
        return {"case": m.id, "objects": objects, "locations": self.location_listing(),
                "variants": {v.name: {"description": v.description, "harder": v.harder,
                                      "set": dict(v.set)} for v in m.variants},
                "default_pose": pose,
                "demonstration": {"tool": demo.tool, "variant": demo.variant,
                                  "location": demo.location, "steps": list(demo.steps),
                                  "pose": pose}}

    def location_listing(self) -> list[dict[str, Any]]:
        """Return the locations as :meth:`listing` shows them, one table each with its
        1-based ``index``."""
        raise NotImplementedError

    @property
    def catalogue(self) -> dict[str, Any]:
        """Return the available objects, ``name -> spec`` (a tool kind's spec)."""
        return {n: item.spec for n, item in self.items.items()}

    def item(self, name: str) -> Any:
        """Return the catalogued object ``name``; KeyError listing the available ones."""
        if name not in self.items:
            raise KeyError(f"unknown tool {name!r}; available tools: {', '.join(self.items)}")
        return self.items[name]

    def with_tool(self, spec: Any, urdf: Optional[Path] = None):
        """Return this world with one more available object, a created tool: ``spec``
        (its kind's), its ``urdf`` (written by :mod:`creative_py.mesh`, checked to
        exist) and the friction of the catalogue's first object (the same printed
        material). A backend that holds only some kinds checks ``spec`` first."""
        if urdf is not None and not Path(urdf).is_file():
            raise FileNotFoundError(f"{urdf}: tool URDF not found")
        friction = next(iter(self.items.values())).friction
        item = CatalogueItem(spec, "created", friction, None if urdf is None else Path(urdf))
        return replace(self, items={**self.items, spec.name: item})

    def with_spec(self, name: str, spec: Any):
        """Return this world with the available object ``name`` given ``spec`` (a drawn
        one), its place in the catalogue and its other fields kept."""
        return replace(self, items={**self.items, name: replace(self.item(name), spec=spec)})

    def with_catalogue(self, order: Sequence[str], numbers: Mapping[str, Mapping[str, float]]):
        """Return this world with its available objects in ``order`` (their names) and
        the spec fields ``numbers[name]`` (``field -> value``) set on their specs, their
        other fields kept (a drawn world's catalogue); KeyError for a name it does not
        have."""
        items = {}
        for name in order:
            item = self.items[name]
            values = dict(numbers.get(name, {}))
            items[name] = replace(item, spec=replace(item.spec, **values)) if values else item
        return replace(self, items=items)
