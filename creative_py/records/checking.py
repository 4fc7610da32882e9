"""The one type checker of a run folder's typed records: a field's JSON value against
the field's annotation, for the trial record (:mod:`creative_py.records.trial`) and
every part of the summary (:mod:`creative_py.records.summary`).

A record is a dataclass whose annotations say what its JSON holds (``int``, ``float``,
``str``, ``bool``, ``list[X]``, ``dict[str, X]`` (its keys checked too: JSON keeps
only text keys, so an int key would read back as another record), ``Union[...]``/``Optional[X]``,
``Any``, or a :class:`Checked` part read by its own ``from_dict``). :func:`typed` returns
the value checked, or raises ValueError naming the field by its place in the file
(``facts[1]``, ``create.created_tools[0].print.filament_g``); a float written as
``"nan"``, ``"inf"`` or ``"-inf"`` (:func:`creative_py.records.trial.jsonable`) reads
back as a float. A new field of a record is one typed line there; nothing here changes.
"""

from __future__ import annotations

import types
import typing
from typing import Any, Callable, Optional, Union

Warn = Optional[Callable[[str], None]]
"""Receives one sentence per dropped field; None: a wrong field raises ValueError."""


class Checked:
    """A part of a record that reads itself: ``from_dict(data, where, warn)`` with its
    place in the file (the summary's parts)."""

    @classmethod
    def from_dict(cls, data: Any, where: str = "", warn: Warn = None) -> Any:
        raise NotImplementedError


class Dropped(Exception):
    """A required field was missing or of the wrong type and ``warn`` said so: the part
    it belongs to is not shown."""


_HINTS: dict[type, dict[str, Any]] = {}


def hints(cls: type) -> dict[str, Any]:
    """Return the resolved annotations of a record class (cached)."""
    if cls not in _HINTS:
        _HINTS[cls] = typing.get_type_hints(cls)
    return _HINTS[cls]


def typed(value: Any, tp: Any, name: str, warn: Warn = None, convert: bool = True) -> Any:
    """Return ``value`` checked against the type ``tp``; raise ValueError naming field
    ``name``.

    A :class:`Checked` part is read by its own ``from_dict``; with ``convert``, a float
    written as ``"nan"`` or ``"inf"`` is read back as a float (a record built in code is
    checked with ``convert=False``). With ``warn``, a list item or mapping value of the
    wrong type is dropped and said.
    """
    origin = typing.get_origin(tp)
    if tp is Any:
        return value
    if isinstance(tp, type) and issubclass(tp, Checked):
        return tp.from_dict(value, name, warn)
    if origin in (Union, types.UnionType):
        return _typed_union(value, tp, name, warn, convert)
    if tp in _SCALARS:
        return _typed_scalar(value, tp, name, convert)
    if origin is list:
        return _typed_list(value, tp, name, warn, convert)
    if origin is dict:
        return _typed_dict(value, tp, name, warn, convert)
    raise TypeError(f"field {name!r}: type {tp} is not one a record can check")


_SCALARS = (type(None), float, int, str, bool)
"""The plain types :func:`_typed_scalar` checks."""


def _typed_union(value: Any, tp: Any, name: str, warn: Warn, convert: bool) -> Any:
    """Return ``value`` checked against the first of union ``tp``'s types it is (None
    first, if allowed); an ``Optional[X]`` raises X's own error."""
    options = typing.get_args(tp)
    if value is None and type(None) in options:
        return None
    options = tuple(o for o in options if o is not type(None))
    if len(options) == 1:  # Optional[X]: X's own error, naming the inner field
        return typed(value, options[0], name, warn, convert)
    for option in options:
        try:
            return typed(value, option, name, warn, convert)
        except ValueError:
            pass
    raise wrong(name, value, tp)


def _typed_scalar(value: Any, tp: type, name: str, convert: bool) -> Any:
    """Return ``value`` if it is of the plain type ``tp`` (None, float, int, str, bool;
    a bool is no number, an int is a float; with ``convert``, ``"nan"``, ``"inf"`` and
    ``"-inf"`` are floats)."""
    if tp is type(None):
        if value is None:
            return value
        raise wrong(name, value, tp)
    if tp is float:
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            return value  # an int stays one: the file is written back as it was read
        if convert and isinstance(value, str) and value in ("nan", "inf", "-inf"):
            return float(value)
        raise wrong(name, value, tp)
    if tp is int:
        if isinstance(value, int) and not isinstance(value, bool):
            return value
        raise wrong(name, value, tp)
    if isinstance(value, tp):
        return value
    raise wrong(name, value, tp)


def _typed_list(value: Any, tp: Any, name: str, warn: Warn, convert: bool) -> list:
    """Return the list ``value`` with each item checked against ``tp``'s item type; with
    ``warn``, a wrong item is dropped and said."""
    if not isinstance(value, list):
        raise wrong(name, value, tp)
    (item,) = typing.get_args(tp) or (Any,)
    out = []
    for i, v in enumerate(value):
        try:
            out.append(typed(v, item, f"{name}[{i}]", warn, convert))
        except Dropped:
            continue
        except ValueError as exc:
            if warn is None:
                raise
            warn(f"{exc}; not shown")
    return out


def _typed_dict(value: Any, tp: Any, name: str, warn: Warn, convert: bool) -> dict:
    """Return the mapping ``value`` with each key checked against ``tp``'s key type and
    each value against its value type; with ``warn``, a wrong entry is dropped and said."""
    if not isinstance(value, dict):
        raise wrong(name, value, tp)
    key, item = typing.get_args(tp) or (Any, Any)
    out_map = {}
    for k, v in value.items():
        try:
            try:  # a key JSON cannot keep (an int is written back as its text)
                typed(k, key, name, None, False)
            except ValueError:
                raise ValueError(f"field {name!r}: key {k!r} is not of type "
                                 f"{type_name(key)}") from None
            out_map[k] = typed(v, item, f"{name}.{k}", warn, convert)
        except ValueError as exc:
            if warn is None:
                raise
            warn(f"{exc}; not shown")
    return out_map


def wrong(name: str, value: Any, tp: Any) -> ValueError:
    """Return the error of ``value`` in field ``name``, which must be of type ``tp``."""
    what = f"field {name!r}: " if name else ""
    if isinstance(tp, type) and issubclass(tp, Checked):
        return ValueError(f"{what}{value!r} is not a JSON object")
    return ValueError(f"{what}{value!r} is not of type {type_name(tp)}")


def type_name(tp: Any) -> str:
    """Return a field type in words (``int or str``, ``object`` for a part)."""
    if typing.get_origin(tp) in (Union, types.UnionType):
        return " or ".join(type_name(t) for t in typing.get_args(tp)
                           if t is not type(None))
    if isinstance(tp, type) and issubclass(tp, Checked):
        return "object"
    if typing.get_origin(tp) is not None:
        return str(tp).replace("typing.", "")
    return getattr(tp, "__name__", None) or str(tp).replace("typing.", "")


__all__ = ["Checked", "Dropped", "Warn", "hints", "type_name", "typed", "wrong"]
