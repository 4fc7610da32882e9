"""Laws checked on random terms: the bridge round trip, LGG laws, term_lgg vs a reference."""

from __future__ import annotations

import math
from typing import Any

from hypothesis import given, settings
from hypothesis import strategies as st

from creative_py.bridge import (FAILED, Compound, Engine, PlString, Var, clause, encode,
                                readable)
from creative_py.bridge.terms import map_variables, variables

SETTINGS = settings(max_examples=200, deadline=None)

# ----------------------------------------------------------------- strict equality


def same(a: Any, b: Any) -> bool:
    """Return whether two Python terms are identical as Prolog terms.

    Stricter than ``==``: ``1`` and ``1.0``, ``0.0`` and ``-0.0`` differ, as they do
    in Prolog's ``==``.
    """
    if type(a) is not type(b):
        return False
    if isinstance(a, float):
        return a.hex() == b.hex()
    if isinstance(a, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, Compound):
        return a.name == b.name and len(a.args) == len(b.args) and all(
            same(x, y) for x, y in zip(a.args, b.args))
    return a == b


# ----------------------------------------------------------------- (1) round trip

ATOM_NAMES = st.one_of(
    st.text(max_size=8),
    st.sampled_from([":-", ",", "|", "[]", "{}", ";", "!", "-", "\\+", "a'b", "\\", "é"]),
)
# '[|]' builds lists and '$VAR' carries variable names: documented aliases, excluded.
FUNCTOR_NAMES = ATOM_NAMES.filter(lambda n: n not in ("[|]", "$VAR"))
NAMED_VARS = st.sampled_from(["X", "Y", "Z", "_A", "Long_name1"]).map(Var)
LEAVES = st.one_of(
    ATOM_NAMES,
    st.integers(),
    st.integers(min_value=-(2**130), max_value=2**130),
    st.floats(allow_nan=False, allow_infinity=False),
    st.text(max_size=8).map(PlString),
    NAMED_VARS,
)
TERMS = st.recursive(
    LEAVES,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.builds(Compound, FUNCTOR_NAMES, st.lists(inner, max_size=3).map(tuple)),
    ),
    max_leaves=20,
)


@SETTINGS
@given(term=TERMS)
def test_any_term_round_trips_through_prolog(engine: Engine, term: Any) -> None:
    back = engine.call("echo", term)
    assert same(back, term), (encode(term), back)


@SETTINGS
@given(term=TERMS)
def test_pretty_text_reads_back_as_the_same_term(engine: Engine, term: Any) -> None:
    back = engine.parse(encode(term, operators=True))
    assert same(back, term), (encode(term, operators=True), back)


PAIRED = st.recursive(TERMS, lambda inner: st.one_of(
    st.builds(lambda a, b: Compound("-", (a, b)), inner, inner),
    st.lists(inner, max_size=3)), max_leaves=12)


@SETTINGS
@given(term=PAIRED)
def test_readable_text_reads_back_as_the_same_term_with_lettered_variables(
        engine: Engine, term: Any) -> None:
    """``readable`` (pairs infix, variables lettered A, B, ...) is Prolog text of the
    same term: only the variables' names differ, each renamed once, in order."""
    text = readable(term)
    letters = {v.name: Var(chr(ord("A") + i)) for i, v in enumerate(variables(term))}
    assert same(engine.parse(text), map_variables(term, lambda v: letters.get(v.name, v))), text


# ----------------------------------------------------------------- (2) LGG laws

CONSTANTS = st.sampled_from(["a", "b", "c", 1, 2, 0.5])
LITERALS = st.one_of(
    st.builds(lambda x, y: Compound("p", (x, y)), CONSTANTS, CONSTANTS),
    st.builds(lambda x: Compound("q", (x,)), CONSTANTS),
    st.builds(lambda x, y: Compound("r", (x, y)), CONSTANTS, CONSTANTS),
)
EXAMPLES = st.builds(
    lambda x, y, body: clause(Compound("t", (x, y)), body),
    CONSTANTS, CONSTANTS, st.lists(LITERALS, min_size=1, max_size=5),
)


def body_length(c: Any) -> int:
    if isinstance(c, Compound) and c.name == ":-" and len(c.args) == 2:
        length, body = 1, c.args[1]
        while isinstance(body, Compound) and body.name == "," and len(body.args) == 2:
            length, body = length + 1, body.args[1]
        return length
    return 0


