"""The Python model of Prolog terms.

A Prolog term is one of these plain Python values:

==========================  =====================================================
Prolog                      Python
==========================  =====================================================
atom ``foo``, ``'a b'``     ``str`` (``"foo"``, ``"a b"``); the atom ``'[]'`` is
                            ``"[]"``, distinct from the empty list
string ``"text"``           :class:`PlString` (``PlString("text")``)
integer, float              ``int`` (any size), ``float`` (NaN and infinities are
                            refused when encoding)
list ``[a, b]``, ``[]``     ``list`` (``["a", "b"]``, ``[]``); a partial list
                            ``[a|T]`` is ``Compound("[|]", ("a", Var("T")))``
compound ``f(a, X)``        :class:`Compound` (``Compound("f", ("a", Var("X")))``)
variable ``X``, ``_``       :class:`Var` (``Var("X")``, anonymous ``Var()``)
==========================  =====================================================

Inside one term, every ``Var`` with the same name is the same Prolog variable; each
anonymous ``Var()`` is a fresh one. Variables that Prolog returns keep the names they
had in the request; new ones are named ``_G0``, ``_G1``, ... (see ``prolog/api.pl``).

Clauses are terms too: ``Head :- Body`` is ``Compound(":-", (head, body))`` with a
right-nested ``","`` conjunction as body; :func:`clause`, :func:`conj` and
:func:`clause_parts` convert between that and ``(head, [literal, ...])``.

The bridge's one Prolog-text writer, :func:`encode`, lives here with the terms it
writes, so ``str()`` of a :class:`Compound`, :class:`Var` or :class:`PlString` is its
Prolog syntax (the clause operators ``:-``, ``,``, ``;`` and ``->`` written infix) and
this module imports nothing of the project. :func:`readable` writes a term for a person
(a reason, a headline): the pairs ``X-Y`` infix too and the variables lettered ``A``,
``B``, ... as SWI-Prolog prints them; never ``str()`` or ``repr()`` a Python list of
terms, which shows the dataclasses (``[Compound(name='-', ...)]``). Requests travel to Prolog as text that
``prolog/api.pl`` parses with ``term_string/3``; :func:`encode_request` writes a whole
request. Nothing else in the project may build Prolog text: use these functions or
``str()`` of a term. Replies are read by :mod:`creative_py.bridge.codec`.
"""

from __future__ import annotations

import functools
import math
import numbers
import re
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Optional, Sequence, Union

_VAR_NAME = re.compile(r"[A-Z_][A-Za-z0-9_]*\Z")


@dataclass(frozen=True)
class PlString:
    """A Prolog string object (``"text"``), as opposed to an atom (a Python ``str``)."""

    value: str

    def __post_init__(self) -> None:
        if not isinstance(self.value, str):
            raise TypeError(f"PlString.value must be a str, got {type(self.value).__name__}")

    def __str__(self) -> str:
        return encode(self, operators=True)


@dataclass(frozen=True)
class Var:
    """A Prolog variable: ``Var("X")`` is ``X``; ``Var()`` is the anonymous ``_``.

    A name must be a Prolog variable name: an upper-case ASCII letter or ``_``, then
    ASCII letters, digits or ``_``. The name ``"_"`` is the anonymous variable.
    """

    name: Optional[str] = None

    def __post_init__(self) -> None:
        if self.name is None:
            return
        if not isinstance(self.name, str) or not _VAR_NAME.match(self.name):
            raise ValueError(
                f"Var.name {self.name!r} is not a Prolog variable name "
                "(an upper-case ASCII letter or '_' then letters, digits or '_')"
            )
        if self.name == "_":
            object.__setattr__(self, "name", None)

    @property
    def anonymous(self) -> bool:
        """Return whether this is the anonymous variable ``_``."""
        return self.name is None

    def __str__(self) -> str:
        return "_" if self.name is None else self.name


@dataclass(frozen=True)
class Compound:
    """A compound term ``name(arg1, ..., argN)``; ``args`` is a tuple (a list is copied).

    Zero arguments (``foo()``) is allowed, as in SWI-Prolog 7 and later; it is not the
    atom ``foo``.
    """

    name: str
    args: tuple = ()

    def __post_init__(self) -> None:
        if not isinstance(self.name, str):
            raise TypeError(f"Compound.name must be a str, got {type(self.name).__name__}")
        if not isinstance(self.args, tuple):
            if isinstance(self.args, list):
                object.__setattr__(self, "args", tuple(self.args))
            else:
                raise TypeError(
                    f"Compound.args must be a tuple or list, got {type(self.args).__name__}"
                )

    @property
    def arity(self) -> int:
        """Return the number of arguments."""
        return len(self.args)

    @property
    def indicator(self) -> str:
        """Return the predicate indicator ``name/arity`` as text (atom name unquoted)."""
        return f"{self.name}/{len(self.args)}"

    def __str__(self) -> str:
        return encode(self, operators=True)


