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

``str()`` of a :class:`Compound`, :class:`Var` or :class:`PlString` is Prolog syntax
(the clause operators ``:-``, ``,``, ``;`` and ``->`` written infix), produced by the
bridge's one writer, :func:`creative_py.bridge.text.encode`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable, Iterator, Optional, Sequence, Union

_TEXT_WRITER: list[Callable[[object], str]] = []
"""The Prolog-text writer, set by :mod:`creative_py.bridge.text` when it is imported
(the package imports it), so that ``str()`` of a term is its Prolog text and this
module stays the leaf of the bridge."""


def set_text_writer(writer: Callable[[object], str]) -> None:
    """Make ``str()`` of every term write its Prolog text with ``writer``."""
    _TEXT_WRITER[:] = [writer]


def _write(term: object) -> str:
    # Importing any module of the package runs its __init__, which imports the writer.
    return _TEXT_WRITER[0](term)

_VAR_NAME = re.compile(r"[A-Z_][A-Za-z0-9_]*\Z")


@dataclass(frozen=True)
class PlString:
    """A Prolog string object (``"text"``), as opposed to an atom (a Python ``str``)."""

    value: str

    def __post_init__(self) -> None:
        if not isinstance(self.value, str):
            raise TypeError(f"PlString.value must be a str, got {type(self.value).__name__}")

    def __str__(self) -> str:
        return _write(self)


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
        return _write(self)


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

