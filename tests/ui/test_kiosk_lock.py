"""A kiosk no visitor can break: no context menus, a toolbar (with STOP) that stays, a start program
nobody writes over, a window that comes back full screen, file dialogs that show and take nothing
outside the kiosk's folders, the robot and Preferences behind the PIN, and nothing of the last
visitor left after an idle reset. Each test drives the real window (offscreen)."""
# ruff: noqa: F811 (the kiosk fixtures come from test_kiosk)
from pathlib import Path

import pytest
from page_tools import run_js
from program_builder import block, number, rockly_document, stack, text
from PySide6.QtCore import QPoint, Qt, QTimer
from PySide6.QtGui import QAction, QContextMenuEvent
from PySide6.QtWidgets import (
    QApplication,
    QFileSystemModel,
    QLineEdit,
    QListView,
    QMenu,
    QTabBar,
    QWidget,
)
from test_kiosk import PIN, clock, folders, open_kiosk, python_shown  # noqa: F401 (fixtures)
from test_running import load
from window_tools import error_boxes, modal_dialog

from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.files.file_dialogs import ConfinedFileDialog
from rockly_desktop.ui.preferences.preferences import PreferencesDialog

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def idle_reset(qtbot, kiosk, clock):
    """Let the kiosk's idle minutes pass and wait until it has started over."""
    clock.now += kiosk.idle.seconds + 1
    qtbot.waitUntil(lambda: "Welcome" in kiosk.frame.statusBar().currentMessage(), timeout=15000)


def with_dialog(qtbot, use) -> list:
    """Call ``use(dialog)`` with the modal dialog the next command opens (run from the event loop).
    Returns a list that gets what ``use`` raised (the dialog is then closed, so the test goes on)."""
    failures = []

    def later():
        dialog = modal_dialog()
        if dialog is None:
            QTimer.singleShot(10, later)
            return
        try:
            use(dialog)
        except Exception as failure:
            failures.append(failure)
            dialog.reject()

    QTimer.singleShot(0, later)
    return failures


def menus_shown_by(qtbot, widget) -> list:
    """The menus a right-click on ``widget`` opens (each closed again at once)."""
    shown, position = [], QPoint(5, 5)

    def close_menus():
        for menu in QApplication.topLevelWidgets():
            if isinstance(menu, QMenu) and menu.isVisible():
                shown.append(menu)
                menu.close()

    QTimer.singleShot(50, close_menus)   # a menu Qt opens with exec() waits here until closed
    event = QContextMenuEvent(QContextMenuEvent.Reason.Mouse, position, widget.mapToGlobal(position))
    QApplication.sendEvent(widget, event)
    qtbot.wait(100)     # nothing to wait for when it works: a menu would be open by now
    close_menus()
    return shown


def test_no_context_menu_on_the_toolbar_docks_tabs_or_menu_bar(qtbot, open_kiosk):
    window, _kiosk = open_kiosk()
    assert window.createPopupMenu() is None                      # the menu that unticks the toolbar
    tabs = [bar for bar in window.findChildren(QTabBar) if bar.isVisible()]
    for part in [window.run_toolbar, window.menuBar(), window.simulator_dock, window.console,
                 window.statusBar(), *tabs]:
        assert menus_shown_by(qtbot, part) == [], part


def test_the_toolbar_with_stop_cannot_be_hidden_and_is_there_after_an_idle_reset(qtbot, open_kiosk, clock):
    window, kiosk = open_kiosk()
    toolbar = window.run_toolbar
    assert not toolbar.toggleViewAction().isEnabled() and not toolbar.isMovable()
    toolbar.toggleViewAction().trigger()                          # what unticking it in a menu does
    toolbar.hide()
    toolbar.setVisible(False)
    assert toolbar.isVisible()
    idle_reset(qtbot, kiosk, clock)
    for action in (toolbar.run_action, toolbar.stop_action, toolbar.reset_action):
        assert toolbar.widgetForAction(action).isVisible()


