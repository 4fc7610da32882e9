"""The ROS 2 backend: the learner drives an arm over ROS 2 (optional: ``make setup-ros``).

An arm offers ros2_control's usual interface: ``sensor_msgs/JointState`` on a topic, a
``control_msgs/FollowJointTrajectory`` action server, a ``control_msgs/GripperCommand``
action server, and the tracked objects' poses as ``geometry_msgs/PoseStamped`` (one topic
per object, as a motion-capture system publishes them). The names come from a robot
profile (``robots/<name>.toml``, :mod:`profile`), so a lab remaps them without code.
``docs/real-robot.md`` is the page for a lab.

``profile``     the robot profile (no ROS needed to read it)
``trajectory``  a trajectory's execution and judgement as a joint trajectory
                controller does it: interpolation, path/goal/time tolerances, the
                standard error codes (no ROS needed)
``limits``      the learner's bounds (joint speed, the gripper's workspace box), checked
                before a goal is sent (no ROS needed)
``standin``     the stand-in robot: the pybullet arm of a profile with a case's scene in its own
                process behind that interface (``python -m creative_py.backends.ros.standin
                --profile NAME|PATH``); with ``twin``, the one module here that imports
                the pybullet backend
``client``      the learner's node: subscriptions, trajectory and gripper goals, timed
``motion``      the learner's side of a motion: straight gripper moves through the
                learner's IK (from the robot's URDF, no scene) sent as bounded trajectory
                goals (LearnerArm), each goal's timings logged
``trainer``     who sets each episode's scene up: the scene request and answer
                (std_msgs/String JSON), the stand-in's side (SceneKeeper)
``twin``        the learner's model of the arm and its scene: the pybullet backend's
                world, episode and kinematics, in DIRECT clients whose physics never
                runs (the one learner module that imports the pybullet backend)
``episode``     the backend's episode (RosEpisode): a learner-side pybullet twin of
                the world files whose tracked objects follow the pose topics, the
                hook-like primitives as trajectory and gripper goals (RosRobot), the
                facts and the oracle measured from the topics
``backend``     the ``ros`` backend of the simulator boundary (load_world,
                open_episode, ...: ``creative run CASE --backend ros``; the arm of the
                manifest's robot profile); imports rclpy
``launch``      the stand-in and a ``creative`` command, two processes
                (``make run CASE=hook BACKEND=ros``)
``check``       a read-only check of an arm's interface against a profile
                (``python -m creative_py.backends.ros.check``): it sends nothing

Nothing here but ``backend`` imports ``rclpy`` at import time: a machine without the
``ros`` extra imports this package, reads profiles and runs the pure checks.
"""
