"""``rockly run``: programs run headless on the simulator, as a user runs them (a real process)."""
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from program_builder import block, number, rockly_document, stack, text

REPO = Path(__file__).resolve().parents[1]


def write(tmp_path, *blocks, name="program.rockly"):
    path = tmp_path / name
    path.write_text(rockly_document(list(blocks)))
    return path


def rockly_run(*args, timeout=120):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", "run", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def block_lines(stdout):
    return [line.split()[1:] for line in stdout.splitlines() if line.startswith("block ")]


def test_the_pick_up_program_runs_block_by_block(tmp_path):
    program = write(tmp_path, stack(*(block(kind, {"movement": value}, id=f"b{i}") for i, (kind, value) in enumerate((
        ("hobbit_arm_gripper", "OpenGripper"), ("hobbit_arm_move", "MoveToPreGraspFloor"),
        ("hobbit_arm_gripper", "CloseGripper"), ("hobbit_arm_move", "MoveToPreGraspTable"),
        ("hobbit_arm_gripper", "OpenGripper"))))))
    result = rockly_run(program, "--speed", "50")
    assert result.returncode == 0, result.stderr
    assert block_lines(result.stdout) == [["b0", "hobbit_arm_gripper"], ["b1", "hobbit_arm_move"],
                                          ["b2", "hobbit_arm_gripper"], ["b3", "hobbit_arm_move"],
                                          ["b4", "hobbit_arm_gripper"]]
    assert result.stdout.splitlines()[-1] == "finished"


def test_tablet_questions_are_answered_in_order_from_the_command_line(tmp_path):
    program = write(tmp_path, stack(
        block("controls_if", id="if",
              inputs={"IF0": block("hobbit_yes_no", {"yes_no": "D_YES"}, {"text": text("Play?")}),
                      "DO0": block("text_print", inputs={"TEXT": text("playing")}, id="yes")}),
        block("text_print", inputs={"TEXT": block("hobbit_user_input", inputs={"text": text("Name?")})}, id="name")))
    result = rockly_run(program, "--answer", "yes", "--answer", "Ada 'the' \"first\"", "--speed", "50")
    assert result.returncode == 0, result.stderr
    assert "print   playing" in result.stdout
    assert "print   Ada 'the' \"first\"" in result.stdout


def test_a_missing_answer_fails_clearly_on_the_asking_block(tmp_path):
    question = block("hobbit_user_input", inputs={"text": text("Name?")})
    program = write(tmp_path, block("text_print", inputs={"TEXT": question}, id="ask"))
    result = rockly_run(program, "--speed", "50")
    assert result.returncode == 1
    assert "error in block ask (text_print)" in result.stderr
    assert "no --answer is left" in result.stderr and "Name?" in result.stderr


def test_an_error_exits_non_zero_naming_the_block(tmp_path):
    path = tmp_path / "typed.rockly"
    distance = block("variables_get", {"VAR": {"id": "d"}})
    far = block("text", {"TEXT": "far"})
    ws_blocks = stack(block("variables_set", {"VAR": {"id": "d"}}, {"VALUE": far}, id="fine"),
                      block("hobbit_move", {"direction": "+"}, {"speed": distance}, id="bad"))
    document = json.loads(rockly_document([ws_blocks]))
    document["workspace"]["variables"] = [{"name": "distance", "id": "d"}]
    path.write_text(json.dumps(document))
    result = rockly_run(path, "--speed", "50")
    assert result.returncode == 1
    assert ("error in block bad (hobbit_move): The robot could not do this: "
            "the distance must be a number, not 'far'") in result.stderr


def test_a_typed_field_given_a_text_stops_on_its_block_before_publishing(tmp_path):
    path = tmp_path / "twist.rockly"
    ws_blocks = stack(block("variables_set", {"VAR": {"id": "s"}}, {"VALUE": text("fast")}, id="fine"),
                      block("ros_publish_message", {"message_type": "geometry_msgs/Twist"},
                            {"topic": text("/cmd_vel"), "field:linear.x": block("variables_get", {"VAR": {"id": "s"}})},
                            id="bad"))
    document = json.loads(rockly_document([ws_blocks]))
    document["workspace"]["variables"] = [{"name": "speed", "id": "s"}]
    path.write_text(json.dumps(document))
    result = rockly_run(path)
    assert result.returncode == 1
    assert ("error in block bad (ros_publish_message): The robot could not do this: "
            "the field linear.x needs a number, not 'fast'") in result.stderr