Term = Union[str, int, float, PlString, Var, Compound, list]
"""Any Prolog term in the Python model (see the module docstring)."""


def conj(literals: Sequence[Term]) -> Term:
    """Return the right-nested conjunction ``(L1, (L2, ...))`` of ``literals``.

    An empty sequence gives the atom ``true``; one literal gives that literal.
    """
    items = list(literals)
    if not items:
        return "true"
    result = items[-1]
    for literal in reversed(items[:-1]):
        result = Compound(",", (literal, result))
    return result


def conj_to_list(body: Term) -> list:
    """Return the literals of a conjunction as a list, flattening nested ``,``/2.

    The atom ``true`` alone is the empty body ``[]``; ``true`` inside a longer
    conjunction is kept (it is a literal there).
    """
    if body == "true":
        return []
    return list(_flatten_conj(body))


def _flatten_conj(term: Term) -> Iterator[Term]:
    stack = [term]
    while stack:
        item = stack.pop()
        if isinstance(item, Compound) and item.name == "," and len(item.args) == 2:
            stack.append(item.args[1])
            stack.append(item.args[0])
        else:
            yield item


def clause(head: Term, body: Sequence[Term] = ()) -> Term:
    """Return the clause ``head :- L1, ..., Ln``, or ``head`` itself for an empty body."""
    literals = list(body)
    if not literals:
        return head
    return Compound(":-", (head, conj(literals)))


def clause_parts(term: Term) -> tuple[Term, list]:
    """Return ``(head, body_literals)`` of a clause; a unit clause has an empty body."""
    if isinstance(term, Compound) and term.name == ":-" and len(term.args) == 2:
        return term.args[0], conj_to_list(term.args[1])
    return term, []


def variables(term: Term) -> list[Var]:
    """Return the named variables of ``term`` in depth-first, left-to-right order, once each."""
    seen: dict[str, Var] = {}
    stack = [term]
    while stack:
        item = stack.pop()
        if isinstance(item, Var):
            if item.name is not None and item.name not in seen:
                seen[item.name] = item
        elif isinstance(item, Compound):
            stack.extend(reversed(item.args))
        elif isinstance(item, list):
            stack.extend(reversed(item))
    return list(seen.values())


def map_variables(term: Term, fn: Callable[[Var], Term]) -> Term:
    """Return ``term`` with every variable ``v`` (named or anonymous) replaced by ``fn(v)``.

    Iterative, so a clause with thousands of body literals (a deep ``,``/2 chain) does
    not reach Python's recursion limit.
    """
    out: list = []
    stack: list = [(term, False)]
    while stack:
        node, built = stack.pop()
        if isinstance(node, Compound):
            if built:
                n = len(node.args)
                args = tuple(out[len(out) - n:]) if n else ()
                del out[len(out) - n:]
                out.append(Compound(node.name, args))
            else:
                stack.append((node, True))
                stack.extend((arg, False) for arg in reversed(node.args))
        elif isinstance(node, list):
            if built:
                n = len(node)
                items = out[len(out) - n:] if n else []
                del out[len(out) - n:]
                out.append(items)
            else:
                stack.append((node, True))
                stack.extend((item, False) for item in reversed(node))
        elif isinstance(node, Var):
            out.append(fn(node))
        else:
            out.append(node)
    return out[0]


def rename_variables(term: Term, suffix: str) -> Term:
    """Return ``term`` with every named variable ``N`` renamed ``N<suffix>``.

    Keeps the variables of separately obtained terms apart when they travel in one
    request (two replies may both name a variable ``_G0``).
    """
    return map_variables(term, lambda v: v if v.name is None else Var(v.name + suffix))


def is_ground(term: Term) -> bool:
    """Return whether ``term`` contains no variable (named or anonymous)."""
    stack = [term]
    while stack:
        item = stack.pop()
        if isinstance(item, Var):
            return False
        if isinstance(item, Compound):
            stack.extend(item.args)
        elif isinstance(item, list):
            stack.extend(item)
    return True


