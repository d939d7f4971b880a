"""How fast HOBBIT's base moves on its own: its driver's discrete motions (``Move``, ``Turn``) and
``move_base``'s goals.

The simulator drives at these speeds, and the commands compare a teacher's limit with them: a
limit below them is kept by driving with ``/cmd_vel`` instead (navigation is refused). A base
configured faster than this must say so here, or a limit between the two speeds would not hold;
the manifest's ``own_speed`` says the same speeds, for the teacher's limits to refuse these motions
from any block (``Move 2`` published by hand, a move_base goal) while a limit is lower.
"""
import math

MOVE_SPEED = 0.3                  # m/s
TURN_SPEED = math.radians(45)     # rad/s
