"""Where a benchmark writes its figures: never over a tracked file unless asked.

``bench/results/`` is tracked: docs/results.md and the README are written from it
(``bench/readme_figures.py``). A benchmark run by hand, to try something, must not
overwrite it. Every benchmark therefore takes the same two options
(:func:`add_output_options`): ``--out FILE`` writes its figures there, ``--record``
writes them to its tracked file in ``bench/results/`` (what ``make bench``,
``bench/run_all.py`` and the Makefile's bench targets ask for); with neither it writes
nothing and says so (:func:`output_path`, :func:`write_figures`).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path
from typing import Any, Optional

RESULTS = Path(__file__).resolve().parent / "results"
"""The tracked results folder (``bench/results/``)."""


def add_output_options(parser: argparse.ArgumentParser, tracked: str,
                       what: str = "the figures (JSON)") -> None:
    """Add ``--out FILE`` and ``--record`` to a benchmark's parser; ``tracked`` is the
    name of its file in ``bench/results/``, ``what`` what is written there."""
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--out", type=Path, default=None, metavar="FILE",
                       help=f"write {what} to FILE (default: write nothing, "
                            "only print)")
    group.add_argument("--record", action="store_true",
                       help=f"write {what} to the tracked bench/results/{tracked}, "
                            "which docs/results.md is made from")


def output_path(args: argparse.Namespace, tracked: str) -> Optional[Path]:
    """Return where the figures go: ``--out``, the tracked ``bench/results/<tracked>``
    under ``--record``, else None (nothing is written)."""
    if getattr(args, "out", None) is not None:
        return Path(args.out)
    return RESULTS / tracked if getattr(args, "record", False) else None


def write_figures(args: argparse.Namespace, tracked: str, figures: Any,
                  indent: int = 1, **dump: Any) -> Optional[Path]:
    """Write ``figures`` as JSON where :func:`output_path` says and print one line
    saying where (or that nothing was written, and how to write it); return the path."""
    path = output_path(args, tracked)
    if path is None:
        print(f"figures not written (give --out FILE, or --record to update the tracked "
              f"bench/results/{tracked})", flush=True)
        return None
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(figures, indent=indent, **dump) + "\n", encoding="utf-8")
    print(f"figures written to {path}", flush=True)
    return path
