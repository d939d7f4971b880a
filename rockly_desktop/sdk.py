"""The public SDK for robot profiles: the only Rockly module profile code imports.

A profile's commands subclass ``RobotCommands`` and talk to the robot through the
``RobotBackend`` they are given (topics, services and actions by ROS names).
"""
from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.core.state_store import field_value
from rockly_desktop.robot.commands import RobotCommands
from rockly_desktop.robot.interface import GoalHandle, GoalOutcome, GoalStatus, RobotBackend

__all__ = [
    "GoalHandle", "GoalOutcome", "GoalStatus", "RobotBackend", "RobotCommandError",
    "RobotCommands", "RobotTimeout", "field_value",
]
