"""A prior for tool-use learning: another case's learned model (transfer, ``--prior``).

The prior is a run folder or its ``model.pl``. Prolog decides what it says about this
case (``prolog/transfer.pl``): the literals of the prior's h_g whose predicate both
cases' ontologies declare with the same meaning and roles. The version space takes
them as open predictions, trusted only as far as the trials confirm them
(``version_space:vs_init_prior/3``): a success settles a spatial one it satisfies, a
success that violates one drops it, a failure is learned from as without a prior
(``vs_prior_events/2``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from creative_py.bridge import Engine
from creative_py.bridge.errors import BridgeError, PrologError, reader_words
from creative_py.bridge.text import PrologTextError


class PriorError(ValueError):
    """A ``--prior`` that cannot be used: one line naming the option and the cause."""


@dataclass(frozen=True)
class Prior:
    """A prior loaded for a case."""

    source: Path
    """The model file read."""
    case: str
    """The prior's case."""
    term: Any
    """``prior(Case, HS, HG)`` as Prolog read it."""
    shared: tuple[str, ...]
    """The prior's h_g literals the ontology maps to the new case, as text."""


def model_file_of(path: Path) -> Path:
    """Return the ``model.pl`` of a run folder, or ``path`` itself for a file."""
    return path / "model.pl" if path.is_dir() else path


def load_prior(engine: Engine, case: str, path: str | Path) -> Prior:
    """Read the prior at ``path`` for ``case``; raise :class:`PriorError` when it is no
    learned model or when the ontology maps none of its literals to ``case``."""
    given = Path(path)
    where = f"--prior {given}"
    model = model_file_of(given)
    if not model.is_file():
        why = ("the run folder has no model.pl" if given.is_dir()
               else "no such run folder or model file")
        raise PriorError(f"{where}: {why}")
    try:
        term = engine.read_prior(model.resolve())
    except PrologTextError as exc:  # too large, not UTF-8, nested too deep
        raise PriorError(f"{where}: {exc}") from None
    except PrologError as exc:
        why = reader_words(exc)
        if why is None:
            first = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
            raise PriorError(f"{where}: not a learned model file ({first})") from None
        raise PriorError(f"{where}: {model.resolve()}: {why}") from None
    except OSError as exc:
        raise PriorError(f"{where}: {exc.strerror or exc}") from None
    prior_case = str(term.args[0])
    try:
        shared = engine.prior_shared(case, term)
    except BridgeError:
        raise PriorError(f"{where}: its case {prior_case!r} is not in the loaded "
                         "ontology") from None
    if not shared:
        raise PriorError(f"{where}: the ontology maps no learned literal of case "
                         f"{prior_case!r} to case {case!r} (no shared tool kind or "
                         "spatial definition): nothing to transfer")
    return Prior(model, prior_case, term, tuple(str(s) for s in shared))
