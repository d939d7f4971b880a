"""The simulated TurtleBot, drawn: its room seen from above with the boxes, the robot, its trail and
what its laser sees, and a panel with a radar of the scan, the speeds and the battery.

The view knows nothing about the simulator; it draws whatever snapshot dict it is given (the
dict ``SimTurtleBot.snapshot()`` returns), tolerating missing or odd values::

    view = TurtleBotSimView(language="de")
    view.set_snapshot(sim.snapshot())

The Simulator dock gives it a new snapshot 30 times a second; each one is drawn as it is.
Map frame: metres, x to the right, y up, theta counter-clockwise from +x.

Modules: widget (the QWidget), model (reading a snapshot without trusting it), palette, texts,
layout (pixels for a size), room (floor, walls and boxes, cached), scan (the laser's rays),
robot (the TurtleBot and its trail), panel (radar, speed, battery). Pens, cards, chips, fonts and
numbers come from the SDK (``rockly_desktop.sdk_view``).
"""
from .model import DEFAULT_SNAPSHOT
from .palette import PANEL_BG, PLATE
from .widget import TurtleBotSimView

__all__ = ["TurtleBotSimView", "DEFAULT_SNAPSHOT", "PANEL_BG", "PLATE"]
