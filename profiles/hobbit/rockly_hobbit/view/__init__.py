"""The simulated HOBBIT, drawn: a room seen from above with the robot in it, and a panel
with HOBBIT's eyes, battery, tablet and the latest notices.

The view knows nothing about the simulator; it draws whatever snapshot dict it is given
(the dict ``SimHobbit.snapshot()`` returns)::

    view = HobbitSimView(language="de")
    view.set_snapshot(sim.snapshot())

It eases its drawing toward the latest snapshot at about 60 Hz, so a drive looks fluid even
when snapshots arrive less often. ``set_animation_enabled(False)`` draws every snapshot
exactly as given, without blinking or floating "z z" (for tests and screenshots).

Map frame: metres, x to the right, y up, theta counter-clockwise from +x. The room spans
x -1..5 and y -2.5..2.5; the visible area grows when the robot or its goal leaves it.

Modules: widget (the QWidget), snapshot (defaults, tolerant reading), animation (easing),
geometry (metres), layout (pixels), scene (one paint's inputs), map_painter, room, furniture,
robot, panel (with details and notices), eyes, tablet, texts, palette, drawing (its own painting
helpers).
"""
from .palette import BASE_COLOR, BUMPER, PANEL_BG, SOS
from .snapshot import DEFAULT_SNAPSHOT, EMOTIONS
from .widget import HobbitSimView

__all__ = ["HobbitSimView", "DEFAULT_SNAPSHOT", "EMOTIONS", "PANEL_BG", "BASE_COLOR", "BUMPER", "SOS"]