def test_a_visitors_save_goes_to_the_visitors_folder_and_never_over_the_start_program(qtbot, open_kiosk, folders,
                                                                                       clock):
    programs, visitors = folders
    start = programs / "start.rockly"
    start.write_text(rockly_document([block("hobbit_sos")]))
    teachers_bytes = start.read_bytes()
    visitors.mkdir()
    (visitors / "taken.rockly").write_text(rockly_document([block("hobbit_sos")]))
    window, kiosk = open_kiosk(start)
    qtbot.waitUntil(lambda: python_shown(window) == "robot.call_sos()\n", timeout=10000)
    load(qtbot, window, stack(block("hobbit_emo", {"emotion": "HAPPY"})))
    window.document.mark_modified()                               # the visitor changed the start program
    seen = []

    def save_in(dialog):
        name = dialog.findChild(QLineEdit, "fileNameEdit")
        seen.append(("in", dialog.directory().absolutePath()))
        for attempt in (str(start), "../kiosk/start.rockly", "taken.rockly"):
            name.setText(attempt)
            qtbot.keyClick(name, Qt.Key.Key_Return)
            box = dialog.problem_box
            seen.append((attempt, dialog.isVisible(), box is not None and box.isVisible() and box.text()))
            box.close()
        name.setText("my robot")
        qtbot.keyClick(name, Qt.Key.Key_Return)

    failures = with_dialog(qtbot, save_in)
    window.findChild(QAction, "action_save").trigger()             # Ctrl+S on the start program
    qtbot.waitUntil(lambda: failures or (visitors / "my robot.rockly").exists(), timeout=15000)
    assert failures == []
    assert seen[0] == ("in", str(visitors))
    for attempt, still_open, message in seen[1:3]:
        assert still_open and "is not in this stand's folders" in message, attempt
    assert seen[3][1] and "“taken.rockly” already exists" in seen[3][2]
    assert start.read_bytes() == teachers_bytes
    assert "hobbit_emo" in (visitors / "my robot.rockly").read_text()

    idle_reset(qtbot, kiosk, clock)                                # every reset reopens the teacher's program
    qtbot.waitUntil(lambda: python_shown(window) == "robot.call_sos()\n", timeout=10000)
    assert start.read_bytes() == teachers_bytes and window.document.path is None


@pytest.mark.parametrize("minimise", ["showMinimized", "state"])
def test_a_minimised_kiosk_comes_back_full_screen(qtbot, open_kiosk, minimise):
    window, _kiosk = open_kiosk()
    assert window.isFullScreen()
    if minimise == "showMinimized":
        window.showMinimized()
    else:                                                          # the window manager's Iconify (Alt+Space)
        window.setWindowState(Qt.WindowState.WindowMinimized)
    qtbot.waitUntil(lambda: window.isFullScreen() and not window.isMinimized(), timeout=5000)
    window.showNormal()
    qtbot.waitUntil(window.isFullScreen, timeout=5000)


def test_the_open_dialog_lists_and_takes_nothing_outside_the_kiosk_folders(qtbot, open_kiosk, folders):
    programs, visitors = folders
    (programs / "lesson.rockly").write_text(rockly_document([block("hobbit_sos")]))
    window, _kiosk = open_kiosk()
    seen = {}

    def look_around(dialog):
        seen["dialog"] = isinstance(dialog, ConfinedFileDialog)
        new_folder = dialog.findChild(QWidget, "newFolderButton")
        seen["new folder"] = new_folder is not None and new_folder.isVisible()
        list_view = dialog.findChild(QListView, "listView")
        seen["menu"] = list_view.contextMenuPolicy()
        seen["sidebar"] = [url.toLocalFile() for url in dialog.sidebarUrls()]
        files = dialog.findChild(QFileSystemModel)
        files.fetchMore(files.index("/etc"))                       # what typing /etc/ made it read
        qtbot.waitUntil(lambda: files.rowCount(files.index("/etc")) > 0, timeout=10000)
        name = dialog.findChild(QLineEdit, "fileNameEdit")
        name.setFocus()
        name.clear()
        qtbot.keyClicks(name, "/etc/")
        completer = name.completer()
        seen["completions"] = [completer.completionModel().index(row, 0).data()
                               for row in range(completer.completionModel().rowCount())]
        qtbot.keyClick(name, Qt.Key.Key_Return)
        box = dialog.problem_box
        seen["after /etc/"] = (dialog.isVisible(), dialog.directory().absolutePath(),
                               box is not None and box.isVisible() and box.text())
        box.close()
        dialog.reject()

    failures = with_dialog(qtbot, look_around)
    outcomes = []
    window.files.open(then=outcomes.append)
    qtbot.waitUntil(lambda: bool(outcomes), timeout=15000)
    assert failures == []
    assert seen["dialog"] and not seen["new folder"] and seen["menu"] == Qt.ContextMenuPolicy.PreventContextMenu
    assert seen["sidebar"] == [str(programs.resolve()), str(visitors.resolve())]
    assert seen["completions"] == []
    still_open, folder, message = seen["after /etc/"]
    assert still_open and folder == str(programs.resolve()) and "“/etc/” is not in this stand" in message
    assert outcomes == [False]


