"""The C calls into the embedded SWI-Prolog (through the library pyswip loads).

This is the only file that imports pyswip, and it does so inside :func:`start`, never
at import time: importing pyswip initialises SWI-Prolog (``PL_initialise`` with
``-q --nosignals``), and that can happen once per process.

Only pyswip's loader and constants are used, not its query machinery: pyswip builds a
new query text per call and caches every text it ever sent (its memory grows with many
distinct queries), and decodes answers with lossy conversions. Here one predicate
handle (``api:api_request/2``) is called with the request as a UTF-8 string argument
and the reply is read back as a UTF-8 string, inside a foreign frame that is
discarded after each call and a string-buffer mark that is released after it (text
converted by ``PL_get_nchars`` outside a foreign predicate otherwise stays allocated
for the life of the process: about 0.5 KiB per call, measured), so a call leaves
nothing behind in either language.
"""

from __future__ import annotations

import ctypes
from ctypes import POINTER, byref, c_char_p, c_int, c_size_t, c_uint, c_void_p
from dataclasses import dataclass
from typing import Any, Callable, Optional


@dataclass(frozen=True)
class Native:
    """Bound C functions and flag values of libswipl (SWI-Prolog 9 foreign interface)."""

    open_frame: Callable[[], int]
    discard_frame: Callable[[int], None]
    new_term_refs: Callable[[int], int]
    put_chars: Callable[[int, int, int, bytes], int]
    get_nchars: Callable[[int, Any, Any, int], int]
    predicate: Callable[[bytes, int, Optional[bytes]], Optional[int]]
    call_predicate: Callable[[Optional[int], int, int, int], int]
    exception: Callable[[int], int]
    clear_exception: Callable[[], None]
    mark_strings: Callable[[Any], None]
    release_strings: Callable[[int], None]
    string_utf8: int
    atom_utf8: int
    get_string_utf8: int
    get_writeq_utf8: int
    query_flags: int


def start() -> Native:
    """Initialise SWI-Prolog in this process (through pyswip) and bind the C calls.

    Raises
    ------
    creative_py.bridge.errors.EngineStateError
        pyswip or libswipl cannot be loaded; the message says why.
    """
    from creative_py.bridge.errors import EngineStateError

    try:
        import pyswip.core as core  # noqa: PLC0415  (initialises SWI-Prolog)
    except Exception as exc:  # pyswip raises bare Exceptions when libswipl is missing
        raise EngineStateError(f"cannot start SWI-Prolog through pyswip: {exc}") from exc

    lib = core._lib  # the CDLL pyswip opened (RTLD_GLOBAL)

    def bind(name: str, restype: Any, *argtypes: Any) -> Callable[..., Any]:
        return ctypes.CFUNCTYPE(restype, *argtypes)((name, lib))

    term_t = c_size_t  # uintptr_t
    return Native(
        open_frame=bind("PL_open_foreign_frame", c_size_t),
        discard_frame=bind("PL_discard_foreign_frame", None, c_size_t),
        new_term_refs=bind("PL_new_term_refs", term_t, c_size_t),
        put_chars=bind("PL_put_chars", c_int, term_t, c_int, c_size_t, c_char_p),
        get_nchars=bind("PL_get_nchars", c_int, term_t, POINTER(c_size_t),
                        POINTER(c_void_p), c_uint),
        predicate=bind("PL_predicate", c_void_p, c_char_p, c_int, c_char_p),
        call_predicate=bind("PL_call_predicate", c_int, c_void_p, c_int, c_void_p, term_t),
        exception=bind("PL_exception", term_t, c_size_t),
        clear_exception=bind("PL_clear_exception", None),
        mark_strings=bind("PL_mark_string_buffers", None, POINTER(c_size_t)),
        release_strings=bind("PL_release_string_buffers_from_mark", None, c_size_t),
        string_utf8=core.PL_STRING | core.REP_UTF8,
        atom_utf8=core.PL_ATOM | core.REP_UTF8,
        get_string_utf8=core.CVT_STRING | core.REP_UTF8 | core.BUF_DISCARDABLE,
        get_writeq_utf8=core.CVT_WRITEQ | core.REP_UTF8 | core.BUF_DISCARDABLE,
        query_flags=core.PL_Q_NODEBUG | core.PL_Q_CATCH_EXCEPTION,
    )


def read_text(native: Native, term: int, flags: int) -> Optional[str]:
    """Return the text of ``term`` converted with ``flags`` (UTF-8), or None if it cannot."""
    length = c_size_t(0)
    pointer = c_void_p(None)
    if not native.get_nchars(term, byref(length), byref(pointer), flags):
        return None
    if length.value == 0:
        return ""
    return ctypes.string_at(pointer.value, length.value).decode("utf-8")
