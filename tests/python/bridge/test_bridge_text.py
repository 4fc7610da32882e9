"""The guarded reader of Prolog text from outside (creative_py/bridge/text.py)."""

from __future__ import annotations

import pytest

from creative_py.bridge import Compound, PrologError
from creative_py.bridge.errors import reader_words
from creative_py.bridge.text import (BRACKETS_MAX, DEPTH_MAX, PrologTextError, check_nesting,
                                     nesting, read_text_file)


@pytest.mark.parametrize("text, depth", [
    ("a", 0), ("f(a)", 1), ("f(g([a, {b}]))", 4), ("[a, b, c]", 1),
    ("'((((('", 0), ('"[[["', 0), ("`{{`", 0), ("0'(", 0), ("f(0')')", 1),
    ("% ((((\na", 0), ("/* ((( */ f(a)", 1), ("'it''s ('", 0), ("'a\\'('", 0),
    ("f(a))))(b)", 1),             # extra closers do not hide later openers
    ("'unterminated (((", 3),      # what follows an unterminated quote counts
])
def test_nesting_counts_brackets_outside_quotes_and_comments(text, depth):
    assert nesting(text) == depth


def test_check_nesting_refuses_text_deeper_than_the_limit():
    ok = "(" * BRACKETS_MAX + "a" + ")" * BRACKETS_MAX
    assert check_nesting(ok, "x") == ok
    with pytest.raises(PrologTextError) as info:
        check_nesting("(" + ok + ")", "where")
    assert str(info.value) == f"where: brackets nested deeper than {BRACKETS_MAX} levels"


def test_read_text_file_checks_size_and_encoding(tmp_path):
    path = tmp_path / "model.pl"
    path.write_bytes(b"a.\nb(\xc3).\n")
    with pytest.raises(PrologTextError) as info:
        read_text_file(path)
    assert str(info.value) == f"{path}: not UTF-8 text (byte 0xc3 at line 2, byte 6)"
    path.write_text("a(1).\n" * 10)
    with pytest.raises(PrologTextError) as info:
        read_text_file(path, max_bytes=50)
    assert str(info.value) == f"{path}: 60 bytes, more than the 50 a model file may have"
    assert read_text_file(path) == "a(1).\n" * 10


def test_the_term_depth_limit_is_prologs(engine):
    assert engine.parse("f(" * DEPTH_MAX + "a" + ")" * DEPTH_MAX) is not None
    with pytest.raises(PrologError) as info:
        engine.parse("f(" * (DEPTH_MAX + 1) + "a" + ")" * (DEPTH_MAX + 1))
    assert info.value.formal == Compound("representation_error",
                                         (Compound("term_depth", (DEPTH_MAX,)),))
    assert reader_words(info.value) == f"a term nested deeper than {DEPTH_MAX} levels"


def test_parse_reads_one_term_and_nothing_after_it(engine):
    with pytest.raises(PrologError) as info:
        engine.parse("a(1). b(2)")                # term_string/3 read a(1) alone
    assert reader_words(info.value) == "syntax error: one term expected"
