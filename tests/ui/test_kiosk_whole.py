"""The kiosk stays whole for the next visitor: the layout cannot be dragged apart and an idle reset puts
it back, whatever the teacher did to it; File → New asks nothing. Each test drives the real window (offscreen)."""
# ruff: noqa: F811 (the kiosk fixtures come from test_kiosk)
from PySide6.QtCore import QPoint, Qt, QTimer
from PySide6.QtGui import QAction
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication
from test_kiosk import PIN, clock, folders, open_kiosk  # noqa: F401 (fixtures)
from test_kiosk_lock import idle_reset


def dock_sizes(window) -> dict:
    return {dock.objectName(): dock.size() for dock in window.docks.values() if dock.isVisible()}


def settled_sizes(qtbot, window) -> dict:
    """The docks' sizes once the window has stopped laying them out."""
    seen = []

    def same_twice():
        seen.append(dock_sizes(window))
        return len(seen) > 2 and seen[-1] == seen[-2] == seen[-3]

    qtbot.waitUntil(same_twice, timeout=10000)
    return seen[-1]


def drag(frame, start: QPoint, by: QPoint):
    """Press the left button at ``start`` in ``frame``, move it ``by`` in steps, and let go."""
    QTest.mouseMove(frame, start)
    QTest.mousePress(frame, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, start)
    for step in range(1, 6):
        QTest.mouseMove(frame, start + by * step / 5)
        QApplication.processEvents()  # a window moves its separator on a timer, as the mouse goes
    QTest.mouseRelease(frame, Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier, start + by)


def between_blocks_and_simulator(window) -> QPoint:
    blocks, simulator = window.centralWidget().geometry(), window.simulator_dock.geometry()
    return QPoint((blocks.right() + simulator.left()) // 2, simulator.center().y())


def test_the_edge_between_blocks_and_simulator_cannot_be_dragged_in_the_kiosk(qtbot, open_kiosk):
    window, _kiosk = open_kiosk()
    before = settled_sizes(qtbot, window)
    drag(window, between_blocks_and_simulator(window), QPoint(window.width() // 3, 0))
    drag(window, QPoint(window.console.geometry().center().x(), window.console.geometry().top() - 2),
         QPoint(0, -window.height() // 3))
    assert settled_sizes(qtbot, window) == before


def test_an_idle_reset_puts_back_every_docks_size(qtbot, open_kiosk, clock):
    window, kiosk = open_kiosk()
    before = settled_sizes(qtbot, window)
    # squashed as a teacher could, behind the PIN: the blocks a strip, the console half the window
    window.resizeDocks([window.simulator_dock], [window.width() - 25], Qt.Orientation.Horizontal)
    window.resizeDocks([window.console], [window.height() // 2], Qt.Orientation.Vertical)
    assert settled_sizes(qtbot, window) != before
    idle_reset(qtbot, kiosk, clock)
    assert settled_sizes(qtbot, window) == before


def test_file_new_in_the_kiosk_asks_nothing_and_keeps_the_visitors_program(qtbot, open_kiosk, folders):
    window, _kiosk = open_kiosk()
    window.document.modified = True  # the visitor changed the blocks
    asked = []

    def refuse_questions():  # a question (Save "Untitled"?) would wait in its own event loop
        question = window.active_dialog()  # the window's own, modal to it and not to Qt (decision 032)
        if question is not None:
            asked.append(question.windowTitle())
            question.reject()

    watcher = QTimer(interval=20, timeout=refuse_questions)
    watcher.start()
    try:
        window.findChild(QAction, "action_new").trigger()
        qtbot.waitUntil(lambda: not window.document.modified or bool(asked), timeout=10000)
    finally:
        watcher.stop()
    assert asked == [] and not window.document.modified
    assert len(list(folders[1].glob("*.rockly"))) == 1