def test_first_rockly_xml_runs_too(tmp_path):
    path = tmp_path / "old.xml"
    path.write_text('<xml xmlns="https://developers.google.com/blockly/xml"><block type="hobbit_head" id="h">'
                    '<field name="head_position">to_grasp</field></block></xml>')
    result = rockly_run(path)
    assert result.returncode == 0, result.stderr
    assert block_lines(result.stdout) == [["h", "hobbit_head"]]


def test_a_broken_program_file_is_explained(tmp_path):
    path = tmp_path / "broken.rockly"
    path.write_text("{")
    result = rockly_run(path)
    assert result.returncode == 1 and result.stderr.startswith("rockly run: ")


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["Ctrl+C", "SIGTERM"])
def test_ctrl_c_or_sigterm_stops_the_program_with_the_safe_stop(tmp_path, signum):
    """Ctrl+C, or SIGTERM as a launch file or a service manager ends a process; exit status 128 + its number."""
    program = write(tmp_path, stack(block("hobbit_wait", inputs={"seconds": number(600)}, id="wait"),
                                    block("hobbit_sos", id="never")))
    process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", "run", str(program)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=REPO)
    for line in process.stdout:
        if line.startswith("block   wait"):
            break
    # The wait block has begun: Ctrl+C from now on ends its wait (a stop requested just
    # before the wait starts ends it at once as well).
    process.send_signal(signum)
    remaining, errors = process.communicate(timeout=20)
    assert process.returncode == 128 + signum, errors
    assert "stopped (the robot was stopped safely)" in remaining
    assert "never" not in remaining


def test_a_program_blockly_refuses_is_explained(tmp_path):
    program = write(tmp_path, block("hobbit_move", {"direction": "+"}, {"speed": block("text", {"TEXT": "far"})}))
    result = rockly_run(program)
    assert result.returncode == 1
    assert result.stderr.startswith("rockly run: ") and "could not load this program" in result.stderr


def test_run_warns_about_a_replaced_value_and_a_missing_profile_and_still_runs(tmp_path):
    path = tmp_path / "pepper.rockly"
    path.write_text(rockly_document([stack(block("hobbit_emo", {"emotion": "FURIOUS"}, id="emo"),
                                           block("text_print", inputs={"TEXT": text("done")}))], profile="pepper"))
    result = rockly_run(path, "--speed", "50")
    assert result.returncode == 0, result.stderr
    warnings = [line for line in result.stderr.splitlines() if line.startswith("rockly run: warning: ")]
    assert len(warnings) == 2
    assert "robot profile 'pepper', which is not installed (installed: hobbit, turtlebot)" in warnings[0]
    assert warnings[1].endswith("block 1 (hobbit_emo): emotion 'FURIOUS' is not a value this block accepts; "
                                "it was replaced by 'HAPPY'")
    assert result.stdout.splitlines()[-1] == "finished"


def test_a_block_without_a_type_is_a_broken_file_not_an_unknown_block(tmp_path):
    path = tmp_path / "untyped.rockly"
    path.write_text(rockly_document([stack(block("hobbit_sos"), {"inputs": {}})]))
    result = rockly_run(path)
    assert result.returncode == 1
    assert "the file is broken: block 2 has no type" in result.stderr and "undefined" not in result.stderr


def distance_program(tmp_path, value="ten"):
    """A program that prints a greeting, then drives a text distance (a robot error on block 'bad')."""
    distance = block("variables_get", {"VAR": {"id": "d"}})
    ws_blocks = stack(block("text_print", inputs={"TEXT": text("hi")}, id="hello"),
                      block("variables_set", {"VAR": {"id": "d"}}, {"VALUE": text(value)}, id="fine"),
                      block("hobbit_move", {"direction": "+"}, {"speed": distance}, id="bad"))
    document = json.loads(rockly_document([ws_blocks]))
    document["workspace"]["variables"] = [{"name": "distance", "id": "d"}]
    path = tmp_path / "distance.rockly"
    path.write_text(json.dumps(document))
    return path


