"""The bridge's one decoder: a JSON reply of ``prolog/api.pl`` -> Python term.

Replies travel back as JSON text written by ``api.pl`` (a fixed, self-describing
schema, so no Prolog lexical rule has to be re-implemented in Python); :func:`decode`
reads it. Requests are written by :func:`creative_py.bridge.terms.encode_request`. The reply schema:

=======================  =========================================
Prolog                   JSON
=======================  =========================================
atom ``foo``             ``"foo"``
``[]``, ``[a, b]``       ``[]``, ``["a", "b"]`` (proper lists only)
integer, float           number (``NaN``, ``Infinity``, ``-Infinity`` for the specials)
string ``"s"``           ``{"s": "s"}``
variable                 ``{"v": "Name"}``
compound ``f(a)``        ``{"f": "f", "a": ["a"]}``
chain ``n(a, n(b, c))``  ``{"r": "n", "a": ["a", "b", "c"]}`` (a right-nested binary
                         chain, e.g. a clause body, sent flat; decoded back to nesting)
blob (stream, clause)    ``{"b": "<stream>(0x...)"}`` (decoded as an atom: its text)
=======================  =========================================
"""

from __future__ import annotations

import json

from creative_py.bridge.errors import BridgeProtocolError
from creative_py.bridge.terms import Compound, PlString, Term, Var


def _object_hook(obj: dict) -> Term:
    if "f" in obj:
        return Compound(obj["f"], tuple(obj["a"]))
    if "r" in obj:
        name, items = obj["r"], obj["a"]
        result = items[-1]
        for item in reversed(items[:-1]):
            result = Compound(name, (item, result))
        return result
    if "s" in obj:
        return PlString(obj["s"])
    if "v" in obj:
        return Var(obj["v"])
    if "b" in obj:
        return obj["b"]
    raise BridgeProtocolError(f"unknown object in a Prolog reply: {obj!r}")


def decode(text: str) -> Term:
    """Return the Python term of a JSON reply written by ``api.pl`` (schema above).

    Raises
    ------
    BridgeProtocolError
        The text is not a reply in the schema above (a bug on one side of the bridge).
    """
    try:
        return json.loads(text, object_hook=_object_hook)
    except (ValueError, KeyError, TypeError) as exc:
        raise BridgeProtocolError(f"malformed reply from Prolog ({exc}): {text[:200]!r}") from exc
