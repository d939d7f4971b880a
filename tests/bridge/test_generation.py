"""Blocks -> Python with the real Blockly generator in QtWebEngine: every HOBBIT block, and quoting."""
import ast

import pytest
from program_builder import block, number, stack, text, workspace

from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.profiles.opening import ProgramToOpen


def generate(editor, profile, *top_blocks) -> str:
    return editor.python_for(ProgramToOpen(path=None, profile=profile, workspace=workspace(*top_blocks)))


STATEMENTS = [
    (block("hobbit_move", {"direction": "+"}, {"speed": number(2)}), "robot.drive(2, 'forward')"),
    (block("hobbit_move", {"direction": "-"}, {"speed": number(0.5)}), "robot.drive(0.5, 'backward')"),
    (block("hobbit_move", {"direction": "+"}), "robot.drive(0, 'forward')"),
    (block("hobbit_turn", {"direction": "+"}, {"angle": number(90)}), "robot.turn(90, 'left')"),
    (block("hobbit_turn", {"direction": "-"}, {"angle": number(180)}), "robot.turn(180, 'right')"),
    (block("hobbit_navigate", inputs={"x": number(1.5), "y": number(-2), "heading": number(90)}),
     "robot.navigate_to(1.5, -2, 90)"),
    (block("hobbit_stop"), "robot.stop()"),
    (block("hobbit_head", {"head_position": "up_left"}), "robot.look('up_left')"),
    (block("hobbit_head", {"head_position": "search_table"}), "robot.look('search_table')"),
    (block("hobbit_emo", {"emotion": "VTIRED"}), "robot.show_emotion('VTIRED')"),
    (block("hobbit_arm_gripper", {"movement": "OpenGripper"}), "robot.gripper('open')"),
    (block("hobbit_arm_gripper", {"movement": "CloseGripper"}), "robot.gripper('close')"),
    (block("hobbit_arm_move", {"movement": "MoveToCandle"}), "robot.move_arm('candle')"),
    (block("hobbit_arm_move", {"movement": "MoveToHome"}), "robot.move_arm('home')"),
    (block("hobbit_arm_move", {"movement": "MoveToPreGraspFloor"}), "robot.move_arm('floor')"),
    (block("hobbit_arm_move", {"movement": "MoveToPreGraspTable"}), "robot.move_arm('table')"),
    (block("hobbit_arm_move", {"movement": "MoveToTray"}), "robot.move_arm('tray')"),
    (block("hobbit_arm_turntable", {"movement": "MoveToLearning"}), "robot.turntable('learn')"),
    (block("hobbit_arm_turntable", {"movement": "StoreTurntable"}), "robot.turntable('store')"),
    (block("hobbit_arm_turntable", {"movement": "TurnTurntableCW"}), "robot.turntable('clockwise')"),
    (block("hobbit_arm_turntable", {"movement": "TurnTurntableCCW"}), "robot.turntable('counterclockwise')"),
    (block("hobbit_arm_joints", inputs={f"joint{i}": number(i * 10) for i in range(1, 7)}),
     "robot.move_arm_to_joints([10, 20, 30, 40, 50, 60])"),
    (block("hobbit_navigation_test", inputs={"pos_x": number(1), "pos_y": number(2), "pos_z": number(0),
                                            "quat_x": number(0), "quat_y": number(0), "quat_z": number(0.7071),
                                            "quat_w": number(0.7071)}),
     "robot.navigate_to_pose(1, 2, 0, 0, 0, 0.7071, 0.7071)"),
    (block("hobbit_show_info", inputs={"text": text("Hello")}), "robot.show_info('Hello')"),
    (block("hobbit_show_info_confirm", inputs={"text": text("Ready?")}), "robot.show_info_and_wait('Ready?')"),
    (block("hobbit_volume", {"change": "louder"}), "robot.change_volume('louder')"),
    (block("hobbit_volume", {"change": "quieter"}), "robot.change_volume('quieter')"),
    (block("hobbit_sos"), "robot.call_sos()"),
    (block("hobbit_wait", inputs={"seconds": number(3)}), "robot.wait(3)"),
    (block("ROS_publisher", {"message_type": "Float64"}, {"message": number(1.5), "topic_name": text("/speed")}),
     "robot.publish('/speed', 'Float64', 1.5)"),
]

EXPRESSIONS = [
    (block("hobbit_battery"), "robot.battery_level()"),
    (block("hobbit_position", {"coordinate": "heading"}), "robot.position('heading')"),
    (block("hobbit_head_position"), "robot.head_position()"),
    (block("hobbit_emotion"), "robot.emotion()"),
    (block("hobbit_arm_moving"), "robot.arm_is_moving()"),
    (block("ros_latest_value", inputs={"topic": text("/odom"), "field": text("pose.pose.position.x")}),
     "robot.latest_value('/odom', 'pose.pose.position.x')"),
]