@SETTINGS
@given(c1=EXAMPLES, c2=EXAMPLES)
def test_clause_lgg_generalises_both_inputs_and_is_commutative(engine: Engine, c1, c2) -> None:
    g12 = engine.clause_lgg(c1, c2)
    g21 = engine.clause_lgg(c2, c1)
    assert engine.theta_subsumes(g12, c1), (g12, c1)
    assert engine.theta_subsumes(g12, c2), (g12, c2)
    # Commutative up to renaming: the two reduced LGGs subsume each other and have
    # the same number of literals (equivalent reduced clauses are variants); the body
    # order follows the first argument, so =@= on the clauses themselves would be
    # too strict.
    assert engine.theta_subsumes(g12, g21) and engine.theta_subsumes(g21, g12), (g12, g21)
    assert body_length(g12) == body_length(g21)


@SETTINGS
@given(c=EXAMPLES)
def test_lgg_of_a_clause_with_itself_is_its_reduction(engine: Engine, c) -> None:
    assert engine.variant(engine.clause_lgg(c, c), engine.clause_reduce(c))


@SETTINGS
@given(t1=st.deferred(lambda: SMALL_TERMS), t2=st.deferred(lambda: SMALL_TERMS))
def test_term_lgg_is_commutative_up_to_renaming(engine: Engine, t1, t2) -> None:
    assert engine.variant(engine.term_lgg(t1, t2), engine.term_lgg(t2, t1))


# ----------------------------------------------------------------- (3) reference LGG

SMALL_LEAVES = st.one_of(
    st.sampled_from(["a", "b", "c", "[]", 1, 2, 1.0, Var("X"), Var("Y")]),
    st.just([]),
)
SMALL_TERMS = st.recursive(
    SMALL_LEAVES,
    lambda inner: st.one_of(
        st.builds(lambda x: Compound("g", (x,)), inner),
        st.builds(lambda x, y: Compound("f", (x, y)), inner, inner),
        st.builds(lambda x, y: Compound("h", (x, y)), inner, inner),
        st.lists(inner, max_size=3),
    ),
    max_leaves=10,
)

NIL = ("nil",)  # the empty list in cons form, distinct from the atom '[]'


def cons_form(t: Any) -> Any:
    """Return ``t`` with Python lists as ``'[|]'`` cells ending in :data:`NIL`."""
    if isinstance(t, list):
        result: Any = NIL
        for item in reversed(t):
            result = Compound("[|]", (cons_form(item), result))
        return result
    if isinstance(t, Compound):
        return Compound(t.name, tuple(cons_form(a) for a in t.args))
    return t


def key(t: Any) -> Any:
    """Return a hashable identity of a cons-form term (Prolog ``==``)."""
    if isinstance(t, Compound):
        return ("c", t.name, tuple(key(a) for a in t.args))
    if isinstance(t, float):
        return ("f", t.hex())
    return (type(t).__name__, t if not isinstance(t, Var) else t.name)


def reference_lgg(s: Any, t: Any, table: dict) -> Any:
    """Plotkin anti-unification: the same pair of differing subterms, the same variable."""
    if key(s) == key(t):
        return s
    if (isinstance(s, Compound) and isinstance(t, Compound) and s.name == t.name
            and len(s.args) == len(t.args)):
        return Compound(s.name, tuple(reference_lgg(a, b, table) for a, b in zip(s.args, t.args)))
    pair = (key(s), key(t))
    if pair not in table:
        table[pair] = Var(f"_R{len(table)}")
    return table[pair]


def canonical(t: Any, names: dict) -> Any:
    """Rename every variable by first occurrence: equal results are then variants.

    (lgg.pl returns a term that shares no variable with its inputs, so an input
    variable comes back renamed; only the pattern of variables is compared.)
    """
    if isinstance(t, Var):
        return names.setdefault(t.name, Var(f"V{len(names)}"))
    if isinstance(t, Compound):
        return Compound(t.name, tuple(canonical(a, names) for a in t.args))
    return t


@SETTINGS
@given(t1=SMALL_TERMS, t2=SMALL_TERMS)
def test_term_lgg_agrees_with_a_reference_anti_unifier(engine: Engine, t1, t2) -> None:
    got = canonical(cons_form(engine.term_lgg(t1, t2)), {})
    want = canonical(reference_lgg(cons_form(t1), cons_form(t2), {}), {})
    assert key(got) == key(want), (encode(t1), encode(t2), got, want)


def test_reference_helpers_tell_apart_what_prolog_tells_apart() -> None:
    assert key(1) != key(1.0)
    assert key(cons_form([])) != key("[]")
    assert not same(0.0, -0.0) and same(math.pi, math.pi)
    assert FAILED is not None
