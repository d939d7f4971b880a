"""The window on a ROS 1 robot reaches the robot's agent over ROS (``rockly agent --backend ros1`` in a process of
its own on the session's master, beside ``rockly sim hobbit --ros``): Robot → Programs on the robot lists, attaches
and STOPs without any TCP address that works, the robot bar shows the run and attaches in one click; an agent
killed mid-run is heard as a lost connection."""
import subprocess
import sys

import pytest
from agent_tools import REPO, AgentProcess
from page_tools import call_page
from program_builder import block, number, rockly_document, stack, workspace
from ros_helpers import ros_environment
from screenshots import screenshot
from standalone_tools import environment, export_standalone
from test_running import highlighted
from window_tools import on_hobbit_over_ros1

from rockly_desktop.runtime.agent.protocol import DEFAULT_PORT
from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog


def linger():
    """Print, wait long, print."""
    return stack(block("text_print", inputs={"TEXT": block("text", {"TEXT": "hello"})}, id="greet"),
                 block("hobbit_wait", inputs={"seconds": number(1000)}, id="linger"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": "done"})}, id="tell"))


@pytest.fixture
def ros_window(window, ros_master, hobbit_on_ros, monkeypatch):
    return on_hobbit_over_ros1(window, ros_master.uri, monkeypatch)


@pytest.fixture
def running(ros_master, hobbit_on_ros, tmp_path):
    """An agent on the session's master running "linger", kept going without an editor;
    ``robot(*args)`` runs ``rockly robot --via ros`` against it."""
    source = tmp_path / "linger.rockly"
    source.write_text(rockly_document([linger()]))
    env = environment(XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    exported = export_standalone(source, tmp_path / "linger.py", "--language", "en", env=env)
    ros_env = ros_environment(ros_master.uri, tmp_path / "ros")
    agent = AgentProcess(tmp_path / "library", "--master", ros_master.uri, backend="ros1", env=ros_env)

    def robot(*args):
        return subprocess.run([sys.executable, "-m", "rockly_desktop", "robot", "--via", "ros", "--master",
                               ros_master.uri, "--language", "en", *map(str, args)], capture_output=True, text=True,
                              timeout=120, cwd=REPO, env=ros_env)
    assert robot("send", exported, "--name", "linger", "--keep-going").returncode == 0
    assert robot("start", "linger").returncode == 0
    yield agent, robot
    robot("stop")
    agent.stop()


def open_and_attach(qtbot, window):
    call_page(qtbot, window.editor, "load", {"workspace": workspace(linger())})
    window.show_robot_programs()
    dialog = window.findChild(RobotProgramsDialog)
    dialog.refresh_button.click()  # asked over ROS: nothing listens on the dialog's TCP address
    qtbot.waitUntil(lambda: dialog.programs.count() == 1 and dialog.attach_button.isEnabled(), timeout=30000)
    assert dialog.running.text().startswith("Running on the robot now: linger")
    dialog.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["linger"], timeout=30000)
    return dialog


def bar_shows_and_attaches(qtbot, window, agent, name: str):
    """The robot bar of ``window`` (its robot chosen on the agent's ROS graph, no TCP way to ``agent``) says
    ``agent`` runs "linger" and its Attach attaches over ROS; returns the ROS it attached over."""
    call_page(qtbot, window.editor, "load", {"workspace": workspace(linger())})
    assert window._agent_address() in (None, ("127.0.0.1", DEFAULT_PORT)) and agent.port != DEFAULT_PORT
    bar = window.agent_bar
    window.robots.sig_robot_changed.emit()  # the robot chosen again, the agent now running
    qtbot.waitUntil(bar.isVisible, timeout=30000)
    assert (bar.label.text(), bar.attach_button.text()) == ("On the robot: linger — running", "Attach")
    window.resize(1280, window.height())  # wide enough for the status bar's parts side by side
    screenshot(window, name)
    with qtbot.waitSignal(window.attached.sig_attached, timeout=30000):
        bar.attach_button.click()
    qtbot.waitUntil(lambda: highlighted(qtbot, window) == ["linger"], timeout=30000)
    assert window.attached.active and window.attached.client.via == "ros"
    assert not bar.isVisible()  # attached: the toolbar and the glowing block say the rest
    kind = window.attached.client.kind
    bar.stop()
    window.attached.detach()
    bar.calls.wait(30)
    window.attached.calls.wait(30)
    return kind


def test_the_robot_bar_of_a_ros_robot_shows_the_run_and_attaches_over_ros(qtbot, ros_window, running):
    agent, _robot = running
    assert bar_shows_and_attaches(qtbot, ros_window, agent, "agent_bar_over_ros1") == "ros1"


def test_the_window_on_a_ros_robot_lists_attaches_and_stops_over_ros(qtbot, ros_window, running, ros_master):
    _agent, robot = running
    dialog = open_and_attach(qtbot, ros_window)
    try:
        assert ros_window.attached.client.via == "ros"  # the dialog opens on the master's host; ROS was taken
        assert "hello" in ros_window.console.lines()
        assert (f"Attached to 'linger' running on the robot at {ros_master.uri} (/rockly_agent)"
                in ros_window.console.lines())
        ros_window.run_toolbar.stop_action.trigger()
        qtbot.waitUntil(lambda: not ros_window.attached.active, timeout=60000)
        assert "running:" not in robot("list").stdout
    finally:
        dialog.calls.wait(30)


def test_an_agent_killed_mid_run_is_a_lost_connection_over_ros(qtbot, ros_window, running):
    agent, _robot = running
    dialog = open_and_attach(qtbot, ros_window)
    try:
        agent.process.kill()
        qtbot.waitUntil(lambda: not ros_window.attached.active, timeout=30000)
        assert ("The connection to the robot's agent was lost: the window is no longer attached."
                in ros_window.console.lines())
    finally:
        dialog.calls.wait(30)
