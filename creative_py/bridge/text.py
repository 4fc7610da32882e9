"""Prolog text from outside the engine, checked before SWI-Prolog reads it.

A prior's ``model.pl`` and a command line's ``--context`` are text that a person or
another program wrote. SWI-Prolog's reader recurses on the C stack for each bracket it
opens, and embedded as pyswip starts it (``--nosignals``) an overflow of that stack is
a SIGSEGV that kills the process without a word: a term nested 100,000 brackets deep
did. So such text is read through :func:`read_text_file` (a size limit, strict UTF-8)
and :func:`check_nesting` (at most :data:`BRACKETS_MAX` brackets deep) before
Prolog sees it; Prolog then checks the depth of every term it read, which operators can nest
without brackets (``prolog/text_terms.pl``, whose ``term_depth_max/1`` is this
module's :data:`DEPTH_MAX`).
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from creative_py.bridge.errors import BridgeError

DEPTH_MAX = 200
"""The deepest nesting of a term read from outside (``prolog/text_terms.pl``'s
``term_depth_max/1``): far above any model file or context (a learned clause nests 3
deep; a list's tail and a clause body's chain do not count), and below what the
bridge's JSON codec takes back (Python's recursion limit, 1,000)."""

BRACKETS_MAX = 1000
"""The deepest nesting of brackets in text read from outside: what SWI-Prolog's reader
takes on the C stack with room to spare (20,000 killed it; 5,000 did not)."""

MODEL_FILE_BYTES_MAX = 16 * 1024 * 1024
"""The largest model file read (a run's ``model.pl`` is a few kilobytes)."""

_TOKEN = re.compile(r"""
      (?<![\w])0'(?:\\.|''|.)                  # a character code 0'c
    | '(?:[^'\\]|\\.|'')*'                     # quoted atom
    | "(?:[^"\\]|\\.|"")*"                     # string
    | `(?:[^`\\]|\\.|``)*`                     # back-quoted text
    | %[^\n]*                                  # line comment
    | /\*.*?\*/                                # block comment
    | [(\[{]                                   # opening bracket
    | [)\]}]                                   # closing bracket
""", re.VERBOSE | re.DOTALL)


class PrologTextError(BridgeError, ValueError):
    """Text from outside that Prolog is not given to read: too large, not UTF-8, or
    nested too deep. The message is ``where: why`` (where the text came from, the
    cause); ``why`` alone is an attribute."""

    def __init__(self, where: str, why: str) -> None:
        super().__init__(f"{where}: {why}")
        self.where, self.why = where, why


def nesting(text: str) -> int:
    """Return how deep the brackets ``( [ {`` of Prolog text nest, outside quoted
    text and comments (an unterminated quote or comment counts what follows it)."""
    depth = deepest = 0
    for match in _TOKEN.finditer(text):
        token = match.group()
        if token in ("(", "[", "{"):
            depth += 1
            deepest = max(deepest, depth)
        elif token in (")", "]", "}"):
            depth = max(depth - 1, 0)
    return deepest


def check_nesting(text: str, where: str) -> str:
    """Return ``text`` if its brackets nest at most :data:`BRACKETS_MAX` deep; raise
    :class:`PrologTextError` naming ``where`` otherwise."""
    if nesting(text) > BRACKETS_MAX:
        raise PrologTextError(where, f"brackets nested deeper than {BRACKETS_MAX} levels")
    return text


def read_text_file(path: Path | str, max_bytes: int = MODEL_FILE_BYTES_MAX) -> str:
    """Return the text of a Prolog file from outside, checked: at most ``max_bytes``,
    UTF-8, brackets at most :data:`BRACKETS_MAX` deep.

    Raises
    ------
    PrologTextError
        The file is larger, not UTF-8 (the message gives the line and the byte), or
        nested deeper; the message names the file.
    OSError
        It cannot be read.
    """
    path = Path(path)
    size = os.stat(path).st_size
    if size > max_bytes:
        raise PrologTextError(str(path), f"{size} bytes, more than the {max_bytes} a model "
                              "file may have")
    data = path.read_bytes()[:max_bytes + 1]
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise PrologTextError(str(path), f"not UTF-8 text (byte 0x{data[exc.start]:02x} "
                              f"at line {line}, byte {exc.start + 1})") from None
    return check_nesting(text, str(path))
