"""STOP as a person reaches it while a dialog or a menu is open (a module of its own: test files import it by
name): a real mouse click at STOP's place in the window, which goes through Qt's window-level delivery, where a
modal dialog blocks it (a click sent straight to the button would not be blocked), and the dialogs opened
through the window's own commands, some of which run an event loop of their own until they close."""
from program_builder import block, number
from PySide6.QtCore import Qt, QTimer
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QDialog
from test_running import load


def stop_button(window):
    toolbar = window.run_toolbar
    return toolbar.widgetForAction(toolbar.stop_action)


def click_stop(window):
    """A left click at the middle of STOP, delivered to the window as the window system delivers it."""
    button = stop_button(window)
    QTest.mouseClick(window.windowHandle(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                     button.mapTo(window, button.rect().center()))


def drive_on(qtbot, window):
    """Start a long drive on the window's robot and return once the robot moves."""
    load(qtbot, window, block("hobbit_move", {"direction": "+"}, {"speed": number(100)}))
    assert window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "running" and window.robot().snapshot()["motion"] == "moving",
                    timeout=15000)


def open_dialog(window, kind: str = QDialog):
    """The newest visible dialog of ``kind`` in ``window`` (at any depth), or None."""
    shown = [dialog for dialog in window.findChildren(kind) if dialog.isVisible() and dialog.isWindow()]
    active = QApplication.activeModalWidget()
    return active if active in shown else (shown[-1] if shown else None)


def while_open(qtbot, open_it, find, act, timeout=30000):
    """Call ``open_it()`` (it may not return until its dialog closes); once ``find()`` gives the dialog, call
    ``act(dialog)`` from the event loop then running, close the dialog, and return what ``act`` returned."""
    outcome = []

    def look():
        dialog = find()
        if dialog is not None and not outcome:
            timer.stop()
            try:
                outcome.append(act(dialog))
            except BaseException as problem:  # handed to the test, out of a nested event loop
                outcome.append(problem)
            if dialog.isVisible():
                dialog.reject()

    timer = QTimer()
    timer.timeout.connect(look)
    timer.start(20)
    try:
        open_it()
        qtbot.waitUntil(lambda: bool(outcome), timeout=timeout)
    finally:
        timer.stop()
    if isinstance(outcome[0], BaseException):
        raise outcome[0]
    return outcome[0]