GERMAN_ERROR = ("Fehler in Block bad (hobbit_move): Das konnte der Roboter nicht tun: "
                "Die Strecke muss eine Zahl sein, nicht 'ten'")


def test_language_de_says_everything_in_german_the_profiles_errors_too(tmp_path):
    result = rockly_run(distance_program(tmp_path), "--language", "de", "--speed", "50")
    assert result.returncode == 1
    assert "Block   hello  text_print" in result.stdout and "Ausgabe hi" in result.stdout
    assert result.stderr.strip() == GERMAN_ERROR


def test_without_language_the_language_chosen_in_the_app_is_used(tmp_path):
    config = tmp_path / "config"
    (config / "Rockly").mkdir(parents=True)
    (config / "Rockly" / "Rockly.conf").write_text("[General]\nlanguage=de\n", encoding="utf-8")
    environment = {**os.environ, "XDG_CONFIG_HOME": str(config)}
    ran = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(distance_program(tmp_path)), "--speed",
                          "50"], capture_output=True, text=True, timeout=120, cwd=REPO, env=environment)
    assert ran.stderr.strip() == GERMAN_ERROR
    english = rockly_run(distance_program(tmp_path), "--language", "en", "--speed", "50")
    assert english.stderr.strip() == ("error in block bad (hobbit_move): The robot could not do this: "
                                      "the distance must be a number, not 'ten'")
    exported = subprocess.run([sys.executable, "-m", "rockly_desktop", "export", str(distance_program(tmp_path)),
                               "-o", str(tmp_path / "out.py")], capture_output=True, text=True, timeout=120,
                              cwd=REPO, env=environment)
    assert exported.returncode == 0 and exported.stdout == f"Geschrieben: {tmp_path / 'out.py'}\n"


def test_a_missing_file_is_explained_in_german(tmp_path):
    result = rockly_run(tmp_path / "nowhere.rockly", "--language", "de")
    assert result.returncode == 1
    assert result.stderr == f"rockly run: {tmp_path / 'nowhere.rockly'}: Die Datei gibt es nicht\n"
def test_run_keeps_the_teachers_limits_from_the_windows_settings(tmp_path, isolated_user_folders):
    from rockly_desktop.settings.app_settings import AppSettings

    settings = AppSettings(isolated_user_folders / "config" / "Rockly" / "Rockly.conf")  # where the window keeps them
    settings.teacher.set_limits("hobbit", max_speed=0.1, max_turn=30, switched_off={"arm"})
    settings.sync()
    program = write(tmp_path, stack(
        block("hobbit_move", {"direction": "+"}, {"speed": number(0.3)}, id="drive"),
        block("text_print", inputs={"TEXT": block("hobbit_position", {"coordinate": "x"})}, id="where"),
        block("hobbit_arm_gripper", {"movement": "OpenGripper"}, id="arm")))
    result = rockly_run(program, "--speed", "20")
    lines = result.stdout.splitlines()
    assert lines[0] == ("The teacher's limits apply: driving at most 0.1 m/s; turning at most 30°/s; "
                        "switched off: Arm and gripper.")
    assert "print   Speed limit: the robot drives at most 0.1 m/s (set by the teacher)." in lines
    printed_x = next(line for line in lines if line.startswith("print   0.")).split()[1]
    assert float(printed_x) == pytest.approx(0.3, abs=0.005)  # the whole way, at the limit
    assert result.returncode == 1
    assert ("error in block arm (hobbit_arm_gripper): The robot could not do this: "
            "the teacher switched off “Arm and gripper” for this robot") in result.stderr


def test_without_teacher_settings_run_says_nothing_of_limits(tmp_path):
    program = write(tmp_path, block("hobbit_arm_gripper", {"movement": "OpenGripper"}, id="arm"))
    result = rockly_run(program, "--speed", "50")
    assert result.returncode == 0, result.stderr
    assert "limits" not in result.stdout and "Speed limit" not in result.stdout
