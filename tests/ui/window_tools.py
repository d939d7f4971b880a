"""Driving real Rockly windows from tests (a module of its own: test files import it by name)."""
from page_tools import call_page
from PySide6.QtCore import QCoreApplication, QEvent, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QMessageBox

from rockly_desktop.app import build_main_window
from rockly_desktop.robot.links import link_kind
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog

SIMULATOR_SPEED = 25.0  # simulated time runs this much faster in tests


class WindowDriver:
    """Opens Rockly windows for a test and waits for their editor."""

    def __init__(self, qtbot, settings_path, extra_profile_dirs=()):
        self.qtbot = qtbot
        self.settings_path = settings_path
        self.extra_profile_dirs = extra_profile_dirs
        self.windows = []

    def close_all(self):
        """Delete every window now (a page left for interpreter exit crashes QtWebEngine)."""
        for window in self.windows:
            window.document.modified = False
            window.close()
            assert window.runs.thread is None, "a program was still running after the window closed"
            window.deleteLater()
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)

    def open_window(self, open_path=None, simulator_speed=SIMULATOR_SPEED):
        """A shown main window whose editor is ready (and whose start-up file is open)."""
        window = build_main_window(self.settings_path, self.extra_profile_dirs)
        window.simulator_speed = simulator_speed
        self.windows.append(window)
        window.show()
        with self.qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
            window.start(open_path)
        return window


def on_hobbit_over_ros1(window, master_uri: str, monkeypatch):
    """``window`` switched to HOBBIT over ROS 1 on the master at ``master_uri`` (the connection dialog accepted as
    it is); returned for a fixture to hand on."""
    window.settings.remember_link_connection(link_kind("ros1"), "hobbit", {"master": master_uri, "host": "127.0.0.1"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert window.robots.kind == "ros1"
    return window


def click_stop(window):
    """A left click at the middle of STOP, delivered to the window as the window system delivers it (where a
    modal dialog blocks it; a click sent straight to the button would not be blocked)."""
    button = window.run_toolbar.widgetForAction(window.run_toolbar.stop_action)
    QTest.mouseClick(window.windowHandle(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                     button.mapTo(window, button.rect().center()))


def modal_dialog():
    """The dialog that waits for an answer: a window's (shown modeless to Qt, so that STOP acts through it:
    decision 032), or Qt's modal one; None when there is none."""
    for window in QApplication.topLevelWidgets():
        dialog = window.active_dialog() if hasattr(window, "active_dialog") and window.isVisible() else None
        if dialog is not None:
            return dialog
    return QApplication.activeModalWidget()


def error_boxes(window) -> list:
    """Texts of the error message boxes the window shows."""
    return [box.text() for box in window.findChildren(QMessageBox) if box.isVisible()]


def state(qtbot, window) -> dict:
    """The editor's current workspace and Python."""
    return call_page(qtbot, window.editor, "getState")


def completed(qtbot, command, *args, timeout=15000):
    """Run a window command that reports its end to ``then`` (save, open, export…) and return its outcome."""
    outcomes = []
    command(*args, then=outcomes.append)
    qtbot.waitUntil(lambda: bool(outcomes), timeout=timeout)
    return outcomes[0]


def opened_recording(qtbot, window, path) -> bool:
    """Open the recording at ``path`` in ``window``'s replay and wait until it is read; whether it is shown."""
    with qtbot.waitSignal(window.replay.sig_opened, timeout=60000) as reading:
        window.replay.open(path)
    return reading.args[0]


def one_screen_platform(folder, width: int, height: int) -> str:
    """``QT_QPA_PLATFORM`` for Qt's offscreen platform with one screen of ``width`` × ``height`` whose windows
    have frames (its configuration written into ``folder``)."""
    import json

    config = folder / "screen.json"
    config.write_text(json.dumps({"windowFrameMargins": True, "screens": [
        {"name": "screen", "x": 0, "y": 0, "width": width, "height": height, "logicalDpi": 96, "logicalBaseDpi": 96,
         "dpr": 1}]}))
    return f"offscreen:configfile={config}"
