"""The simulator's value types, now the boundary's: :mod:`creative_py.simulator.types`.

Re-exported here so that the pybullet backend's modules and older imports
(``from creative_py.sim.types import Verdict``) keep working; new code imports them
from :mod:`creative_py.simulator`.
"""

from creative_py.simulator.types import (SKILL_STATUSES, TRIAL_OUTCOMES, Fact, Observation,
                                         PoseTarget, SkillOutcome, SkillStatus, TrialOutcome,
                                         TrialResult, Verdict)

__all__ = ["Fact", "Observation", "PoseTarget", "SKILL_STATUSES", "SkillOutcome",
           "SkillStatus", "TRIAL_OUTCOMES", "TrialOutcome", "TrialResult", "Verdict"]
