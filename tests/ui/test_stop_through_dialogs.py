"""STOP stops the robot at once whatever is open (issue 29): a click at STOP with a modal dialog of the window's
open, Esc inside a dialog, the first click on STOP with a menu open; on the simulator and on a ROS 1 wire."""
import struct

import pytest
from program_builder import block, number
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication, QFileDialog, QLineEdit, QMessageBox
from stop_tools import drive_on, open_dialog, while_open
from test_running import load
from window_tools import click_stop, on_hobbit_over_ros1
from wire_recorder import WireRecorder

from rockly_desktop.ui.blockmaker.maker_dialog import BlockMakerDialog
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.preferences.preferences import PreferencesDialog


def stopped(qtbot, window) -> bool:
    """The run ended as stopped and the simulated robot stands still (waits for it)."""
    qtbot.waitUntil(lambda: window.runs.state == "idle", timeout=5000)
    snapshot = window.robot().snapshot()
    return (window.runs.last_result.outcome == "stopped"
            and (snapshot["linear"], snapshot["angular"], snapshot["motion"]) == (0, 0, "idle"))


def a_message_box(window):
    plain_message_box(window, QMessageBox.Icon.Information, "Rockly", "A message").open()


def save_as_with_ctrl_s(window):  # the visitor's way: the program has no file yet, so Save asks where
    QTest.keyClick(window.windowHandle(), Qt.Key.Key_S, Qt.KeyboardModifier.ControlModifier)


DIALOGS = {
    "message box": (a_message_box, QMessageBox),
    "file dialog": (save_as_with_ctrl_s, QFileDialog),
    "preferences": (lambda window: window.show_preferences(), PreferencesDialog),
    "block maker": (lambda window: window.make_block(), BlockMakerDialog),
}


@pytest.mark.parametrize("name", list(DIALOGS))
def test_a_click_on_stop_with_a_dialog_open_stops_the_simulated_robot(qtbot, driver, name):
    window = driver.open_window(simulator_speed=1.0)
    drive_on(qtbot, window)
    open_it, kind = DIALOGS[name]

    def click(dialog):
        assert dialog.isModal()  # to the person: the window waits for its answer
        click_stop(window)
        return stopped(qtbot, window)

    assert while_open(qtbot, lambda: open_it(window), lambda: open_dialog(window, kind), click)


def test_a_click_on_stop_with_a_box_over_preferences_stops(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    drive_on(qtbot, window)

    def box_over(preferences):
        box = plain_message_box(preferences, QMessageBox.Icon.Warning, "Rockly", "Over Preferences")
        box.open()
        qtbot.waitUntil(box.isVisible)
        click_stop(window)
        done = stopped(qtbot, window)
        box.reject()
        return done

    assert while_open(qtbot, window.show_preferences, lambda: open_dialog(window, PreferencesDialog), box_over)


def test_other_clicks_on_the_window_still_wait_for_the_dialog(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    drive_on(qtbot, window)
    run_button = window.run_toolbar.widgetForAction(window.run_toolbar.pause_action)

    def click_pause(_box):
        QTest.mouseClick(window.windowHandle(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                         run_button.mapTo(window, run_button.rect().center()))
        return window.runs.state

    assert while_open(qtbot, lambda: a_message_box(window), lambda: open_dialog(window, QMessageBox),
                      click_pause) == "running"
    window.runs.stop()
    assert stopped(qtbot, window)


def test_the_window_under_a_dialog_gives_the_keys_back_to_the_dialog(qtbot, window):
    def activate_the_window(box):
        window.activateWindow()  # as a window manager may do on a click, or Alt+Tab
        qtbot.waitUntil(lambda: QApplication.focusWindow() is box.windowHandle())
        return True

    assert while_open(qtbot, lambda: a_message_box(window), lambda: open_dialog(window, QMessageBox),
                      activate_the_window)


def test_the_first_esc_in_a_dialogs_text_field_stops_the_robot(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    drive_on(qtbot, window)

    def esc_in_the_name_field(dialog):
        field = dialog.findChild(QLineEdit, "fileNameEdit")
        field.setFocus()
        qtbot.waitUntil(lambda: QApplication.focusWidget() is field)
        QTest.keyClick(dialog.windowHandle(), Qt.Key.Key_Escape)  # as the keyboard sends it: to the field
        return stopped(qtbot, window)

    assert while_open(qtbot, lambda: save_as_with_ctrl_s(window), lambda: open_dialog(window, QFileDialog),
                      esc_in_the_name_field)


def test_the_first_click_on_stop_with_a_menu_open_stops(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    drive_on(qtbot, window)
    file_menu = window.menuBar().actions()[0]
    QTest.mouseClick(window.windowHandle(), Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier,
                     window.menuBar().mapTo(window, window.menuBar().actionGeometry(file_menu).center()))
    qtbot.waitUntil(file_menu.menu().isVisible)
    click_stop(window)
    assert stopped(qtbot, window)
    qtbot.waitUntil(lambda: not file_menu.menu().isVisible())  # the same click closed the menu


def twists(recorder):
    """The (linear x, angular z) of every Twist seen on /cmd_vel."""
    values = [struct.unpack("<6d", data) for _type, data in recorder.on("/cmd_vel")]
    return [(twist[0], twist[5]) for twist in values]


def motion_commands(recorder):
    """The texts seen on HOBBIT's /DiscreteMotionCmd (a std_msgs/String: its length, then its bytes)."""
    return [data[4:].decode() for _type, data in recorder.on("/DiscreteMotionCmd")]


def test_a_click_on_stop_with_a_dialog_open_stops_hobbit_on_the_ros1_wire(qtbot, window, ros_master, hobbit_on_ros,
                                                                          monkeypatch):
    on_hobbit_over_ros1(window, ros_master.uri, monkeypatch)
    qtbot.waitUntil(lambda: "ROS connected" in window.robots.status.text(), timeout=10000)
    recorder = WireRecorder(ros_master, ["/cmd_vel", "/DiscreteMotionCmd"])  # a node in a process of its own
    try:
        load(qtbot, window, block("hobbit_turn", {"direction": "+"}, {"angle": number(3600)}))  # on the spot
        assert window.runs.run()
        qtbot.waitUntil(lambda: any(command.startswith("Turn") for command in motion_commands(recorder)),
                        timeout=15000)

        def click(_box):
            assert twists(recorder) == []  # nothing stopped the turn yet
            click_stop(window)
            qtbot.waitUntil(lambda: set(twists(recorder)) == {(0, 0)} and motion_commands(recorder)[-1] == "Stop",
                            timeout=5000)
            qtbot.waitUntil(lambda: window.runs.state == "idle", timeout=5000)
            return window.runs.last_result.outcome

        assert while_open(qtbot, lambda: a_message_box(window), lambda: open_dialog(window, QMessageBox),
                          click) == "stopped"
    finally:
        recorder.stop()


def test_a_click_on_stop_without_a_dialog_still_stops(qtbot, driver):
    window = driver.open_window(simulator_speed=1.0)
    drive_on(qtbot, window)
    click_stop(window)
    assert stopped(qtbot, window)

