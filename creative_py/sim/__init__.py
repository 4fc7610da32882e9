"""The simulator: a case's world built in pybullet, driven by the manifest's skills.

Public API::

    from creative_py.sim import load_world, open_episode, run_trial
    world = load_world(manifest)                # World
    with open_episode(world, variant, location, tool) as ep:
        ep.run_skill("pick_up")                 # SkillOutcome
"""

from creative_py.sim.episode import Episode, PoseTarget, open_episode, run_trial
from creative_py.sim.types import (SKILL_STATUSES, TRIAL_OUTCOMES, Fact, Observation,
                                   SkillOutcome, TrialResult)
from creative_py.sim.world import World, load_world

__all__ = ["Episode", "Fact", "Observation", "PoseTarget", "SKILL_STATUSES", "SkillOutcome",
           "TRIAL_OUTCOMES", "TrialResult", "World", "load_world", "open_episode", "run_trial"]
