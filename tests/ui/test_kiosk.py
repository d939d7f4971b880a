"""Kiosk mode for a fair stand: full screen on stage, no way out without the PIN or the key chord,
file dialogs kept in one folder, and a fresh start for the next visitor after idling."""
import json

import pytest
from fake_time import FakeTime
from page_tools import run_js
from program_builder import block, number, rockly_document, stack
from PySide6.QtCore import QCoreApplication, QEvent, QPoint, QPointF, Qt, QTimer
from PySide6.QtGui import QMouseEvent
from PySide6.QtWidgets import QApplication, QDialog, QFileDialog, QMenu
from stop_tools import drive_on, open_dialog, while_open
from test_running import load
from window_tools import click_stop, modal_dialog

from rockly_desktop.app import build_main_window, start_kiosk
from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.kiosk import idle_watch
from rockly_desktop.ui.kiosk.kiosk import LeaveDialog
from rockly_desktop.ui.run.run_toolbar import RunToolbar

PIN = "4711"
CHORD = "Ctrl+Alt+Shift+K"


@pytest.fixture
def clock(monkeypatch):
    fake = FakeTime()
    monkeypatch.setattr(idle_watch, "time", fake)
    return fake


@pytest.fixture
def folders(tmp_path):
    programs, visitors = tmp_path / "kiosk", tmp_path / "visitors"
    programs.mkdir()
    return programs, visitors


@pytest.fixture
def start_program(tmp_path):
    path = tmp_path / "start.rockly"
    path.write_text(rockly_document([block("hobbit_sos")]))
    return path


@pytest.fixture
def open_kiosk(qtbot, driver, folders, clock):
    """Opens a kiosk window (PIN and chord set) with a start program; leaves it at the end."""
    settings = AppSettings(driver.settings_path)
    settings.teacher.set_pin(PIN)
    settings.kiosk.programs_folder, settings.kiosk.visitors_folder = folders
    settings.kiosk.quit_chord = CHORD
    settings.sync()
    kiosks = []

    def open_it(start=None):
        window = build_main_window(driver.settings_path, kiosk=True)
        window.simulator_speed = 25.0
        driver.windows.append(window)
        kiosk = start_kiosk(window, start)
        kiosks.append(kiosk)
        with qtbot.waitSignal(window.editor.sig_ready, timeout=30000):
            window.start(start)
        return window, kiosk

    yield open_it
    for kiosk in kiosks:
        kiosk.frame.document.modified = False
        kiosk.leave()


def python_shown(window):
    return window.code_dock.view.toPlainText()


def test_the_kiosk_is_full_screen_on_stage_with_a_big_stop(qtbot, driver, open_kiosk, start_program):
    window, kiosk = open_kiosk(start_program)
    qtbot.waitUntil(lambda: python_shown(window) == "robot.call_sos()\n", timeout=10000)
    assert window.isFullScreen() and window.stage.active and not window.stage.action.isEnabled()
    stop = window.run_toolbar.widgetForAction(window.run_toolbar.stop_action)
    usual = RunToolbar("en")
    qtbot.addWidget(usual)
    assert stop.sizeHint().height() > 1.4 * usual.widgetForAction(usual.stop_action).sizeHint().height()
    assert not window.run_toolbar.backend.isVisible()                   # a kiosk runs on the simulator
    assert window.document.path is None              # Save asks for a name: the start program stays as it is
    assert window.settings.reset_before_run           # on by default in kiosk mode...
    assert AppSettings(driver.settings_path).reset_before_run is False   # ...not outside it
    assert not window.plot_dock.toggleViewAction().isEnabled()
    teacher = AppSettings(driver.settings_path)
    teacher.add_recent_file("/home/teacher/lesson.rockly")
    window.settings.clear_recent_files()                    # File → Open Recent → Clear List, in the kiosk
    assert window.settings.recent_files == [] and teacher.recent_files == ["/home/teacher/lesson.rockly"]


def test_the_kiosk_cannot_be_closed_without_the_pin(qtbot, open_kiosk):
    window, kiosk = open_kiosk()
    assert not window.close()
    dialog = kiosk.leave_dialog
    assert isinstance(dialog, LeaveDialog) and dialog.isVisible()
    dialog.pin.setText("0000")
    dialog.accept()
    assert dialog.isVisible() and dialog.problem.text() == "Wrong PIN." and window.isVisible()
    dialog.reject()
    window.findChild(type(window.run_toolbar.run_action), "action_quit").trigger()   # File → Quit asks too
    dialog = kiosk.leave_dialog
    assert dialog.isVisible() and window.isVisible()
    dialog.pin.setText(PIN)
    dialog.accept()
    qtbot.waitUntil(lambda: not window.isVisible(), timeout=5000)


