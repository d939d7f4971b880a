"""The ROS versions and ROS 2 distributions a profile may name in ``ros_versions``.

The manifest's validation and the robot's resolution (``robot/wrappers/ros_versions.py``) both read them.
"""

DISTRIBUTIONS = ("humble", "iron", "jazzy", "kilted", "rolling")  # oldest first
VERSIONS = ("ros1", "ros2")
KEYS = VERSIONS + DISTRIBUTIONS
