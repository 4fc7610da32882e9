"""Perception: camera frames (RGB, depth buffer, segmentation) to primitive facts.

Pure numpy and scipy; nothing here imports pybullet (the renderer lives in
:mod:`creative_py.backends.pybullet.camera`).
"""

from creative_py.perception.estimate import EstimatorConfig, ObjectEstimate, estimate_objects
from creative_py.perception.facts import facts_from_estimates
from creative_py.perception.frame import Frame
from creative_py.perception.noise import NoiseModel

__all__ = ["EstimatorConfig", "Frame", "NoiseModel", "ObjectEstimate", "estimate_objects",
           "facts_from_estimates"]
