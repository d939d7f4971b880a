"""The ROS 2 graph's services, actions and parameters as the link reads them (for the block maker),
against the plain test node and a node whose parameter listing never answers."""
import time
from pathlib import Path

import pytest
from ros2_fixtures import plain_node, requests_to
from waiting import eventually

MUTE_NODE = Path(__file__).parent / "ros2_mute_parameters_node.py"
COUNTED_NODE = Path(__file__).parent / "ros2_counting_parameters_node.py"


@pytest.fixture
def mute_node(ros2_settings):
    with plain_node(ros2_settings, MUTE_NODE, "the mute parameters node") as node:
        yield node


@pytest.fixture
def counted_node(ros2_settings):
    with plain_node(ros2_settings, COUNTED_NODE, "the counted parameters node") as node:
        yield node


def test_the_links_graph_has_the_test_nodes_service_action_and_parameters(ros2_robot):
    ros2_robot.follow_graph()
    ros2_robot.want_parameters(True)
    eventually(lambda: "/test_robot:max_speed" in ros2_robot.graph_parameters(), timeout=30)
    assert "/test_robot:robot_name" in ros2_robot.graph_parameters()
    # the followed graph's next look may come after the parameters' listing
    eventually(lambda: ("/set_light", "std_srvs/SetBool") in ros2_robot.graph_services(), timeout=30)
    eventually(lambda: ("/fibonacci", "test_msgs/FibonacciAction") in ros2_robot.graph_actions(), timeout=30)


def test_a_node_that_never_lists_its_parameters_holds_the_listing_up_no_longer_than_its_bound(ros2_robot, mute_node):
    eventually(lambda: "/mute/list_parameters" in ros2_robot.helper.call("graph", timeout=10)["services"], timeout=30)
    for _try in range(2):  # the first ask of a new server may be lost; either way the bound holds
        started = time.monotonic()
        names = ros2_robot.helper.call("parameters", 1.0, timeout=30)
        assert time.monotonic() - started < 8  # 1 s bound; generous on a loaded machine
    assert "/test_robot:max_speed" in names and not [name for name in names if name.startswith("/mute")]


def test_a_followed_graph_asks_the_nodes_for_their_parameters_only_while_they_are_wished(ros2_robot, counted_node):
    ros2_robot.want_parameters(False)
    ros2_robot.follow_graph()
    eventually(lambda: "/counted/list_parameters" in ros2_robot.helper.call("graph", timeout=10)["services"],
               timeout=30)
    with requests_to(ros2_robot.helper) as asked:
        eventually(lambda: asked.count("graph") >= 5, timeout=30)  # over 4 s: more than one parameter poll's period
        assert "parameters" not in asked
    asked_on_the_node = [line for line in counted_node.lines if line.get("asked")]
    assert asked_on_the_node == [] and ros2_robot.graph_parameters() == []

    ros2_robot.want_parameters(True)
    eventually(lambda: "/counted:volume" in ros2_robot.graph_parameters(), timeout=30)
    assert {"asked": "list_parameters"} in counted_node.lines

    ros2_robot.want_parameters(False)
    assert ros2_robot.graph_parameters() == []  # not listed from an old poll either
    with requests_to(ros2_robot.helper) as asked:
        eventually(lambda: asked.count("graph") >= 2, timeout=30)  # a poll already on its way may end first
        asked_before = len([line for line in counted_node.lines if line.get("asked")])
        eventually(lambda: asked.count("graph") >= 7, timeout=30)
    assert len([line for line in counted_node.lines if line.get("asked")]) == asked_before
