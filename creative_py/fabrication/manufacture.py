"""Manufacture a new tool: qualitative spec -> sized spec -> printable files.

This is the path of ``creative make-tool`` and of steps 3-9 of the paper's Algorithm 2
(tool creation): the structural literals a new tool must have (``hook(T)``,
``handle_length(T, long)``, ...) are sized by the CLP(R) size model in Prolog
(``geometry_clp:solve_size/5``) against the task's geometry, and the sized tool is
written as URDF, SDF, OpenSCAD, STL and a manifest by
:func:`creative_py.mesh.export.write_tool_files`::

    engine = Engine.instance()
    literals = parse_spec("hook", "handle_length=long,hook_side=left")
    sized = size_tool(engine, "hook", literals, default_context("hook", "long_tube"),
                      "hook_new1")                     # or raises InfeasibleSpec
    files = make_tool(engine, "hook", literals, default_context("hook", "long_tube"),
                      "hook_new1", "runs/tools")      # sizes, then writes

Units are those of :mod:`creative_py.mesh.spec`: metres, degrees where a name says
``_deg``. The printed mass is PLA density times volume (``mass=None`` in the spec).

Sizing always happens before anything is written, and the writer is atomic: when
:func:`make_tool` raises, no file or folder of the tool exists (the output folder
itself is not even created when sizing fails).

The qualitative vocabulary of a case (its tool kinds, their class literals, property
names and values) is the ontology's (:func:`tool_vocabulary`: the case's tool class in
``ontology/kinds/``, its ``class_property/2``, ``qualitative_range/5`` and
``size_choice/4`` facts); nothing here names a case or a property.
"""

from __future__ import annotations

import difflib
import logging
import math
import re
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Sequence

from creative_py.bridge import (Compound, Engine, PrologError, Term, Var, conj_to_list,
                               encode, fact_term)
from creative_py.bridge.errors import reader_words
from creative_py.bridge.text import PrologTextError
from creative_py.mesh.printability import PrintSettings
from creative_py.kinds import spec_classes, spec_from_dict
from creative_py.mesh.spec import KindSpec

if TYPE_CHECKING:
    from creative_py.mesh.export import ToolFiles

log = logging.getLogger(__name__)

PLACEHOLDER_TOOL = "new_tool"
"""The tool atom of the literals :func:`parse_spec` returns (renamed by :func:`size_tool`)."""

def context_facts(engine: Engine, case: Optional[str] = None) -> dict[str, int]:
    """Return ``name -> arity`` of the task facts the size model reads (the ontology's
    ``size_constraint/3`` and ``size_parameter/3``, e.g. ``tube_length_m/2``): of
    ``case``'s size model, or of any case's (None)."""
    return {str(i.args[0]): int(i.args[1]) for i in engine.size_context_facts(case)}

_ATOM = re.compile(r"[a-z][a-zA-Z0-9_]*\Z")


class InfeasibleSpec(ValueError):
    """No tool has the spec's literals and also suits the task.

    Attributes
    ----------
    name : str
        The tool that was to be made.
    conflicts : list of str
        A minimal conflict, as Prolog text: spec literals and task facts that cannot
        hold together (dropping any one of them makes the spec feasible).
    """

    def __init__(self, name: str, literals: Sequence[str], facts: Sequence[str]) -> None:
        self.name = name
        self.conflicts = list(literals) + list(facts)
        parts = []
        if literals:
            parts.append("the spec's " + ", ".join(literals))
        if facts:
            parts.append("the task's " + ", ".join(facts))
        super().__init__(
            f"{name}: no tool satisfies {' together with '.join(parts)} (a minimal "
            f"conflict: dropping any one of these makes the spec feasible)")


