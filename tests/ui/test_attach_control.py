"""The window attached to a run on the robot (``rockly agent --backend sim`` in a process of its own), as a user
tries it: breakpoints set in the window pause the robot's run, the timeline records what the window saw,
attaching never waits on the window's thread, a second window watches (and its STOP stops the robot, it takes
control when the first goes), and attaching again after a lost connection shows the run as it is."""
import json
import socket
import subprocess

import pytest
from agent_tools import REPO, AgentProcess
from page_tools import call_page, run_js
from program_builder import block, number, stack, workspace
from PySide6.QtCore import QTimer
from screenshots import screenshot
from standalone_tools import environment, export_standalone
from test_running import highlighted
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient


def two_drives():
    """count := 7, drive 1 m, print "half way", drive 1 m, print "done"."""
    return stack(block("variables_set", {"VAR": {"id": "count"}}, {"VALUE": number(7)}, id="count"),
                 block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": "half way"})}, id="half"),
                 block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="again"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": "done"})}, id="tell"))


def program_workspace():
    return {**workspace(two_drives()), "variables": [{"name": "count", "id": "count"}]}


@pytest.fixture(scope="module")
def exported(tmp_path_factory):
    folder = tmp_path_factory.mktemp("attach-control-program")
    source = folder / "drives.rockly"
    source.write_text(json.dumps({"format": "rockly-program", "version": 1, "profile": "hobbit",
                                  "workspace": program_workspace()}))
    env = environment(XDG_CONFIG_HOME=str(folder / "config"), XDG_DATA_HOME=str(folder / "data"))
    return export_standalone(source, folder / "drives.py", "--language", "en", env=env).read_text()


class Robot:
    """An agent at ``speed`` times real time, the program kept (keep going), and a client watching every event."""

    def __init__(self, library, program, speed):
        self.agent = AgentProcess(library, "--speed", speed)
        self.port = self.agent.port
        self.events = []
        self.watcher = AgentClient("127.0.0.1", self.port, on_event=self.events.append)
        self.watcher.send("drives", program, on_lost_editor="keep_going")
        self.watcher.attach(control=False)

    def start(self):
        """Start the program and wait until it drives."""
        self.watcher.start("drives")
        eventually(lambda: (self.watcher.programs()["run"] or {}).get("block") == "drive", 60)

    def event(self, wanted, timeout=60):
        eventually(lambda: any(wanted(event) for event in list(self.events)), timeout)
        return next(event for event in list(self.events) if wanted(event))

    def close(self):
        self.watcher.close()
        self.agent.stop()


@pytest.fixture
def robot_at(tmp_path, exported):
    made = []

    def make(speed):
        made.append(Robot(tmp_path / f"library-{len(made)}", exported, speed))
        return made[-1]
    yield make
    for robot in made:
        robot.close()


@pytest.fixture
def attach(qtbot, window):
    """Attach the window to the agent at ``port``, as the dialog and the robot bar do; wait until it is."""
    def attached(port):
        with qtbot.waitSignal(window.attached.sig_attached, timeout=20000):
            window.attached.attach("127.0.0.1", port)
    yield attached
    window.attached.detach()
    window.attached.calls.wait(30)


@pytest.fixture
def controlling_process():
    """``rockly robot attach`` (another client controlling the run) in a process of its own."""
    started = []

    def start(robot):
        process = subprocess.Popen(robot.agent.robot_command("attach"), cwd=REPO, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True)
        started.append(process)
        answer = json.loads(process.stdout.readline())
        assert answer["controller"]
        return process
    yield start
    for process in started:
        if process.poll() is None:
            process.kill()
        process.wait(30)
        process.stdout.close()
        process.stderr.close()


def toggle_breakpoint(qtbot, window, block_id):
    """Set or clear a breakpoint on ``block_id`` from its block menu, as a user does."""
    with qtbot.waitSignal(window.editor.sig_breakpoints, timeout=5000):
        run_js(qtbot, window.editor, "Blockly.ContextMenuRegistry.registry.getItem('rocklyBreakpoint')"
                                     f".callback({{block: Blockly.getMainWorkspace().getBlockById('{block_id}')}})")


def paused_at(block_id):
    return lambda event: event.get("event") == "paused" and event.get("block") == block_id


def test_breakpoints_set_before_and_while_attached_pause_the_robots_run_and_continue_and_step_work(
        qtbot, window, robot_at, attach):
    robot = robot_at(0.25)  # each drive takes 4 s
    call_page(qtbot, window.editor, "load", {"workspace": program_workspace()})
    toggle_breakpoint(qtbot, window, "half")  # before attaching: sent on attach
    robot.start()
    attach(robot.port)
    assert robot.event(paused_at("half"))["reason"] == "breakpoint"
    qtbot.waitUntil(lambda: window.attached.state == "paused" and highlighted(qtbot, window) == ["half"],
                    timeout=20000)
    assert window.run_toolbar.continue_action.isEnabled() and window.run_toolbar.step_action.isEnabled()
    assert window.statusBar().currentMessage() == "Paused at a breakpoint"
    toggle_breakpoint(qtbot, window, "tell")  # while attached: sent at once
    eventually(lambda: robot.watcher.programs()["run"]["breakpoints"] == ["half", "tell"])
    window.run_toolbar.continue_action.trigger()
    assert robot.event(paused_at("tell"))["reason"] == "breakpoint"
    qtbot.waitUntil(lambda: window.attached.state == "paused" and highlighted(qtbot, window) == ["tell"],
                    timeout=20000)
    window.run_toolbar.step_action.trigger()
    assert robot.event(lambda event: event.get("event") == "finished")["outcome"] == "finished"
    qtbot.waitUntil(lambda: not window.attached.active, timeout=20000)
    assert "done" in window.console.lines()
    assert window.statusBar().currentMessage() == ""


def test_the_timeline_records_what_the_window_saw_and_the_replay_shows_it_after_the_run(
        qtbot, window, robot_at, attach):
    robot = robot_at(0.25)
    call_page(qtbot, window.editor, "load", {"workspace": program_workspace()})
    toggle_breakpoint(qtbot, window, "half")
    robot.start()
    attach(robot.port)
    qtbot.waitUntil(lambda: window.attached.state == "paused", timeout=30000)
    assert not window.replay_bar.isVisible()
    window.run_toolbar.stop_action.trigger()
    assert robot.event(lambda event: event.get("event") == "finished")["outcome"] == "stopped"
    qtbot.waitUntil(lambda: not window.attached.active and window.replay_bar.isVisible(), timeout=30000)
    assert "breakpoint" in [marker.kind for marker in window.replay_bar.markers.markers]
    window.replay.show_moment(0.0)  # the moment of attaching: the drive
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    window.replay.show_moment(window.replay.moments.duration)  # the pause at the breakpoint, and the STOP
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["half"], timeout=10000)
    assert window.variables.values() == {"count": "7"}