ROS_STATEMENTS = [
    (block("ros_publish_value", {"message_type": "Int64"}, {"value": number(3), "topic": text("/count")}),
     "ros.publish('/count', 'Int64', 3)"),
    (block("ros_publish_message", {"message_type": "std_msgs/String"},
           {"topic": text("/chatter"), "field:data": text("it's \"quoted\"\nand two lines")}),
     "ros.publish_message('/chatter', 'std_msgs/String', {'data': 'it\\'s \"quoted\"\\nand two lines'})"),
    (block("ros_cancel_goals", inputs={"action": text("move_base")}), "ros.cancel_goals('move_base')"),
    (block("ros_set_param", inputs={"name": text("/speed"), "value": number(2)}), "ros.set_param('/speed', 2)"),
    (block("ros_wait", inputs={"seconds": number(2)}), "ros.wait(2)"),
    (block("ros_log", {"level": "warn"}, {"text": text("careful")}), "ros.log('warn', 'careful')"),
]
ROS_EXPRESSIONS = [
    (block("ros_wait_message", inputs={"topic": text("/odom"), "timeout": number(5)}),
     "ros.wait_for_message('/odom', 5)"),
    (block("ros_message_field", inputs={"path": text("pose.pose.position.x"),
                                        "message": block("ros_wait_message", inputs={"topic": text("/odom")})}),
     "ros.field(ros.wait_for_message('/odom', 10), 'pose.pose.position.x')"),
    (block("ros_call_service", {"service_type": "std_srvs/SetBool"},
           {"name": text("/enable"), "field:data": block("logic_boolean", {"BOOL": "TRUE"})}),
     "ros.call_service('/enable', 'std_srvs/SetBool', {'data': True})"),
    (block("ros_send_goal", {"action_type": "hobbit_msgs/ArmServerAction"},
           {"action": text("hobbit_arm"), "field:command.data": text("MoveToHome")}),
     "ros.send_goal('hobbit_arm', 'hobbit_msgs/ArmServerAction', {'command': {'data': 'MoveToHome'}, 'velocity': 0}, "
     "while_waiting=None)"),
    (block("ros_get_param", inputs={"name": text("/speed")}), "ros.get_param('/speed')"),
    (block("ros_latest_field", inputs={"path": text("percentage"), "topic": text("/battery_state")}),
     "ros.latest('/battery_state', 'percentage')"),
]


@pytest.mark.parametrize(("program", "expected"), ROS_STATEMENTS, ids=[b["type"] for b, _ in ROS_STATEMENTS])
def test_generic_ros_statement_blocks(headless_editor, hobbit, program, expected):
    assert generate(headless_editor, hobbit, program).strip() == expected


@pytest.mark.parametrize(("expression", "expected"), ROS_EXPRESSIONS, ids=[b["type"] for b, _ in ROS_EXPRESSIONS])
def test_generic_ros_value_blocks(headless_editor, hobbit, expression, expected):
    code = generate(headless_editor, hobbit, block("text_print", inputs={"TEXT": expression}))
    assert code.strip().splitlines()[-1] == f"print({expected})"  # after the goal's feedback variable


@pytest.mark.parametrize(("expression", "expected"), EXPRESSIONS, ids=[b["type"] for b, _ in EXPRESSIONS])
def test_sensor_blocks_become_their_queries(headless_editor, hobbit, expression, expected):
    code = generate(headless_editor, hobbit, block("text_print", inputs={"TEXT": expression}))
    assert code.strip() == f"print({expected})"


@pytest.mark.parametrize(("program", "expected"), STATEMENTS,
                         ids=[f"{b['type']}-{i}" for i, (b, _) in enumerate(STATEMENTS)])
def test_statement_block_becomes_its_command(headless_editor, hobbit, program, expected):
    assert generate(headless_editor, hobbit, program).strip() == expected


def test_yes_no_block_compares_the_answer_with_the_chosen_one(headless_editor, hobbit):
    asked_yes = block("controls_if", inputs={
        "IF0": block("hobbit_yes_no", {"yes_no": "D_YES"}, {"text": text("Tea?")}),
        "DO0": block("hobbit_sos")})
    asked_no = block("controls_if", inputs={
        "IF0": block("hobbit_yes_no", {"yes_no": "D_NO"}, {"text": text("Tea?")}),
        "DO0": block("hobbit_sos")})
    assert generate(headless_editor, hobbit, asked_yes).splitlines()[0] == "if robot.ask_yes_no('Tea?') == True:"
    assert generate(headless_editor, hobbit, asked_no).splitlines()[0] == "if robot.ask_yes_no('Tea?') == False:"


def test_expression_blocks_nest_inside_other_blocks(headless_editor, hobbit):
    greeting = block("hobbit_show_info", inputs={"text": block("text_join", inputs={
        "ADD0": text("Hi "), "ADD1": block("hobbit_user_input", inputs={"text": text("Name?")})},
        extraState={"itemCount": 2})})
    code = generate(headless_editor, hobbit, greeting)
    assert "robot.show_info('Hi ' + str(robot.ask_text('Name?')))" in code


