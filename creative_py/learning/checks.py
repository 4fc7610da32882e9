"""Checks of a case before a run touches the physics: the manifest against its ontology
(:func:`check_manifest`), the catalogue against the ontology's vocabulary
(:func:`check_catalogue`), the display for ``--gui`` (:func:`require_display`), and the
qualitative ranges of the catalogued numbers (:func:`catalogue_ranges`)."""

from __future__ import annotations

from typing import Any, Optional

from creative_py.bridge import Compound, Engine, PrologError, fact_term
from creative_py.bridge.errors import reader_words
from creative_py.bridge.text import PrologTextError
from creative_py.simulator import World, backend_for


def catalogue_ranges(engine: Engine, world: World) -> dict[str, dict[str, tuple]]:
    """Return ``object -> {catalogue fact -> (low, high, bounds, value)}``: the
    qualitative range of each catalogued number and the value it stands for (the
    engine's ``catalogue_ranges``; what the backend's ``draw_world`` draws inside)."""
    facts = [fact_term(f) for spec in world.catalogue.values() for f in spec.catalogue_facts()]
    ranges: dict[str, dict[str, tuple[float, float, str, str]]] = {}
    for r in engine.catalogue_ranges(world.manifest.id, facts):
        obj, fact, _x, _prop, value, lo, hi, bounds = r.args
        ranges.setdefault(str(obj), {})[str(fact)] = (float(lo), float(hi), str(bounds),
                                                      str(value))
    return ranges


def require_display(manifest: Optional[Any] = None) -> None:
    """Raise ValueError unless the simulator's window (``--gui``) can open on the
    display: the window of ``manifest``'s backend, or, without a manifest (the command
    line's check before it reads one), the default backend's (its
    ``display_reachable``)."""
    from creative_py.simulator import backend

    physics = backend() if manifest is None else backend_for(manifest)
    why = physics.display_reachable()
    if why:
        raise ValueError(f"--gui: {why}; run without --gui, or under a display "
                         f"(e.g. xvfb-run)")


def check_manifest(engine: Engine, manifest: Any) -> None:
    """Check that a case manifest agrees with its ontology file; raise ValueError naming
    the manifest's file and field where they differ.

    The manifest binds the skills to simulator primitives and names the goal, the roles
    and the pose; the ontology (``ontology/cases/<case>.pl``) holds the knowledge behind
    the same names, so the two must say the same.
    """
    where = manifest.folder / "case.toml"
    try:
        info = engine.case_info(manifest.id)
    except PrologError as exc:
        raise ValueError(f"{where}: field 'id': the ontology does not know case "
                         f"{manifest.id!r} (add ontology/cases/{manifest.ontology}.pl): "
                         f"{exc}") from None
    missing = [f"{i.args[0]}/{i.args[1]}" for i in engine.case_missing_hooks(manifest.id)]
    if missing:
        raise ValueError(f"ontology/cases/{manifest.ontology}.pl: case {manifest.id} does "
                         f"not answer the engine's hook predicate(s) {', '.join(missing)} "
                         f"(ontology/README.md lists them)")
    skills, goal, target, context, pose_term = info.args
    checks = [
        ("skill", [s.name for s in manifest.skills], [str(s) for s in skills]),
        ("goal", [str(_literal(engine, where, i, g)) for i, g in enumerate(manifest.goal)],
         [str(g) for g in goal]),
        ("roles.target", manifest.target, str(target)),
        ("roles.context", manifest.context, str(context)),
        ("pose.term", manifest.pose_term, str(pose_term)),
    ]
    for field, mine, theirs in checks:
        if mine != theirs:
            raise ValueError(f"{where}: field {field!r}: {mine} differs from the ontology's "
                             f"{theirs} (ontology/cases/{manifest.ontology}.pl)")


def _literal(engine: Engine, where: Any, index: int, text: str) -> Any:
    """Return the goal literal ``text`` (item ``index`` of the manifest's ``goal``) as
    Prolog reads it; raise ValueError naming the file, the field and the item when it
    does not read (a syntax error, a term nested too deep)."""
    shown = text if len(text) <= 80 else f"{text[:60]}...{text[-12:]}"
    try:
        return engine.parse(text)
    except PrologTextError as exc:
        why = exc.why
    except PrologError as exc:
        why = reader_words(exc) or str(exc)
    raise ValueError(f"{where}: field 'goal', item {index + 1} {shown!r}: not a Prolog "
                     f"literal ({why})")


def check_catalogue(engine: Engine, world: World) -> None:
    """Check that every catalogued object's facts (its kind's, as the robot perceives
    them) are in the ontology's vocabulary (the catalogue predicates of the case's tool
    class); raise ValueError naming the object and the fact otherwise."""
    from creative_py.fabrication.manufacture import tool_vocabulary

    m = world.manifest
    known = {(str(i.args[0]), int(i.args[1])) for i in engine.catalogue_predicates(m.id)}
    kinds = tool_vocabulary(engine, m.id).kinds
    for kind, (_classes, properties) in kinds.items():
        for prop, values in properties.items():
            if not values:
                raise ValueError(f"ontology: the property {prop} of a {kind} has no values "
                                 f"(no qualitative_range/5 in ontology/ranges.pl, nor a "
                                 f"size_choice/4 in ontology/kinds/)")
    where = m.folder / "objects.toml"
    for name, spec in world.catalogue.items():
        facts = spec.catalogue_facts()
        for fact in facts:
            if (fact[0], len(fact) - 1) not in known:
                raise ValueError(
                    f"{where}: {name}: the catalogue fact {fact[0]}/{len(fact) - 1} is not "
                    f"in the ontology's vocabulary of the case's tools "
                    f"({', '.join(f'{n}/{a}' for n, a in sorted(known))})")
        # Every property of the object's kind must take a qualitative value: a number
        # outside every range of the ontology would leave the learner blind to it.
        literals = engine.abstract_state(m.id, [fact_term(f) for f in facts])
        have = {lit.name for lit in literals
                if isinstance(lit, Compound) and lit.args and lit.args[0] == name}
        kind = str(facts[0][2]) if facts and facts[0][0] == "object_kind" else None
        missing = [p for p in kinds.get(kind, ((), {}))[1] if p not in have]
        if missing and not world.items[name].outside_ranges:
            raise ValueError(
                f"{where}: {name}: {', '.join(missing)} outside every qualitative range of "
                f"the ontology (ontology/ranges.pl); the learner could not tell its value "
                f"(write outside_ranges = true in its table if that is meant)")
