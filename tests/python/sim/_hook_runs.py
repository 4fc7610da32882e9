"""Hook trials shared by several test files, each run once per test session."""

from __future__ import annotations

from functools import lru_cache

from creative_py.sim.trial import TrialResult, load_case_world, run_trial


@lru_cache(maxsize=None)
def hook_world():
    """Return the shipped hook world."""
    return load_case_world("hook")


@lru_cache(maxsize=None)
def hook_trial(tool: str, variant: str, location: int,
               pose: tuple[float, float, float] | None = None, seed: int = 0) -> TrialResult:
    """Return the result of one hook trial (cached: trials are deterministic)."""
    return run_trial("hook", hook_world(), tool, variant, location, pose=pose, seed=seed)
