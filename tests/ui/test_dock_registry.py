"""A dock is one entry in ui/docks/registry.py's table: the window builds it where the entry says,
lists it in the View menu, renames it with the language, and the stage and the kiosk treat it as
the entry says, with no other change anywhere."""
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDockWidget, QPlainTextEdit

from rockly_desktop.app import build_main_window, start_kiosk
from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.docks import registry
from rockly_desktop.ui.docks.registry import DockSpec, InKiosk, OnStage


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


def test_the_kiosk_shows_a_dock_again_for_the_next_visitor_when_its_entry_says(qtbot, driver, monkeypatch, tmp_path):
    _add_notes_dock(monkeypatch, in_kiosk=InKiosk.SHOWN)
    settings = AppSettings(driver.settings_path)
    settings.kiosk.programs_folder, settings.kiosk.visitors_folder = tmp_path / "kiosk", tmp_path / "visitors"
    settings.kiosk.quit_chord = "Ctrl+Alt+Shift+K"
    settings.sync()
    window = build_main_window(driver.settings_path, kiosk=True)
    driver.windows.append(window)
    kiosk = start_kiosk(window)
    with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
        window.start()
    notes = window.docks["notes_dock"]
    assert not notes.isVisible()                                     # on stage, as every dock but the big ones
    kiosk.idle.sig_idle.emit()                                       # nobody touched it for minutes
    qtbot.waitUntil(lambda: "Welcome" in window.statusBar().currentMessage(), timeout=15000)
    assert notes.isVisible()
    window.document.modified = False
    kiosk.leave()
