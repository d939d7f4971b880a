"""The ROS 2 graph's services, actions and parameters as the link reads them (for the block maker),
against the plain test node and a node whose parameter listing never answers."""
import time
from pathlib import Path

import pytest
from json_line_node import JsonLineNode
from ros2_fixtures import TEST_ROBOT_PYTHON
from waiting import eventually

MUTE_NODE = Path(__file__).parent / "ros2_mute_parameters_node.py"


@pytest.fixture
def mute_node(ros2_settings):
    node = JsonLineNode([TEST_ROBOT_PYTHON, MUTE_NODE], ros2_settings.environment(), "the mute parameters node")
    yield node
    node.stop()


def test_the_links_graph_has_the_test_nodes_service_action_and_parameters(ros2_robot):
    ros2_robot.follow_graph()
    eventually(lambda: "/test_robot:max_speed" in ros2_robot.graph_parameters(), timeout=30)
    assert "/test_robot:robot_name" in ros2_robot.graph_parameters()
    assert ("/set_light", "std_srvs/SetBool") in ros2_robot.graph_services()
    assert ("/fibonacci", "test_msgs/FibonacciAction") in ros2_robot.graph_actions()


def test_a_node_that_never_lists_its_parameters_holds_the_listing_up_no_longer_than_its_bound(ros2_robot, mute_node):
    eventually(lambda: "/mute/list_parameters" in ros2_robot.helper.call("graph", timeout=10)["services"], timeout=30)
    for _try in range(2):  # the first ask of a new server may be lost; either way the bound holds
        started = time.monotonic()
        names = ros2_robot.helper.call("parameters", 1.0, timeout=30)
        assert time.monotonic() - started < 8  # 1 s bound; generous on a loaded machine
    assert "/test_robot:max_speed" in names and not [name for name in names if name.startswith("/mute")]
