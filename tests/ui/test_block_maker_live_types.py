"""The block maker on a live graph whose types Rockly has no definition for (issue 22's first open point).
ROS 1: a plain rospy node's topic shows its fields, learnt from the wire off the window's thread (nested
ones by path), a sensor block made from it reads the node and a command block publishes what an
independent subscriber receives; a service whose definition cannot be learnt says why and what to do.
ROS 2: a plain rclpy node's topic, its type described by the node, becomes a block the node hears."""
import importlib.util
import sys
from pathlib import Path

import pytest
from json_line_node import JsonLineNode
from program_builder import block, number, stack, text
from PySide6.QtCore import Qt
from ros2_fixtures import TEST_ROBOT_PYTHON
from ros_helpers import ros_environment
from test_block_maker import made_and_run, open_maker
from test_ros2_window import connected
from waiting import eventually
from window_tools import on_hobbit_over_ros1
from wire_recorder import WireRecorder

from rockly_desktop.core import ros_definitions
from rockly_desktop.robot.ros2 import live_definitions

GADGET_NODE = Path(__file__).parents[1] / "robot" / "ros1" / "ros1_gadget_node.py"
GADGET = "rockly_test_custom/Gadget"
NESTED_NODE = Path(__file__).parents[1] / "robot" / "ros2" / "ros2_nested_node.py"


@pytest.fixture
def ros_window(window, ros_master, hobbit_on_ros, monkeypatch):
    """The window on HOBBIT over ROS 1 (the ROS-level simulator in its own process, a real master)."""
    return on_hobbit_over_ros1(window, ros_master.uri, monkeypatch)


@pytest.fixture
def gadget(ros_master):
    """A plain rospy node publishing /gadget/state and serving /gadget/blink, of types only it has."""
    node = JsonLineNode([sys.executable, GADGET_NODE], ros_environment(ros_master.uri, ros_master.home / "gadget"),
                        "the gadget node")
    yield node
    node.stop()