def test_the_key_chord_leaves_the_kiosk(qtbot, open_kiosk):
    window, kiosk = open_kiosk()
    window.activateWindow()
    qtbot.keyClick(window.editor, Qt.Key.Key_K, Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.AltModifier
                   | Qt.KeyboardModifier.ShiftModifier)
    qtbot.waitUntil(lambda: not window.isVisible(), timeout=5000)


def test_the_kiosk_has_blocklys_menus_but_not_the_browsers(qtbot, open_kiosk):
    window, _kiosk = open_kiosk()
    # Full screen and on stage, the page is resized after it is ready: a click meanwhile may miss.
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "[window.innerWidth, window.innerHeight]")
                    == [window.editor.width(), window.editor.height()], timeout=5000)
    page = window.editor.focusProxy() or window.editor
    qtbot.mouseClick(page, Qt.MouseButton.RightButton, pos=QPoint(40, page.height() - 60))   # under the categories
    assert not [menu for menu in window.findChildren(QMenu) if menu.isVisible()]    # no Back, Reload, Save page
    # A right click that lands while the stage's zoom still settles the workspace opens nothing (red once in a
    # loaded CI run): the person clicks again, and so does the test, until Blockly's menu shows.
    for _attempt in range(5):
        qtbot.mouseClick(page, Qt.MouseButton.RightButton, pos=QPoint(page.width() // 2, page.height() // 2))
        try:
            qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "!!document.querySelector('.blocklyContextMenu')"),
                            timeout=2000)                                 # the workspace's own menu
            break
        except qtbot.TimeoutError:
            pass
    assert run_js(qtbot, window.editor, "!!document.querySelector('.blocklyContextMenu')")
    assert not [menu for menu in window.findChildren(QMenu) if menu.isVisible()]    # no Back, Reload, Save page


def test_kiosk_file_dialogs_stay_in_the_kiosk_folder(qtbot, open_kiosk, folders, tmp_path):
    programs, _visitors = folders
    inside = programs / "visitor.rockly"
    inside.write_text(rockly_document([block("hobbit_sos")]))
    outside = tmp_path / "secret.rockly"
    outside.write_text(rockly_document([block("hobbit_sos")]))
    window, kiosk = open_kiosk()
    seen = []

    def use_the_dialog():
        dialog = modal_dialog()
        seen.append(("starts in", isinstance(dialog, QFileDialog), dialog.directory().absolutePath()))
        dialog.setDirectory(str(tmp_path))
        dialog.directoryEntered.emit(str(tmp_path))               # as when the person goes up a folder
        seen.append(("after going up", dialog.directory().absolutePath()))
        dialog.selectFile(str(outside))
        dialog.accept()
        seen.append(("outside accepted", dialog.result() == QDialog.DialogCode.Accepted and not dialog.isVisible()))
        dialog.selectFile(str(programs / ".." / outside.name))
        dialog.accept()
        seen.append(("dot-dot accepted", not dialog.isVisible()))
        dialog.selectFile(str(inside))
        dialog.accept()

    QTimer.singleShot(0, use_the_dialog)
    outcomes = []
    window.files.open(then=outcomes.append)
    qtbot.waitUntil(lambda: bool(outcomes), timeout=10000)
    assert seen == [("starts in", True, str(programs)), ("after going up", str(programs)),
                    ("outside accepted", False), ("dot-dot accepted", False)]
    assert outcomes == [True] and python_shown(window) == "robot.call_sos()\n"
    assert window.document.path is None             # shown as new: Save asks for a new name in the visitors' folder


def test_after_idling_the_kiosk_keeps_the_visitors_program_and_starts_over(qtbot, open_kiosk, folders, clock,
                                                                            start_program):
    _programs, visitors = folders
    window, kiosk = open_kiosk(start_program)
    qtbot.waitUntil(lambda: python_shown(window) == "robot.call_sos()\n", timeout=10000)
    load(qtbot, window, stack(block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}, id="drive")))
    window.document.mark_modified()                          # the visitor made a program...
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        assert window.runs.run()                             # ...and ran it: the robot is away from the start
    assert window.robot().snapshot()["x"] > 0.4

    clock.now += 100
    QApplication.sendEvent(window.windowHandle(), QMouseEvent(QEvent.Type.MouseMove, QPointF(5, 5), QPointF(5, 5),
                                                      Qt.MouseButton.NoButton, Qt.MouseButton.NoButton,
                                                      Qt.KeyboardModifier.NoModifier))
    clock.now += 179                                         # 2:59 after the last input
    with qtbot.assertNotEmitted(kiosk.idle.sig_idle):
        kiosk.idle.check()
    assert not visitors.exists() and window.document.modified

    clock.now += 1                                           # 3:00: the next visitor gets a fresh start
    with qtbot.waitSignal(kiosk.idle.sig_idle, timeout=3000):
        pass
    qtbot.waitUntil(lambda: visitors.exists() and len(list(visitors.iterdir())) == 1, timeout=10000)
    kept = next(visitors.iterdir())
    assert kept.name[:4].isdigit() and kept.suffix == ".rockly"        # e.g. 2026-11-23_21-55-44.rockly
    types = [item["type"] for item in json.loads(kept.read_text())["workspace"]["blocks"]["blocks"]]
    assert types == ["hobbit_move"]
    qtbot.waitUntil(lambda: python_shown(window) == "robot.call_sos()\n", timeout=10000)
    qtbot.waitUntil(lambda: window.robot().snapshot()["x"] == 0.0, timeout=5000)
    assert not window.document.modified and window.document.path is None
    assert "Welcome" in window.statusBar().currentMessage()

    clock.now += 1000                                        # nobody came: it does not start over again and again
    with qtbot.assertNotEmitted(kiosk.idle.sig_idle):
        kiosk.idle.check()
    assert len(list(visitors.iterdir())) == 1