@dataclass(frozen=True)
class SizedTool:
    """A new tool with its dimensions chosen.

    Attributes
    ----------
    name : str
        The tool's object name (a Prolog atom).
    case : str
        ``"hook"`` or ``"wedge"``.
    kind : str
        The new tool's class (``"hook"``, ``"stick"``, ``"block"``: a class of a tool
        kind, :func:`creative_py.kinds.spec_classes`).
    literals : tuple of str
        The literals it was sized for, Prolog text, with the tool named ``name``.
    dims : dict
        Spec field -> value as the size model chose it (metres; ``hook_angle_deg`` in
        whole degrees; ``hook_side`` and ``shape`` as names).
    spec : KindSpec
        The spec built from ``dims`` (mass None: PLA density times volume).
    seconds : float
        Wall time of the sizing call, seconds.
    """

    name: str
    case: str
    kind: str
    literals: tuple[str, ...]
    dims: dict
    spec: KindSpec
    seconds: float

    def catalogue_facts(self) -> list[Term]:
        """Return the tool's catalogue facts (metres, degrees): its kind's, as the robot
        perceives them for every catalogued object
        (:meth:`creative_py.kinds.parts.KindSpec.catalogue_facts`), so the knowledge
        base derives the tool's structural literals the same way."""
        return [fact_term(f) for f in self.spec.catalogue_facts()]


@dataclass(frozen=True)
class ToolVocabulary:
    """What a qualitative spec of a case's new tool may say, from the ontology.

    Attributes
    ----------
    case : str
        The case id.
    kinds : dict
        Tool class (:func:`creative_py.kinds.spec_classes`, e.g. ``hook``, ``stick``)
        -> ``(class_literals, properties)``: the class literal names every tool of that
        kind carries (outermost first, the kind last) and ``property -> values``.
    """

    case: str
    kinds: dict[str, tuple[tuple[str, ...], dict[str, tuple[str, ...]]]]

    @property
    def default_kind(self) -> str:
        """Return the kind a spec has when it names none (the first the ontology lists)."""
        return next(iter(self.kinds))

    @property
    def properties(self) -> dict[str, tuple[str, ...]]:
        """Return every property a spec may give and its values; ``kind`` when the case
        has several kinds."""
        out: dict[str, tuple[str, ...]] = {}
        if len(self.kinds) > 1:
            out["kind"] = tuple(self.kinds)
        for _classes, props in self.kinds.values():
            for p, values in props.items():
                out.setdefault(p, values)
        return out

    def subject_names(self) -> set[str]:
        """Return the names of the literals whose first argument is the tool."""
        names = set(self.kinds)
        for classes, props in self.kinds.values():
            names |= set(classes) | set(props)
        return names


_VOCABULARIES: dict[tuple[int, str], ToolVocabulary] = {}


def tool_vocabulary(engine: Engine, case: str) -> ToolVocabulary:
    """Return the qualitative vocabulary of ``case``'s new tools (asked once per engine).

    Raises
    ------
    ValueError
        ``case`` is not a case of the ontology (the message lists the known ones).
    """
    from creative_py.case import load_cases

    key = (id(engine), case)
    if key not in _VOCABULARIES:
        try:
            classes = engine.tool_vocabulary(case)
        except PrologError:
            known = ", ".join(sorted(load_cases()))
            raise ValueError(f"unknown case {case!r}; known cases: {known}") from None
        kinds = {}
        for cls in classes:
            name, ancestors, props = cls.args
            if name in spec_classes():
                kinds[str(name)] = (tuple(str(a) for a in ancestors) + (str(name),),
                                    {str(p.args[0]): tuple(str(v) for v in p.args[1])
                                     for p in props})
        if not kinds:
            raise ValueError(f"case {case}: the ontology's tool classes name no class of a "
                             f"tool kind ({', '.join(spec_classes())})")
        _VOCABULARIES[key] = ToolVocabulary(case, kinds)
    return _VOCABULARIES[key]


