"""The experiment strategies of tool-use learning (``--strategy``), as values.

A strategy is two things: a clause group in Prolog that chooses the experiment
(``experiment:strategy_experiment/3``, declared by ``experiment:experiment_strategy/1``;
``prolog/strategy.pl`` has the shipped ones), and an entry of :data:`STRATEGIES` here
that tells the learning loop (:meth:`ToolUseLearner.learn
<creative_py.learning.tool_use.ToolUseLearner.learn>`) what to send to Prolog, when to
stop and which experiments not to run again. Adding a strategy is one clause group and
one entry; every option check (``RunOptions``, ``creative run --strategy``,
``creative sweep --strategies``) reads this registry.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from creative_py.bridge.terms import Compound, Term


@dataclass(frozen=True)
class Strategy:
    """One experiment strategy: what Prolog is asked, and the loop's rules for it.

    Parameters
    ----------
    name : str
        The ``--strategy`` value and the functor of the term sent to Prolog.
    summary : str
        One line for ``--help``.
    stop : str
        ``use.stop`` when Prolog proposes no experiment (nothing left to test) and the
        loop stops: ``certified``, ``exhausted``, ``confirmed``.
    confirm : bool
        Stop only once the last K trials also succeeded (Algorithm 1); until then the
        robot uses the learned model. Without it the loop stops at once, with no
        confirmation trials (evaluation confirms the model afterwards).
    repeat_taught : bool
        Run again an experiment whose trial taught something (Algorithm 1 repeats the
        task after a failure), unless it left h_s and h_g as they were. Without it an
        experiment once run is not proposed again (the physics would answer the same).
    pose_any_tool : bool
        A pose test once run is not proposed again with another tool either (what it
        shows of the pose it has shown). A pose the arm could not carry out is never
        proposed again, whatever the tool.
    seeded : bool
        The term sent is ``name(Seed)`` with Seed = run seed x 1000 + trial number (the
        same run draws the same experiments, also when resumed); else the atom ``name``.
    catalogue_first : bool
        Tool creation tries the catalogued objects that the generalised model admits
        before it makes a tool (``RunOptions.catalogue_first`` left unset follows
        this); the paper's Algorithm 2 makes one at once.
    """

    name: str
    summary: str
    stop: str
    confirm: bool = False
    repeat_taught: bool = False
    pose_any_tool: bool = False
    seeded: bool = False
    catalogue_first: bool = True

    def term(self, seed: int, trial: int) -> Term:
        """Return the strategy term of ``next_experiment``'s ``strategy(S)`` option for
        trial number ``trial`` of a run with seed ``seed``."""
        return Compound(self.name, (seed * 1000 + trial,)) if self.seeded else self.name

    def skip(self, experiment: Compound, taught: bool, idle: bool) -> Optional[Term]:
        """Return ``skip(Object, Literal)`` for an experiment just run that must not be
        proposed again (``skip(any, Literal)``: with no tool), or None.

        ``taught``: the trial's outcome labelled the version space (success, failure,
        blocked); ``idle``: it left h_s and h_g as they were.
        """
        if taught and self.repeat_taught and not idle:
            return None
        tool, tested, negated = experiment.args[0], experiment.args[1], experiment.args[5]
        pose_test = bool(negated)
        any_tool = pose_test and (not taught or self.pose_any_tool)
        return Compound("skip", ("any" if any_tool else tool, tested))


STRATEGIES: dict[str, Strategy] = {
    "paper": Strategy(
        "paper", "Algorithm 1: one literal per trial, K successes to stop",
        stop="confirmed", confirm=True, repeat_taught=True, catalogue_first=False),
    "informative": Strategy(
        "informative", "largest expected reduction of the version space, certified stop",
        stop="certified", pose_any_tool=True),
    "random": Strategy(
        "random", "a seeded draw among the experiments h_g covers", stop="exhausted",
        seeded=True),
}
"""The strategies by name, in the order the help lists them (``prolog/strategy.pl`` has
their clause groups)."""


class UnknownStrategy(ValueError):
    """A strategy name that :data:`STRATEGIES` does not hold."""

    def __init__(self, name: object) -> None:
        self.name = name
        super().__init__(f"unknown strategy {name!r}; strategies: {', '.join(STRATEGIES)}")


def strategy_named(name: object) -> Strategy:
    """Return the registered strategy ``name``; raise :class:`UnknownStrategy` if none."""
    found = STRATEGIES.get(name) if isinstance(name, str) else None
    if found is None:
        raise UnknownStrategy(name)
    return found


def strategies_help() -> str:
    """Return the strategies with their summaries, for ``--help``."""
    return "; ".join(f"{s.name} ({s.summary})" for s in STRATEGIES.values())
