"""What every backend's world does with its catalogue, written once.

A backend's ``World`` (a frozen dataclass with ``items``: ``name -> entry``, each entry
a dataclass with a ``spec``) subclasses :class:`CatalogueWorld` and gets the
protocol's ``catalogue``, ``item``, ``with_spec`` and ``with_catalogue`` from it.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any, Mapping, Sequence


class CatalogueWorld:
    """The catalogue half of :class:`creative_py.simulator.protocol.World`."""

    items: dict[str, Any]

    @property
    def catalogue(self) -> dict[str, Any]:
        """Return the available objects, ``name -> spec`` (a tool kind's spec)."""
        return {n: item.spec for n, item in self.items.items()}

    def item(self, name: str) -> Any:
        """Return the catalogued object ``name``; KeyError listing the available ones."""
        if name not in self.items:
            raise KeyError(f"unknown tool {name!r}; available tools: {', '.join(self.items)}")
        return self.items[name]

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
