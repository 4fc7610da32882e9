"""Randomised worlds (``--world-seed N``), drawn above the simulator boundary.

:func:`draw_world` draws, from one :func:`numpy.random.default_rng` of the world seed,
a permutation of the catalogue, each catalogued number inside its own qualitative range
and each location's scene values within the manifest's ``[randomise]`` bounds;
:func:`apply_drawn` makes the drawn world. Both are written against the
:class:`~creative_py.simulator.protocol.World` protocol, once for every backend: a
backend's world gives its locations' scene values (``location_values``,
``scene_value``) and takes new ones (``with_locations``, where its checks run again);
its catalogue is a :class:`~creative_py.simulator.catalogue.CatalogueWorld`'s
(``with_catalogue``). Whether a drawn object lies still and whether the demonstration
still works in a drawn world is the physics': the caller's ``keeps`` and
``demonstrates`` ask the backend (:func:`creative_py.learning.run.draw_catalogue_world`).

Units: the world's (metres, radians; a catalogued angle in degrees where its fact says
so). A drawn world is JSON-ready data, what ``run.json`` keeps as ``drawn_world``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Mapping, Optional

import numpy as np

if TYPE_CHECKING:
    from creative_py.simulator.protocol import World

Range = tuple[float, float, str]
"""A qualitative range: low, high and which ends it holds (``closed_open``,
``closed_closed``, ``open_closed``; ``ontology/ranges.pl``)."""

ValueRange = tuple[float, float, str, str]
"""A :data:`Range` and the qualitative value it stands for (``short``)."""


def _inside(x: float, rng_: Range) -> bool:
    lo, hi, bounds = rng_
    if bounds == "closed_open":
        return lo <= x < hi
    if bounds == "open_closed":
        return lo < x <= hi
    return lo <= x <= hi


def _check_value_bounds(world: World, ranges: Mapping[str, Mapping[str, ValueRange]]) -> None:
    """Raise ValueError naming case.toml's table when a value table of
    ``[randomise.catalogue.<field>]`` names a value no catalogued object has."""
    seen: dict[str, set[str]] = {}
    catalogue = world.catalogue
    for name, facts in ranges.items():
        if name not in catalogue:
            continue
        fields = catalogue[name].FACT_FIELDS
        for fact, (_lo, _hi, _bounds, value) in facts.items():
            if fact in fields:
                seen.setdefault(fields[fact], set()).add(value)
    for fld, value, _lo, _hi in world.manifest.catalogue_value_bounds:
        if value not in seen.get(fld, set()):
            known = ", ".join(sorted(seen.get(fld, set()))) or "none"
            raise ValueError(f"{world.manifest.folder / 'case.toml'}: "
                             f"[randomise.catalogue.{fld}] {value!r}: no catalogued object "
                             f"has this value (values of {fld}: {known})")


def draw_world(world: World, seed: int, ranges: Mapping[str, Mapping[str, ValueRange]],
               keeps: Optional[Callable[[str, Any], bool]] = None,
               attempts: int = 200,
               demonstrates: Optional[Callable[[dict[str, Any]], bool]] = None,
               redraws: int = 20) -> dict[str, Any]:
    """Draw a randomised world from ``world`` and return it as JSON-ready data.

    Deterministic: one :func:`numpy.random.default_rng` of ``seed`` makes, in order,
    the catalogue's new order (a permutation), each object's numbers (objects in file
    order, facts in name order), each location's jittered values and, while
    ``demonstrates`` says the demonstration fails in the drawn world, the
    demonstration's location again (the generator goes on: the same seed gives the
    same redraws).

    Parameters
    ----------
    world : World
        The world as its files say.
    seed : int
        The world seed.
    ranges : mapping
        ``object -> {catalogue fact -> (low, high, bounds, value)}``: the qualitative
        range of each number the object has and the value it stands for (the engine's
        ``catalogue_ranges``). Each number is drawn uniformly inside its own range
        (narrowed by the manifest's ``[randomise.catalogue]``, for the field and for
        the object's value, where given), rounded to 0.1 mm (0.0001 degree), so the
        object keeps its qualitative values; a number without a range is kept, and so
        are the numbers of the demonstration's tool (the trainer's demonstration is
        part of the case and must work: drawn, a hook with a long, wide prong on a thin
        handle tipped off its stand at the trainer's grasp).
    keeps : callable or None
        ``keeps(name, spec)`` says whether a drawn object still has every structural
        literal of the original (a ratio of two numbers can change its value) and lies
        still where the world puts it; the object is drawn again until it does, at most
        ``attempts`` times.
    demonstrates : callable or None
        ``demonstrates(drawn)`` says whether the trainer's demonstration reaches the
        goal in the drawn world (the physics: a location can be drawn where it does
        not, e.g. a cube jittered onto the tube's axis, where perception error decides
        the side the prong is turned to); the demonstration's location is drawn again
        until it does, at most ``redraws`` times, else ValueError naming the world
        seed.
    redraws : int
        The most redraws of the demonstration's location.

    Returns
    -------
    dict
        ``seed``, ``order`` (the catalogue's names in their new order), ``objects``
        (``name -> {spec field: value}``, the drawn numbers), ``locations`` (each
        location's ``set`` table with the jittered keys of the manifest's
        ``[randomise]``, each kept within its ``min`` and ``max``) and ``redraws``
        (how many times the demonstration's location was drawn again).

    Raises
    ------
    ValueError
        The world's backend draws no worlds (its ``location_values`` says so, naming
        ``case.toml``), a ``[randomise.catalogue]`` table leaves an object no number or
        names a value no object has, or the attempts ran out (naming the world seed).
    """
    tables = [dict(world.location_values(i)) for i in world.locations]
    _check_value_bounds(world, ranges)
    m = world.manifest
    rng = np.random.default_rng(seed)
    catalogue = world.catalogue
    names = list(catalogue)
    order = [names[int(i)] for i in rng.permutation(len(names))]
    objects: dict[str, dict[str, float]] = {}
    for name in names:
        if name == m.demonstration.tool:
            continue
        todo = _object_ranges(m, catalogue[name], ranges.get(name, {}))
        if todo:
            objects[name] = _draw_object(m, seed, name, catalogue[name], todo, rng, keeps,
                                         attempts)
    locations = [_jittered(world, i, tables[i - 1], rng) for i in world.locations]
    drawn = {"seed": int(seed), "order": order, "objects": objects, "locations": locations,
             "redraws": 0}
    if demonstrates is None:
        return drawn
    return _demonstrated(world, drawn, tables, rng, demonstrates, redraws)


def _object_ranges(m: Any, spec: Any, facts: Mapping[str, ValueRange]) -> list[tuple]:
    """Return ``(fact, (low, high, bounds, own range))`` of each number of a catalogued
    object to draw, facts in name order: its own qualitative range narrowed by the
    manifest's ``[randomise.catalogue]`` for the field and for the object's value."""
    narrow = {f: (lo, hi) for f, lo, hi in m.catalogue_bounds}
    by_value = {(f, v): (lo, hi) for f, v, lo, hi in m.catalogue_value_bounds}
    fields = spec.FACT_FIELDS
    todo = []
    for fact, (lo, hi, bounds, value) in sorted(facts.items()):
        if fact not in fields:
            continue
        a, b = narrow.get(fields[fact], (lo, hi))
        c, d = by_value.get((fields[fact], value), (a, b))
        todo.append((fact, (max(lo, a, c), min(hi, b, d), bounds, (lo, hi, bounds))))
    return todo


def _draw_object(m: Any, seed: int, name: str, spec: Any, todo: list[tuple],
                 rng: np.random.Generator, keeps: Optional[Callable[[str, Any], bool]],
                 attempts: int) -> dict[str, float]:
    """Return the drawn numbers (``spec field -> value``, those that changed) of the
    catalogued object ``name``: each inside its range of ``todo``, rounded to 0.1 mm,
    drawn again until ``keeps`` accepts the object, at most ``attempts`` times."""
    fields = spec.FACT_FIELDS
    for _attempt in range(attempts):
        values = {}
        for fact, (lo, hi, bounds, own) in todo:
            if lo > hi:
                raise ValueError(f"{m.folder / 'case.toml'}: "
                                 f"[randomise.catalogue.{fields[fact]}] leaves {name} "
                                 f"no number in its own range {list(own[:2])}")
            x = round(float(rng.uniform(lo, hi)), 4)
            while not (_inside(x, own) and lo <= x <= hi):
                x = round(float(rng.uniform(lo, hi)), 4)
            values[fields[fact]] = x
        drawn = spec.redrawn(values)
        if keeps is None or keeps(name, drawn):
            return {f: getattr(drawn, f) for f in sorted(set(fields.values()))
                    if getattr(drawn, f) != getattr(spec, f)}
    raise ValueError(f"world seed {seed}: {name}: no draw in {attempts} attempts "
                     f"keeps its qualitative values")


def _demonstrated(world: World, drawn: dict[str, Any], tables: list[dict[str, Any]],
                  rng: np.random.Generator, demonstrates: Callable[[dict[str, Any]], bool],
                  redraws: int) -> dict[str, Any]:
    """Return ``drawn`` once ``demonstrates`` says the demonstration reaches the goal in
    it, its location drawn again (``rng`` going on) at most ``redraws`` times; else
    ValueError naming the world seed."""
    m = world.manifest
    demo = m.demonstration
    locations = drawn["locations"]
    if not m.location_jitter:
        redraws = 0  # nothing to draw again
    for n in range(redraws + 1):
        if demonstrates(drawn):
            return drawn
        if n < redraws:
            locations[demo.location - 1] = _jittered(world, demo.location,
                                                     tables[demo.location - 1], rng)
            drawn["redraws"] = n + 1
    raise ValueError(f"world seed {drawn['seed']}: the demonstration ({demo.tool} at "
                     f"location {demo.location}) failed in the physics in {redraws + 1} "
                     f"draws of location {demo.location} (its [randomise.location] jitter "
                     f"of {m.folder / 'case.toml'} may need narrowing)")


def _jittered(world: World, location: int, table: Mapping[str, Any],
              rng: np.random.Generator) -> dict[str, Any]:
    """Return location ``location``'s scene values ``table`` with the manifest's
    ``[randomise]`` keys jittered by ``rng`` (each kept within its ``min`` and ``max``;
    a key the table does not set starts from the scene's value)."""
    demo = world.manifest.demonstration
    new = dict(table)
    for j in world.manifest.location_jitter:
        base = (float(table[j.key]) if j.key in table
                else float(world.scene_value(j.key, demo.variant, location, demo.tool)))
        new[j.key] = round(min(j.max, max(j.min, base + float(rng.uniform(-j.jitter,
                                                                           j.jitter)))), 5)
    return new


def apply_drawn(world: World, drawn: Mapping[str, Any]) -> World:
    """Return ``world`` with a drawn world's catalogue order, numbers and locations
    (:func:`draw_world`; also what a resumed run reads back from ``run.json``) and its
    ``variation`` ``world seed N``.

    The world's own checks run again (every scene value of every variant and location
    resolves: its ``with_locations``); errors (ValueError) name the world seed.
    """
    order = list(drawn["order"])
    if sorted(order) != sorted(world.catalogue):
        raise ValueError(f"world seed {drawn.get('seed')}: the drawn catalogue "
                         f"{sorted(order)} is not the world's {sorted(world.catalogue)}")
    new = world.with_catalogue(order, drawn["objects"])
    locations = tuple(dict(s) for s in drawn["locations"])
    if len(locations) != len(world.locations):
        raise ValueError(f"world seed {drawn.get('seed')}: {len(locations)} locations "
                         f"drawn, the world has {len(world.locations)}")
    return new.with_locations(locations, f"world seed {drawn.get('seed')}")
