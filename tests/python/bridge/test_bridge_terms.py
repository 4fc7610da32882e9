"""The term model and the codec, without Prolog."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

from creative_py.bridge import (
    BridgeProtocolError,
    Compound,
    PlString,
    Var,
    clause,
    clause_parts,
    conj,
    conj_to_list,
    decode,
    encode,
    is_ground,
    readable,
    variables,
)

X, Y = Var("X"), Var("Y")


def test_importing_the_bridge_starts_no_prolog() -> None:
    code = (
        "import sys, creative_py.bridge, creative_py.bridge.engine;"
        "assert 'pyswip' not in sys.modules, 'pyswip imported';"
        "assert creative_py.bridge.Engine._instance is None"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=60)


@pytest.mark.parametrize(
    ("value", "text"),
    [
        ("foo", "foo"),
        ("fooBar_1", "fooBar_1"),
        ("Foo", "'Foo'"),
        ("_x", "'_x'"),
        ("", "''"),
        ("[]", "'[]'"),
        ([], "[]"),
        ("{}", "'{}'"),
        (":-", "':-'"),
        (",", "','"),
        ("a b", "'a b'"),
        ("it's", "'it\\'s'"),
        ("back\\slash", "'back\\\\slash'"),
        ("two\nlines\t", "'two\\nlines\\t'"),
        ("nul\x00bell\x07", "'nul\\x0\\bell\\x7\\'"),
        ("é😀", "'é😀'"),
        (PlString('say "hi"\n'), '"say \\"hi\\"\\n"'),
        (PlString("it's"), '"it\'s"'),
        (-3, "-3"),
        (2**80, "1208925819614629174706176"),
        (0.5, "0.5"),
        (1e-300, "1.0e-300"),
        (1e22, "1.0e+22"),
        (-0.0, "-0.0"),
        (np.float64(0.25), "0.25"),
        (np.int64(7), "7"),
        (Var(), "_"),
        (Var("_"), "_"),
        (Compound("f", ()), "f()"),
        (Compound("f", ("a", [1, X], PlString("s"))), 'f(a,[1,X],"s")'),
        (Compound(":-", ("h", Compound(",", ("a", "b")))), "':-'(h,','(a,b))"),
        (Compound("f", (1, Compound("f", (2, Compound("f", (3, 4)))))), "f(1,f(2,f(3,4)))"),
        (Compound("f", (1, Compound("f", (2, Compound("g", (3, 4)))))), "f(1,f(2,g(3,4)))"),
        (Compound("f", (Compound("f", (1, 2)), 3)), "f(f(1,2),3)"),
    ],
)
def test_encode_writes_canonical_prolog_text(value, text) -> None:
    assert encode(value) == text


def test_pretty_text_writes_clause_operators_with_needed_parentheses() -> None:
    body = Compound(",", (Compound(";", ("a", "b")), Compound(",", ("c", ":-"))))
    term = Compound(":-", (Compound("p", (X,)), body))
    assert encode(term, operators=True) == "p(X) :- (a ; b), c, (:-)".replace("(:-)", "(':-')")
    nested = Compound("f", (Compound(",", ("a", "b")),))
    assert str(nested) == "f((a, b))"
    assert str(Compound(",", (Compound(",", ("a", "b")), "c"))) == "(a, b), c"
    chain = Compound(":-", (Compound(":-", ("a", "b")), "c"))
    assert str(chain) == "(a :- b) :- c"
    assert str(Compound(":-", ("a", Compound(":-", ("b", "c"))))) == "a :- (b :- c)"


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, np.float64("nan")])
def test_encode_refuses_nan_and_infinity(bad) -> None:
    with pytest.raises(ValueError, match="NaN and infinities are refused"):
        encode(Compound("f", ("a", [bad])))


@pytest.mark.parametrize(
    ("bad", "message"),
    [
        (True, "bool True is not a Prolog term"),
        (("a", "b"), "tuple"),
        (None, "NoneType"),
        ({"a": 1}, "dict"),
    ],
)
def test_encode_refuses_values_outside_the_model_and_says_where(bad, message) -> None:
    with pytest.raises(TypeError, match=message) as info:
        encode(Compound("f", ("a", bad)))
    assert "argument 2 of f/2" in str(info.value)


def test_encode_refuses_lone_surrogates() -> None:
    with pytest.raises(ValueError, match="surrogate"):
        encode("a\ud800")


@pytest.mark.parametrize("name", ["x", "1X", "X-Y", "Ä", "", 3])
def test_var_refuses_names_that_are_not_prolog_variables(name) -> None:
    with pytest.raises(ValueError, match="not a Prolog variable name"):
        Var(name)


def test_compound_copies_a_list_of_arguments_to_a_tuple_and_checks_types() -> None:
    assert Compound("f", ["a", 1]).args == ("a", 1)
    with pytest.raises(TypeError, match="Compound.name"):
        Compound(3, ())
    with pytest.raises(TypeError, match="Compound.args"):
        Compound("f", "ab")


def test_clause_helpers_round_trip_bodies() -> None:
    head = Compound("p", (X,))
    body = [Compound("q", (X,)), Compound("r", (X, Y)), "s"]
    c = clause(head, body)
    assert c == Compound(":-", (head, Compound(",", (body[0], Compound(",", (body[1], "s"))))))
    assert clause_parts(c) == (head, body)
    assert clause(head, []) == head
    assert clause_parts(head) == (head, [])
    assert conj([]) == "true"
    assert conj_to_list("true") == []
    left_nested = Compound(",", (Compound(",", ("a", "b")), "c"))
    assert conj_to_list(left_nested) == ["a", "b", "c"]
    assert variables(c) == [X, Y]
    assert not is_ground(c)
    assert is_ground(Compound("p", ("a", [1, PlString("s")])))


def test_decode_reads_every_kind_of_reply_value() -> None:
    text = (
        '{"f":"ok","a":[["a",1,-2.5,NaN,Infinity,{"s":"x"},{"v":"_G0"},'
        '{"f":"g","a":[]},{"b":"<stream>(0x1)"},{"r":",","a":["x","y","z"]}]]}'
    )
    reply = decode(text)
    assert reply.name == "ok"
    items = reply.args[0]
    assert items[:3] == ["a", 1, -2.5]
    assert math.isnan(items[3]) and items[4] == math.inf
    assert items[5:] == [PlString("x"), Var("_G0"), Compound("g", ()), "<stream>(0x1)",
                         Compound(",", ("x", Compound(",", ("y", "z"))))]


@pytest.mark.parametrize("bad", ['{"f":"ok"', '{"zz": 1}', '{"v": "lower"}'])
def test_decode_rejects_malformed_replies(bad) -> None:
    with pytest.raises(BridgeProtocolError):
        decode(bad)


def test_a_list_of_engine_terms_reads_as_prolog_text_with_lettered_variables() -> None:
    """What a person is shown of the engine's reply (a reason, a headline): Prolog text,
    pairs infix and the engine's fresh variables lettered, never the dataclasses."""
    G0, G1 = Var("_G0"), Var("_G1")
    exhausted = [Compound("-", (Compound("handle_length", (G0, "medium")), "tried")),
                 Compound("-", (Compound("stick", (G1,)), Compound("infeasible", (
                     [Compound("handle_length", (G1, "medium")),
                      Compound("tube_length_m", ("tube1", 0.45))],))))]
    assert readable(exhausted) == (
        "[handle_length(A,medium)-tried,"
        "stick(B)-infeasible([handle_length(B,medium),tube_length_m(tube1,0.45)])]")
    assert readable(Compound("-", ("a", -1))) == "a- -1"
    assert readable(Compound("-", ("a", Compound("-", ("b", "c"))))) == "a-(b-c)"
    assert readable(Compound("-", (Compound("-", ("a", "b")), "c"))) == "a-b-c"
    assert readable(Compound(":-", (Compound("p", (Var("X"),)), Compound(
        ",", (Compound("q", (Var("X"), G0)), "r"))))) == "p(A) :- q(A,B), r"
    letters = [Compound("f", (Var(f"_G{i}"),)) for i in range(28)]
    assert readable(letters).endswith("f(Y),f(Z),f(A1),f(B1)]")
    assert str(exhausted[0]) == "'-'(handle_length(_G0,medium),tried)"  # str() unchanged
