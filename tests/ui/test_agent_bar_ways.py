"""The robot bar asks a ROS robot's agent the way the Programs dialog reaches it (over the robot's graph first), and
a look that finds no ROS node or helper of the window's own starts none: it would otherwise start one every
``LOOK_MS``."""
import pytest

from rockly_desktop.robot.ros1.connection import RosConnection
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.runtime.agent.protocol import DEFAULT_PORT
from rockly_desktop.ui.agent.agent_bar import AgentBar, AgentWay


def test_the_window_asks_a_ros_robots_agent_over_its_graph_first(window):
    assert window._agent_way() is None  # the simulator, no agent ever reached
    window.settings.agent_address = "robot.local:7000"
    assert window._agent_way() == AgentWay("robot.local", 7000)
    chosen, window.robots.kind = window.robots.kind, "ros2"  # as chosen, without its link being opened
    try:
        assert window._agent_way() == AgentWay("robot.local", 7000, "auto", "ros2")
        window.settings.agent_address = ""
        assert window._agent_way() == AgentWay(None, DEFAULT_PORT, "auto", "ros2")
    finally:
        window.robots.kind = chosen


@pytest.mark.parametrize("kind", ["ros1", "ros2"])
def test_a_look_on_a_graph_the_window_is_not_on_starts_no_node_or_helper(qtbot, window, kind):
    at_hand = (RosConnection._instance, Ros2Helper.running())
    bar = AgentBar(window.attached, lambda: "en", lambda: AgentWay(None, DEFAULT_PORT, "auto", kind), window)
    bar.look()
    qtbot.waitUntil(lambda: not bar.calls.busy, timeout=20000)
    assert bar.shown_at is None and not bar.isVisible()
    assert (RosConnection._instance, Ros2Helper.running()) == at_hand
    bar.stop()
    bar.calls.wait(30)