def parse_spec(case: str, text: str, tool: str = PLACEHOLDER_TOOL, *,
               engine: Optional[Engine] = None) -> list[Compound]:
    """Return the structural literals of a command-line spec, class literals first.

    Parameters
    ----------
    case : str
        The case the tool is for; its vocabulary is the ontology's
        (:func:`tool_vocabulary`).
    text : str
        Comma-separated ``property=value`` pairs, e.g.
        ``"handle_length=long,hook_side=left,hook_length=long"`` or
        ``"shape=triangular_prism,block_length=long"``. When the case has several tool
        kinds, ``kind=<kind>`` chooses one (default: the first); a property the kind
        does not have (a stick's prong) is refused.
    tool : str
        The tool atom of the literals.
    engine : Engine or None
        The Prolog engine (default: the process's one).

    Returns
    -------
    list of Compound
        e.g. ``[tool(new_tool), hook_like(new_tool), hook(new_tool),
        handle_length(new_tool, long), hook_side(new_tool, left)]``.

    Raises
    ------
    ValueError
        An unknown case, property or value (the message lists the allowed ones), a
        malformed or repeated pair, an empty spec, or a property the kind lacks.
    """
    vocab = tool_vocabulary(engine or Engine.instance(), case)
    props = vocab.properties
    allowed = "; ".join(f"{p}={'|'.join(vs)}" for p, vs in props.items())
    if not isinstance(text, str) or not text.strip():
        raise ValueError(f"{case} spec: empty; give property=value pairs separated by "
                         f"commas, from: {allowed}")
    chosen = _spec_pairs(case, text, props, allowed)
    kind = chosen.pop("kind", vocab.default_kind)
    classes, kind_props = vocab.kinds[kind]
    lacking = [p for p in chosen if p not in kind_props]
    if lacking:
        raise ValueError(f"{case} spec {_shown(text)!r}: a {kind} has no "
                         f"{', '.join(lacking)} "
                         f"(its properties: {', '.join(kind_props)})")
    _check_atom(tool, "tool")
    return ([Compound(c, (tool,)) for c in classes]
            + [Compound(p, (tool, v)) for p, v in chosen.items()])


def _spec_pairs(case: str, text: str, props: dict[str, Any], allowed: str) -> dict[str, str]:
    """Return the ``property -> value`` pairs of a spec's text, each property and value
    one that ``props`` allows; raise ValueError naming the pair that is not."""
    chosen: dict[str, str] = {}
    for item in text.split(","):
        prop, sep, value = (s.strip() for s in item.partition("="))
        if not sep or not prop or not value:
            raise ValueError(f"{case} spec {_shown(text)!r}: {_shown(item.strip())!r} is not "
                             "property=value; "
                             f"allowed: {allowed}")
        if prop not in props:
            raise ValueError(f"{case} spec {_shown(text)!r}: unknown property "
                             f"{_shown(prop)!r}"
                             f"{_did_you_mean(prop, props)}; allowed properties: "
                             f"{', '.join(props)}")
        if value not in props[prop]:
            raise ValueError(f"{case} spec {_shown(text)!r}: {prop} cannot be "
                             f"{_shown(value)!r}"
                             f"{_did_you_mean(value, props[prop])}; allowed values: "
                             f"{', '.join(props[prop])}")
        if prop in chosen and chosen[prop] != value:
            raise ValueError(f"{case} spec {_shown(text)!r}: {prop} given twice ({chosen[prop]} "
                             f"and {value})")
        chosen[prop] = value
    return chosen


def parse_context(engine: Engine, text: str) -> list[Term]:
    """Return the task facts of a command-line context such as
    ``"max_tool_length(0.3), tube_length_m(tube1, 0.45)"`` (Prolog syntax, metres).

    The text is read as one Prolog term, a conjunction of facts, by the bridge's
    guarded reader (:meth:`Engine.parse`: read as data, never called, never nested
    deeper than :data:`creative_py.bridge.text.DEPTH_MAX`), so no bracket in it can
    end a list it was put in and a directive (``:- halt``) is only an unknown fact.

    Raises
    ------
    ValueError
        The text does not parse or nests too deep, a fact is not ground, a number is
        not finite, or it is not one of the facts the size model reads
        (:func:`context_facts`; it would silently ignore it). The message shows the
        text (its start and end when long).
    """
    where = f"--context {_shown(text)!r}"
    if not text.strip():
        return []
    try:
        facts = conj_to_list(engine.parse(text))
    except PrologTextError as exc:
        raise ValueError(f"{where}: not Prolog facts ({exc.why})") from None
    except PrologError as exc:
        raise ValueError(f"{where}: not Prolog facts ({reader_words(exc) or exc})") \
            from None
    known_facts = context_facts(engine)
    for fact in facts:
        name = fact.name if isinstance(fact, Compound) else fact
        arity = len(fact.args) if isinstance(fact, Compound) else 0
        if not isinstance(name, str) or known_facts.get(name) != arity:
            known = ", ".join(f"{n}/{a}" for n, a in known_facts.items())
            raise ValueError(f"{where}: unknown task fact {_fact_text(fact)}; the size "
                             f"model understands {known}")
        if not all(isinstance(a, (int, float, str)) for a in fact.args):
            raise ValueError(f"{where}: {_fact_text(fact)} must be ground (atoms and "
                             "numbers)")
        if not all(math.isfinite(a) for a in fact.args if isinstance(a, float)):
            raise ValueError(f"{where}: {_fact_text(fact)}: a number is not finite")
    return facts


