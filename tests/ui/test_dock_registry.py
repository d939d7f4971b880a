"""A dock is one entry in ui/docks/registry.py's table: the window builds it where the entry says,
lists it in the View menu, renames it with the language, and the stage and the kiosk treat it as
the entry says, with no other change anywhere."""
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QPlainTextEdit

from rockly_desktop.ui.docks import registry
from rockly_desktop.ui.docks.registry import DockSpec, OnStage


def _notes_dock(_language, parent):
    dock = QDockWidget(parent)
    dock.setWidget(QPlainTextEdit(dock))
    return dock


def _add_notes_dock(monkeypatch, **how):
    notes = DockSpec("notes_dock", "plot_dock", Qt.DockWidgetArea.BottomDockWidgetArea, "bottom", _notes_dock, **how)
    monkeypatch.setattr(registry, "DOCKS", registry.DOCKS + (notes,))


def view_menu(window):
    return window.menuBar().actions()[3].menu().actions()


def test_a_dock_in_the_table_is_built_listed_renamed_and_closed_on_stage(qtbot, driver, monkeypatch):
    _add_notes_dock(monkeypatch, on_stage=OnStage.HIDDEN)
    window = driver.open_window()
    notes = window.docks["notes_dock"]
    assert notes.objectName() == "notes_dock" and notes.windowTitle() == "Plot"
    assert window.dockWidgetArea(notes) == Qt.DockWidgetArea.BottomDockWidgetArea
    assert notes in window.tabifiedDockWidgets(window.console)       # a tab of its group
    assert window.console.isVisible()                                # the group's first stays on top
    assert notes.toggleViewAction() in view_menu(window)
    notes.raise_()
    qtbot.waitUntil(notes.isVisible, timeout=3000)
    window.stage.set_active(True)
    qtbot.waitUntil(lambda: not notes.isVisible() and window.console.isVisible(), timeout=3000)
    window.stage.set_active(False)
    qtbot.waitUntil(notes.isVisible, timeout=3000)                   # the layout from before the stage
    window.set_language("de")
    qtbot.waitUntil(lambda: window.language == "de", timeout=15000)
    assert notes.windowTitle() == "Diagramm"
    assert notes.toggleViewAction() in view_menu(window)              # the View menu made anew lists it too
