"""A run to stop while a dialog is open (a module of its own: test files import it by name): a long drive, and
the dialogs opened through the window's own commands, some of which run an event loop of their own until they
close. The click at STOP is ``window_tools.click_stop``."""
from program_builder import block, number
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QDialog
from test_running import load
from window_tools import modal_dialog


def drive_on(qtbot, window, turn=False):
    """Start a long drive (or a long turn on the spot, where no wall is in the way however fast the simulated
    time runs) on the window's robot and return once the robot moves."""
    load(qtbot, window, block("hobbit_turn", {"direction": "+"}, {"angle": number(360000)}) if turn
         else block("hobbit_move", {"direction": "+"}, {"speed": number(100)}))
    assert window.runs.run()
    qtbot.waitUntil(lambda: window.runs.state == "running" and window.robot().snapshot()["motion"] != "idle",
                    timeout=15000)


def open_dialog(window, kind: str = QDialog):
    """The newest visible dialog of ``kind`` in ``window`` (at any depth), or None."""
    shown = [dialog for dialog in window.findChildren(kind) if dialog.isVisible() and dialog.isWindow()]
    active = modal_dialog()
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
