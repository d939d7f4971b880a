"""The built-in simulator: a profile's simulated robot, run without any ROS.

The in-process ROS-like graph a simulator plugs into and the backend a program drives it with
(sim_world), the simulators' base class (simulator), their solid worlds as data (world_map), reading
a snapshot in a view (snapshot_values), the tablet's question kinds (tablet) and the ``--answer``
list that answers them on the command line (answer_list), the simulator as a robot link (link) and
how a simulator served on ROS 1 or ROS 2 ends (served_simulator). It names no middleware: the ROS
links (``robot/ros1``, ``robot/ros2``) serve it on ROS, not the other way round.
"""