def test_service_block_returns_the_response(headless_editor, hobbit):
    program = block("variables_set", {"VAR": {"id": "v1"}}, {"VALUE": block(
        "hobbit_call_service", {"has_parameters": "no_params"},
        {"service_name": text("/trigger"), "service_type": text("std_srvs/Trigger")})})
    ws = workspace(program)
    ws["variables"] = [{"name": "answer", "id": "v1"}]
    code = headless_editor.python_for(ProgramToOpen(path=None, profile=hobbit, workspace=ws))
    assert "answer = robot.call_service('/trigger', 'std_srvs/Trigger', None, False)" in code


def test_the_thesis_pick_up_program(headless_editor, hobbit):
    program = stack(*(block(kind, {"movement": value}) for kind, value in (
        ("hobbit_arm_gripper", "OpenGripper"), ("hobbit_arm_move", "MoveToPreGraspFloor"),
        ("hobbit_arm_gripper", "CloseGripper"), ("hobbit_arm_move", "MoveToPreGraspTable"),
        ("hobbit_arm_gripper", "OpenGripper"))))
    assert generate(headless_editor, hobbit, program).split() == [
        "robot.gripper('open')", "robot.move_arm('floor')", "robot.gripper('close')",
        "robot.move_arm('table')", "robot.gripper('open')"]


def test_every_hobbit_block_is_covered_here(hobbit):
    covered = ({b["type"] for b, _ in STATEMENTS + EXPRESSIONS + ROS_STATEMENTS + ROS_EXPRESSIONS}
               | {"hobbit_yes_no", "hobbit_user_input", "hobbit_call_service"})
    assert covered == hobbit.block_types


NASTY_TEXTS = [
    "it's",
    'say "hi"',
    "back\\slash \\n not a newline",
    "two\nlines\r\nand\ttab",
    '"""triple"""',
    "'''triple'''",
    "'); import os #",
    '"); __import__("os").system("echo pwned") #',
    "{speed} {{braces}} %s",
    "Grüße, 你好, مرحبا, 🤖👋, e\u0301",
    "line\u2028separator\u2029paragraph\x00nul\x7fdel",
    "\\",
    "",
]

TEXT_INPUTS = [
    ("hobbit_show_info", "text"), ("hobbit_show_info_confirm", "text"), ("hobbit_yes_no", "text"),
    ("hobbit_user_input", "text"), ("ROS_publisher", "message"), ("ROS_publisher", "topic_name"),
    ("hobbit_call_service", "service_name"), ("hobbit_call_service", "service_type"),
]


def _as_statement(block_type, input_name, value):
    inner = block(block_type, inputs={input_name: text(value)})
    if block_type in ("hobbit_yes_no", "hobbit_user_input", "hobbit_call_service"):
        return block("text_print", inputs={"TEXT": inner})
    return inner


@pytest.mark.parametrize(("block_type", "input_name"), TEXT_INPUTS)
def test_user_text_reaches_python_as_the_exact_string_never_as_code(headless_editor, hobbit, block_type, input_name):
    for value in NASTY_TEXTS:
        code = generate(headless_editor, hobbit, _as_statement(block_type, input_name, value))
        tree = parse_python(code)
        strings = [node.value for node in ast.walk(tree)
                   if isinstance(node, ast.Constant) and isinstance(node.value, str)]
        assert value in strings, f"{value!r} not carried exactly by {code!r}"
        assert not [node for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))]
        calls = [node.func for node in ast.walk(tree) if isinstance(node, ast.Call)]
        assert all(isinstance(func, (ast.Attribute, ast.Name)) for func in calls)
        assert "system" not in {getattr(func, "attr", getattr(func, "id", None)) for func in calls}


HOSTILE_COMMENTS = [
    "note\rprint('INJECTED')",
    "note\r\nprint('INJECTED')",
    "note\u2028print('INJECTED')\u2029x = 1",
    "note\nprint('INJECTED')",
    "nul\x00byte",
]


def test_block_comments_never_become_code(headless_editor, hobbit):
    for comment in HOSTILE_COMMENTS:
        program = block("hobbit_sos", icons={"comment": {"text": comment, "pinned": False, "height": 80, "width": 160}})
        for code in (generate(headless_editor, hobbit, program), headless_editor.call_and_wait("getRunCode")["code"]):
            tree = parse_python(code)
            calls = [node.func.attr if isinstance(node.func, ast.Attribute) else node.func.id
                     for node in ast.walk(tree) if isinstance(node, ast.Call)]
            assert "print" not in calls, (comment, code)
            assert [line for line in code.replace("\r", "\n").splitlines()
                    if "INJECTED" in line and not line.lstrip().startswith("#")] == []
