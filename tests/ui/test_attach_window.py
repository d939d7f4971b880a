"""Attaching the window to a program that runs on the robot under its agent (``rockly agent --backend sim`` in a
process of its own): the running block glows, the Console fills, Pause and STOP act on the robot's run, and
closing the dialog or the window detaches without stopping a keep-going program; an agent that never answers
leaves the window responsive."""
import socket

import pytest
from agent_tools import AgentProcess
from page_tools import call_page
from program_builder import block, number, stack, workspace
from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QInputDialog
from screenshots import screenshot
from standalone_tools import exported_program
from test_running import highlighted
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.ui.agent.program_difference import same_program
from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog


def greet_and_drive(last="done"):
    """Print "hello", drive 1 m (20 s at the agent's slow simulated time), print ``last``."""
    return stack(block("text_print", inputs={"TEXT": block("text", {"TEXT": "hello"})}, id="greet"),
                 block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": last})}, id="tell"))


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    """The program's standalone export (as ``rockly export --standalone`` writes it) and its ``.rockly`` text."""
    standalone, source = exported_program(tmp_path_factory.mktemp("attach-program"), greet_and_drive())
    return standalone.read_text(), source.read_text()


@pytest.fixture
def robot(tmp_path, exported):
    """An agent with slow simulated time, running the program (kept going when the editor goes) at its drive."""
    agent = AgentProcess(tmp_path / "library", "--speed", 0.05)
    events = []
    watcher = AgentClient("127.0.0.1", agent.port, on_event=events.append)
    watcher.send("drive", *exported, on_lost_editor="keep_going")
    watcher.attach(control=False)
    watcher.start("drive")
    eventually(lambda: (watcher.programs()["run"] or {}).get("block") == "drive", 60)
    yield agent, watcher, events
    watcher.close()
    agent.stop()


ASKING = "Asking the robot…"


@pytest.fixture
def dialogs(qtbot):
    """Makes dialogs; at the end, waits for the threads of their calls to the agent to end."""
    made = []

    def make(window, port, **options):
        dialog = RobotProgramsDialog(window.attached, "en", window, host="127.0.0.1", port=port, **options)
        qtbot.addWidget(dialog)
        made.append(dialog)
        return dialog

    yield make
    for dialog in made:
        dialog.calls.wait(30)


def open_dialog(qtbot, window, agent, dialogs, program=None):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(program or greet_and_drive())})
    dialog = dialogs(window, agent.port, open_copy=lambda path, name: window.files.open_copy(path, name))
    dialog.show()
    dialog.refresh()
    qtbot.waitUntil(lambda: dialog.programs.count() == 1 and dialog.status.text() != ASKING, timeout=20000)
    assert [dialog.programs.item(row).text() for row in range(dialog.programs.count())] == ["drive  (hobbit 1.0.0)"]
    assert dialog.running.text() == "Running on the robot now: drive (running)"
    return dialog


def test_attached_the_block_glows_the_console_fills_and_pause_and_stop_reach_the_robot(qtbot, window, robot, dialogs):
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    assert "hello" in window.console.lines()
    screenshot(dialog, "attach_dialog")
    assert window.run_toolbar.pause_action.isEnabled() and window.run_toolbar.stop_action.isEnabled()
    window.run_toolbar.pause_action.trigger()
    eventually(lambda: any(event.get("event") == "paused" for event in list(events)), 60)
    qtbot.waitUntil(lambda: window.attached.state == "paused" and window.run_toolbar.continue_action.isEnabled(),
                    timeout=10000)
    assert window.runs.state == "idle"  # the window's own run never started
    screenshot(window, "attach_window_paused")
    window.run_toolbar.stop_action.trigger()
    eventually(lambda: any(event.get("event") == "finished" for event in list(events)), 60)
    finished = next(event for event in events if event.get("event") == "finished")
    assert finished["outcome"] == "stopped"
    qtbot.waitUntil(lambda: window.attached.state == "idle" and window.run_toolbar.run_action.isEnabled(),
                    timeout=20000)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == [], timeout=10000)


def test_closing_the_dialog_and_the_window_detaches_and_a_keep_going_program_finishes(qtbot, window, robot, dialogs):
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    dialog.close()
    assert window.attached.active  # the dialog is only the way in
    window.document.modified = False
    window.close()
    assert not window.attached.active
    assert (watcher.programs()["run"] or {}).get("state") == "running"  # no STOP was sent
    eventually(lambda: any(event.get("event") == "run" and event.get("state") == "ended" for event in list(events)),
               120)
    assert next(event for event in events if event.get("event") == "print" and event.get("text") == "done")
    finished = next(event for event in events if event.get("event") == "finished")
    assert finished["outcome"] == "finished"


def test_attaching_again_shows_the_current_state(qtbot, window, robot, dialogs):
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    window.attached.detach()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == [], timeout=10000)
    assert window.run_toolbar.run_action.isEnabled()
    qtbot.waitUntil(dialog.attach_button.isEnabled, timeout=20000)
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    assert window.attached.state == "running"
    watcher.stop()
    qtbot.waitUntil(lambda: not window.attached.active, timeout=60000)


