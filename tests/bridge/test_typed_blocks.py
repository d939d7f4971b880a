"""Typed ROS blocks in the real editor: inputs per field of the chosen type, checks, saving, handlers."""

from page_tools import add_block_as_user, call_page, print_value, run_js
from program_builder import block, number, stack, text, workspace

from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.profiles.opening import ProgramToOpen

FIELD_INPUTS = """(() => {
    const b = Blockly.getMainWorkspace().getBlockById(%r);
    return b.inputList.filter(i => i.name.startsWith('field:'))
        .map(i => [i.name.slice(6), (i.connection.getCheck() || [null])[0]]); })()"""


def choose_type(qtbot, view, block_id, field, value):
    run_js(qtbot, view,
           f"Blockly.getMainWorkspace().getBlockById({block_id!r}).setFieldValue({value!r}, {field!r}) || true")


def test_the_publish_block_grows_one_checked_input_per_field_of_the_chosen_type(qtbot, editor):
    block_id = add_block_as_user(qtbot, editor, "ros_publish_message")
    assert run_js(qtbot, editor, FIELD_INPUTS % block_id) == [
        ["linear.x", "Number"], ["linear.y", "Number"], ["linear.z", "Number"],
        ["angular.x", "Number"], ["angular.y", "Number"], ["angular.z", "Number"]]
    options = run_js(qtbot, editor, f"Blockly.getMainWorkspace().getBlockById({block_id!r})"
                                    ".getField('message_type').getOptions().map(o => o[1])")
    assert {"std_msgs/String", "std_msgs/Bool", "sensor_msgs/LaserScan", "nav_msgs/Odometry",
            "geometry_msgs/PoseStamped", "hobbit_msgs/arm_joints"} <= set(options)   # the profile's own too
    choose_type(qtbot, editor, block_id, "message_type", "sensor_msgs/BatteryState")
    battery = dict(map(tuple, run_js(qtbot, editor, FIELD_INPUTS % block_id)))
    assert battery["percentage"] == "Number" and battery["present"] == "Boolean"
    assert battery["location"] == "String" and battery["cell_voltage"] == "Array"


def test_a_new_pose_goal_starts_as_a_valid_pose(qtbot, editor):
    block_id = add_block_as_user(qtbot, editor, "ros_send_goal")
    choose_type(qtbot, editor, block_id, "action_type", "move_base_msgs/MoveBaseAction")
    print_value(qtbot, editor, block_id)  # a loose value block is not generated: it is run in a print
    qtbot.waitUntil(lambda: "ros.send_goal" in call_page(qtbot, editor, "getState")["python"], timeout=5000)
    python = call_page(qtbot, editor, "getState")["python"]
    assert "'orientation': {'x': 0, 'y': 0, 'z': 0, 'w': 1}" in python   # no rotation, not an invalid all-zero one


def test_a_number_field_refuses_a_text_block(qtbot, editor):
    block_id = add_block_as_user(qtbot, editor, "ros_publish_message")
    fits = run_js(qtbot, editor, f"""(() => {{
        const ws = Blockly.getMainWorkspace();
        const input = ws.getBlockById({block_id!r}).getInput('field:linear.x');
        const fits = (type) => ws.connectionChecker.canConnect(
            input.connection, ws.newBlock(type).outputConnection, false);
        return [fits('text'), fits('math_number'), fits('math_arithmetic'), fits('logic_boolean')]; }})()""")
    assert fits == [False, True, True, False]