def fact_term(fact: tuple) -> Term:
    """Return a primitive fact given as a tuple, ``("pose", "cube1", x, y, z, yaw)``, as a
    term: the first item is the predicate name; ``bool`` becomes the atom ``true`` or
    ``false`` and a numpy scalar its Python number."""
    name, *args = fact
    plain = tuple(("true" if a else "false") if isinstance(a, bool)
                  else (a.item() if hasattr(a, "item") else a) for a in args)
    return Compound(name, plain) if plain else name


# The one Prolog-text writer.

_PLAIN_ATOM = re.compile(r"[a-z][A-Za-z0-9_]*\Z")

# Infix operators written as operators by encode(..., operators=True):
# name -> (priority, type). Standard SWI-Prolog priorities.
_INFIX = {
    ":-": (1200, "xfx"),
    ";": (1100, "xfy"),
    "->": (1050, "xfy"),
    ",": (1000, "xfy"),
}
_READABLE_INFIX = {**_INFIX, "-": (500, "yfx")}
"""The operators :func:`readable` writes infix: the clause operators and the pair
``Key-Value`` (``yfx`` 500, as in SWI-Prolog)."""
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
    return _encode(value, _INFIX if operators else {}, _TOP_PRIORITY)


def readable(value: Any) -> str:
    """Return a term as a person reads it, for reasons, headlines and reports.

    The text :func:`encode` writes with ``operators=True``, with the pairs ``K-V``
    infix too, and every named variable renamed ``A``, ``B``, ... ``Z``, ``A1``, ... in
    order of first appearance (the engine's fresh ``_G0``, ``_G1`` read as SWI-Prolog
    prints them), so ``[handle_length(_G0,long)-tried]`` reads
    ``[handle_length(A,long)-tried]``. A Python list of terms is written as a Prolog
    list. It reads back as the same term up to the variables' names.

    Raises
    ------
    ValueError, TypeError
        As :func:`encode`.
    """
    return _encode(lettered(value), _READABLE_INFIX, _TOP_PRIORITY)


def lettered(value: Any) -> Any:
    """Return ``value`` with every named variable renamed ``A``, ``B``, ... ``Z``,
    ``A1``, ... in order of first appearance (as :func:`readable` writes them)."""
    names = {v.name: Var(_letter(i)) for i, v in enumerate(variables(value))}
    return map_variables(value, lambda v: names.get(v.name, v))


def _letter(index: int) -> str:
    """``A`` .. ``Z``, then ``A1`` .. ``Z1``, ... (SWI-Prolog's ``'$VAR'(N)`` names)."""
    return chr(ord("A") + index % 26) + (str(index // 26) if index >= 26 else "")


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
        _encode(arg, {}, _ARG_PRIORITY, (Compound(op, tuple(args)), i), False,
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


def _encode(value: Any, operators: dict, max_priority: int, path: tuple = (),
            operand: bool = False, suffix: str = "") -> str:
    # ``operators`` maps the names written infix to (priority, type): {} (the wire
    # format), _INFIX or _READABLE_INFIX.
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


def _encode_binary(value: Compound, operators: dict, max_priority: int, operand: bool,
                   suffix: str) -> str:
    items = _chain(value)
    links = len(items) - 1
    if value.name in operators:
        priority, kind = operators[value.name]
        if kind != "xfy":
            items, links = [value.args[0], value.args[1]], 1
        left_max = priority if kind == "yfx" else priority - 1
        right_max = priority if kind == "xfy" else priority - 1
        sep = {",": ", ", "-": "-"}.get(value.name, f" {value.name} ")
        parts = [_encode(item, operators, left_max, (value, 0), True, suffix)
                 for item in items[:-1]]
        parts.append(_encode(items[-1], operators, right_max, (value, 1), True, suffix))
        if sep == "-" and parts[-1][:1] in "-+":  # a-(-1) is written a- -1
            parts[-1] = " " + parts[-1]
        text = sep.join(parts)
        return "(" + text + ")" if priority > max_priority else text
    functor = _atom(value.name) + "("
    parts = [functor + _encode(item, operators, _ARG_PRIORITY, (value, 0), False, suffix) + ","
             for item in items[:-1]]
    parts.append(_encode(items[-1], operators, _ARG_PRIORITY, (value, 1), False, suffix))
    parts.append(")" * links)
    return "".join(parts)
