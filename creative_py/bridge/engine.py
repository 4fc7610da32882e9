"""The Prolog engine: one embedded SWI-Prolog per process, reached through the facade.

Usage::

    from creative_py.bridge import Engine, clause
    engine = Engine.instance()                 # starts Prolog, loads prolog/creative.pl
    g = engine.clause_lgg(c1, c2)              # a Compound with Var("_G0") ...
    engine.call("theta_subsumes", g, c1)       # "true", or FAILED

pyswip embeds one SWI-Prolog per process and it cannot be restarted, so :class:`Engine`
is a singleton by construction: the first ``Engine(...)`` (or ``Engine.instance()``)
starts Prolog; a second ``Engine(...)`` raises :class:`EngineStateError`;
``Engine.instance()`` always returns the one engine. Only the thread that created the
engine may call it (others get :class:`WrongThreadError`), and a forked child may not
use its parent's engine.

Every call runs one operation of ``prolog/api.pl`` (its table ``api_op/3`` lists
them): the request ``op(arg1, ...)`` is encoded as text by
:func:`creative_py.bridge.terms.encode`, parsed by Prolog, run deterministically, and
answered by exactly one reply:

* ``ok(Result)``: :meth:`Engine.call` returns the decoded ``Result``;
* ``failed``: :meth:`Engine.call` returns the sentinel :data:`FAILED` (falsy);
* ``error(E)``: :meth:`Engine.call` raises :class:`PrologError` with the operation
  name and the decoded ``E``.
"""

from __future__ import annotations

import logging
import os
import threading
from ctypes import byref, c_size_t
from dataclasses import dataclass
from pathlib import Path
from typing import ClassVar, Optional, Sequence, Union

from creative_py.bridge import _native
from creative_py.bridge.codec import decode
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
from creative_py.bridge.terms import Compound, Term, Var, map_variables, variables
from creative_py.bridge.terms import argument_suffix, encode_request

log = logging.getLogger(__name__)

PathLike = Union[str, os.PathLike]

PROJECT_ROOT = Path(__file__).resolve().parents[2]
"""The repository root (the folder holding ``prolog/`` and ``ontology/``)."""

FACADE_FILE = PROJECT_ROOT / "prolog" / "api.pl"
"""The facade module, always loaded first."""

DEFAULT_LOAD = (PROJECT_ROOT / "prolog" / "creative.pl",)
"""Files an engine loads when ``load`` is not given: the whole learning engine."""


class _Failed:
    """The type of :data:`FAILED`."""

    _made = False

    def __new__(cls) -> "_Failed":
        if cls._made:
            raise TypeError("FAILED is a singleton; compare with `is FAILED`")
        cls._made = True
        return super().__new__(cls)

    def __bool__(self) -> bool:
        return False

    def __repr__(self) -> str:
        return "FAILED"

    def __reduce__(self) -> str:
        return "FAILED"


FAILED = _Failed()
"""What :meth:`Engine.call` returns when the operation's goal fails (Prolog's "no")."""


@dataclass(frozen=True)
class LoadReport:
    """What consulting a file printed that was not an error.

    Attributes
    ----------
    path
        The absolute path that was loaded.
    warnings
        The warnings printed while loading (e.g. singleton variables), in order.
    """

    path: str
    warnings: tuple[LoadMessage, ...] = ()


