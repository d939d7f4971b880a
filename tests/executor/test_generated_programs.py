"""Real Blockly-generated, instrumented programs: stepping order through loops, functions, if/else."""
import ast

from program_builder import block, number, stack, text, workspace
from test_runner import step_through as step_through_code

from rockly_desktop.core.python_syntax import parse_python
from rockly_desktop.executor.events import OutputPrinted, RunFinished


def run_code(editor, ws):
    editor.call_and_wait("load", {"workspace": ws})
    return editor.call_and_wait("getRunCode")


def step_through(run):
    """Step through a page's getRunCode answer; the run must finish."""
    visited, recorder = step_through_code(run["code"], run["variables"])
    assert recorder.events[-1] == RunFinished("finished"), recorder.events[-1]
    return visited, recorder


def printing(block_id, value):
    return block("text_print", inputs={"TEXT": text(value)}, id=block_id)


def test_steps_follow_a_repeat_loop(headless_editor):
    program = stack(printing("before", "go"),
                    block("controls_repeat_ext", inputs={"TIMES": number(2), "DO": printing("inside", "x")}, id="loop"),
                    printing("after", "end"))
    visited, recorder = step_through(run_code(headless_editor, workspace(program)))
    # Blockly's loop trap re-enters the loop block after each pass, so a child sees the loop "count".
    assert visited == ["before", "loop", "inside", "loop", "inside", "loop", "after"]
    assert [e.text for e in recorder.of(OutputPrinted)] == ["go", "x", "x", "end"]


def test_steps_follow_if_else(headless_editor):
    program = block("controls_if", id="if", extraState={"hasElse": True}, inputs={
        "IF0": block("logic_boolean", {"BOOL": "FALSE"}),
        "DO0": printing("then", "yes"),
        "ELSE": printing("else", "no")})
    visited, _ = step_through(run_code(headless_editor, workspace(program)))
    assert visited == ["if", "else"]


def test_steps_enter_functions_and_variables_are_read(headless_editor):
    ws = workspace(
        block("procedures_defnoreturn", {"NAME": "greet"}, id="def", x=0, y=200,
              inputs={"STACK": block("math_change", {"VAR": {"id": "v"}}, {"DELTA": number(5)}, id="add")}),
        stack(block("variables_set", {"VAR": {"id": "v"}}, {"VALUE": number(1)}, id="set"),
              block("procedures_callnoreturn", id="call1", extraState={"name": "greet"}),
              block("procedures_callnoreturn", id="call2", extraState={"name": "greet"})))
    ws["variables"] = [{"name": "points", "id": "v"}]
    run = run_code(headless_editor, ws)
    assert run["variables"] == {"points": "points"}
    visited, recorder = step_through(run)
    assert visited == ["set", "call1", "def", "add", "call2", "def", "add"]
    assert recorder.events[-2].values == {"points": "11"}


def test_block_ids_full_of_quotes_stay_data(headless_editor):
    nasty = "x'); import os #\\"
    run = run_code(headless_editor, workspace(printing(nasty, "hi")))
    visited, recorder = step_through(run)
    assert visited == [nasty]
    tree = parse_python(run["code"])
    assert not [node for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))]


def test_with_values_on_every_expression_block_hands_its_value_in_and_the_program_does_the_same(headless_editor):
    from test_runner import run_to_end

    ws = workspace(
        block("procedures_defreturn", {"NAME": "double"}, id="def", x=0, y=400, extraState={"params": [
            {"name": "n", "id": "n"}]}, inputs={"RETURN": block("math_arithmetic", {"OP": "MULTIPLY"}, {
                "A": block("variables_get", {"VAR": {"id": "n"}}, id="n_in"), "B": number(2)}, id="twice")}),
        stack(block("variables_set", {"VAR": {"id": "v"}}, {"VALUE": block("lists_create_with", id="list",
              extraState={"itemCount": 2}, inputs={"ADD0": number(3), "ADD1": number(4)})}, id="set"),
              block("lists_setIndex", {"MODE": "SET", "WHERE": "FIRST"}, {
                  "LIST": block("variables_get", {"VAR": {"id": "v"}}, id="v_list"), "TO": number(5)}, id="first"),
              block("text_print", inputs={"TEXT": block("text_join", id="join", extraState={"itemCount": 2}, inputs={
                  "ADD0": block("lists_getIndex", {"MODE": "GET", "WHERE": "FROM_START"}, {
                      "VALUE": block("variables_get", {"VAR": {"id": "v"}}, id="v_get"), "AT": number(2)}, id="at"),
                  "ADD1": block("logic_ternary", inputs={"IF": block("logic_compare", {"OP": "GT"}, {
                      "A": block("procedures_callreturn", extraState={"name": "double", "params": ["n"]},
                                 inputs={"ARG0": number(4)}, id="call"), "B": number(7)}, id="more"),
                      "THEN": text("!"), "ELSE": text("?")}, id="pick")})}, id="say")))
    ws["variables"] = [{"name": "points", "id": "v"}, {"name": "n", "id": "n"}]
    headless_editor.call_and_wait("load", {"workspace": ws})
    plain = headless_editor.call_and_wait("getRunCode")
    watched = headless_editor.call_and_wait("getRunCode", {"values": True})
    assert "__rockly__.value" not in plain["code"] and "__rockly__.value('pick'" in watched["code"]
    outputs = []
    for run in (plain, watched):
        runner, recorder = run_to_end(run["code"], variables=run["variables"])
        assert recorder.events[-1] == RunFinished("finished"), recorder.events[-1]
        outputs.append([event.text for event in recorder.of(OutputPrinted)])
    assert outputs[0] == outputs[1] == ["4!"]
    assert runner.values_snapshot() == {"list": "[5, 4]", "v_list": "[5, 4]", "join": "“4!”", "v_get": "[5, 4]",
                                        "at": "4", "n_in": "4", "twice": "8", "call": "8", "more": "true",
                                        "pick": "“!”"}
