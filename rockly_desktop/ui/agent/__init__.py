"""The window's side of the agent on the robot: its programs, and attaching to the run there."""