class Engine:
    """The process's embedded SWI-Prolog, with the facade ``prolog/api.pl`` loaded.

    Parameters
    ----------
    load
        Prolog files to consult after the facade, in order (paths, relative to the
        current directory or absolute). None loads :data:`DEFAULT_LOAD`, i.e.
        ``prolog/creative.pl`` (every module of ``prolog/``); ``[]`` loads only the
        facade and the modules it uses.

    Raises
    ------
    EngineStateError
        An engine already exists in this process (use :meth:`instance`), or
        SWI-Prolog cannot be started.
    PrologLoadError, PrologSyntaxError, PrologFileNotFoundError
        A file of ``load`` has errors or does not exist. The engine exists anyway
        (Prolog cannot be restarted): :meth:`instance` returns it.
    """

    _instance: ClassVar[Optional["Engine"]] = None
    _creating: ClassVar[threading.Lock] = threading.Lock()

    def __init__(self, load: Optional[Sequence[PathLike]] = None) -> None:
        with Engine._creating:
            if Engine._instance is not None:
                raise EngineStateError(
                    "a Prolog engine already exists in this process (pyswip embeds one "
                    "SWI-Prolog per process); use Engine.instance()"
                )
            self._thread = threading.get_ident()
            self._pid = os.getpid()
            self._loaded: list[str] = []
            self._native = _native.start()
            self._predicate = self._native.predicate(b"api_request", 2, b"api")
            self._bootstrap()
            Engine._instance = self
        for path in DEFAULT_LOAD if load is None else load:
            self.consult(path)

    @classmethod
    def instance(cls, load: Optional[Sequence[PathLike]] = None) -> "Engine":
        """Return the process's engine, creating it on the first call.

        ``load`` is used as by the constructor when the engine is created; on later
        calls, the files of ``load`` that this engine has not consulted yet are
        consulted (``None`` then means nothing more).
        """
        engine = cls._instance
        if engine is None:
            return cls(load)
        for path in load or ():
            if str(Path(path).resolve()) not in engine._loaded:
                engine.consult(path)
        return engine

    @property
    def loaded(self) -> tuple[str, ...]:
        """Return the absolute paths consulted through this engine, in order."""
        return tuple(self._loaded)

    # ------------------------------------------------------------------ transport

    def _check_caller(self) -> None:
        if os.getpid() != self._pid:
            raise EngineStateError(
                "this Prolog engine belongs to the parent process; a forked child "
                "cannot use it"
            )
        if threading.get_ident() != self._thread:
            raise WrongThreadError(
                "the Prolog engine may only be called from the thread that created it "
                f"(thread {self._thread}); this is thread {threading.get_ident()}"
            )

    def _call_predicate(self, predicate: int, text: str, kind: int,
                        want_reply: bool) -> Optional[str]:
        native = self._native
        data = text.encode("utf-8")
        mark = c_size_t(0)
        native.mark_strings(byref(mark))
        frame = native.open_frame()
        try:
            t0 = native.new_term_refs(2)
            if not native.put_chars(t0, kind, len(data), data):
                raise BridgeError(f"could not pass {len(data)} bytes of text to Prolog")
            if not native.call_predicate(None, native.query_flags, predicate, t0):
                exc = native.exception(0)
                if exc:
                    detail = _native.read_text(native, exc, native.get_writeq_utf8)
                    native.clear_exception()
                    raise PrologError("api_request", detail)
                raise PrologFailed("api_request", "the facade must never fail")
            if not want_reply:
                return None
            reply = _native.read_text(native, t0 + 1, native.get_string_utf8)
            if reply is None:
                raise BridgeProtocolError("the facade's reply is not a string")
            return reply
        finally:
            native.discard_frame(frame)
            native.release_strings(mark.value)

    def request_text(self, request: str) -> str:
        """Send one request text to the facade and return its JSON reply text.

        This is the raw transport under :meth:`call`, for tests and benchmarks:
        ``request`` is Prolog text (one term, no full stop).
        """
        self._check_caller()
        reply = self._call_predicate(self._predicate, request, self._native.string_utf8,
                                     want_reply=True)
        assert reply is not None
        return reply

    def _bootstrap(self) -> None:
        consult = self._native.predicate(b"ensure_loaded", 1, b"user")
        self._call_predicate(consult, str(FACADE_FILE), self._native.atom_utf8,
                             want_reply=False)
        status = self.call("load_status")
        errors, warnings = status.args
        if errors or warnings:
            message = LoadMessage(
                "error" if errors else "warning", str(FACADE_FILE), None,
                f"{errors} error(s) and {warnings} warning(s) printed to stderr while "
                "loading the facade and the modules it uses",
            )
            if errors:
                raise PrologLoadError(str(FACADE_FILE), [message])
            log.warning("%s", message)

    # ------------------------------------------------------------------ operations

    def call(self, op: str, *args: Term, share_variables: bool = False) -> Union[Term, _Failed]:
        """Run the facade operation ``op(*args)`` and return its result.

        The arguments' variables are kept apart: a variable ``X`` of the first argument
        and a variable ``X`` of the second are different Prolog variables, because terms
        obtained from separate replies reuse the names ``_G0``, ``_G1``, ... Pass
        ``share_variables=True`` to make same-named variables of different arguments one
        variable. On the wire, argument ``i``'s variables carry the suffix ``_A<i>``;
        request variables that come back in the result get their own names again
        wherever that name is free (two different ``X`` in one result stay ``X_A0`` and
        ``X_A1``).

        Parameters
        ----------
        op
            An operation name of ``api_op/3`` in ``prolog/api.pl``.
        args
            Its arguments, Python terms (see :mod:`creative_py.bridge.terms`).

        Returns
        -------
        The decoded ``Result`` of ``ok(Result)``, or :data:`FAILED` if the goal failed.

        Raises
        ------
        PrologError
            Prolog raised an exception (including an unknown operation:
            ``existence_error(api_operation, Op/Arity)``); ``predicate`` is ``op``.
        TypeError, ValueError
            An argument is not a term, or is a NaN or infinite float.
        WrongThreadError
            Called from a thread other than the creator.
        """
        if not isinstance(op, str):
            raise TypeError(f"operation name must be a str, got {type(op).__name__}")
        separate = not share_variables and len(args) > 1
        reply = decode(self.request_text(
            encode_request(op, args, separate_variables=separate)))
        if separate:
            reply = _restore_variable_names(reply, args)
        if isinstance(reply, Compound) and len(reply.args) == 1:
            if reply.name == "ok":
                return reply.args[0]
            if reply.name == "error":
                raise PrologError(op, reply.args[0])
        if reply == "failed":
            return FAILED
        raise BridgeProtocolError(f"{op}: unexpected reply {reply!r}")

    def _must(self, op: str, *args: Term) -> Term:
        result = self.call(op, *args)
        if result is FAILED:
            raise PrologFailed(op)
        return result

    def _holds(self, op: str, *args: Term) -> bool:
        return self.call(op, *args) is not FAILED

    def consult(self, path: PathLike) -> LoadReport:
        """Load a Prolog file into module ``user`` and report what loading printed.

        The path is checked before Prolog sees it. Errors and warnings printed while
        loading are captured (not printed); warnings are logged and returned.

        Raises
        ------
        PrologFileNotFoundError
            ``path`` is not an existing file (also a ``FileNotFoundError``).
        PrologSyntaxError
            The file has syntax errors; ``file`` and ``line`` locate the first, and
            ``messages`` lists every error. The rest of the file is loaded, as
            SWI-Prolog does.
        PrologLoadError
            Loading printed other errors (e.g. a directive raised).
        """
        self._check_caller()
        resolved = Path(path).expanduser().resolve()
        if not resolved.is_file():
            reason = "it is a directory" if resolved.is_dir() else "no such file"
            raise PrologFileNotFoundError(str(path), reason)
        try:
            report = self._must("consult", str(resolved))
        except PrologError as exc:
            formal = exc.formal
            if isinstance(formal, Compound) and formal.name == "existence_error":
                raise PrologFileNotFoundError(str(path), "Prolog cannot find it") from exc
            raise
        loaded_path, errors, warnings = report.args
        errors = [_load_message(m) for m in errors]
        warnings = tuple(_load_message(m) for m in warnings)
        if str(resolved) not in self._loaded:
            self._loaded.append(str(resolved))
        syntax = [m for m in errors if m.kind == "syntax_error"]
        if syntax:
            raise PrologSyntaxError(str(path), syntax + [m for m in errors if m not in syntax],
                                    warnings)
        if errors:
            raise PrologLoadError(str(path), errors, warnings)
        for warning in warnings:
            log.warning("%s", warning)
        return LoadReport(loaded_path, warnings)

    # ------------------------------------------------------------------ the bridge ops

    def ping(self) -> str:
        """Return ``"pong"``: the cheapest round trip through the facade."""
        return self._must("ping")

    def version(self) -> dict:
        """Return the facade's API version and SWI-Prolog's, e.g. ``{"api": 1, "swipl": (9, 0, 4)}``."""
        reply = self._must("version")
        api, swipl = reply.args
        return {"api": api.args[0], "swipl": tuple(swipl.args)}

    def operations(self) -> list[str]:
        """Return ``name/arity`` of every operation the facade dispatches, in table order."""
        return [f"{op.args[0]}/{op.args[1]}" for op in self._must("operations")]

    def variant(self, a: Term, b: Term) -> bool:
        """Return whether ``a`` and ``b`` are variants (equal up to renaming, Prolog ``=@=``)."""
        return self._holds("variant", a, b)

    def parse(self, text: str) -> Term:
        """Return the term that Prolog reads from ``text`` (one term, no full stop).

        Variables keep their names; anonymous ones come back as ``_G0``, ``_G1``, ...
        A syntax error raises :class:`PrologError` with ``syntax_error(...)``; a term
        nested deeper than :data:`creative_py.bridge.text.DEPTH_MAX` raises
        :class:`~creative_py.bridge.text.PrologTextError` (brackets, before Prolog reads
        it) or :class:`PrologError` with ``representation_error(term_depth(Max))``.
        """
        from creative_py.bridge.terms import PlString
        from creative_py.bridge.text import check_nesting

        return self._must("parse", PlString(check_nesting(text, "text")))

    def load_ontology(self, path: PathLike) -> None:
        """Load a background-knowledge file with ``knowledge:load_ontology/1``.

        ``path`` is a file path (checked first) or an alias term such as
        ``Compound("ontology", ("tools_hook",))``.
        """
        spec: Term
        if isinstance(path, Compound):
            spec = path
        else:
            resolved = Path(path).expanduser().resolve()
            if not resolved.is_file():
                raise PrologFileNotFoundError(str(path))
            spec = str(resolved)
        self._must("load_ontology", spec)

    def load_default_ontology(self) -> None:
        """Load every background-knowledge file of ``ontology/`` (``knowledge:load_default_ontology/0``)."""
        self._must("load_default_ontology")

    # ------------------------------------------------------------------ learning ops

    def term_lgg(self, t1: Term, t2: Term) -> Term:
        """Return Plotkin's least general generalisation of two terms (``lgg:term_lgg/3``)."""
        return self._must("term_lgg", t1, t2)

    def clause_lgg(self, c1: Term, c2: Term) -> Term:
        """Return the reduced, constrained LGG of two clauses (``lgg:clause_lgg/3``).

        Two different numbers generalise to a variable plus a body literal
        ``in_range(V, Lo, Hi)`` (Lo, Hi the two numbers, in the units of the inputs).
        """
        return self._must("clause_lgg", c1, c2)

    def theta_subsumes(self, general: Term, specific: Term,
                       options: Optional[Sequence[Term]] = None) -> bool:
        """Return whether ``general`` theta-subsumes ``specific`` (clauses or atoms).

        ``options`` is the option list of ``subsumption:theta_subsumes/3``, e.g.
        ``[Compound("inference_limit", (100000,))]``.
        """
        if options is None:
            return self._holds("theta_subsumes", general, specific)
        return self._holds("theta_subsumes", general, specific, list(options))

    def clause_reduce(self, c: Term, options: Optional[Sequence[Term]] = None) -> Term:
        """Return the Plotkin reduction of clause ``c`` (``subsumption:clause_reduce/2,3``)."""
        if options is None:
            return self._must("clause_reduce", c)
        return self._must("clause_reduce", c, list(options))

    def clause_covers(self, c: Term, example: Term) -> bool:
        """Return whether clause ``c`` covers the example clause ``Head :- Facts``."""
        return self._holds("clause_covers", c, example)

    def clause_violations(self, c: Term, example: Term,
                          options: Optional[Sequence[Term]] = None) -> Optional[list]:
        """Return the body literals of ``c`` that ``example`` leaves unsatisfied.

        ``[]`` means ``c`` covers ``example``; None means the heads do not unify.
        """
        args = (c, example) if options is None else (c, example, list(options))
        result = self.call("clause_violations", *args)
        return None if result is FAILED else result

    def rlgg(self, e1: Term, e2: Term, background: Sequence[Term],
             options: Optional[Sequence[Term]] = None) -> Term:
        """Return the relative LGG of ground examples ``e1``, ``e2`` w.r.t. ground facts.

        ``options`` as for ``rlgg:rlgg/5``: ``depth(I)`` (default 2),
        ``link_numbers(Bool)``.
        """
        if options is None:
            return self._must("rlgg", e1, e2, list(background))
        return self._must("rlgg", e1, e2, list(background), list(options))

    def nbr_reduce(self, c: Term, negatives: Sequence[Term]) -> Term:
        """Return ``c`` with its body reduced against the negative examples (``nbr:nbr_reduce/3``)."""
        return self._must("nbr_reduce", c, list(negatives))

    def vs_init(self, example: Term) -> Term:
        """Return the version space of a first positive example (an opaque term)."""
        return self._must("vs_init", example)

    def vs_init_prior(self, case: str, example: Term, literals: Sequence[Term]) -> Term:
        """Return the version space of a first positive example with ``literals`` (of
        the example's body, in ``case``'s vocabulary) noted as a prior's open
        predictions (``version_space:vs_init_prior/3``, their kinds from
        ``transfer:prior_kinds/3``)."""
        return self._must("vs_init_prior", case, example, list(literals))

    def vs_prior_events(self, vs: Term) -> list:
        """Return, oldest first, ``settled(L, E)``, ``confirmed(L, E)`` and
        ``dropped(L, E)``: what the physics did to the prior's literals
        (``version_space:vs_prior_events/2``)."""
        return self._must("vs_prior_events", vs)

    def vs_prior(self, vs: Term) -> tuple[list, list]:
        """Return ``(kept, dropped)``: the prior's literals still in h_g, and the
        ``Literal-Example`` pairs the physics contradicted (``version_space:vs_prior/3``)."""
        reply = self._must("vs_prior", vs)
        return reply.args[0], reply.args[1]

    def read_prior(self, path: PathLike) -> Term:
        """Return ``prior(Case, HS, HG)`` read from a run's ``model.pl``
        (``transfer:read_prior_text/3``; Prolog's errors as :meth:`call` raises them).

        The file is read here, checked (:func:`creative_py.bridge.text.read_text_file`:
        size, UTF-8, nesting; :class:`~creative_py.bridge.text.PrologTextError`), and
        its text given to Prolog, which reads its terms as data."""
        from creative_py.bridge.terms import PlString
        from creative_py.bridge.text import read_text_file

        text = read_text_file(path)
        return self._must("read_prior_text", PlString(text), str(path))

    def prior_shared(self, case: str, prior: Term) -> list:
        """Return the literals of the prior's h_g that the ontology maps to ``case``."""
        return self._must("prior_shared", case, prior)

    def prior_literals(self, case: str, prior: Term, example: Term) -> list:
        """Return the literals of ``example``'s body the prior's h_g gives
        (``transfer:prior_literals/4``)."""
        return self._must("prior_literals", case, prior, example)

    def prior_contradicted(self, case: str, prior: Term, example: Term) -> list:
        """Return the prior's mapped literals that the demonstration ``example``
        violates (``transfer:prior_contradicted/4``): not taken."""
        return self._must("prior_contradicted", case, prior, example)

    def vs_update(self, vs: Term, labelled: Term) -> Term:
        """Return the version space after ``pos(Example)`` or ``neg(Example)``."""
        return self._must("vs_update", vs, labelled)

    def vs_bounds(self, vs: Term) -> tuple[Term, Term]:
        """Return ``(h_s, h_g)``, the two boundary clauses, sharing their head variables."""
        bounds = self._must("vs_bounds", vs)
        return bounds.args[0], bounds.args[1]

    def vs_unknown(self, vs: Term) -> list:
        """Return the literals of h_s not yet in h_g (the ones experiments test)."""
        return self._must("vs_unknown", vs)

    def vs_examples(self, vs: Term) -> tuple[list, list]:
        """Return ``(positives, negatives)`` seen so far, in arrival order."""
        examples = self._must("vs_examples", vs)
        return examples.args[0], examples.args[1]

    def vs_converged(self, vs: Term) -> bool:
        """Return whether h_s and h_g agree."""
        return self._holds("vs_converged", vs)

    def vs_covers(self, vs: Term, bound: str, example: Term) -> bool:
        """Return whether the boundary ``bound`` (``"hs"`` or ``"hg"``) covers ``example``."""
        return self._holds("vs_covers", vs, bound, example)

    def vs_count(self, vs: Term) -> tuple[int, bool]:
        """Return ``(count, exact)``: the hypotheses of the version space that exclude
        every recorded negative (``version_space:vs_count/3``); ``exact`` is False when
        the count is an upper bound."""
        reply = self._must("vs_count", vs)
        return int(reply.args[0]), str(reply.args[1]) == "true"

    def vs_notes(self, vs: Term) -> list:
        """Return the inconsistencies met, newest first (``hg_weakened/2``, ``noisy_negative/1``)."""
        return self._must("vs_notes", vs)

    def replacement(self, literal: Term) -> Optional[tuple[Term, list]]:
        """Return ``(general, alternatives)`` of a structural literal, or None if no
        replacement operator of the loaded ontology covers it."""
        result = self.call("replacement", literal)
        if result is FAILED:
            return None
        return result.args[0], result.args[1]

    def abstract_state(self, case: str, facts: Sequence[Term]) -> list:
        """Return the sorted qualitative literals that hold in primitive ``facts``.

        ``facts`` are ground primitive facts (world frame, metres, radians), e.g.
        ``Compound("pose", ("cube1", 0.9, 0.0, -0.01, 0.0))``.
        """
        return self._must("abstract_state", case, list(facts))

    def pose_numbers(self, case: str, tool: str, facts: Sequence[Term]) -> Optional[Term]:
        """Return ``hook_pose(Dx, Dy, Roll)`` / ``wedge_pose(R, Gap, Yaw)`` of ``tool``
        (metres, radians, relative to the target), or None if a fact is missing."""
        result = self.call("pose_numbers", case, tool, list(facts))
        return None if result is FAILED else result

    # ------------------------------------------------------------------ geometry ops

    def solve_pose(self, case: str, required: Sequence[Term], negated: Sequence[Term],
                   context: Sequence[Term]) -> Term:
        """Return ``pose(PoseTerm)`` or ``infeasible(Conflict)`` (``geometry_clp:solve_pose/5``).

        ``case`` is ``"hook"`` or ``"wedge"``; the pose numbers are metres and radians
        relative to the target, as the shared vocabulary defines ``hook_pose/3`` and
        ``wedge_pose/3``.
        """
        return self._must("solve_pose", case, list(required), list(negated), list(context))

    def pose_reachable(self, case: str, tool: str, required: Sequence[Term],
                       context: Sequence[Term]) -> Term:
        """Return ``reachable(Pose)``, ``unreachable(Conflict, Params)`` or ``undecided``:
        whether the held ``tool`` reaches a pose where the spatial literals ``required``
        hold in the task ``context`` (``geometry_clp:pose_reachable/5``; ``Params`` are
        ``param(Name, Value, Meaning)`` of the reach's geometry parameters)."""
        return self._must("pose_reachable", case, tool, list(required), list(context))

    def solve_size(self, case: str, kind: str, literals: Sequence[Term],
                   context: Sequence[Term]) -> Term:
        """Return ``dims([Field=Value, ...])`` (metres, degrees where named ``_deg``) or
        ``infeasible(Conflict)`` for a new tool of ``kind`` for the task of ``case``: the
        size constraints are those of the case's own file, its tool kind's and the shared
        ones (``geometry_clp:solve_size/5``)."""
        return self._must("solve_size", case, kind, list(literals), list(context))

    # ------------------------------------------------------------------ learning ops
    # The operations of the learning loop (Algorithms 1 and 2). ``case`` is a case id
    # of a manifest (``worlds/<folder>/case.toml``); the ontology answers for it.

    def case_info(self, case: str) -> Term:
        """Return ``case(Skills, Goal, Target, Context, PoseTerm)``: what the ontology
        says of ``case`` (skill names in plan order, goal literals, the target and
        context objects, the pose term's name)."""
        return self._must("case_info", case)

    def tool_vocabulary(self, case: str) -> list:
        """Return ``class(Class, Ancestors, [Property-Values, ...])`` for the case's tool
        class and every class below it: the vocabulary of a new tool's spec."""
        return self._must("tool_vocabulary", case)

    def case_missing_hooks(self, case: str) -> list:
        """Return the ``Name/Arity`` terms of the engine's hook predicates that the case's
        ontology file does not answer (empty when it answers them all)."""
        return self._must("case_missing_hooks", case)

    def catalogue_ranges(self, case: str, facts: Sequence[Term]) -> list:
        """Return ``range(Object, Fact, Number, Property, Value, Low, High, Bounds)`` for
        every numeric catalogue fact of ``facts`` that the case's tool hierarchy reads
        into a qualitative value (``case:catalogue_ranges/3``)."""
        return self._must("catalogue_ranges", case, list(facts))

    def catalogue_predicates(self, case: str) -> list:
        """Return the ``Name/Arity`` terms of the catalogue facts of the case's tool class
        (the ontology's vocabulary for describing a catalogued object)."""
        return self._must("catalogue_predicates", case)

    def size_context_facts(self, case: str | None = None) -> list:
        """Return the ``Name/Arity`` terms of the task facts the size model reads: of
        ``case``'s size model, or of any case's (None)."""
        if case is None:
            return self._must("size_context_facts")
        return self._must("size_context_facts", case)

    def learn_from_demonstration(self, case: str, steps: Sequence[Term]) -> tuple[Term, Term, Term]:
        """Return ``(matched, new_models, example)`` learned from the demonstration's
        ``step(Skill, Args, FactsBefore, FactsAfter)`` terms."""
        reply = self._must("learn_from_demonstration", case, list(steps))
        if not (isinstance(reply, Compound) and reply.name == "models" and len(reply.args) == 3):
            raise BridgeProtocolError(f"learn_from_demonstration: unexpected reply {reply!r}")
        return reply.args[0], reply.args[1], reply.args[2]

    def next_experiment(self, case: str, vs: Term, facts: Sequence[Term],
                        skip: Sequence[Term] = (), strategy: Optional[Term] = None) -> Term:
        """Return ``experiment(Tool, Tested, Violated, Pose, Required, Negated)``, an
        ``exploit(Tool, Violated, Pose, Required)`` when nothing is left to test, or
        ``no_experiment(Why)`` (Algorithm 1's choice, ``experiment:plan_experiment/6``).

        ``strategy`` is a strategy term that Prolog declares (``experiment_strategies``):
        ``"paper"`` (the default), ``"informative"``, ``Compound("random", (seed,))``;
        ``creative_py.learning.strategies`` says which term each strategy sends.
        """
        if strategy is None:
            return self._must("next_experiment", case, vs, list(facts), list(skip))
        return self._must("next_experiment", case, vs, list(facts), list(skip),
                          [Compound("strategy", (strategy,))])

    def experiment_strategies(self) -> list:
        """Return the strategy templates that Prolog declares
        (``experiment:experiment_strategies/1``): ``"paper"``, ``"informative"``,
        ``Compound("random", ("integer",))``, each argument named by its type."""
        return self._must("experiment_strategies")

    def label_trial(self, case: str, vs: Term, experiment: Term, facts: Sequence[Term],
                    label: str, mode: str) -> Term:
        """Return the version space after a trial labelled ``pos``/``neg``; ``mode`` is
        ``observed`` (the example from ``facts``) or ``planned`` (from the experiment)."""
        return self._must("label_trial", case, vs, experiment, list(facts), label, mode)

    def plan_use(self, case: str, vs: Term, facts: Sequence[Term],
                 options: Sequence[Term] = ()) -> Term:
        """Return ``exploit(Tool, Violated, Pose, Required)`` for the learned model's best
        tool and pose in the task ``facts`` (option ``tool(T)`` fixes the tool), or a
        reason term when there is none."""
        return self._must("plan_use", case, vs, list(facts), list(options))

    def next_tool(self, case: str, vs: Term, tried: Sequence[Term],
                  facts: Sequence[Term]) -> Term:
        """Return ``create(Replaced, General, Instance, Structural, Dims)`` or
        ``exhausted(Why)`` (Algorithm 2's choice, ``creation:next_tool/6``)."""
        return self._must("next_tool", case, vs, list(tried), list(facts))

    def catalogue_first(self, case: str, vs: Term, facts: Sequence[Term],
                        exclude: Sequence[str] = ()) -> Term:
        """Return ``catalogue(Replaced, General, Objects)``: the available objects (in the
        task ``facts``) that the generalised model admits, best first, each as
        ``catalogued(Object, Value, Use)`` with ``Use`` an ``exploit/4`` plan; or
        ``none`` (``creation:catalogue_first/5``). ``exclude`` names objects to leave
        out."""
        return self._must("catalogue_first", case, vs, list(facts), list(exclude))

    def created_models(self, models: Term, vs: Term, replaced: Term, instance: Term) -> list:
        """Return the harder task's action models: the learned ones with ``replaced``
        swapped for ``instance``."""
        return self._must("created_models", models, vs, replaced, instance)

    def plan_task(self, case: str, models: Term, vs: Term, facts: Sequence[Term],
                  options: Sequence[Term] = ()) -> Term:
        """Return ``plan(Steps)`` (or a reason) for the case's goal with the learned
        models; option ``pddl(Domain, Problem)`` also writes the PDDL files."""
        return self._must("plan_task", case, models, vs, list(facts), list(options))

    def plan_models(self, case: str, learned: Sequence[Term], facts: Sequence[Term],
                    options: Sequence[Term] = ()) -> Term:
        """Return ``plan(Steps)`` (or a reason) for the case's goal with the given learned
        action models (e.g. :meth:`created_models`) and the innate skills; option
        ``pddl(Domain, Problem)`` also writes the PDDL files, ``domain_name(N)`` and
        ``problem_name(N)`` name their domain and problem."""
        return self._must("plan_models", case, list(learned), list(facts), list(options))

    def write_model_file(self, path: PathLike, case: str, models: Term, vs: Term,
                         created: Sequence[Term] = ()) -> None:
        """Write ``model.pl`` (learned models and hypotheses, and ``created(Variant,
        Models)`` of the harder task) to ``path``."""
        if created:
            self._must("write_model_file", str(path), case, models, vs, list(created))
        else:
            self._must("write_model_file", str(path), case, models, vs)

    def pose_target(self, case: str, tool: str, facts: Sequence[Term],
                    pose: Term) -> Optional[Term]:
        """Return the world-frame target of a pose term (the ontology's pose geometry),
        e.g. ``tip(X, Y, Roll)`` or ``place(X, Y, Heading)``, from the perceived ``facts``;
        None if the facts lack what it needs (the target is not seen)."""
        result = self.call("pose_target", case, tool, list(facts), pose)
        return None if result is FAILED else result


def _restore_variable_names(reply: Term, args: Sequence[Term]) -> Term:
    """Give request variables that come back in ``reply`` their names without the
    per-argument suffix, wherever that name is not taken by another variable."""
    originals: dict[str, str] = {}
    for i, arg in enumerate(args):
        suffix = argument_suffix(i)
        for var in variables(arg):
            originals[var.name + suffix] = var.name
    names = {var.name for var in variables(reply)}
    wanted: dict[str, list[str]] = {}
    for name in names:
        if name in originals:
            wanted.setdefault(originals[name], []).append(name)
    mapping = {
        sources[0]: target for target, sources in wanted.items()
        if len(sources) == 1 and target not in names
    }
    if not mapping:
        return reply
    return map_variables(reply, lambda v: Var(mapping[v.name]) if v.name in mapping else v)


def _load_message(term: Term) -> LoadMessage:
    kind, file, line, text = term.args
    return LoadMessage(
        kind,
        None if file == "none" else file,
        None if line == "none" else line,
        text.value if hasattr(text, "value") else str(text),
        term,
    )

