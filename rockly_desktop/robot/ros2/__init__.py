"""The ROS 2 backend: the only part of Rockly that talks to ROS 2.

ROS 2 runs in its own process (``node``, started with ``.venv-ros2``'s Python, which has
rclpy from pinned wheels), because Debian's ROS 1 packages own the same module names.
Rockly's side (``client``, ``backend``, ``link``) talks to it over pipes (``wire``).
Only ``node`` and the modules it imports (``ros_values``, ``qos``, ``graph_ops``) import rclpy.
"""
