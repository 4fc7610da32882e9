"""Typed exceptions of the bridge.

Every exception the bridge raises is a :class:`BridgeError`. A Prolog exception caught
by the facade becomes a :class:`PrologError` that carries the operation (the facade
predicate's request name) and the decoded error term; loading problems have their own
types with the file and line.

A *failure* (the operation's goal has no solution) is not an exception:
:meth:`creative_py.bridge.engine.Engine.call` returns the sentinel
:data:`creative_py.bridge.engine.FAILED`; the typed convenience methods turn it into
``False`` or ``None`` where "no" is a normal answer, or raise :class:`PrologFailed`
where the operation must not fail.
"""

from __future__ import annotations

import errno
from typing import Any, Optional, Sequence

from creative_py.bridge.terms import Compound, encode


class BridgeError(Exception):
    """Base class of every error raised by the bridge."""


class BridgeProtocolError(BridgeError):
    """A reply from Prolog did not follow the reply schema (a bug in the bridge)."""


class EngineStateError(BridgeError):
    """The engine was used in a way the one embedded SWI-Prolog cannot support.

    Examples: constructing a second :class:`Engine` in one process, using it from a
    forked child process.
    """


class WrongThreadError(EngineStateError):
    """The engine was called from a thread other than the one that created it."""


class PrologError(BridgeError):
    """Prolog raised an exception while running a facade operation.

    Attributes
    ----------
    predicate
        The operation name, e.g. ``"clause_lgg"`` (``"api_request"`` for a request
        that could not be parsed).
    error_term
        The decoded Prolog error term, e.g.
        ``Compound("error", (Compound("type_error", ("list", "foo")), Var("_G0")))``.
    """

    def __init__(self, predicate: str, error_term: Any) -> None:
        self.predicate = predicate
        self.error_term = error_term
        super().__init__(f"{predicate}: {_show(error_term)}")

    @property
    def formal(self) -> Any:
        """Return the formal part of an ISO ``error(Formal, Context)`` term, else the term."""
        term = self.error_term
        if isinstance(term, Compound) and term.name == "error" and len(term.args) == 2:
            return term.args[0]
        return term


class PrologFailed(BridgeError):
    """An operation that must produce an answer failed instead (``predicate`` names it)."""

    def __init__(self, predicate: str, detail: str = "") -> None:
        self.predicate = predicate
        super().__init__(f"{predicate} failed" + (f": {detail}" if detail else ""))


class PrologFileNotFoundError(BridgeError, FileNotFoundError):
    """A file to consult does not exist (checked before Prolog is asked)."""

    def __init__(self, path: str, reason: str = "no such file") -> None:
        super().__init__(errno.ENOENT, f"cannot consult {path}: {reason}", path)
        self.path = path
        self.reason = reason

    def __str__(self) -> str:
        return f"cannot consult {self.path}: {self.reason}"


class LoadMessage:
    """One error or warning printed while loading a file: kind, file, line and text."""

    __slots__ = ("kind", "file", "line", "text", "term")

    def __init__(self, kind: str, file: Optional[str], line: Optional[int], text: str,
                 term: Any = None) -> None:
        self.kind = kind
        self.file = file
        self.line = line
        self.text = text
        self.term = term

    def __repr__(self) -> str:
        return f"LoadMessage({self.kind!r}, {self.file!r}, {self.line!r}, {self.text!r})"

    def __str__(self) -> str:
        where = f"{self.file}:{self.line}" if self.line is not None else f"{self.file}"
        return f"{where}: {self.kind}: {self.text}"


class PrologLoadError(BridgeError):
    """Loading a file printed errors (other than syntax errors, see the subclass).

    Attributes
    ----------
    path
        The file that was consulted.
    messages
        Every error :class:`LoadMessage` (file, line, text), in the order printed.
    warnings
        The warning messages of the same load.
    """

    def __init__(self, path: str, messages: Sequence[LoadMessage],
                 warnings: Sequence[LoadMessage] = ()) -> None:
        self.path = path
        self.messages = list(messages)
        self.warnings = list(warnings)
        first = self.messages[0] if self.messages else None
        self.file = first.file if first else path
        self.line = first.line if first else None
        detail = "; ".join(str(m) for m in self.messages[:5])
        more = f" (and {len(self.messages) - 5} more)" if len(self.messages) > 5 else ""
        super().__init__(f"errors while consulting {path}: {detail}{more}")


class PrologSyntaxError(PrologLoadError):
    """A consulted file has a syntax error; ``file`` and ``line`` locate the first one."""


def reader_words(error: "PrologError") -> Optional[str]:
    """Return in words what the reader said of text it could not take: a syntax error
    (``syntax error: operator expected at line 3``; the line when the text was read
    from a stream, the character when from a string) or a term nested too deep
    (``prolog/text_terms.pl``); None for any other error."""
    formal = error.formal
    if not isinstance(formal, Compound) or len(formal.args) != 1:
        return None
    (what,) = formal.args
    if formal.name == "syntax_error":
        words = " ".join(str(what).replace("_", " ").split())
        context = error.error_term.args[1] if (
            isinstance(error.error_term, Compound) and len(error.error_term.args) == 2) \
            else None
        where = ""
        if (isinstance(context, Compound) and context.name == "stream"
                and len(context.args) == 4 and context.args[1] != 0):  # 0: at the end
            where = f" at line {context.args[1]}, column {context.args[2]}"
        elif isinstance(context, Compound) and context.name == "string" and len(context.args) == 2:
            where = f" at character {context.args[1]}"
        return f"syntax error: {words}{where}"
    if (formal.name == "representation_error" and isinstance(what, Compound)
            and what.name == "term_depth" and len(what.args) == 1):
        return f"a term nested deeper than {what.args[0]} levels"
    return None


def _show(term: Any) -> str:
    try:
        return encode(term, operators=True)
    except (TypeError, ValueError):
        return repr(term)
