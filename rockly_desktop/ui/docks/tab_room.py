"""Docks that share a side of the window as tabs get the room to show their titles whole ("Lessons", not "Less…").

Qt's main window elides the titles of tabified docks when their area is narrower than the tabs: four docks
in a 330 px side area showed "Python co… Variab… Robot st… Less…". ``give_tabs_room(docks, screen_width)``
makes every dock of one tab group at least as wide as the group's tabs need for their whole titles (as they
are now: a replayed dock's title is longer), as far as the screen leaves room beside BLOCKS_ROOM for the
rest of the window (the blocks, the bottom tabs under them); on a small screen Qt elides again, and the
window still fits. The bottom area is as wide as the blocks: its tabs have room.
"""
from PySide6.QtWidgets import QTabBar

BLOCKS_ROOM = 860  # px of the screen's width the rest of the window keeps (at 1280 px, 420 are left for tabs)


def tabs_width(titles) -> int:
    """The width (px) a dock tab bar in the window's style needs for ``titles`` whole, side by side."""
    probe = QTabBar()
    for title in titles:
        probe.addTab(title)
    return sum(probe.tabSizeHint(index).width() for index in range(probe.count()))


def give_tabs_room(docks, screen_width: int):
    """Make each of ``docks`` (one tab group at a side) at least as wide as the tabs of their titles need, as
    far as ``screen_width`` leaves room beside BLOCKS_ROOM (none: the docks' own minimum)."""
    width = max(0, min(tabs_width([dock.windowTitle() for dock in docks]), screen_width - BLOCKS_ROOM))
    for dock in docks:
        dock.setMinimumWidth(width)