def test_changing_the_type_keeps_the_blocks_of_fields_both_types_have_and_sets_the_others_aside(qtbot, editor):
    call_page(qtbot, editor, "load", {"workspace": workspace(block(
        "ros_publish_message", {"message_type": "geometry_msgs/Vector3"},
        {"topic": text("/v"), "field:x": block("math_arithmetic", {"OP": "ADD"}, {"A": number(1), "B": number(2)}),
         "field:y": block("text_length", inputs={"VALUE": text("abc")})}, id="pub"))})
    choose_type(qtbot, editor, "pub", "message_type", "geometry_msgs/Point")       # also x, y, z
    assert "{'x': 1 + 2, 'y': len('abc'), 'z': 0}" in call_page(qtbot, editor, "getState")["python"]
    choose_type(qtbot, editor, "pub", "message_type", "std_msgs/String")
    assert run_js(qtbot, editor, FIELD_INPUTS % "pub") == [["data", "String"]]
    top = run_js(qtbot, editor, "Blockly.getMainWorkspace().getTopBlocks(true).map(b => b.type).sort()")
    assert top == ["math_arithmetic", "ros_publish_message", "text_length"]   # nothing lost


def test_a_saved_typed_block_opens_with_its_fields_even_where_its_type_is_unknown(qtbot, editor):
    saved = block("ros_publish_message", {"message_type": "lab_msgs/Beep"},
                  {"topic": text("/beep"), "field:pitch": number(440), "field:label": text('say "hi"\n')},
                  id="beep", extraState={"type": "lab_msgs/Beep", "fields": [["pitch", "Number"], ["label", "String"]]})
    call_page(qtbot, editor, "load", {"workspace": workspace(saved)})
    state = call_page(qtbot, editor, "getState")
    assert state["python"].strip() == ("ros.publish_message('/beep', 'lab_msgs/Beep', "
                                       "{'pitch': 440, 'label': 'say \"hi\"\\n'})")
    again = state["workspace"]["blocks"]["blocks"][0]
    assert again["extraState"] == {"type": "lab_msgs/Beep",
                                   "fields": [["pitch", "Number", None], ["label", "String", None]]}
    assert again["fields"]["message_type"] == "lab_msgs/Beep"


def test_a_goal_with_a_while_waiting_handler_becomes_a_function_the_command_calls(headless_editor, hobbit):
    feedback = block("variables_get", {"VAR": {"id": "fb"}})
    handler = block("variables_set", {"VAR": {"id": "seen"}}, {"VALUE": block(
        "ros_message_field", inputs={"path": text("feedback.data"), "message": feedback})})
    goal = block("ros_send_goal", {"action_type": "hobbit_msgs/ArmServerAction", "feedback": {"id": "fb"}},
                 {"action": text("hobbit_arm"), "field:command.data": text("MoveToCandle"), "while_waiting": handler})
    ws = workspace(block("variables_set", {"VAR": {"id": "outcome"}}, {"VALUE": goal}))
    ws["variables"] = [{"name": "feedback", "id": "fb"}, {"name": "seen", "id": "seen"},
                       {"name": "outcome", "id": "outcome"}]
    code = headless_editor.python_for(ProgramToOpen(path=None, profile=hobbit, workspace=ws))
    parse_python(code)
    assert ("def while_waiting(received):\n"
            "  global outcome, feedback, seen\n"
            "  feedback = received\n"
            "  seen = ros.field(feedback, 'feedback.data')\n") in code
    assert ("outcome = ros.send_goal('hobbit_arm', 'hobbit_msgs/ArmServerAction', "
            "{'command': {'data': 'MoveToCandle'}, 'velocity': 0}, while_waiting=while_waiting)") in code


def test_two_handlers_get_two_functions(headless_editor, hobbit):
    def goal(command):
        return block("ros_send_goal", {"action_type": "hobbit_msgs/ArmServerAction", "feedback": {"id": "fb"}},
                     {"action": text("hobbit_arm"), "field:command.data": text(command),
                      "while_waiting": block("text_print", inputs={"TEXT": text(command)})})
    ws = workspace(stack(block("text_print", inputs={"TEXT": goal("MoveToHome")}),
                         block("text_print", inputs={"TEXT": goal("MoveToTray")})))
    ws["variables"] = [{"name": "feedback", "id": "fb"}]
    code = headless_editor.python_for(ProgramToOpen(path=None, profile=hobbit, workspace=ws))
    parse_python(code)
    assert "def while_waiting(received):" in code and "def while_waiting2(received2):" in code
    assert "while_waiting=while_waiting)" in code and "while_waiting=while_waiting2)" in code
