"""Choosing and reaching a robot: the robot choice, the connection dialog, the health light."""
