"""ROS 2: the agent as a process next to the robot's bringup (docs/agent.md). ``ros2 launch rockly_agent.launch.py``;
on shutdown launch sends SIGINT, and the agent stops a running program with the robot's safe stop first."""
import os

from launch import LaunchDescription
from launch.actions import ExecuteProcess


def generate_launch_description():
    agent = os.path.expanduser("~/rockly/bin/rockly-agent")  # in the venv the runtime is installed in
    return LaunchDescription([
        ExecuteProcess(
            cmd=[agent, "--backend", "ros2", "--library", os.path.expanduser("~/rockly-programs")],
            additional_env={"ROCKLY_ROS2_PYTHON": "/usr/bin/python3"},
            output="screen", respawn=True, respawn_delay=2.0, sigterm_timeout="30"),
    ])
