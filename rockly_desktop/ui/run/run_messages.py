"""The box a run's error opens, in words a child can read.

A robot's own refusal (a bump, a part the teacher switched off, a goal it could not reach) is what
the robot says: its name in the title, its words and where to look, no "Something went wrong" and
no traceback, for nothing in Rockly or the program broke. Any other error (in the Python the person
wrote, or in Rockly itself) keeps its traceback behind Show Details, except in a kiosk, where a
visitor sees no tracebacks at all. The box stands beside the block the error came from, not over it.
"""
from PySide6.QtCore import QPoint, QRect
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import tr


def run_problem_box(parent, result, robot_name: str, language: str, kiosk: bool = False) -> QMessageBox:
    """A (not yet shown) box for the error ``result`` (an ``executor.events.RunFinished``) of a run on
    the robot called ``robot_name``; ``kiosk``: show no traceback."""
    if result.by_robot:
        text = result.message
        if result.block_id is not None:
            text += "\n\n" + tr("robot_refused_block", language, robot=robot_name)
        box = plain_message_box(parent, QMessageBox.Icon.Information,
                                tr("robot_refused_title", language, robot=robot_name), text)
    else:
        box = plain_message_box(parent, QMessageBox.Icon.Warning, tr("error_title", language), result.message)
        if result.details and not kiosk:
            box.setDetailedText(result.details)
    box.setObjectName("run_error_box")
    return box


GAP = 16  # pixels between a block and the box beside it


def place_beside(box: QMessageBox, block: QRect, area: QRect) -> bool:
    """Move the shown ``box`` beside ``block`` (global pixels) inside ``area`` (the window's frame): to its right,
    left, below or above, the first side with room. False (the box stays) when no side has room."""
    size = box.frameGeometry().size()
    width, height = size.width(), size.height()
    top = min(max(block.top(), area.top()), area.bottom() - height + 1)  # level with the block, inside the area
    left = min(max(block.left(), area.left()), area.right() - width + 1)
    for corner in (QPoint(block.right() + GAP, top), QPoint(block.left() - GAP - width, top),
                   QPoint(left, block.bottom() + GAP), QPoint(left, block.top() - GAP - height)):
        place = QRect(corner, size)
        if area.contains(place) and not place.intersects(block):
            box.move(box.pos() + corner - box.frameGeometry().topLeft())
            return True
    return False
