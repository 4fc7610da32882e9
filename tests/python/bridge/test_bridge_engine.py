"""The engine: round trips through SWI-Prolog, errors, consult, threads."""

from __future__ import annotations

import math
import threading
from pathlib import Path

import pytest

from creative_py.bridge import (
    FAILED,
    Compound,
    Engine,
    EngineStateError,
    PlString,
    PrologError,
    PrologFileNotFoundError,
    PrologLoadError,
    PrologSyntaxError,
    Var,
    WrongThreadError,
    clause,
    clause_parts,
    encode,
    decode,
)

X, Y, Z = Var("X"), Var("Y"), Var("Z")

NASTY_ATOMS = [
    "", "[]", "{}", "|", "!", ";", ",", ":-", "-->", "\\+", "'", "''", "\\", "\\\\",
    "a'b", 'a"b', "a\\nb", "line\nbreak", "tab\there", "\x00", "\x7f\x80\x9f", "é",
    "Ångström", "日本語", "😀 emoji", "Var", "_under", "a b", "1abc", "end_of_file",
    "$VAR", "[|]", "true", "false", "null", "-", "+", "- 1",
]


@pytest.mark.parametrize("atom", NASTY_ATOMS)
def test_nasty_atoms_round_trip(engine: Engine, atom: str) -> None:
    assert engine.call("echo", atom) == atom
    assert engine.call("echo", Compound(atom, (atom,))) == Compound(atom, (atom,))


@pytest.mark.parametrize(
    "text", ["", "plain", 'quote " and \\ backslash', "multi\nline\r\n", "\x00nul", "日本 😀"]
)
def test_strings_round_trip_as_strings_not_atoms(engine: Engine, text: str) -> None:
    assert engine.call("echo", PlString(text)) == PlString(text)
    assert engine.variant(PlString(text), text) is False


@pytest.mark.parametrize(
    "number",
    [0, -1, 7, -(2**200), 2**64 + 1, 0.1, -2.5, 1e-300, 5e-324, 1.7976931348623157e308,
     1e22, 123456789.123456789],
)
def test_numbers_round_trip_exactly(engine: Engine, number) -> None:
    back = engine.call("echo", number)
    assert type(back) is type(number)
    assert back == number


def test_negative_zero_and_int_float_distinction_survive(engine: Engine) -> None:
    back = engine.call("echo", [-0.0, 1, 1.0])
    assert math.copysign(1.0, back[0]) == -1.0
    assert [type(v) for v in back[1:]] == [int, float]
    assert engine.variant(1, 1.0) is False


def test_nested_compounds_lists_and_zero_arity_compounds_round_trip(engine: Engine) -> None:
    term = Compound("f", (
        [], [[], [1, [2, [3]]]], Compound("g", ()), Compound("{}", ("a",)),
        Compound("h", (Compound("i", (Compound("j", ("k",)),)),)), "[]",
    ))
    assert engine.call("echo", term) == term


def test_shared_variables_of_a_clause_keep_their_names(engine: Engine) -> None:
    c = clause(Compound("p", (X, Y)), [Compound("q", (X, Z)), Compound("r", (Z, Y, X))])
    assert engine.call("echo", c) == c
    assert engine.variant(c, engine.call("echo", c))


def test_anonymous_and_new_variables_get_fresh_names_avoiding_request_names(
        engine: Engine) -> None:
    back = engine.call("echo", Compound("f", (Var(), Var(), Var("_G0"))))
    assert back.args[2] == Var("_G0")
    assert len({back.args[0], back.args[1], back.args[2]}) == 3
    assert all(isinstance(a, Var) for a in back.args)


def test_partial_lists_come_back_as_list_cells(engine: Engine) -> None:
    back = engine.parse("[a, b|T]")
    assert back == Compound("[|]", ("a", Compound("[|]", ("b", Var("T")))))
    assert engine.call("echo", back) == back


def test_pretty_text_of_a_clause_reads_back_as_the_same_clause(engine: Engine) -> None:
    body = [Compound(";", (Compound("q", (X,)), Compound("->", ("a", "b")))), ":-", "-",
            Compound(",", ("c", "d"))]
    c = clause(Compound("p", (X, -1, ":-")), body)
    assert engine.parse(str(c)) == c


def test_failure_is_the_failed_sentinel(engine: Engine) -> None:
    result = engine.call("theta_subsumes", Compound("p", ("a",)), Compound("p", ("b",)))
    assert result is FAILED
    assert not result
    assert engine.call("theta_subsumes", Compound("p", (X,)), Compound("p", ("b",))) == "true"


