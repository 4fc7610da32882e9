"""A robot profile's ROS 2 interface: the names of an arm's topics and actions.

A profile (``robots/<name>.toml``, read by :mod:`creative_py.robots`, the one reader of
robot profiles) says, besides the arm's model and kinematics, which topics and action
servers the arm offers, the joints and frames, the controller's default tolerances and
the bounds the learner keeps to. A lab remaps its arm by writing a profile, without
code. Reading it needs no ROS installation.
"""

from __future__ import annotations

from pathlib import Path

from creative_py.robots import ROBOTS_ROOT, RobotProfile
from creative_py.robots import load_profile as _load_profile
from creative_py.world_files import WorldFileError

__all__ = ["ROBOTS_ROOT", "RobotProfile", "load_profile"]


def load_profile(spec: str | Path) -> RobotProfile:
    """Return the profile ``spec`` (a shipped profile's name or a path) with its ROS 2
    interface.

    Raises
    ------
    WorldFileError
        The file is missing, a field is missing, mistyped, out of bounds or unknown, or
        the profile has no ROS 2 interface tables (one line naming the file and the
        field).
    """
    profile = _load_profile(spec)
    if not profile.has_ros:
        raise WorldFileError(f"{profile.source}: field 'arm': missing: the profile has no "
                             "ROS 2 interface tables ([frames], [joint_states], [arm], "
                             "[gripper], [objects], [limits]; docs/real-robot.md)")
    return profile