def with_context(perceived: Sequence[Term], given: Sequence[Term]) -> list[Term]:
    """Return the task facts ``perceived`` (:func:`default_context`) with the ``given``
    ones (:func:`parse_context`) after them; raise ValueError when a given fact is about
    an object the task does not have (``tube_length_m(tube2, 0.45)`` where the task
    has ``tube1``): the size model would ignore it without a word."""
    objects = {f.args[0] for f in perceived
               if isinstance(f, Compound) and len(f.args) >= 2 and isinstance(f.args[0], str)}
    for fact in given:
        if (isinstance(fact, Compound) and len(fact.args) >= 2
                and isinstance(fact.args[0], str) and fact.args[0] not in objects):
            raise ValueError(f"--context: {_fact_text(fact)} is about {fact.args[0]}, "
                             "which the task does not have (its objects: "
                             f"{', '.join(sorted(objects)) or 'none'})")
    return list(perceived) + list(given)


def _shown(text: str) -> str:
    """Return command-line text for a message: its start and end when long."""
    return text if len(text) <= 80 else f"{text[:60]}...{text[-12:]}"


def _fact_text(fact: Term) -> str:
    """Return a context fact as Prolog text for a message (80 characters at most)."""
    def arg(a: Term) -> str:  # a non-finite float as SWI-Prolog writes it
        if isinstance(a, float) and not math.isfinite(a):
            return "1.5NaN" if math.isnan(a) else ("1.0Inf" if a > 0 else "-1.0Inf")
        return encode(a, operators=True)

    if isinstance(fact, Compound):
        text = encode(fact.name) + "(" + ",".join(arg(a) for a in fact.args) + ")"
    else:
        text = arg(fact)
    return text if len(text) <= 80 else f"{text[:60]}...{text[-12:]}"


def default_context(case: str, variant: Optional[str] = None, *,
                    world_dir: Path | str | None = None) -> list[Compound]:
    """Return the task facts the size model needs, as the robot perceives the task.

    The scene of ``variant`` (default: the demonstration's) is built in the simulator
    and observed once at its first location; of what the robot perceives, the facts the
    size model reads (:func:`context_facts`, e.g. ``tube_length_m(Tube, L)`` or
    ``door_gap_m(Door, G)``, metres) are returned. ``world_dir`` names a world folder
    with its own ``case.toml`` (default: the shipped one of ``case``).

    Raises
    ------
    WorldFileError
        A world file is missing or lacks a field (the message names file and field).
    ValueError
        An unknown case or variant (the message lists the known ones).
    """
    from creative_py.case import get_case, read_manifest
    from creative_py.simulator.trial import task_facts
    from creative_py.simulator import backend_for

    try:
        manifest = get_case(case) if world_dir is None else read_manifest(Path(world_dir))
        variant = variant or manifest.demonstration.variant
        manifest.variant(variant)
    except KeyError as exc:
        raise ValueError(exc.args[0]) from None
    world = backend_for(manifest).load_world(manifest)
    facts = task_facts(world, variant, world.locations[0])
    known = context_facts(Engine.instance(), manifest.id)
    return [fact_term(f) for f in facts if known.get(f[0]) == len(f) - 1]


