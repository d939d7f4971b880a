"""The ROS 2 backend: the only part of Rockly that talks to ROS 2, in two processes.

ROS 2 runs in a helper process of its own (the ``helper`` package: ``helper.node``, started with
``.venv-ros2``'s Python, which has rclpy from pinned wheels), because Debian's ROS 1 packages own
the same module names. Rockly's side, the modules here (``link``, ``client``, ``backend``,
``state_feed``, ``environment``, ``sim_bridge``, ``recording_codec``, ``cdr_encoding``), talks to
it over pipes (``wire``, the one module both sides import). Only ``helper`` imports rclpy, and
Rockly's side never imports ``helper`` (contracts in pyproject.toml).
"""
