"""Tool kinds as plug-ins: one module per kind, found by the name of its ontology file.

A kind of tool is two files: ``ontology/kinds/<kind>.pl`` (its hierarchy, catalogue ->
structural literals, size model) and ``creative_py/kinds/<kind>.py`` (its spec: parts,
catalogue facts, OpenSCAD model, printable dimensions, strength model, and how the
simulator holds it, as data). The registry is the ontology's folder: every
``<kind>.pl`` there names the module imported here, so a new kind is registered by
adding its two files and nothing else. A kind module exports ``CLASSES``: the ontology
classes of its tools (the ``kind`` of an ``objects.toml`` table, a new tool's class
literal) -> the spec class (a frozen dataclass deriving from
:class:`~creative_py.kinds.parts.KindSpec`, with a ``from_fields(kind, data)``
constructor).

This package is below :mod:`creative_py.backends.pybullet` and :mod:`creative_py.mesh`: it imports
nothing else of the project and no third-party engine (numbers, parts, text).
"""

from __future__ import annotations

import importlib
from functools import cache
from pathlib import Path
from types import ModuleType
from typing import Any

from creative_py.kinds.parts import KindSpec

KINDS_DIR = Path(__file__).resolve().parents[2] / "ontology" / "kinds"
"""The ontology's folder of tool kinds; its file names are the registry's keys."""


@cache
def kind_names() -> tuple[str, ...]:
    """Return the registered kinds: the names of ``ontology/kinds/*.pl``, sorted."""
    return tuple(sorted(p.stem for p in KINDS_DIR.glob("*.pl")))


@cache
def kind_module(name: str) -> ModuleType:
    """Return the plug-in module of the kind ``name`` (``creative_py.kinds.<name>``).

    Raises
    ------
    KeyError
        ``name`` has no ontology file (the message lists the kinds).
    ImportError
        The ontology file has no plug-in module, or it lacks ``CLASSES``.
    """
    if name not in kind_names():
        raise KeyError(f"no tool kind {name!r}; kinds (ontology/kinds/*.pl): "
                       f"{', '.join(kind_names())}")
    try:
        module = importlib.import_module(f"{__name__}.{name}")
    except ModuleNotFoundError as exc:
        if exc.name != f"{__name__}.{name}":
            raise
        raise ImportError(f"{KINDS_DIR / (name + '.pl')}: the tool kind has no plug-in "
                          f"module creative_py/kinds/{name}.py") from None
    if not isinstance(getattr(module, "CLASSES", None), dict):
        raise ImportError(f"creative_py/kinds/{name}.py: a kind module must export CLASSES "
                          "(ontology class -> spec class)")
    return module


@cache
def spec_classes() -> dict[str, type]:
    """Return every tool class of every kind -> its spec class (``hook`` -> HookSpec)."""
    out: dict[str, type] = {}
    for name in kind_names():
        for cls_name, spec_cls in kind_module(name).CLASSES.items():
            out[cls_name] = spec_cls
    return out


def kind_of(spec: Any) -> str:
    """Return the kind (module name) of a spec, e.g. ``hook_like`` for a stick."""
    for name in kind_names():
        if type(spec) in kind_module(name).CLASSES.values():
            return name
    raise TypeError(f"{type(spec).__name__} is no spec of a tool kind; kinds: "
                    f"{', '.join(kind_names())}")


def spec_from_dict(data: dict, *, source: str = "<dict>") -> KindSpec:
    """Build a spec from a TOML table or a manifest's ``spec``; its ``kind`` field is
    the tool's ontology class. Errors name ``source`` and the offending field."""
    data = dict(data)
    kind = data.pop("kind", None)
    classes = spec_classes()
    cls = classes.get(kind)
    if cls is None:
        raise ValueError(f"{source}: object {data.get('name', '?')!r}: field 'kind' must be "
                         f"one of {', '.join(classes)}, got {kind!r}")
    known = {f for f in cls.__dataclass_fields__ if f != "kind"}
    unknown = sorted(set(data) - known)
    if unknown:
        raise ValueError(f"{source}: object {data.get('name', '?')!r}: unknown field(s) "
                         f"{', '.join(unknown)}; expected some of {', '.join(sorted(known))}")
    for f in cls.__dataclass_fields__.values():  # numbers first: True is no length
        if f.name in data and str(f.type) in ("float", "float | None"):
            v = data[f.name]
            if isinstance(v, bool) or not (isinstance(v, (int, float))
                                           or (v is None and "None" in str(f.type))):
                raise ValueError(f"{source}: object {data.get('name', '?')!r}: field "
                                 f"{f.name!r} must be a number, got {v!r}")
    try:
        return cls.from_fields(kind, data)
    except TypeError as exc:
        raise ValueError(f"{source}: object {data.get('name', '?')!r}: {exc}") from None
    except ValueError as exc:
        raise ValueError(f"{source}: {exc}") from None