def size_tool(engine: Engine, case: str, literals: Sequence[Term],
              context_facts: Sequence[Term], name: str, *,
              settings: PrintSettings = PrintSettings()) -> SizedTool:
    """Choose the dimensions of a new tool that has ``literals`` and suits the task.

    Parameters
    ----------
    engine : Engine
        The Prolog engine, with the ontology loaded (``engine.load_default_ontology()``).
    case : str
        The case the tool is for (its tool vocabulary, :func:`tool_vocabulary`).
    literals : sequence of terms
        The tool's literals (e.g. from :func:`parse_spec`, or the body of a hypothesis:
        spatial and task literals are ignored). Their tool argument (an atom or a
        variable) must be the same in all of them; it is renamed ``name``. The kind is
        the spec kind whose class literal is among them (``stick(T)``), else the case's
        first kind.
    context_facts : sequence of terms
        Task facts (:func:`context_facts`, e.g. :func:`default_context`); others are ignored.
    name : str
        The new tool's object name.
    settings : PrintSettings
        The printer: unless the context has a ``min_wall_m`` fact, every solid dimension
        is kept at or above ``settings.min_feature``; unless it has a
        ``min_tip_height_m`` fact, a wedge's tip at or above ``settings.min_tip``.

    Returns
    -------
    SizedTool

    Raises
    ------
    InfeasibleSpec
        No size satisfies the literals and the task facts; the message names a minimal
        conflict.
    ValueError
        A bad case or name, literals about two different tools, or a literal the
        knowledge base does not know (is the ontology loaded?).
    """
    vocab = tool_vocabulary(engine, case)
    _check_atom(name, "tool name")
    renamed = _rename_tool(vocab, literals, name)
    kind = next((lit.name for lit in renamed if lit.name in vocab.kinds
                 and lit.args == (name,)), vocab.default_kind)
    start = time.perf_counter()
    dims = _solved_dims(engine, case, kind, renamed,
                        _with_printer(context_facts, settings), name)
    seconds = time.perf_counter() - start
    spec = spec_from_dict({"kind": kind, "name": name, "mass": None, **dims},
                          source=f"solve_size({kind}) for {name}")
    log.info("sized %s %s in %.1f ms: %s", kind, name, 1e3 * seconds, dims)
    return SizedTool(name=name, case=case, kind=kind, literals=tuple(str(t) for t in renamed),
                     dims=dims, spec=spec, seconds=seconds)


def _with_printer(context_facts: Sequence[Term], settings: PrintSettings) -> list[Term]:
    """Return the task facts with the printer's least wall and least wedge tip added
    (``min_wall_m``, ``min_tip_height_m``), unless the facts give their own."""
    context = list(context_facts)
    if not any(isinstance(f, Compound) and f.name == "min_wall_m" for f in context):
        context.append(Compound("min_wall_m", (settings.min_feature,)))
    if not any(isinstance(f, Compound) and f.name == "min_tip_height_m" for f in context):
        context.append(Compound("min_tip_height_m", (settings.min_tip,)))
    return context


def _solved_dims(engine: Engine, case: str, kind: str, literals: list[Term],
                 context: list[Term], name: str) -> dict[str, Any]:
    """Return the dimensions CLP(R) gives a ``kind`` tool with ``literals`` in
    ``context`` (``geometry_clp:solve_size/5``); raise InfeasibleSpec naming a minimal
    conflict, or ValueError for a literal the knowledge base does not know."""
    try:
        result = engine.solve_size(case, kind, literals, context)
    except PrologError as exc:
        formal = exc.formal
        if isinstance(formal, Compound) and formal.name == "domain_error":
            raise ValueError(
                f"{name}: the knowledge base does not know the literal {formal.args[1]} "
                f"({exc}); load the ontology first (engine.load_default_ontology())") from None
        raise
    if result.name == "infeasible":
        conflict = result.args[0]
        lits = [str(t) for t in conflict if t in literals]
        facts = [str(t) for t in conflict if t not in literals]
        raise InfeasibleSpec(name, lits, facts)
    return {eq.args[0]: eq.args[1] for eq in result.args[0]}