def test_the_same_program_is_not_flagged_and_another_one_is_and_the_robots_copy_opens(qtbot, window, robot, dialogs):
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    with qtbot.waitSignal(window.attached.sig_state_changed, timeout=10000):
        dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    assert call_page(qtbot, window.editor, "getState", None)  # the comparison's page call has been answered
    assert dialog.difference.isHidden() and dialog.open_copy_button.isHidden()
    window.attached.detach()
    call_page(qtbot, window.editor, "load", {"workspace": workspace(greet_and_drive(last="bye"))})
    qtbot.waitUntil(dialog.attach_button.isEnabled, timeout=20000)
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: dialog.difference.isVisible() and dialog.open_copy_button.isVisible(), timeout=10000)
    assert dialog.difference.text() == "The program running on the robot is not the one open here."
    window.document.modified = False
    dialog.open_copy_button.click()
    qtbot.waitUntil(lambda: "'TEXT': 'done'" in str(call_page(qtbot, window.editor, "getState", None)), timeout=10000)
    assert window.attached.active  # opening the copy keeps the window attached
    watcher.stop()
    qtbot.waitUntil(lambda: not window.attached.active, timeout=60000)


def test_the_open_program_is_sent_exported_and_starts_on_the_robot(qtbot, window, tmp_path, dialogs):
    agent = AgentProcess(tmp_path / "library", "--speed", 20)
    events = []
    watcher = AgentClient("127.0.0.1", agent.port, on_event=events.append)
    try:
        watcher.attach(control=False)
        call_page(qtbot, window.editor, "load", {"workspace": workspace(greet_and_drive())})
        dialog = dialogs(window, agent.port, document=window.document,
                         limits=lambda: window.settings.teacher.limits("hobbit"))
        dialog.keep_going.setChecked(True)
        dialog.send_button.click()
        qtbot.waitUntil(lambda: dialog.findChild(QInputDialog) is not None, timeout=5000)
        dialog.findChild(QInputDialog).textValueSelected.emit("program")   # the name it is asked for
        qtbot.waitUntil(lambda: dialog.status.text() == "'program' is on the robot now", timeout=20000)
        [about] = watcher.programs()["programs"]
        assert (about["name"], about["on_lost_editor"]) == ("program", "keep_going")
        assert same_program(watcher.source("program"), workspace(greet_and_drive()))
        qtbot.waitUntil(lambda: dialog.programs.count() == 1, timeout=20000)
        dialog.programs.item(0).setSelected(True)
        assert dialog.start_button.isEnabled()   # once a program is chosen
        dialog.start_button.click()
        eventually(lambda: any(event.get("event") == "run" and event.get("state") == "ended" for event in list(events)),
                   120)
        assert [event["text"] for event in events if event.get("event") == "print"] == ["hello", "done"]
    finally:
        watcher.close()
        agent.stop()


def test_a_lost_connection_detaches_and_says_so(qtbot, window, robot, dialogs):
    agent, watcher, events = robot
    dialog = open_dialog(qtbot, window, agent, dialogs)
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    agent.process.kill()  # the agent gone at once, as a network cut looks to the window
    qtbot.waitUntil(lambda: not window.attached.active, timeout=20000)
    assert ("The connection to the robot's agent was lost: the window is no longer attached."
            in window.console.lines())
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == [], timeout=10000)
    assert window.run_toolbar.run_action.isEnabled()


def test_an_agent_that_never_answers_leaves_the_window_responsive(qtbot, window, dialogs):
    silent = socket.socket()  # takes the connection and never reads: the client's hello waits for an answer
    silent.bind(("127.0.0.1", 0))
    silent.listen(0)
    dialog = dialogs(window, silent.getsockname()[1])
    dialog.show()
    ticks = []
    timer = QTimer()
    timer.timeout.connect(lambda: ticks.append(1))
    timer.start(10)
    try:
        dialog.refresh_button.click()
        assert dialog.status.text() == ASKING
        assert not any(button.isEnabled() for button in (dialog.refresh_button, dialog.start_button,
                                                         dialog.stop_button, dialog.attach_button))
        qtbot.waitUntil(lambda: len(ticks) >= 20, timeout=3000)  # the window's event loop goes on meanwhile
        assert dialog.status.text() == ASKING
        dialog.close()  # closed while asking: its answer is never shown
        dialog.show()
        assert dialog.refresh_button.isEnabled()
    finally:
        timer.stop()
        silent.close()  # the waiting connection is reset: the call ends
    qtbot.waitUntil(lambda: not dialog.calls.busy, timeout=30000)
    assert dialog.status.text() == ASKING
    dialog.refresh_button.click()
    qtbot.waitUntil(lambda: dialog.status.text() != ASKING, timeout=30000)
    assert "127.0.0.1" in dialog.status.text()  # the agent cannot be reached now: said, as before