def test_attaching_returns_at_once_and_an_agent_that_does_not_answer_or_is_not_there_is_said(qtbot, window):
    silent = socket.socket()  # takes the connection and never answers
    silent.bind(("127.0.0.1", 0))
    silent.listen(1)
    port = silent.getsockname()[1]
    ticks = []
    timer = QTimer()
    timer.timeout.connect(lambda: ticks.append(1))
    timer.start(10)
    try:
        with qtbot.waitSignal(window.attached.sig_attach_failed, timeout=30000) as failed:
            window.attached.attach("127.0.0.1", port)  # returns at once: the window's event loop goes on
            qtbot.waitUntil(lambda: len(ticks) >= 20, timeout=3000)
        assert failed.args == [f"the robot's agent at 127.0.0.1:{port} did not answer within 5 s "
                               "(is the network to the robot slow or cut?)"]
    finally:
        timer.stop()
        silent.close()
    with qtbot.waitSignal(window.attached.sig_attach_failed, timeout=30000) as refused:
        window.attached.attach("127.0.0.1", port)  # nobody listens there now
    assert refused.args[0].startswith(f"the robot's agent at 127.0.0.1:{port} cannot be reached")
    assert not window.attached.active and window.run_toolbar.run_action.isEnabled()
    window.attached.calls.wait(30)


