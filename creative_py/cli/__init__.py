"""The ``creative`` command line.

``creative run CASE`` runs a case end to end (demonstration, tool-use learning, tool
creation) and writes a run folder; ``creative repl [RUN]`` opens SWI-Prolog with the
engine (and a run's learned model) loaded; ``creative report RUN`` summarises a run
folder; ``creative make-tool CASE SPEC`` sizes and writes a tool from a qualitative spec.
``creative trial CASE ...`` runs one physical trial in pybullet and prints its result
(JSON with ``--json``); ``creative trial CASE --list`` prints the case's objects,
locations, variants and default pose as JSON; ``creative cases`` lists the cases. The
command is generic: a case is a world folder with a ``case.toml`` manifest
(:mod:`creative_py.case`).

One module per command (or pair of commands): :mod:`.run` (run, resume), :mod:`.sweep`,
:mod:`.trial`, :mod:`.listings` (robots, cases), :mod:`.report`, :mod:`.repl`,
:mod:`.make_tool`; the options they share are checked in :mod:`.options`, and every error
becomes one line through :mod:`.errors`. This module holds the app, its global options
and the ``creative`` script.
"""

from __future__ import annotations

import inspect
import logging
import sys
from typing import Any, Callable, Optional

import typer

from creative_py.cli import listings, make_tool, repl, report, run, sweep, trial
from creative_py.cli.errors import DEBUG as _DEBUG

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="CREATIVE: learn to use tools from one demonstration, and create new ones.")


def _flags_take_no_value() -> None:
    """Show no value type beside a plain flag (``--gui``, ``--help``) in ``--help``:
    typer's rich help panel labels every flag ``<bool>`` although a flag takes no value
    (its plain help, ``get_help_record``, already leaves flags out)."""
    from typer.core import TyperOption

    shown = TyperOption.display_type_rich
    if getattr(shown, "creative_flags", False):
        return

    def display_type_rich(self, ctx):  # type: ignore[no-untyped-def]
        return None if self.is_flag or self.count else shown(self, ctx)

    display_type_rich.creative_flags = True  # type: ignore[attr-defined]
    TyperOption.display_type_rich = display_type_rich  # type: ignore[method-assign]


_flags_take_no_value()


@app.callback()
def main(ctx: typer.Context,
         verbose: bool = typer.Option(False, "--verbose", "-v", help="Log progress."),
         debug: bool = typer.Option(False, "--debug", help="Show the traceback of an "
                                    "error instead of its one-line message.")) -> None:
    """CREATIVE in Python and Prolog (Wicaksono & Sammut, IJECE 2020)."""
    _DEBUG["on"] = debug
    logging.basicConfig(level=logging.INFO if verbose else logging.WARNING,
                        format="%(levelname)s %(name)s: %(message)s")


def _command(fn: Callable[..., Any], name: Optional[str] = None) -> None:
    """Register ``fn`` as a command of :data:`app`, its help its docstring with each
    paragraph on one line: typer's rich help keeps a docstring's line breaks, so
    ``--help`` would break a sentence where the source wraps, not where the terminal
    does."""
    paragraphs = inspect.cleandoc(fn.__doc__ or "").split("\n\n")
    app.command(name, help="\n\n".join(" ".join(p.split()) for p in paragraphs))(fn)


# The commands, in the order ``creative --help`` lists them.
_command(listings.robots)
_command(listings.cases)
_command(trial.trial)
_command(sweep.sweep)
_command(run.run)
_command(report.report)
_command(repl.repl)
_command(make_tool.make_tool_cmd, "make-tool")


def main(args: Optional[list[str]] = None) -> None:
    """The ``creative`` command (``pyproject.toml``'s script): :data:`app`, with a
    wrong command line (an unknown option, ``--seed 1.5``, a missing argument) told in
    one line ``error: ...`` naming the option and the command's ``--help``, exit code
    2, instead of click's usage box."""
    # typer's click (its own copy or click itself): the bases of its BadParameter
    bases = {c.__name__: c for c in typer.BadParameter.__mro__}
    UsageError, ClickException, Abort = (bases["UsageError"], bases["ClickException"],
                                         typer.Abort)

    try:
        code = app(args=args, standalone_mode=False)
    except UsageError as exc:
        if type(exc).__name__ == "NoArgsIsHelpError":  # bare ``creative``: help shown
            sys.exit(exc.exit_code)
        where = f" (see {exc.ctx.command_path} --help)" if exc.ctx else ""
        text = " ".join(exc.format_message().split()).rstrip(".")
        typer.echo(f"error: {text}{where}", err=True)
        sys.exit(2)
    except ClickException as exc:
        typer.echo(f"error: {' '.join(exc.format_message().split())}", err=True)
        sys.exit(exc.exit_code)
    except Abort:
        typer.echo("aborted", err=True)
        sys.exit(1)
    sys.exit(code if isinstance(code, int) else 0)
