"""ROS 2 types the robot offers but Rockly's profile has no definition for: from Rockly's ROS 2
environment's files, else (a topic) as its publisher's node describes it (``~/get_type_description``),
against a plain rclpy node publishing test_msgs/msg/Nested; a service's definition is not on this
ROS 2's wire; every ask is bounded in time."""
import time
from pathlib import Path

import pytest
from ros2_fixtures import plain_node
from waiting import eventually

from rockly_desktop.core import ros_definitions
from rockly_desktop.core.errors import DefinitionNotLearnt
from rockly_desktop.core.ros_definitions import DefinitionCatalog, learn_definition
from rockly_desktop.robot.ros2 import live_definitions

NESTED_NODE = Path(__file__).parent / "ros2_nested_node.py"
NESTED = "test_msgs/Nested"


@pytest.fixture
def nested_node(ros2_settings):
    with plain_node(ros2_settings, NESTED_NODE, "the nested node") as node:
        yield node


@pytest.fixture
def nothing_here(monkeypatch):
    """Rockly's ROS 2 environment has no definition files, and nothing is learnt yet: only the robot can say."""
    monkeypatch.setattr(live_definitions, "ros2_definition_dirs", lambda: [])
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})


def nested_fields(learnt) -> dict:
    learn_definition(learnt.type_name, learnt.kind, learnt.text, learnt.nested)
    return {entry.path: entry.check for entry in DefinitionCatalog(installed_dirs=[]).fields(NESTED)}


def test_a_topics_type_rockly_has_no_file_for_is_described_by_its_publishers_node(ros2_robot, nested_node,
                                                                                   nothing_here):
    assert not DefinitionCatalog(installed_dirs=[]).knows(NESTED)
    eventually(lambda: "/nested" in [name for name, *_ in ros2_robot.helper.call("graph", timeout=10)["topics"]],
               timeout=30)
    learnt = ros2_robot.interface_definition("topic", "/nested", NESTED)
    assert learnt.type_name == NESTED and "test_msgs/BasicTypes" in learnt.nested
    fields = nested_fields(learnt)
    assert fields["basic_types_value.int32_value"] == "Number" and fields["basic_types_value.bool_value"] == "Boolean"


def test_a_type_rocklys_ros_2_environment_has_files_for_comes_from_them(ros2_robot, monkeypatch):
    monkeypatch.setattr(ros_definitions, "_LEARNT", {})
    monkeypatch.setattr(ros2_robot.helper, "call", lambda *_args, **_options: pytest.fail("the robot was asked"))
    assert "basic_types_value.float64_value" in nested_fields(ros2_robot.interface_definition("topic", "/x", NESTED))


def test_a_topic_nobody_publishes_or_a_service_not_installed_here_says_why_within_its_bound(ros2_robot, nothing_here):
    started = time.monotonic()
    with pytest.raises(DefinitionNotLearnt) as said:
        ros2_robot.interface_definition("topic", "/nobody/publishes", "nowhere_msgs/Thing")
    assert time.monotonic() - started < 15  # 2 s bound; generous on a loaded machine
    assert "No publisher of /nobody/publishes described its type nowhere_msgs/Thing" in str(said.value)
    with pytest.raises(DefinitionNotLearnt) as said:
        ros2_robot.interface_definition("service", "/nowhere", "nowhere_msgs/Ask")
    assert "does not say its fields" in str(said.value) and "Rocklys ROS-2-Umgebung" in said.value.in_language("de")


def test_rockly_blocks_make_learning_a_type_puts_nothing_on_cmd_vel_while_a_runs_end_still_stops_it(
        test_robot, ros2_settings, tmp_path):
    """``rockly blocks make --backend ros2`` only reads the robot: the TurtleBot's safe stop (a zero /cmd_vel, heard
    by the plain rclpy test node) would stop a program another client runs; a run's end still sends it."""
    import subprocess
    import sys

    from program_builder import block, rockly_document, stack, text

    repo = Path(__file__).resolve().parents[3]
    where = ("--backend", "ros2", "--domain", str(ros2_settings.domain_id), "--discovery", "localhost")

    def rockly(*args):
        return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)], capture_output=True,
                              text=True, timeout=180, cwd=repo, env=ros2_settings.environment())

    before = len(test_robot.received("/cmd_vel"))
    made = rockly("blocks", "make", "--profile", "turtlebot", "--pack", "nested_quiet", "--id", "nested_quiet",
                  "--kind", "publish", "--interface", "/nested", "--type", NESTED,
                  "--input", "flag=basic_types_value.bool_value", "--sentence-en", "nest %1", "--colour", "#4c97ff",
                  "--category-en", "Nested", *where)
    assert made.returncode == 0, made.stderr
    heard_while_making = len(test_robot.received("/cmd_vel")) - before
    program = tmp_path / "nothing.rockly"
    program.write_text(rockly_document([stack(block("text_print", inputs={"TEXT": text("done")}))]))
    ran = rockly("run", program, *where)
    assert ran.returncode == 0, ran.stderr
    eventually(lambda: len(test_robot.received("/cmd_vel")) > before, timeout=20)  # the run's end: its safe stop
    assert heard_while_making == 0
