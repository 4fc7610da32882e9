"""The bridge's one Prolog-text writer: Python term -> Prolog text.

Requests travel to Prolog as text that ``prolog/api.pl`` parses with ``term_string/3``;
:func:`encode` writes that text, :func:`encode_request` a whole request. Nothing else in
the project may build Prolog text: use these functions, or ``str()`` of a term of
:mod:`creative_py.bridge.terms` (which this module makes write through :func:`encode`).
This module depends only on the term model; replies are read by
:mod:`creative_py.bridge.codec`.
"""

from __future__ import annotations

import functools
import math
import numbers
import re
from typing import Any, Sequence

from creative_py.bridge import terms
from creative_py.bridge.terms import Compound, PlString, Var

_PLAIN_ATOM = re.compile(r"[a-z][A-Za-z0-9_]*\Z")

# Infix operators written as operators by encode(..., operators=True):
# name -> (priority, type). Standard SWI-Prolog priorities.
_INFIX = {
    ":-": (1200, "xfx"),
    ";": (1100, "xfy"),
    "->": (1050, "xfy"),
    ",": (1000, "xfy"),
}
_ARG_PRIORITY = 999
_TOP_PRIORITY = 1200

# Atoms that are (prefix or infix) operators in standard SWI-Prolog; written as an
# operand of an infix operator they get parentheses so the text reads back the same.
_OPERATOR_ATOMS = frozenset(
    ":- --> ?- ; | -> *-> , := \\+ = \\= == \\== @< @> @=< @>= =.. is =:= =\\= < > =< >= "
    "as >:< :< + - /\\ \\/ xor * / // rdiv << >> mod rem div divmod ** ^ \\ $ : "
    "dynamic discontiguous initialization meta_predicate module_transparent multifile "
    "public thread_local table".split()
)


def _escape(text: str, quote: str) -> str:
    out = []
    for ch in text:
        code = ord(ch)
        if ch == "\\":
            out.append("\\\\")
        elif ch == quote:
            out.append("\\" + quote)
        elif ch == "\n":
            out.append("\\n")
        elif ch == "\t":
            out.append("\\t")
        elif code < 0x20 or 0x7F <= code <= 0x9F:
            out.append(f"\\x{code:x}\\")
        elif 0xD800 <= code <= 0xDFFF:
            raise ValueError(
                f"text {text!r} contains the lone surrogate U+{code:04X}, which is not a character"
            )
        else:
            out.append(ch)
    return "".join(out)


@functools.lru_cache(maxsize=4096)
def _atom(name: str) -> str:
    if _PLAIN_ATOM.match(name):
        return name
    return "'" + _escape(name, "'") + "'"


def _float(value: float, path: tuple = ()) -> str:
    if not math.isfinite(value):
        raise ValueError(
            f"{_where(path)}: {value!r} cannot be sent to Prolog: NaN and infinities are refused"
        )
    text = repr(float(value))
    mantissa, e, exponent = text.partition("e")
    if "." not in mantissa:
        mantissa += ".0"
    return mantissa + e + exponent


def encode(value: Any, *, operators: bool = False) -> str:
    """Return the Prolog text of a Python term (see :mod:`creative_py.bridge.terms`).

    Parameters
    ----------
    value
        ``str`` (atom), ``int``, ``float``, :class:`PlString`, :class:`Var`,
        :class:`Compound` or ``list`` of these, nested to any depth below Python's
        recursion limit. Any ``numbers.Integral`` / ``numbers.Real`` (e.g. numpy
        scalars) is accepted as an integer / float.
    operators
        False (the wire format): canonical text, every compound in functional
        notation, e.g. ``':-'(p(X),','(q(X),r))``. True (for people): the clause
        operators ``:-``, ``;``, ``->`` and ``,`` are written infix with the
        parentheses their priorities need, e.g. ``p(X) :- q(X), r``. Both read back
        as the same term in SWI-Prolog.

    Raises
    ------
    ValueError
        A float is NaN or infinite, or text holds a lone surrogate.
    TypeError
        A value is not part of the term model (``bool``, ``tuple``, ``dict``, ``None``,
        ...); the message names the type and where it was found.
    """
    return _encode(value, operators, _TOP_PRIORITY)


def argument_suffix(index: int) -> str:
    """Return the suffix :func:`encode_request` gives the variables of argument ``index``."""
    return f"_A{index}"


