"""How fast HOBBIT's base moves on its own: its driver's discrete motions (``Move``, ``Turn``) and
``move_base``'s goals.

The simulator drives at these speeds, and the commands compare a teacher's limit with them: a
limit below them is kept by driving with ``/cmd_vel`` instead (navigation is refused). A base
configured faster than this must say so here, or a limit between the two speeds would not hold.
"""
import math

MOVE_SPEED = 0.3                  # m/s
TURN_SPEED = math.radians(45)     # rad/s
