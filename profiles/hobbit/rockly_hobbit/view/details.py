"""The details card: what the arm, gripper, head and turntable do, in words people use.

A row is "label  value" on one line when both fit, else the label with the value wrapped and
indented on the lines below it: a value is never cut off (the layout asks ``details_height`` for the room).
"""
from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QColor, QFontMetricsF

from rockly_desktop.sdk_view import card, wrap_lines

from .palette import ARM, INK, INK_SOFT
from .snapshot import num

LEFT = Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignLeft
RIGHT = Qt.AlignmentFlag.AlignVCenter | Qt.AlignmentFlag.AlignRight


def _named(names, value, default):
    """``value``'s name for people, or the value itself when the view has no name for it."""
    value = str(value or default)
    return names.get(value, value)


def detail_rows(scene):
    """(label, value, progress or None) for the arm, gripper, head and turntable."""
    snap, texts = scene.snapshot, scene.texts
    arm = _named(texts["arm_poses"], snap.get("arm"), "home")
    target = snap.get("arm_target")
    progress = num(snap.get("arm_progress"), 0.0, 0.0, 1.0) if target else None
    arm_text = f"{arm} → {_named(texts['arm_poses'], target, 'home')}" if target else arm
    turntable = (f"{texts['out']} {num(snap.get('turntable_angle')):.0f}°" if snap.get("turntable") == "out"
                 else texts["stored"])
    return [(texts["arm"], arm_text, progress),
            (texts["gripper"], texts["open"] if snap.get("gripper") == "open" else texts["closed"], None),
            (texts["head"], _named(texts["heads"], snap.get("head"), "center_center"), None),
            (texts["turntable"], turntable, None)]


def _fonts(scene, u):
    return scene.font(12 * u), scene.font(12 * u, True)


def _padding(u):
    return max(5.0, 7.0 * u)


def detail_lines(scene, width, u):
    """[(label, value lines, progress)]: one value line beside the label when both fit in ``width``
    pixels of card, else the value's lines (wrapped, never cut) under the label."""
    font, bold = _fonts(scene, u)
    fm, fm_bold = QFontMetricsF(font), QFontMetricsF(bold)
    inner = width - 2 * _padding(u)
    rows = detail_rows(scene)
    label_w = max(fm.horizontalAdvance(label) for label, _value, _progress in rows) + _padding(u)
    lines = []
    for label, value, progress in rows:
        if label_w + fm_bold.horizontalAdvance(value) <= inner:
            lines.append((label, [value], progress))
        else:
            lines.append((label, [""] + wrap_lines(value, bold, inner - _padding(u)), progress))
    return lines


def details_height(scene, width, u):
    """How tall the card must be to show every row whole at ``width`` pixels."""
    count = sum(len(values) for _label, values, _progress in detail_lines(scene, width, u))
    return count * QFontMetricsF(_fonts(scene, u)[0]).lineSpacing() + 2 * _padding(u) + 4


def paint_details(p, scene, rect, u):
    """The card; a bar under the arm's row shows a moving arm's progress."""
    card(p, rect, max(8.0, 10.0 * u))
    font, bold = _fonts(scene, u)
    fm = QFontMetricsF(font)
    pad = _padding(u)
    y = rect.top() + pad
    for label, values, progress in detail_lines(scene, rect.width(), u):
        line = QRectF(rect.left() + pad, y, rect.width() - 2 * pad, fm.height())
        p.setFont(font)
        p.setPen(INK_SOFT)
        p.drawText(line, LEFT, label)
        p.setFont(bold)
        p.setPen(INK)
        if len(values) == 1:
            p.drawText(line, RIGHT, values[0])
        for index, value in enumerate(values[1:], 1):   # wrapped under the label, indented
            p.drawText(line.adjusted(pad, index * fm.lineSpacing(), 0, index * fm.lineSpacing()), LEFT, value)
        if progress is not None:
            _paint_progress(p, line.translated(0, (len(values) - 1) * fm.lineSpacing()), progress)
        y += len(values) * fm.lineSpacing()


def _paint_progress(p, line, progress):
    bar = QRectF(line.left() + line.width() * 0.45, line.bottom() - 1, line.width() * 0.55, 3)
    p.setPen(Qt.PenStyle.NoPen)
    p.setBrush(QColor("#E3E6F3"))
    p.drawRoundedRect(bar, 1.5, 1.5)
    bar.setWidth(bar.width() * progress)
    p.setBrush(ARM)
    p.drawRoundedRect(bar, 1.5, 1.5)