def test_kiosk_mode_fixes_the_teacher_level(qtbot, open_kiosk):
    from rockly_desktop.ui.preferences.preferences import PreferencesDialog

    window, _kiosk = open_kiosk()
    dialog = PreferencesDialog("en", window, window.profile, window.settings.teacher,
                               kiosk=window.settings.kiosk, kiosk_mode=True)
    dialog.teacher_tab.pin.setText(PIN)
    dialog.teacher_tab.unlock()
    assert dialog.teacher_tab.unlocked and not dialog.teacher_tab.level_box.isEnabled()
    assert dialog.kiosk_tab.idle_minutes.isEnabled() and dialog.kiosk_tab.idle_minutes.value() == 3
    assert dialog.kiosk_tab.quit_chord.keySequence().toString() == CHORD
    dialog.kiosk_tab.idle_minutes.setValue(5)
    dialog.kiosk_tab.apply()
    assert window.settings.kiosk.idle_minutes == 5
    dialog.deleteLater()


def test_without_a_pin_a_kiosk_offers_no_teacher_settings(qtbot, tmp_path, hobbit):
    from rockly_desktop.ui.preferences.preferences import PreferencesDialog

    settings = AppSettings(tmp_path / "s.ini")
    settings.kiosk.quit_chord = CHORD           # the teacher leaves with the chord; a visitor must not set a PIN
    dialog = PreferencesDialog("en", None, hobbit, settings.teacher, kiosk=settings.kiosk, kiosk_mode=True)
    qtbot.addWidget(dialog)
    assert dialog.teacher_tab is None and dialog.kiosk_tab is None and dialog.tabs.count() == 1


def test_the_kiosk_tab_is_locked_until_the_teacher_tab_is_unlocked(qtbot, tmp_path, hobbit):
    from rockly_desktop.ui.preferences.preferences import PreferencesDialog

    settings = AppSettings(tmp_path / "s.ini")
    settings.teacher.set_pin(PIN)
    dialog = PreferencesDialog("de", None, hobbit, settings.teacher,
                               kiosk=settings.kiosk)
    qtbot.addWidget(dialog)
    assert not dialog.kiosk_tab.idle_minutes.isEnabled() and not dialog.kiosk_tab.note.isHidden()
    dialog.kiosk_tab.idle_minutes.setValue(9)
    dialog.kiosk_tab.apply()
    assert settings.kiosk.idle_minutes == 3                  # locked: nothing kept
    assert dialog.tabs.tabText(dialog.tabs.count() - 1) == "Kiosk"
    dialog.teacher_tab.pin.setText(PIN)
    dialog.teacher_tab.unlock()
    assert dialog.kiosk_tab.idle_minutes.isEnabled() and dialog.kiosk_tab.note.isHidden()


def test_a_kiosk_nobody_could_leave_does_not_start(qtbot, driver, monkeypatch):
    from PySide6.QtWidgets import QMessageBox

    shown = []
    monkeypatch.setattr(QMessageBox, "critical", lambda _parent, title, text: shown.append(title))
    window = build_main_window(driver.settings_path, kiosk=True)
    assert start_kiosk(window) is None and shown == ["Kiosk mode needs a way out"]
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)    # the window is gone


@pytest.mark.parametrize("prompt", ["leaving", "teacher"])
def test_the_big_stop_stops_the_robot_with_the_pin_prompt_open(qtbot, open_kiosk, start_program, prompt):
    window, kiosk = open_kiosk(start_program)
    drive_on(qtbot, window, turn=True)
    ask = {"leaving": kiosk.ask_pin, "teacher": lambda: kiosk.ask_teacher(lambda: None)}[prompt]

    def click_the_big_stop(dialog):
        assert dialog.isModal()  # a PIN prompt waits for its answer
        click_stop(window)
        qtbot.waitUntil(lambda: window.runs.state == "idle", timeout=5000)
        snapshot = window.robot().snapshot()
        return window.runs.last_result.outcome, snapshot["linear"], snapshot["angular"]

    assert while_open(qtbot, ask, lambda: open_dialog(window), click_the_big_stop) == ("stopped", 0, 0)
