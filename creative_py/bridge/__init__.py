"""The bridge: the only way from Python to SWI-Prolog (the only importer of pyswip).

Importing this package starts nothing; :class:`Engine` (``Engine.instance()``) starts
the one embedded SWI-Prolog of the process and loads the facade ``prolog/api.pl``.
Terms are plain Python values (:mod:`creative_py.bridge.terms`, which holds the one
encoder of Prolog text too); one decoder (:mod:`creative_py.bridge.codec`) reads the
replies.
"""

from creative_py.bridge.codec import decode
from creative_py.bridge.engine import FAILED, Engine, LoadReport
from creative_py.bridge.errors import (
    BridgeError,
    BridgeProtocolError,
    EngineStateError,
    LoadMessage,
    PrologError,
    PrologFailed,
    PrologFileNotFoundError,
    PrologLoadError,
    PrologSyntaxError,
    WrongThreadError,
)
from creative_py.bridge.terms import (
    Compound,
    PlString,
    Term,
    Var,
    clause,
    clause_parts,
    conj,
    conj_to_list,
    encode,
    fact_term,
    is_ground,
    lettered,
    readable,
    variables,
)

__all__ = [
    "FAILED", "BridgeError", "fact_term", "BridgeProtocolError", "Compound", "Engine",
    "EngineStateError", "LoadMessage", "LoadReport", "PlString", "PrologError",
    "readable", "PrologFailed", "PrologFileNotFoundError", "PrologLoadError", "PrologSyntaxError",
    "Term", "Var", "WrongThreadError", "clause", "clause_parts", "conj", "conj_to_list",
    "decode", "encode", "is_ground", "lettered", "variables",
]
