"""The window on a ROS 2 robot reaches the robot's agent over ROS 2 (``rockly agent --backend ros2`` in a process of
its own on the test run's domain, beside a plain rclpy test robot): Robot → Programs on the robot lists, attaches
and STOPs without any TCP address that works; the robot bar shows the run and attaches in one click."""
import subprocess
import sys

import pytest
from agent_tools import REPO, AgentProcess
from program_builder import rockly_document
from standalone_tools import environment, export_standalone
from test_attach_window_over_ros import bar_shows_and_attaches, linger, open_and_attach
from test_ros2_window import connected


@pytest.fixture
def running(ros2_settings, test_robot, tmp_path):
    """An agent on the test run's domain running "linger", kept going without an editor; ``robot(*args)`` runs
    ``rockly robot --via ros --domain N`` against it."""
    source = tmp_path / "linger.rockly"
    source.write_text(rockly_document([linger()]))
    env = environment(XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    exported = export_standalone(source, tmp_path / "linger.py", "--language", "en", env=env)
    agent = AgentProcess(tmp_path / "library", "--domain", ros2_settings.domain_id, "--discovery", "localhost",
                         backend="ros2", env=ros2_settings.environment())

    def robot(*args):
        return subprocess.run([sys.executable, "-m", "rockly_desktop", "robot", "--via", "ros", "--domain",
                               str(ros2_settings.domain_id), "--language", "en", *map(str, args)],
                              capture_output=True, text=True, timeout=120, cwd=REPO, env=ros2_settings.environment())
    sent = robot("send", exported, "--name", "linger", "--keep-going")
    assert sent.returncode == 0, sent.stderr
    begun = robot("start", "linger")
    assert begun.returncode == 0, begun.stderr
    yield agent, robot
    robot("stop")
    agent.stop()


def test_the_window_on_a_ros2_robot_lists_attaches_and_stops_over_ros2(qtbot, window, ros2_settings, running,
                                                                         monkeypatch):
    _agent, robot = running
    ros2_window = connected(window, ros2_settings, monkeypatch)
    dialog = open_and_attach(qtbot, ros2_window)
    try:
        assert ros2_window.attached.client.via == "ros" and ros2_window.attached.client.kind == "ros2"
        assert "hello" in ros2_window.console.lines()
        assert (f"Attached to 'linger' running on the robot at domain {ros2_settings.domain_id}, localhost "
                "(/rockly_agent)" in ros2_window.console.lines())
        ros2_window.run_toolbar.stop_action.trigger()
        qtbot.waitUntil(lambda: not ros2_window.attached.active, timeout=60000)
        assert "running:" not in robot("list").stdout
    finally:
        dialog.calls.wait(30)


def test_the_robot_bar_of_a_ros2_robot_shows_the_run_and_attaches_over_ros2(qtbot, window, ros2_settings, running,
                                                                          monkeypatch):
    agent, _robot = running
    ros2_window = connected(window, ros2_settings, monkeypatch)
    assert bar_shows_and_attaches(qtbot, ros2_window, agent, "agent_bar_over_ros2") == "ros2"
