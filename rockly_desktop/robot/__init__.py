"""The backend-neutral robot interface a profile's commands are written against, and its backends.

The top of this package is the seam every backend meets: what a backend offers (interface), what a
robot link offers (link) and the registry of links (links), what the links share (link_parts), the
profile's safe stop (safe_stop), a link's health (health), interruptible waits (interrupt), what
the ROS backends and state feeds share (next_message, followed_topics), and what programs hold: the
base of a profile's commands (commands), the generic ``ros`` commands (ros_commands), what a laser
sees "ahead" (laser) and the base of a profile's way to offer the agent's programs on the robot's own UI
(program_menu). Its wings:

* ``sim``: the built-in simulator, run without any ROS;
* ``wrappers``: the backends wrapped around a run's (a teacher's limits, ROS versions, recording);
* ``ros1``, ``ros2``: the links to real robots, reached only through the registry.
"""
