"""The learner's model of the arm and its scene: the pybullet backend's, without its physics.

An arm over ROS 2 tells the learner its joint states and the tracked objects' poses,
nothing else. What the learner computes from them it computes on a model of the world
(read by :mod:`creative_py.world`, as for every backend) and of the robot's URDF, and
that model is the pybullet backend's, in DIRECT clients of the learner's own process
whose physics never runs:

* :data:`TwinEpisode`: the pybullet backend's episode of the world, which
  :class:`~creative_py.backends.ros.episode.RosEpisode` extends: its tracked bodies
  follow the pose topics, its arm the joint states; the pybullet backend's primitives
  and perception and the world's oracle then run unchanged on what the topics gave;
* :func:`kinematics_arm`, :func:`kinematics_model`, :func:`base_pose`: the robot's
  kinematics from the profile's URDF (IK, forward kinematics), the base where a world
  places it;
* :func:`set_frame_pose`, :func:`local_extents`: a twin body moved to a topic's pose,
  an object's box in its own frame;
* :func:`tool_rests`: whether a tool rests where a (drawn) world puts it, as the world
  files' physics says.

This module is the one place of the learner's side that imports the pybullet backend
(the stand-in's is :mod:`.standin`, which serves a pybullet scene behind the arm's
interface): docs/architecture.md section 3 states the rule, and
``tests/python/architecture/test_layers.py`` holds every other module of this package to
its row. Nothing here reads a world file or a profile: the readers are
:mod:`creative_py.world` and :mod:`creative_py.robots`.
"""

from __future__ import annotations

from typing import Any

from creative_py.backends.pybullet import tool_rests
from creative_py.backends.pybullet.arm import Arm, base_pose, kinematics_model
from creative_py.backends.pybullet.bodies import local_extents, set_frame_pose
from creative_py.backends.pybullet.core import Sim
from creative_py.backends.pybullet.episode import Episode as TwinEpisode
from creative_py.world_files import PhysicsSettings

__all__ = ["TwinEpisode", "base_pose", "kinematics_arm", "kinematics_model", "local_extents",
           "set_frame_pose", "tool_rests"]


def kinematics_arm(profile: Any, base: Any = None) -> tuple[Any, Any]:
    """Return ``(sim, arm)``: the profile's arm alone in a DIRECT client of its own (no
    scene), its base at ``base`` (position, quaternion; None: the profile's
    ``[base]``), for IK and forward kinematics. Close the arm, then the sim."""
    sim = Sim(PhysicsSettings(1 / 240, 50, (0.0, 0.0, -9.81)))
    try:
        return sim, Arm(sim, profile, base=base)
    except BaseException:
        sim.close()
        raise
