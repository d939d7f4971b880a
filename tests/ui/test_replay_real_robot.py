"""Replaying a real robot's run (ROS 1: a real master, the ROS-level HOBBIT in its own process): no
simulator snapshots, so the Simulator dock shows a plan view of the recorded /odom and the Robot
state panels show the recorded topics at the moment."""
import math

import pytest
from page_tools import call_page
from program_builder import block, number, stack, workspace
from test_replay import shot

from rockly_desktop.recording import channels
from rockly_desktop.recording.odometry import RecordedPath
from rockly_desktop.robot.links import link_kind
from rockly_desktop.ui.docks.plan_view import PlanView
from rockly_desktop.ui.robot.connection_dialog import ConnectionDialog

ROS1 = link_kind("ros1")


@pytest.fixture
def ros_window(window, ros_master, hobbit_on_ros, monkeypatch):
    window.settings.remember_link_connection(ROS1, "hobbit", {"master": ros_master.uri, "host": "127.0.0.1"})
    monkeypatch.setattr(ConnectionDialog, "exec", lambda dialog: 1)
    backend = window.run_toolbar.backend
    backend.setCurrentIndex(backend.findData("ros1"))
    assert window.robots.kind == "ros1"
    return window


def test_a_real_robots_replay_shows_its_recorded_path_in_plan_and_its_state_then(qtbot, ros_window):
    window = ros_window
    qtbot.waitUntil(lambda: window.robot().state.latest("/odom") is not None, timeout=10000)
    assert window.simulator_dock.isHidden()  # a real robot has no simulator view
    window.settings.recording_topic_rate = 100  # the ROS-level HOBBIT runs 20 times faster than time: a finer path
    call_page(qtbot, window.editor, "load", {"workspace": workspace(stack(
        block("hobbit_move", {"direction": "+"}, {"speed": number(0.6)}, id="ahead"),
        block("hobbit_turn", {"direction": "+"}, {"angle": number(90)}, id="left"),
        block("hobbit_move", {"direction": "+"}, {"speed": number(0.4)}, id="on")))})
    with qtbot.waitSignal(window.runs.sig_finished, timeout=30000) as blocker:
        assert window.runs.run()
    assert blocker.args[0].outcome == "finished", blocker.args[0]
    qtbot.waitUntil(window.replay_bar.isVisible, timeout=5000)
    recording = window.replay.moments.recording
    assert recording.on(channels.SIMULATOR) == []
    path = RecordedPath(window.replay.topics)
    assert len(path.poses) > 3
    # it turned left and drove on (from wherever and however the session's robot was left by earlier tests)
    assert (path.poses[-1][2] - path.poses[0][2]) % (2 * math.pi) == pytest.approx(math.pi / 2, abs=0.2)
    assert math.dist(path.poses[-1][:2], path.poses[0][:2]) > 0.5

    last_leg = next(entry.time for entry in recording.on(channels.BLOCKS) if entry.data["block"] == "on")
    window.replay_bar.jump_to((last_leg + window.replay_bar.duration) / 2)  # on its way after the turn
    qtbot.waitUntil(lambda: isinstance(window.simulator_dock.widget(), PlanView), timeout=5000)
    plan = window.simulator_dock.widget()
    moment = window.replay_bar.position
    assert plan.isVisible() and not window.simulator_dock.isHidden()
    assert plan.poses == path.until(moment) and plan.poses[-1] == path.until(moment)[-1]
    x = window.replay.topics.latest_at("/odom", moment)["pose"]["pose"]["position"]["x"]
    qtbot.waitUntil(lambda: window.state_dock.widget().values()["Position x"] == f"{x:.2f} m", timeout=5000)
    window.state_dock.raise_()
    shot(window, "replay_real_robot_plan")
    shot(plan, "replay_real_robot_plan_only")

    window.replay_bar.close_timeline()
    assert window.simulator_dock.isHidden() and not isinstance(window.simulator_dock.widget(), PlanView)
    assert window.state_dock.widget().store is window.robot().state