def make_tool(engine: Engine, case: str, literals: Sequence[Term],
              context_facts: Sequence[Term], name: str, out_dir: Path | str, *,
              settings: PrintSettings = PrintSettings(), overwrite: bool = False,
              picture: bool = True, gcode: bool = True) -> ToolFiles:
    """Size a new tool (:func:`size_tool`) and write its files into ``out_dir/<name>/``.

    The files are those of :func:`creative_py.mesh.export.write_tool_files` (URDF, SDF,
    OpenSCAD, STL, manifest, optional PNG, the printed pieces: split to fit
    ``settings.build_volume`` and, with ``gcode``, sliced with PrusaSlicer). The mass is
    PLA density times volume. Sizing happens first, and the writer is atomic: on any
    error nothing of the tool is left in ``out_dir`` (and ``out_dir`` is not created if
    sizing fails).

    Raises
    ------
    InfeasibleSpec, ValueError
        As :func:`size_tool`; or a dimension the printer cannot print, or a tool that
        cannot be split into pieces that fit (:class:`creative_py.mesh.split.SplitError`).
    SliceError
        The slicer rejected a piece (:class:`creative_py.mesh.slicer.SliceError`).
    FileExistsError
        ``out_dir/<name>`` exists and ``overwrite`` is false.
    """
    # The writer (trimesh, the renderers, the ROS and Gazebo exporters) is imported once a
    # tool is sized: a spec, context or name that is refused costs its check only (about
    # 1.5 s of imports less for each refused make-tool).
    from creative_py.mesh.export import write_tool_files

    sized = size_tool(engine, case, literals, context_facts, name, settings=settings)
    start = time.perf_counter()
    files = write_tool_files(sized.spec, out_dir, settings=settings, overwrite=overwrite,
                             picture=picture, gcode=gcode)
    log.info("made %s: sized in %.1f ms, written in %.1f ms", name, 1e3 * sized.seconds,
             1e3 * (time.perf_counter() - start))
    return files


def _did_you_mean(word: str, choices) -> str:
    close = difflib.get_close_matches(word, list(choices), n=1)
    return f" (did you mean {close[0]!r}?)" if close else ""


def _check_atom(name: str, what: str) -> None:
    if not (isinstance(name, str) and _ATOM.match(name)):
        raise ValueError(f"{what} {name!r} must be a Prolog atom: a lower-case ASCII letter "
                         "followed by letters, digits or underscores")


def _rename_tool(vocab: ToolVocabulary, literals: Sequence[Term], name: str) -> list[Term]:
    """Return ``literals`` with their tool (first argument of class and structural
    literals) replaced by the atom ``name`` everywhere."""
    if isinstance(literals, (str, Compound)):
        raise ValueError(f"{name}: literals must be a list of terms, got {literals!r}")
    subjects = []
    subjects_of = vocab.subject_names()
    for lit in literals:
        if not isinstance(lit, Compound):
            raise ValueError(f"{name}: literal {lit!r} is not a compound term")
        if lit.name in subjects_of and lit.args and lit.args[0] not in subjects:
            subjects.append(lit.args[0])
    if len(subjects) > 1:
        raise ValueError(f"{name}: the literals describe more than one tool: "
                         f"{', '.join(str(s) for s in subjects)}")
    if not subjects:
        raise ValueError(f"{name}: no class or structural literal of the {vocab.case} case among "
                         f"{', '.join(str(lit) for lit in literals) or 'no literals'}")
    subject = subjects[0]
    if isinstance(subject, Var) and subject.anonymous:
        raise ValueError(f"{name}: the tool argument of the literals is the anonymous variable")
    return [_replace(lit, subject, name) for lit in literals]


def _replace(term: Term, old: Term, new: Term) -> Term:
    if term == old and type(term) is type(old):
        return new
    if isinstance(term, Compound):
        return Compound(term.name, tuple(_replace(a, old, new) for a in term.args))
    if isinstance(term, list):
        return [_replace(a, old, new) for a in term]
    return term