def test_prolog_exception_becomes_prolog_error_with_predicate_and_term(engine: Engine) -> None:
    with pytest.raises(PrologError) as info:
        engine.call("clause_lgg", Compound("p", ("a",)), Compound("q", ("a", "b")))
    assert info.value.predicate == "clause_lgg"
    assert isinstance(info.value.error_term, Compound)
    assert info.value.error_term.name == "error"
    assert info.value.formal.name == "domain_error"
    assert "clause_lgg" in str(info.value)


def test_unknown_operation_is_an_existence_error(engine: Engine) -> None:
    with pytest.raises(PrologError) as info:
        engine.call("no_such_operation", 1)
    assert info.value.formal == Compound(
        "existence_error", ("api_operation", Compound("/", ("no_such_operation", 1))))


def test_request_that_does_not_parse_is_an_error_reply(engine: Engine) -> None:
    reply = decode(engine.request_text("ping("))
    assert reply.name == "error"
    assert reply.args[0].args[0].name == "syntax_error"
    assert engine.ping() == "pong"


def test_ping_version_and_operation_table(engine: Engine) -> None:
    assert engine.ping() == "pong"
    version = engine.version()
    assert version["api"] == 1 and version["swipl"][0] >= 9
    ops = engine.operations()
    for op in ["ping/0", "version/0", "variant/2", "consult/1", "clause_lgg/2",
               "term_lgg/2", "theta_subsumes/2", "clause_reduce/1"]:
        assert op in ops


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_consult_detects_a_syntax_error_with_file_and_line(engine: Engine,
                                                            tmp_path: Path) -> None:
    bad = _write(tmp_path / "bad_syntax.pl",
                 "bridge_ok_fact(1).\n\nbridge_bad(X :- .\nbridge_ok_fact(2).\n")
    with pytest.raises(PrologSyntaxError) as info:
        engine.consult(bad)
    assert info.value.file == str(bad)
    assert info.value.line == 3
    assert "bad_syntax.pl:3" in str(info.value)
    assert engine.ping() == "pong"


def test_consult_reports_directive_errors_and_returns_warnings(engine: Engine,
                                                              tmp_path: Path) -> None:
    broken = _write(tmp_path / "directive.pl", "fact_a(1).\n:- atom_length(1, a).\n")
    with pytest.raises(PrologLoadError) as info:
        engine.consult(broken)
    assert not isinstance(info.value, PrologSyntaxError)
    assert info.value.messages[0].line == 2
    assert "Type error" in info.value.messages[0].text
    warn = _write(tmp_path / "warn.pl", "bridge_warn_p(X) :- true.\n")
    report = engine.consult(warn)
    assert [(w.kind, w.line) for w in report.warnings] == [("warning", 1)]
    assert "Singleton" in report.warnings[0].text


def test_consult_loads_clauses_into_user(engine: Engine, tmp_path: Path) -> None:
    good = _write(tmp_path / "model.pl", "bridge_model_fact(a, 1).\n")
    report = engine.consult(good)
    assert report.path == str(good) and report.warnings == ()
    assert str(good) in engine.loaded


def test_missing_file_is_a_typed_error_and_the_engine_survives(engine: Engine,
                                                              tmp_path: Path) -> None:
    missing = tmp_path / "nowhere" / "missing.pl"
    with pytest.raises(PrologFileNotFoundError) as info:
        engine.consult(missing)
    assert isinstance(info.value, FileNotFoundError)
    assert str(missing) in str(info.value)
    with pytest.raises(PrologFileNotFoundError, match="directory"):
        engine.consult(tmp_path)
    # Past the Python check, straight to Prolog: still an error reply, not a dead
    # process, and the debugger is not left on (assertz in a later load works).
    with pytest.raises(PrologError) as raw:
        engine.call("consult", str(missing))
    assert raw.value.formal.name == "existence_error"
    later = _write(tmp_path / "later.pl", ":- assertz(bridge_after_missing(ok)).\n")
    engine.consult(later)
    assert engine.ping() == "pong"


def test_calls_from_another_thread_are_refused(engine: Engine) -> None:
    caught: list[BaseException] = []

    def worker() -> None:
        try:
            engine.ping()
        except BaseException as exc:  # noqa: BLE001 - handed to the main thread
            caught.append(exc)

    thread = threading.Thread(target=worker)
    thread.start()
    thread.join(timeout=30)
    assert len(caught) == 1 and isinstance(caught[0], WrongThreadError)
    assert engine.ping() == "pong"


def test_a_second_engine_is_refused_and_instance_returns_the_one(engine: Engine) -> None:
    with pytest.raises(EngineStateError, match="Engine.instance"):
        Engine()
    assert Engine.instance() is engine


