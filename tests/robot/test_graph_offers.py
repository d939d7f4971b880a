"""What a robot's live graph offers beyond topics (for the block maker): services with their types,
actions and parameters, read from the simulator's world, a ROS 1 master's topics and servers, and
ROS 2's service list; every ask of a server bounded in time."""
import socket
import threading
import time

import pytest

from rockly_desktop.robot.ros1 import graph_offers
from rockly_desktop.robot.ros1.graph_offers import ServiceTypes, graph_actions, probe_service_type
from rockly_desktop.robot.ros2.helper.graph_offers import typed_actions, typed_services
from rockly_desktop.robot.sim.link import SimulatedRobot


def test_the_simulators_services_actions_and_parameters_are_what_its_world_has(hobbit):
    robot = SimulatedRobot(hobbit)
    try:
        assert robot.graph_services() == [("/MMUI", "hobbit_msgs/Request")]
        assert ("move_base", "move_base_msgs/MoveBaseAction") in robot.graph_actions()
        assert robot.graph_parameters() == []
        robot.world.params["/max_speed"] = 0.3
        assert robot.graph_parameters() == ["/max_speed"]
    finally:
        robot.shutdown()


def test_ros_1_actions_are_the_goal_topics_of_action_goal_types_beside_their_result():
    topics = {"/move_base/goal": "move_base_msgs/MoveBaseActionGoal",
              "/move_base/result": "move_base_msgs/MoveBaseActionResult",
              "/lonely/goal": "x_msgs/LonelyActionGoal",  # no result topic: no server
              "/soccer/goal": "std_msgs/String"}
    assert graph_actions(topics) == [("/move_base", "move_base_msgs/MoveBaseAction")]


@pytest.fixture
def silent_server():
    """A TCP server that takes connections and never says anything."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    taken = []
    threading.Thread(target=lambda: taken.append(server.accept()), daemon=True).start()
    yield f"rosrpc://127.0.0.1:{server.getsockname()[1]}"
    for connection, _address in taken:
        connection.close()
    server.close()


def test_a_ros_1_service_whose_server_does_not_answer_the_probe_gives_up_within_its_bound(silent_server):
    started = time.monotonic()
    with pytest.raises(OSError):
        probe_service_type(silent_server, "/mute", timeout=0.5)
    assert time.monotonic() - started < 5  # the promise: bounded (the machine is loaded: generous)


def test_a_ros_1_graph_of_many_mute_servers_is_typed_a_few_at_a_time_and_listed_at_once(monkeypatch):
    asked = []
    monkeypatch.setattr(graph_offers, "ask_master", lambda _uri, _method, name: f"rosrpc://127.0.0.1:9/{name}")
    monkeypatch.setattr(graph_offers, "probe_service_type", lambda _uri, name: asked.append(name) or "std_srvs/Empty")
    types = ServiceTypes("http://127.0.0.1:11311")
    names = [f"/mute_{number:02}" for number in range(12)]
    first = types.typed(names)
    assert [name for name, _type in first] == names and len(asked) == graph_offers.PROBES_AT_ONCE
    assert dict(first)["/mute_11"] == ""  # listed now, typed by a later call
    types.typed(names), types.typed(names)
    assert dict(types.typed(names))["/mute_11"] == "std_srvs/Empty" and sorted(asked) == names  # each asked once


def test_a_ros_1_service_the_master_cannot_find_is_listed_without_a_type():
    types = ServiceTypes("http://127.0.0.1:9")  # nothing listens there: the master does not answer
    assert types.typed(["/gone"]) == [("/gone", "")]
    assert types.typed([]) == []  # a service no longer listed is forgotten


def test_ros_2_services_leave_out_actions_parts_and_nodes_parameter_services_and_are_typed_as_profiles_name_them():
    services = [("/set_light", ["std_srvs/srv/SetBool"]),
                ("/test_robot/list_parameters", ["rcl_interfaces/srv/ListParameters"]),
                ("/test_robot/get_type_description", ["type_description_interfaces/srv/GetTypeDescription"]),
                ("/fibonacci/_action/send_goal", ["test_msgs/action/Fibonacci_SendGoal"]),
                ("/fibonacci/_action/cancel_goal", ["action_msgs/srv/CancelGoal"])]
    assert typed_services(services) == [("/set_light", "std_srvs/SetBool")]
    assert typed_actions(services) == [("/fibonacci", "test_msgs/FibonacciAction")]
