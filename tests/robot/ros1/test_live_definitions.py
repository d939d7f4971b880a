"""Types a ROS 1 robot offers but Rockly has no definition for: learnt from the wire (a publisher's
connection header), against a plain rospy node whose types exist only in it (generated at run time);
a service's definition is not on the wire; every ask is bounded in time."""
import socket
import sys
import threading
import time
from pathlib import Path

import pytest
from json_line_node import JsonLineNode
from ros_helpers import ros_environment
from waiting import eventually
from wire_recorder import WireRecorder

from rockly_desktop.core import ros_definitions
from rockly_desktop.core.errors import DefinitionNotLearnt
from rockly_desktop.core.ros_definitions import DefinitionCatalog, learn_definition
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros1 import live_definitions

GADGET_NODE = Path(__file__).parent / "ros1_gadget_node.py"
GADGET = "rockly_test_custom/Gadget"


@pytest.fixture(scope="module")
def gadget(ros_master):
    """The plain node publishing /gadget/state and serving /gadget/blink, of types only it has."""
    node = JsonLineNode([sys.executable, GADGET_NODE], ros_environment(ros_master.uri, ros_master.home / "gadget"),
                        "the gadget node")
    yield node
    node.stop()


@pytest.fixture(scope="module")
def robot(ros_master, hobbit):
    from rockly_desktop.robot.ros1.link import RosRobot

    return RosRobot(hobbit, ros_master.uri)


def test_a_topic_of_a_type_rockly_has_no_definition_for_gets_its_fields_from_its_publisher(robot, gadget, monkeypatch):
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})  # nothing learnt before (learning holds for the process)
    catalog = DefinitionCatalog()
    assert not catalog.knows(GADGET)
    learnt = robot.interface_definition("topic", "/gadget/state", GADGET)
    assert learnt.type_name == GADGET and set(learnt.nested) == {"rockly_test_custom/Eye", "std_msgs/Header"}
    learn_definition(learnt.type_name, "msg", learnt.text, learnt.nested)
    fields = {entry.path: (entry.ros_type, entry.check) for entry in catalog.fields(GADGET)}
    assert fields == {"header.stamp": ("time", "Number"), "header.frame_id": ("string", "String"),
                      "name": ("string", "String"), "left_eye.brightness": ("float64", "Number"),
                      "left_eye.open": ("bool", "Boolean"), "levels": ("float32[]", "Array")}  # MODE_OFF: a constant


def test_a_block_of_that_type_publishes_it_and_an_independent_subscriber_receives_it(robot, gadget, ros_master,
                                                                                      monkeypatch):
    from rockly_desktop.robot.ros1.backend import Ros1Backend
    from rockly_desktop.robot.ros1.message_classes import MessageTypes

    monkeypatch.setattr(robot.graph, "types", MessageTypes())  # nothing learnt yet: a run learns it from the wire

    recorder = WireRecorder(ros_master, ["/gadget/state"])
    try:
        Ros1Backend(robot.graph, Interrupt()).publish("/gadget/state", GADGET, {"name": "made without code",
                                                                               "left_eye": {"brightness": 0.5}})
        from ros1_gadget_node import gadget_classes

        cls = gadget_classes()[GADGET]
        heard = lambda: [cls().deserialize(data) for msg_type, data in recorder.on("/gadget/state")]  # noqa: E731
        eventually(lambda: [message for message in heard() if message.name == "made without code"], timeout=10)
        made = next(message for message in heard() if message.name == "made without code")
        assert made.left_eye.brightness == 0.5  # the value Rockly sent, decoded independently
    finally:
        recorder.stop()


def test_a_topic_nobody_publishes_says_so_unless_its_package_is_installed_here(robot):
    with pytest.raises(DefinitionNotLearnt) as said:
        robot.interface_definition("topic", "/nobody/publishes", "rockly_test_custom/Nothing")
    assert "Nothing publishes /nobody/publishes" in str(said.value)
    assert "Gerade sendet niemand auf /nobody/publishes" in said.value.in_language("de")
    installed = robot.interface_definition("topic", "/nobody/publishes", "geometry_msgs/PoseStamped")
    assert "Pose pose" in installed.text and "geometry_msgs/Quaternion" in installed.nested


def test_a_services_or_actions_definition_is_not_on_the_wire_and_one_not_installed_here_says_what_to_do(
        robot, gadget):
    eventually(lambda: ("/gadget/blink", "rockly_test_custom/Blink") in live_types(robot), timeout=20)
    with pytest.raises(DefinitionNotLearnt) as said:
        robot.interface_definition("service", "/gadget/blink", "rockly_test_custom/Blink")
    assert "does not say its fields" in str(said.value) and "rockly_test_custom/Blink" in str(said.value)
    installed = robot.interface_definition("service", "/any/switch", "std_srvs/SetBool")
    request, response = installed.text.split("\n---\n")  # from its installed Python package
    assert "bool data" in request and "string message" in response and "bool success" in response
    with pytest.raises(DefinitionNotLearnt) as said:  # an action server only subscribes to its goals
        robot.interface_definition("action", "/gadget/wave", "rockly_test_custom/WaveAction")
    assert "An action's server does not say its goal's fields" in str(said.value)
    installed = robot.interface_definition("action", "/move_base", "move_base_msgs/MoveBaseAction")
    goal, result, feedback = installed.text.split("\n---\n")
    assert "geometry_msgs/PoseStamped target_pose" in goal and "base_position" in feedback


def live_types(robot):
    robot.follow_graph()
    return robot.graph_services()


@pytest.fixture
def mute_publisher(monkeypatch):
    """A TCP server listed as /mute's publisher that takes connections and never says anything."""
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    taken = []
    threading.Thread(target=lambda: taken.append(server.accept()), daemon=True).start()
    answers = {"getSystemState": [[["/mute", ["/mute_node"]]], [], []], "lookupNode": "http://127.0.0.1:9",
               "requestTopic": ["TCPROS", "127.0.0.1", server.getsockname()[1]]}
    monkeypatch.setattr(live_definitions, "ask_master", lambda _uri, method, *_args: answers[method])
    yield
    for connection, _address in taken:
        connection.close()
    server.close()


def test_a_publisher_that_never_answers_gives_up_within_its_bound(mute_publisher):
    started = time.monotonic()
    with pytest.raises(DefinitionNotLearnt) as said:
        live_definitions.topic_definition("http://127.0.0.1:11311", "/mute", timeout=0.5)
    assert time.monotonic() - started < 5  # the promise: bounded (the machine is loaded: generous)
    assert "No publisher of /mute said its message's fields within 0.5 s" in str(said.value)