def test_nan_is_refused_before_prolog_is_asked(engine: Engine) -> None:
    with pytest.raises(ValueError, match="NaN"):
        engine.call("echo", Compound("pose", (math.nan,)))
    assert engine.ping() == "pong"


def _example(tool: str, body: list) -> Compound:
    return clause(Compound("tool_pose", (tool, "cube1", "tube1")), body)


def test_version_space_state_travels_through_python_intact(engine: Engine) -> None:
    pos = _example("hook_a2", [Compound("hook", ("hook_a2",)),
                               Compound("behind", ("hook_a2", "cube1")),
                               Compound("handle_length", ("hook_a2", "medium"))])
    vs = engine.vs_init(pos)
    assert engine.variant(engine.call("echo", vs), vs)
    hs, hg = engine.vs_bounds(vs)
    head = hs.args[0]
    assert all(isinstance(v, Var) for v in head.args)
    assert hg == head  # h_g starts as the bare head, sharing h_s's head variables
    neg = _example("hook_b1", [Compound("hook", ("hook_b1",)),
                               Compound("handle_length", ("hook_b1", "medium"))])
    vs2 = engine.vs_update(vs, Compound("neg", (neg,)))
    assert not engine.vs_covers(vs2, "hg", neg)
    assert engine.vs_covers(vs2, "hg", pos)
    positives, negatives = engine.vs_examples(vs2)
    assert positives == [pos] and negatives == [neg]
    assert isinstance(engine.vs_unknown(vs2), list)
    assert engine.vs_converged(vs2) in (True, False)


def test_learning_operations_answer_through_the_bridge(engine: Engine) -> None:
    bk = [Compound("parent", p) for p in [("ann", "mary"), ("ann", "tom"), ("tom", "eve"),
                                           ("tom", "ian")]]
    bk += [Compound("female", (f,)) for f in ("ann", "mary", "eve")]
    c = engine.rlgg(Compound("daughter", ("mary", "ann")), Compound("daughter", ("eve", "tom")),
                    bk)
    assert engine.theta_subsumes(c, clause(Compound("daughter", ("mary", "ann")), bk))
    reduced = engine.nbr_reduce(
        clause(Compound("p", (X,)), [Compound(n, (X,)) for n in ("a", "b", "c")]),
        [clause(Compound("p", ("n1",)), [Compound("a", ("n1",)), Compound("c", ("n1",))])])
    assert not engine.clause_covers(
        reduced, clause(Compound("p", ("n1",)), [Compound("a", ("n1",)), Compound("c", ("n1",))]))
    assert engine.clause_violations(Compound("p", (X,)), Compound("q", ("a",))) is None


def test_a_clause_with_thousands_of_literals_crosses_without_recursion_errors(
        engine: Engine) -> None:
    body = [Compound("q", (i, X)) for i in range(5000)]
    c = clause(Compound("p", (X,)), body)
    back = engine.call("echo", c)
    head, literals = clause_parts(back)
    assert head == Compound("p", (X,)) and literals == body
    assert clause_parts(engine.parse(encode(c, operators=True))) == (Compound("p", (X,)), body)
    assert engine.theta_subsumes(Compound("p", (Y,)), c)


def test_each_argument_is_its_own_variable_scope() -> None:
    from creative_py.bridge.terms import encode_request

    term = Compound("g", (X,))
    assert encode_request("f", [X, term]) == "f(X_A0,g(X_A1))"
    assert encode_request("f", [X, term], separate_variables=False) == "f(X,g(X))"
    assert encode_request("f", [term]) == "g(X)".join(["f(", ")"])
    assert encode_request("ping", []) == "ping"


def test_request_variables_come_back_with_their_own_names(engine: Engine) -> None:
    c = clause(Compound("p", (Var("T"),)), [Compound("q", (Var("T"), Var("U")))])
    example = clause(Compound("p", ("a",)), [Compound("r", ("a",))])
    assert engine.clause_violations(c, example) == [Compound("q", (Var("T"), Var("U")))]


def test_two_different_variables_of_one_name_stay_apart_in_a_result() -> None:
    from creative_py.bridge.engine import _restore_variable_names

    reply = Compound("ok", ([Var("X_A0"), Var("X_A1"), Var("Y_A1"), Var("_G0")],))
    restored = _restore_variable_names(reply, [Var("X"), Compound("f", (Var("X"), Var("Y")))])
    assert restored.args[0] == [Var("X_A0"), Var("X_A1"), Var("Y"), Var("_G0")]
