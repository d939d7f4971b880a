"""The TurtleBot profile (profiles/turtlebot/): it validates, and its manifest, blocks, toolbox and commands agree."""
import inspect
import re
import shutil
import subprocess
import sys

import pytest
from profile_copies import REPO, SHARED_TOOLBOXES

from rockly_desktop.profiles.i18n import is_localized, localize
from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.profiles.registry import ProfileRegistry

TURTLEBOT_DIR = REPO / "profiles" / "turtlebot"
PROFILE = load_profile(TURTLEBOT_DIR, SHARED_TOOLBOXES)
TurtleBot = PROFILE.load_object("api")
api = sys.modules[TurtleBot.__module__]

CATEGORY_COLOURS = {"Drive": "#2E86DE", "Sensors": "#E8743B", "Time": "#5C6B7A"}
COMMANDS = ("drive", "turn", "drive_for", "stop", "distance", "obstacle_closer_than", "battery_level", "wait")


def rockly(*args):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=90, cwd=REPO)


def test_rockly_plugins_validate_says_ok():
    result = rockly("profiles", "validate", TURTLEBOT_DIR)
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == ("OK  turtlebot 1.0.0: 8 blocks, 11 toolbox categories, "
                                     "commands rockly_turtlebot.api:TurtleBot")


def test_validate_catches_a_template_calling_a_command_the_turtlebot_lacks(tmp_path):
    copy = tmp_path / "turtlebot"
    shutil.copytree(TURTLEBOT_DIR, copy, ignore=shutil.ignore_patterns("__pycache__"))
    blocks = copy / "blocks.yaml"
    blocks.write_text(blocks.read_text().replace('python: "robot.stop()"', 'python: "robot.halt()"'))
    result = rockly("profiles", "validate", copy)
    assert result.returncode == 1
    assert "calls robot.halt(), which TurtleBot does not have" in result.stderr


def test_it_is_installed_next_to_hobbit_and_hobbit_stays_the_default():
    registry = ProfileRegistry.discover()
    assert registry.errors == []
    assert registry.get("turtlebot").display_name() == "TurtleBot"
    assert registry.default().id == "hobbit"
    assert not registry.get("turtlebot").own_block_types & registry.get("hobbit").own_block_types


def test_the_ros_interface_is_the_turtlebots():
    interface = PROFILE.manifest["ros_interface"]
    assert interface == {
        "subscribes": {"/cmd_vel": "geometry_msgs/Twist"},
        "publishes": {"/odom": "nav_msgs/Odometry", "/scan": "sensor_msgs/LaserScan",
                      "/battery_state": "sensor_msgs/BatteryState", "/sensor_state": "turtlebot3_msgs/SensorState"},
        "streams": ["/odom", "/scan", "/battery_state", "/sensor_state"],
    }
    assert PROFILE.manifest["safe_stop"] == [
        {"publish": {"topic": "/cmd_vel", "type": "geometry_msgs/Twist", "message": {}}}]


def test_state_panels_show_pose_speed_nearest_obstacle_and_battery():
    rows = {(localize(panel["panel"], "en"), localize(row["label"], "en")): row
            for panel in PROFILE.manifest["state"] for row in panel["rows"]}
    assert rows[("Position", "Position x")]["field"] == "pose.pose.position.x"
    assert rows[("Position", "Heading")]["transform"] == "yaw_degrees"
    assert rows[("Speed", "Driving")]["field"] == "twist.twist.linear.x"
    ahead = rows[("Laser", "Nearest obstacle ahead")]
    assert (ahead["topic"], ahead["field"], ahead["transform"]) == ("/scan", "ranges", "nearest_ahead")
    assert rows[("Speed", "Turning")]["transform"] == "degrees"
    assert rows[("Battery", "Charge")]["transform"] == "percent"
    for panel in PROFILE.manifest["state"]:
        assert is_localized(panel["panel"]) and set(panel["panel"]) == {"en", "de"}
        assert all(set(row["label"]) == {"en", "de"} for row in panel["rows"])


def test_every_command_has_a_block_and_every_block_calls_a_public_command():
    called = set()
    for spec in PROFILE.blocks:
        names = re.findall(r"\brobot\.(\w+)\(", spec.code)
        assert len(names) == 1, spec.type
        name = names[0]
        assert not name.startswith("_") and inspect.isfunction(getattr(TurtleBot, name, None)), spec.type
        called.add(name)
    assert called == set(COMMANDS)


def test_blocks_speak_english_and_german_with_tooltips():
    for spec in PROFILE.blocks:
        definition = spec.definition
        for key in ("message0", "tooltip"):
            assert set(definition[key]) == {"en", "de"}, (spec.type, key)
            assert all(text.strip() for text in definition[key].values())
        placeholders = set(re.findall(r"%\d", definition["message0"]["en"]))
        assert set(re.findall(r"%\d", definition["message0"]["de"])) == placeholders, spec.type
        for arg in definition.get("args0", []):
            for label, _value in arg.get("options", []):
                assert set(label) == {"en", "de"}, (spec.type, arg["name"])


def test_toolbox_has_drive_sensors_time_and_the_shared_categories_in_their_colours():
    toolbox = PROFILE.editor_config("de")["toolbox"]["contents"]
    assert [category["name"] for category in toolbox][:3] == ["Fahren", "Sensoren", "Zeit"]
    english = localize(PROFILE.toolbox_categories, "en")
    assert [category["name"] for category in english] == [
        "Drive", "Sensors", "Time", "ROS", "Logic", "Loops", "Math", "Text", "Lists", "Variables", "Functions"]
    for category in english[:3]:
        assert category["colour"] == CATEGORY_COLOURS[category["name"]]
        for entry in category["contents"]:
            assert PROFILE.block(entry["type"]).definition["colour"] == category["colour"], entry["type"]
    listed = {entry["type"] for category in english[:3] for entry in category["contents"]}
    assert listed == PROFILE.own_block_types


@pytest.mark.parametrize("block_type, choices", [
    ("turtlebot_drive", api.DIRECTIONS), ("turtlebot_turn", api.TURN_DIRECTIONS),
    ("turtlebot_distance", api.SIDES), ("turtlebot_obstacle", api.SIDES),
])
def test_dropdown_values_are_the_commands_choices(block_type, choices):
    (options,) = [arg["options"] for arg in PROFILE.block(block_type).definition["args0"]
                  if arg.get("name") == "direction"]
    assert [value for _label, value in options] == list(choices)
    assert "direction" not in PROFILE.block(block_type).values


def test_expression_blocks_give_numbers_and_truth_values():
    assert PROFILE.block("turtlebot_distance").definition["output"] == "Number"
    assert PROFILE.block("turtlebot_battery").definition["output"] == "Number"
    assert PROFILE.block("turtlebot_obstacle").definition["output"] == "Boolean"
    statements = {spec.type for spec in PROFILE.blocks if not spec.is_expression}
    assert statements == {"turtlebot_drive", "turtlebot_turn", "turtlebot_drive_for", "turtlebot_stop",
                          "turtlebot_wait"}
