"""What the "Programs on the robot" dialog says stays true (issue 29, item 17), against a real agent process: the
list and what runs follow the robot while the dialog is open, a wrong port leaves no old list, Start waits for a
chosen program, an unsaved program is sent under a name the person gives, STOP's end is said once, and while
attached the Simulator dock says it is not the robot."""
from agent_tools import AgentProcess
from page_tools import call_page
from program_builder import workspace
from PySide6.QtCore import Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QInputDialog, QLineEdit
from ros_helpers import free_port
from test_attach_window import dialogs, exported, greet_and_drive, open_dialog, robot  # noqa: F401 (fixtures)
from test_running import highlighted
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient

NOTHING_RUNS = "Nothing runs on the robot now."


def test_what_runs_follows_the_robot_while_the_dialog_is_open(qtbot, window, robot, dialogs):  # noqa: F811
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)   # says "drive (running)"
    watcher.stop()   # the robot's run ends; nobody presses Show programs
    qtbot.waitUntil(lambda: dialog.running.text() == NOTHING_RUNS, timeout=20000)
    assert not dialog.attach_button.isEnabled()


def test_a_wrong_port_leaves_no_old_list(qtbot, window, robot, dialogs):  # noqa: F811
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    dialog.port.setValue(free_port())   # nobody listens there
    dialog.refresh_button.click()
    qtbot.waitUntil(lambda: dialog.programs.count() == 0 and dialog.running.text() == "", timeout=20000)
    assert dialog.status.text() and not dialog.start_button.isEnabled() and not dialog.attach_button.isEnabled()


def test_start_waits_for_a_chosen_program(qtbot, window, tmp_path, dialogs, exported):  # noqa: F811
    agent = AgentProcess(tmp_path / "library", "--speed", 20)
    watcher = AgentClient("127.0.0.1", agent.port)
    try:
        watcher.send("drive", *exported)
        dialog = dialogs(window, agent.port)
        dialog.show()
        dialog.refresh()
        qtbot.waitUntil(lambda: dialog.programs.count() == 1 and dialog.running.text() == NOTHING_RUNS, timeout=20000)
        assert dialog.chosen() is None and not dialog.start_button.isEnabled()
        row = dialog.programs.visualItemRect(dialog.programs.item(0)).center()
        QTest.mouseClick(dialog.programs.viewport(), Qt.MouseButton.LeftButton, pos=row)
        assert dialog.chosen() == "drive" and dialog.start_button.isEnabled()
    finally:
        watcher.close()
        agent.stop()


def test_an_unsaved_program_is_sent_under_the_name_the_person_gives(qtbot, window, tmp_path, dialogs):  # noqa: F811
    agent = AgentProcess(tmp_path / "library", "--speed", 20)
    watcher = AgentClient("127.0.0.1", agent.port)
    try:
        call_page(qtbot, window.editor, "load", {"workspace": workspace(greet_and_drive())})
        assert window.document.path is None
        dialog = dialogs(window, agent.port, document=window.document,
                         limits=lambda: window.settings.teacher.limits("hobbit"))
        dialog.show()
        dialog.send_button.click()
        qtbot.waitUntil(lambda: dialog.findChild(QInputDialog) is not None
                        and dialog.findChild(QInputDialog).isVisible(), timeout=5000)
        asked = dialog.findChild(QInputDialog)
        QTest.keyClicks(asked.findChild(QLineEdit), "greeting")
        QTest.keyClick(asked.findChild(QLineEdit), Qt.Key.Key_Return)
        qtbot.waitUntil(lambda: dialog.status.text() == "'greeting' is on the robot now", timeout=20000)
        assert [about["name"] for about in watcher.programs()["programs"]] == ["greeting"]
    finally:
        watcher.close()
        agent.stop()


def test_after_stop_the_console_says_the_run_ended_and_not_that_it_goes_on(qtbot, window, robot, dialogs):  # noqa: F811
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    assert window.simulator_dock.windowTitle() == "Simulator"
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    assert window.simulator_dock.windowTitle() == "Simulator — on this computer, not the robot"
    window.run_toolbar.stop_action.trigger()
    eventually(lambda: any(event.get("event") == "finished" for event in list(events)), 60)
    qtbot.waitUntil(lambda: not window.attached.active, timeout=20000)
    lines = window.console.lines()
    assert "'drive' has ended on the robot." in lines
    assert not [line for line in lines if "goes on" in line], lines
    assert window.simulator_dock.windowTitle() == "Simulator"
