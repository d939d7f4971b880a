from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QDockWidget


def dock_of(w):
    while w is not None and not isinstance(w, QDockWidget):
        w = w.parentWidget()
    return w


def test_shots(window, qtbot):
    window.resize(1280, 800)
    window.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is window, timeout=5000)
    qtbot.wait(500)
    done = set()
    for i in range(30):
        QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Tab)
        qtbot.wait(150)
        f = QApplication.focusWidget()
        d = dock_of(f)
        name = d.objectName() if d else type(f).__name__
        if name in done:
            continue
        done.add(name)
        window.grab().save(f"/tmp/keys_shots/{i:02d}_{name}.png")
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_2, Qt.KeyboardModifier.ControlModifier)
    qtbot.wait(300)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_T)
    qtbot.wait(300)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Right)
    qtbot.wait(500)
    window.grab().save("/tmp/keys_shots/40_blockly_flyout.png")
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Enter)
    qtbot.wait(300)
    QTest.keyClick(QApplication.focusWidget(), Qt.Key.Key_Enter)
    qtbot.wait(500)
    window.grab().save("/tmp/keys_shots/41_blockly_block.png")