def test_open_recording_is_confined_to_the_recordings_folder(qtbot, open_kiosk, tmp_path):
    window, kiosk = open_kiosk()
    recordings = Path(window.settings.recordings_folder).resolve()
    settings_file = Path(AppSettings(None)._store.fileName())     # the teacher's PIN lives here
    seen = {}

    def use(dialog):
        seen["kind"] = (isinstance(dialog, ConfinedFileDialog), dialog.directory().absolutePath())
        name = dialog.findChild(QLineEdit, "fileNameEdit")
        name.setText(str(settings_file.parent))
        qtbot.keyClick(name, Qt.Key.Key_Return)
        box = dialog.problem_box
        seen["config"] = (dialog.isVisible(), dialog.directory().absolutePath(), box is not None and box.isVisible())
        box.close()
        dialog.reject()

    window.findChild(QAction, "action_open_recording").trigger()   # the teacher's, behind the PIN
    kiosk.teacher_dialog.pin.setText(PIN)
    failures = with_dialog(qtbot, use)
    kiosk.teacher_dialog.accept()
    assert failures == []
    assert seen["kind"] == (True, str(recordings))
    assert seen["config"] == (True, str(recordings), True)


def test_the_robot_menu_run_on_and_preferences_ask_for_the_pin_in_a_kiosk(qtbot, open_kiosk):
    window, kiosk = open_kiosk()
    assert not window.run_toolbar.backend.isVisible()             # the Run-on box: not there in a kiosk
    turtlebot = next(action for action in window.profile_actions.actions() if action.data() == "turtlebot")
    turtlebot.trigger()
    dialog = kiosk.teacher_dialog
    assert dialog is not None and dialog.isVisible() and window.profile.id == "hobbit"
    dialog.pin.setText("0000")
    dialog.accept()
    assert dialog.isVisible() and dialog.problem.text().startswith("Wrong PIN.") and window.profile.id == "hobbit"
    dialog.reject()

    opened = []
    failures = with_dialog(qtbot, lambda shown: (opened.append(shown), shown.reject()))
    window.findChild(QAction, "action_preferences").trigger()      # Preferences (and the language in it)
    dialog = kiosk.teacher_dialog
    assert dialog.isVisible() and not [shown for shown in opened if isinstance(shown, PreferencesDialog)]
    dialog.pin.setText(PIN)
    dialog.accept()
    qtbot.waitUntil(lambda: any(isinstance(shown, PreferencesDialog) for shown in opened), timeout=5000)
    assert failures == []

    turtlebot.trigger()
    kiosk.teacher_dialog.pin.setText(PIN)
    kiosk.teacher_dialog.accept()
    qtbot.waitUntil(lambda: window.profile.id == "turtlebot", timeout=10000)


