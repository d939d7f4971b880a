"""Accessible names for the main window's controls, from the catalogue, in the window's language.

Qt's accessibility tree (what a screen reader reads) names a button by its text but a slider, a
table or the block editor by nothing at all. Every control that takes the keyboard gets a name here:
its own text, what it is for (the run toolbar's speed and Run-on), or its panel's title and its kind.
Names given here carry the ``rockly_named`` property so that a language switch renames them; a name
set elsewhere stays.
"""
from PySide6.QtWidgets import (
    QAbstractButton,
    QAbstractItemView,
    QAbstractSlider,
    QAbstractSpinBox,
    QComboBox,
    QDockWidget,
    QLineEdit,
    QPlainTextEdit,
    QTabBar,
    QTextEdit,
    QToolBar,
    QWidget,
)

from rockly_desktop.ui.texts import tr

_KINDS = ((QTabBar, "a11y_tabs"), (QAbstractItemView, "a11y_table"), (QLineEdit, "a11y_text_field"),
          (QPlainTextEdit, "a11y_text"), (QTextEdit, "a11y_text"), (QComboBox, "a11y_choice"),
          (QAbstractSlider, "a11y_slider"), (QAbstractSpinBox, "a11y_number"))


def name_controls(window, language: str, editor, run_toolbar):
    """Name every control of ``window`` (a QMainWindow) that takes the keyboard and has no name of its
    own; the block ``editor`` and ``run_toolbar``'s speed and Run-on say what they are for."""
    editor_name = tr("a11y_block_editor", language)
    special = {editor: editor_name, editor.focusProxy(): editor_name,
               run_toolbar.speed: tr("speed", language),
               run_toolbar.backend: tr("run_on", language).rstrip(": ")}
    for widget in window.findChildren(QWidget):
        if not (widget.focusPolicy() or widget in special or isinstance(widget, QAbstractButton)
                or isinstance(widget.parentWidget(), QDockWidget)):
            continue
        if widget.accessibleName() and not widget.property("rockly_named"):
            continue
        name = special.get(widget) or _name(widget, window, language)
        if name:
            widget.setAccessibleName(name)
            widget.setProperty("rockly_named", True)


def _name(widget, window, language: str) -> str:
    if isinstance(widget, QAbstractButton):
        action = getattr(widget, "defaultAction", lambda: None)()
        text = action.text() if action is not None else widget.text()
        if text:
            return text.replace("&&", "\0").replace("&", "").replace("\0", "&")
    if isinstance(widget, QLineEdit) and widget.placeholderText():
        return widget.placeholderText()
    kind = next((tr(key, language) for cls, key in _KINDS if isinstance(widget, cls)), "")
    if isinstance(widget, QTabBar) and widget.parentWidget() is window:
        return tr("a11y_panel_tabs", language)
    place = _place(widget, window)
    return f"{place}: {kind}" if place and kind else place or kind


def _place(widget, window) -> str:
    """The title of the dock (or toolbar) ``widget`` is in."""
    node = widget
    while node is not None and node is not window:
        if isinstance(node, (QDockWidget, QToolBar)):
            return node.windowTitle()
        node = node.parentWidget()
    return ""
