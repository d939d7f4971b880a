"""A teacher's limits hold in ``rockly run`` against crafted program files and copied profiles
(a real process on the simulator, the teacher's settings where the window keeps them)."""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from profile_copies import copy_profile
from program_builder import block, number, rockly_document, stack, text

REPO = Path(__file__).resolve().parents[1]


def rockly_run(*args, timeout=120):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", "run", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def teacher(folders):
    from rockly_desktop.settings.app_settings import AppSettings

    return AppSettings(folders / "config" / "Rockly" / "Rockly.conf")  # where the window keeps them


def where_it_went(*blocks):
    """``blocks``, a short wait and a print of HOBBIT's x position (block id ``where``)."""
    return stack(*blocks, block("hobbit_wait", inputs={"seconds": number(0.5)}, id="wait"),
                 block("text_print", inputs={"TEXT": block("hobbit_position", {"coordinate": "x"})}, id="where"))


@pytest.mark.parametrize(("speed", "check"), [(text("1.0"), "String"),
                                              (block("logic_boolean", {"BOOL": "TRUE"}), "Boolean")],
                         ids=["text", "true"])
def test_a_crafted_velocity_of_an_unknown_type_is_refused_under_a_speed_limit(tmp_path, isolated_user_folders,
                                                                              speed, check):
    """The issue's file: a type Rockly does not know, saved with the field it chose (a text or a
    boolean linear.x); before, HOBBIT drove 1.0 m/s under the 0.1 m/s limit."""
    settings = teacher(isolated_user_folders)
    settings.teacher.set_limits("hobbit", max_speed=0.1)
    settings.sync()
    crafted = block("ros_publish_message", {"message_type": "lab_msgs/Twist"},
                    {"topic": text("/cmd_vel"), "field:linear.x": speed}, id="crafted",
                    extraState={"type": "lab_msgs/Twist", "fields": [["linear.x", check]]})
    path = tmp_path / "crafted.rockly"
    path.write_text(rockly_document([where_it_went(crafted)]))
    result = rockly_run(path, "--speed", "5")
    assert result.returncode == 1, result.stdout
    assert ("error in block crafted (ros_publish_message): The robot could not do this: the teacher's speed limit "
            "can only be kept on /cmd_vel for geometry_msgs/Twist / geometry_msgs/TwistStamped, not for "
            "lab_msgs/Twist") in result.stderr
    assert not any(line.startswith("print") and "Speed limit" not in line for line in result.stdout.splitlines())


def test_a_copy_of_hobbits_profile_under_another_id_keeps_hobbits_limits(tmp_path, isolated_user_folders):
    copy_profile(isolated_user_folders / "data" / "rockly" / "profiles" / "hobbit_copy", "hobbit_copy")
    settings = teacher(isolated_user_folders)
    settings.teacher.set_limits("hobbit", max_speed=0.1, max_turn=30, switched_off={"arm"})
    settings.sync()
    path = tmp_path / "copy.rockly"
    path.write_text(rockly_document([stack(
        block("hobbit_move", {"direction": "+"}, {"speed": number(0.3)}, id="drive"),
        block("text_print", inputs={"TEXT": block("hobbit_position", {"coordinate": "x"})}, id="where"),
        block("hobbit_arm_gripper", {"movement": "OpenGripper"}, id="arm"))], profile="hobbit_copy"))
    assert json.loads(path.read_text())["profile"] == "hobbit_copy"
    result = rockly_run(path, "--speed", "20")
    lines = result.stdout.splitlines()
    assert lines[0] == ("The teacher's limits apply: driving at most 0.1 m/s; turning at most 30°/s; "
                        "switched off: Arm and gripper.")
    assert "print   Speed limit: the robot drives at most 0.1 m/s (set by the teacher)." in lines
    assert result.returncode == 1
    assert ("error in block arm (hobbit_arm_gripper): The robot could not do this: "
            "the teacher switched off “Arm and gripper” for this robot") in result.stderr
