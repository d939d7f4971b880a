"""Rockly: program ROS robots by snapping Blockly blocks together."""

__version__ = "0.1.0"