def gadget_node():
    """The gadget node's module (its message classes, which Rockly does not use)."""
    spec = importlib.util.spec_from_file_location("ros1_gadget_node", GADGET_NODE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def field_paths(maker) -> list:
    return [maker.fields.item(row, 0).text() for row in range(maker.fields.rowCount())]


def test_on_ros_1_a_topic_of_a_type_rockly_has_no_definition_for_shows_its_fields_and_its_blocks_reach_it(
        qtbot, ros_window, gadget, ros_master):
    qtbot.waitUntil(lambda: "/gadget/state" in [topic for topic, *_ in ros_window.robot().graph_topics()],
                    timeout=15000)
    maker = open_maker(qtbot, ros_window)
    assert maker.choose_named("/gadget/state")
    assert maker.interface_type.text() == GADGET and maker.kind.currentData() == "publish"
    # asked off the window's thread: the answer can only come through the event loop, after choosing returned
    assert maker.fields_note.text() == f"Asking the robot for the fields of {GADGET}…" and not field_paths(maker)
    qtbot.waitUntil(lambda: bool(field_paths(maker)), timeout=10000)  # the node's publisher said them
    assert field_paths(maker) == ["header.stamp", "header.frame_id", "name", "left_eye.brightness", "left_eye.open",
                                  "levels"]
    assert maker.fields_note.isHidden()

    maker.kind.setCurrentIndex(maker.kind.findData("sensor_value"))
    maker.read_field.setCurrentIndex(maker.read_field.findText("left_eye.brightness"))
    maker.sentence["en"].setText("the gadget's eye")
    maker.block_id.setText("made_gadget_eye")
    made_and_run(qtbot, ros_window, block("text_print", inputs={"TEXT": block("made_gadget_eye")}, id="say"))
    assert float(ros_window.console.lines()[-2]) == pytest.approx(0.25)  # what the node publishes

    maker = open_maker(qtbot, ros_window)
    assert maker.choose_named("/gadget/state")
    assert field_paths(maker)[2:4] == ["name", "left_eye.brightness"]  # learnt once: shown at once
    maker.fields.set_use("name", "input", "hello")
    maker.fields.set_use("left_eye.brightness", "fixed", "0.5")
    maker.sentence["en"].setText("show %1 on the gadget")
    maker.block_id.setText("made_gadget_show")
    recorder = WireRecorder(ros_master, ["/gadget/state"])
    try:
        made_and_run(qtbot, ros_window, stack(block("made_gadget_show", inputs={"name": text("made without code")})))
        gadget_class = gadget_node().gadget_classes()[GADGET]

        def heard():
            return [message for message in (gadget_class().deserialize(data) for _type, data
                                            in recorder.on("/gadget/state")) if message.name == "made without code"]
        eventually(heard, timeout=10)
        assert heard()[0].left_eye.brightness == 0.5  # decoded by the node's own class, not Rockly's
    finally:
        recorder.stop()


def test_on_ros_1_a_service_whose_definition_cannot_be_learnt_says_why_and_what_to_do(qtbot, ros_window, gadget):
    robot = ros_window.robot()
    eventually(lambda: ("/gadget/blink", "rockly_test_custom/Blink") in robot.graph_services(), timeout=20)
    maker = open_maker(qtbot, ros_window)
    assert maker.choose_named("/gadget/blink")
    qtbot.waitUntil(lambda: "does not say its fields" in maker.fields_note.text(), timeout=10000)
    assert not maker.fields_note.isHidden() and maker.fields.rowCount() == 0
    assert "rockly_test_custom/Blink" in maker.fields_note.text() and "messages folder" in maker.fields_note.text()
    assert not maker.save_button.isEnabled()


def test_on_ros_2_a_topic_of_a_type_rockly_has_no_file_for_shows_its_fields_and_its_block_publishes(
        qtbot, window, ros2_settings, monkeypatch):
    monkeypatch.setattr(live_definitions, "ros2_definition_dirs", lambda: [])  # only the robot can say
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})
    node = JsonLineNode([TEST_ROBOT_PYTHON, NESTED_NODE], ros2_settings.environment(), "the nested node")
    try:
        ros2_window = connected(window, ros2_settings, monkeypatch)
        qtbot.waitUntil(lambda: "/nested" in [topic for topic, *_ in ros2_window.robot().graph_topics()],
                        timeout=20000)
        maker = open_maker(qtbot, ros2_window)
        assert maker.choose_named("/nested") and maker.interface_type.text() == "test_msgs/Nested"
        qtbot.waitUntil(lambda: bool(field_paths(maker)), timeout=15000)  # described by the node
        assert {"basic_types_value.int32_value", "basic_types_value.bool_value"} <= set(field_paths(maker))
        maker.fields.set_use("basic_types_value.int32_value", "input", "1")
        maker.sentence["en"].setText("count %1")
        maker.block_id.setText("made_nested")
        made_and_run(qtbot, ros2_window, block("made_nested", inputs={"basic_types_value_int32_value": number(42)}))
        eventually(lambda: {"int32_value": 42, "float64_value": 0.0} in [line["message"] for line in node.lines],
                   timeout=10)
    finally:
        node.stop()


def test_on_ros_1_a_maker_closed_while_it_asks_drops_the_answer(qtbot, ros_window, gadget, monkeypatch):
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})
    qtbot.waitUntil(lambda: "/gadget/state" in [topic for topic, *_ in ros_window.robot().graph_topics()],
                    timeout=15000)
    maker = open_maker(qtbot, ros_window)
    learning = maker.learning
    assert maker.choose_named("/gadget/state")
    assert learning.asking(maker.offers.currentItem().data(Qt.ItemDataRole.UserRole))
    maker.close()
    learning.wait(10)
    qtbot.waitUntil(lambda: not learning.busy, timeout=10000)  # delivered on the window's thread: dropped
    assert not ros_definitions._LEARNT