def test_a_window_watching_a_run_another_controls_is_told_has_no_pause_and_its_stop_stops_the_robot(
        qtbot, window, robot_at, attach, controlling_process):
    robot = robot_at(0.25)
    robot.start()
    controlling_process(robot)
    attach(robot.port)
    assert ("Another window controls this run: this window watches it. Pause, Step and Continue are that window's; "
            "STOP here still stops the robot." in window.console.lines())
    toolbar = window.run_toolbar
    assert not toolbar.pause_action.isEnabled() and not toolbar.step_action.isEnabled()
    assert toolbar.pause_action.toolTip().startswith("Another window controls this run on the robot")
    assert toolbar.stop_action.isEnabled()
    screenshot(window, "attach_watching")
    toolbar.stop_action.trigger()
    assert robot.event(lambda event: event.get("event") == "finished")["outcome"] == "stopped"
    qtbot.waitUntil(lambda: not window.attached.active, timeout=30000)
    assert toolbar.pause_action.toolTip() != toolbar.stop_action.toolTip()
    assert not toolbar.pause_action.toolTip().startswith("Another window")


def test_the_watching_window_takes_control_when_the_controlling_one_goes(
        qtbot, window, robot_at, attach, controlling_process):
    robot = robot_at(0.1)  # each drive takes 10 s
    robot.start()
    editor = controlling_process(robot)
    attach(robot.port)
    assert not window.run_toolbar.pause_action.isEnabled()
    editor.kill()  # the controlling window gone
    qtbot.waitUntil(lambda: window.run_toolbar.pause_action.isEnabled(), timeout=20000)
    assert ("The window that controlled the run has gone: this window controls it now (its breakpoints apply)."
            in window.console.lines())
    window.run_toolbar.pause_action.trigger()
    robot.event(lambda event: event.get("event") == "paused")
    qtbot.waitUntil(lambda: window.attached.state == "paused", timeout=20000)
    window.run_toolbar.stop_action.trigger()
    qtbot.waitUntil(lambda: not window.attached.active, timeout=30000)


def test_attaching_again_after_the_connection_was_lost_shows_the_running_block_and_the_variables_at_once(
        qtbot, window, robot_at, attach):
    robot = robot_at(0.05)  # the first drive takes 20 s
    call_page(qtbot, window.editor, "load", {"workspace": program_workspace()})
    robot.start()
    attach(robot.port)
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"] and window.variables.values() == {"count": "7"},
                    timeout=10000)  # the variables while the run goes on
    window.attached.client._line._socket.shutdown(socket.SHUT_RDWR)  # the network to the robot gone
    qtbot.waitUntil(lambda: not window.attached.active, timeout=20000)
    assert ("The connection to the robot's agent was lost: the window is no longer attached."
            in window.console.lines())
    window.variables.clear()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == [], timeout=10000)
    attach(robot.port)
    assert window.variables.values() == {"count": "7"}  # from the run's state, at once
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    assert window.attached.state == "running"


def test_the_robot_bar_shows_what_the_agent_runs_and_attaches_in_one_click_and_shows_nothing_without_one(
        qtbot, window, robot_at):
    robot = robot_at(0.05)
    call_page(qtbot, window.editor, "load", {"workspace": program_workspace()})
    robot.start()
    bar = window.agent_bar
    assert not bar.isVisible()  # no agent known
    window.settings.agent_address = f"127.0.0.1:{robot.port}"  # where the Programs dialog reached it
    window.robots.sig_robot_changed.emit()  # the robot chosen again
    qtbot.waitUntil(bar.isVisible, timeout=20000)
    assert (bar.label.text(), bar.attach_button.text()) == ("On the robot: drives — running", "Attach")
    screenshot(window.statusBar(), "attach_robot_bar")
    with qtbot.waitSignal(window.attached.sig_attached, timeout=20000):
        bar.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["drive"], timeout=10000)
    assert not bar.isVisible()  # attached: the toolbar and the glowing block say the rest
    window.attached.detach()
    qtbot.waitUntil(bar.isVisible, timeout=20000)  # still running there
    nobody = socket.socket()
    nobody.bind(("127.0.0.1", 0))
    free_port = nobody.getsockname()[1]
    nobody.close()
    window.settings.agent_address = f"127.0.0.1:{free_port}"
    bar.look()
    qtbot.waitUntil(lambda: not bar.isVisible() and not bar.calls.busy, timeout=20000)
    bar.stop()
    bar.calls.wait(30)
    window.attached.calls.wait(30)
