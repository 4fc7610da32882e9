"""``creative repl``: SWI-Prolog with the engine loaded (and a run's learned model)."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Optional

import typer

from creative_py.cli.errors import fail


def repl(run_dir: Optional[Path] = typer.Argument(None, help="A run folder whose model.pl "
                                                   "is loaded.")) -> None:
    """Open SWI-Prolog with the engine loaded (and a run's learned model)."""
    import shutil

    root = Path(__file__).resolve().parents[2]
    goals = []
    if run_dir is not None:
        model = Path(run_dir) / "model.pl"
        if not model.exists():
            fail(f"{model}: no such file (is {run_dir} a run folder?)")
        goals.append(f"load_model_file({_quoted(str(model.resolve()))})")
    banner = ("CREATIVE-py engine loaded. Try:\n"
              "  ?- learned_model(Task, Action, Pre, Eff).\n"
              "  ?- learned_hypothesis(Task, hg, Clause).\n"
              "  ?- term_lgg(f(a, g(a)), f(b, g(b)), G).\n"
              "  ?- replacement(handle_length(T, medium), G, Alternatives).\n"
              "  ?- case_info(Case, Info).\n")
    goals.append(f"format({_quoted(banner)})")
    swipl = shutil.which("swipl")
    if swipl is None:
        fail("swipl is not installed (make setup installs it)")
    # Options must precede the file: swipl passes what follows it to the program.
    os.execv(swipl, [swipl, "-g", ", ".join(goals), str(root / "prolog" / "creative.pl")])


def _quoted(text: str) -> str:
    """Return ``text`` as a quoted Prolog atom (the bridge's encoder)."""
    from creative_py.bridge import encode

    return encode(text)
