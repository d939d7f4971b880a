"""The backends wrapped around a run's backend: what changes a program's commands on their way to the robot.

``run_setup`` wraps whatever backend a run has (the simulator's, ROS 1's, ROS 2's) in these, each
a ``WrappedBackend`` (wrapped_backend: every call passes through but what a wrapper changes): a
teacher's limits (limits; what a drive message must be for a speed limit to hold on it:
velocity_messages; every name a switched-off part is reached by: capability_coverage; motions at
the robot's own speed: own_speed), the types that differ per ROS version, sent as the robot wants
them (ros_versions), and what a recording notes (recorded). A wrapper works on any RobotBackend:
it names no simulator, no ROS link and no registry.
"""
