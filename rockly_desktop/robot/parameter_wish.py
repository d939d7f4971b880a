"""``ParameterWish``: what the ROS 1 and ROS 2 state feeds share about the robot's parameter names. Asking
every node (or the master) for them costs the robot, so a feed lists them only while someone wishes them
(the block maker while it is open)."""
import threading


class ParameterWish:
    """A feed's wish for the parameter names: its poll asks only while ``wanted`` is set and keeps the
    answer in ``names`` unless the wish was taken back meanwhile."""

    def __init__(self):
        self.wanted = threading.Event()
        self.names = []

    def want(self, wanted: bool):
        """Ask from now on (``wanted``), or no more, forgetting the names."""
        if wanted:
            self.wanted.set()
        else:
            self.wanted.clear()
            self.names = []

    def keep(self, names: list):
        """The names a poll was told, kept if they are still wished."""
        if self.wanted.is_set():
            self.names = names