def encode_request(op: str, args: Sequence[Any], *, separate_variables: bool = True) -> str:
    """Return the wire text of the request ``op(args...)`` (canonical, as :func:`encode`).

    With ``separate_variables`` (and more than one argument) each argument is its own
    variable scope: a variable ``X`` of argument ``i`` is written ``X_A<i>``, so terms
    that came from separate replies (which all name variables ``_G0``, ``_G1``, ...)
    do not alias. Without it, equal names in different arguments are one variable.
    """
    if not args:
        return _atom(op)
    if not separate_variables or len(args) == 1:
        return encode(Compound(op, tuple(args)))
    parts = [
        _encode(arg, False, _ARG_PRIORITY, (Compound(op, tuple(args)), i), False,
                argument_suffix(i))
        for i, arg in enumerate(args)
    ]
    return _atom(op) + "(" + ",".join(parts) + ")"


def _where(path: tuple) -> str:
    if not path:
        return "term"
    parent, index = path
    if isinstance(parent, Compound):
        return f"argument {index + 1} of {parent.indicator}"
    return f"list element {index + 1}"


def _encode(value: Any, operators: bool, max_priority: int, path: tuple = (),
            operand: bool = False, suffix: str = "") -> str:
    # ``path`` is (parent, index) of value, turned into text only for an error message;
    # ``suffix`` is appended to every variable name (see encode_request).
    if isinstance(value, str):
        if _PLAIN_ATOM.match(value):
            return value
        text = _atom(value)
        if operand and value in _OPERATOR_ATOMS:
            return "(" + text + ")"
        return text
    if isinstance(value, Compound):
        if len(value.args) == 2:
            return _encode_binary(value, operators, max_priority, operand, suffix)
        args = ",".join([
            _encode(arg, operators, _ARG_PRIORITY, (value, i), False, suffix)
            for i, arg in enumerate(value.args)
        ])
        return _atom(value.name) + "(" + args + ")"
    if isinstance(value, list):
        return "[" + ",".join([
            _encode(item, operators, _ARG_PRIORITY, (value, i), False, suffix)
            for i, item in enumerate(value)
        ]) + "]"
    if isinstance(value, float):
        return _float(value, path)
    if isinstance(value, Var):
        return "_" if value.name is None else value.name + suffix
    if isinstance(value, PlString):
        return '"' + _escape(value.value, '"') + '"'
    if isinstance(value, bool):
        raise TypeError(
            f"{_where(path)}: bool {value!r} is not a Prolog term; use the atom 'true' or 'false'"
        )
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return _float(float(value), path)
    raise TypeError(
        f"{_where(path)}: {type(value).__name__} {value!r} is not a Prolog term "
        "(expected str, int, float, PlString, Var, Compound or list)"
    )


def _chain(value: Compound) -> list:
    """Return the links of a right-nested chain ``n(a, n(b, n(c, d)))`` as [a, b, c, d].

    A long clause body is such a chain; walking it in a loop keeps deep bodies clear
    of Python's recursion limit.
    """
    name = value.name
    items = []
    while isinstance(value, Compound) and value.name == name and len(value.args) == 2:
        items.append(value.args[0])
        value = value.args[1]
    items.append(value)
    return items


def _encode_binary(value: Compound, operators: bool, max_priority: int, operand: bool,
                   suffix: str) -> str:
    items = _chain(value)
    links = len(items) - 1
    if operators and value.name in _INFIX:
        priority, kind = _INFIX[value.name]
        if kind != "xfy":
            items, links = [value.args[0], value.args[1]], 1
        left_max = priority - 1
        right_max = priority if kind == "xfy" else priority - 1
        sep = ", " if value.name == "," else f" {value.name} "
        parts = [_encode(item, operators, left_max, (value, 0), True, suffix)
                 for item in items[:-1]]
        parts.append(_encode(items[-1], operators, right_max, (value, 1), True, suffix))
        text = sep.join(parts)
        return "(" + text + ")" if priority > max_priority else text
    functor = _atom(value.name) + "("
    parts = [functor + _encode(item, operators, _ARG_PRIORITY, (value, 0), False, suffix) + ","
             for item in items[:-1]]
    parts.append(_encode(items[-1], operators, _ARG_PRIORITY, (value, 1), False, suffix))
    parts.append(")" * links)
    return "".join(parts)


terms.set_text_writer(lambda term: encode(term, operators=True))