def test_preferences_in_a_kiosk_ask_the_pin_once_and_a_wrong_pin_opens_nothing(qtbot, open_kiosk):
    window, kiosk = open_kiosk()
    shown = []

    def look(dialog):
        shown.append({"dialog": type(dialog).__name__, "teacher_unlocked": dialog.teacher_tab.unlocked,
                      "kiosk_tab_usable": dialog.kiosk_tab.idle_minutes.isEnabled()})
        dialog.reject()

    failures = with_dialog(qtbot, look)
    window.findChild(QAction, "action_preferences").trigger()
    gate = kiosk.teacher_dialog
    gate.pin.setText("0000")
    gate.accept()                                                  # a wrong PIN: refused, nothing opens
    assert gate.isVisible() and gate.problem.text().startswith("Wrong PIN.") and shown == []
    gate.pin.setText(PIN)
    gate.accept()                                                  # the right one: Preferences, asking no more
    qtbot.waitUntil(lambda: bool(shown), timeout=5000)
    assert failures == []
    assert shown == [{"dialog": "PreferencesDialog", "teacher_unlocked": True, "kiosk_tab_usable": True}]


def test_an_idle_reset_clears_console_replay_variables_and_badges(qtbot, open_kiosk, folders, clock):
    programs, _visitors = folders
    start = programs / "start.rockly"
    start.write_text(rockly_document([stack(
        block("variables_set", {"VAR": {"id": "laps"}},
              {"VALUE": block("math_arithmetic", {"OP": "ADD"}, {"A": number(1), "B": number(2)}, id="sum")}),
        block("text_print", inputs={"TEXT": text("hello")}),
        block("hobbit_show_info", inputs={"text": block("text", {"TEXT": "Hi"})}, id="info"))]).replace(
        '"blocks": {', '"variables": [{"name": "laps", "id": "laps"}], "blocks": {', 1))
    window, kiosk = open_kiosk(start)
    qtbot.waitUntil(lambda: "call_sos" not in python_shown(window) and "laps" in python_shown(window), timeout=10000)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        assert window.runs.run()                                   # the visitor runs the start program as it is
    qtbot.waitUntil(lambda: window.replay_bar.isVisible() and window.variables.values().get("laps") == "3",
                    timeout=10000)
    assert "hello" in window.console.lines()
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyValues.lastValue('sum')") is not None, timeout=5000)

    idle_reset(qtbot, kiosk, clock)
    qtbot.waitUntil(lambda: "laps" in python_shown(window), timeout=10000)
    assert window.console.lines() == [] and window.console.recorded_lines() == []
    assert not window.replay_bar.isVisible() and window.variables.values() == {}
    assert window.variables.table.rowCount() == 0
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, "RocklyValues.lastValue('sum')") is None, timeout=5000)
    assert run_js(qtbot, window.editor, "document.querySelectorAll('.rocklyBadge').length") == 0


def test_a_teacher_can_lock_the_robot_choice(qtbot, driver):
    settings = AppSettings(driver.settings_path)
    settings.teacher.set_pin(PIN)
    settings.sync()
    window = driver.open_window()

    def lock(dialog):
        dialog.teacher_tab.pin.setText(PIN)
        dialog.teacher_tab.unlock()
        dialog.teacher_tab.lock_robot.setChecked(True)
        dialog.accept()

    failures = with_dialog(qtbot, lock)
    window.findChild(QAction, "action_preferences").trigger()
    assert failures == []
    locked = "The teacher locked the robot choice."
    turtlebot = next(action for action in window.profile_actions.actions() if action.data() == "turtlebot")
    assert not turtlebot.isEnabled() and turtlebot.toolTip() == locked
    backend = window.run_toolbar.backend
    assert not backend.isEnabled() and backend.toolTip() == locked
    turtlebot.trigger()
    assert window.profile.id == "hobbit"

    load(qtbot, window, block("hobbit_emo", {"emotion": "HAPPY"}))
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000):
        window.runs.run()                                          # a run enables what it disabled: not these
    assert not turtlebot.isEnabled() and not backend.isEnabled()

    outcomes = []
    window.files.open(str(EXAMPLES / "turtlebot" / "avoid-obstacles.rockly"), then=outcomes.append)
    qtbot.waitUntil(lambda: bool(outcomes), timeout=10000)
    assert outcomes == [False] and window.profile.id == "hobbit"
    assert any("the teacher locked the robot choice to HOBBIT" in shown for shown in error_boxes(window))
