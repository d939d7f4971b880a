"""Real Blockly-generated, instrumented programs: stepping order through loops, functions, if/else."""
import ast

from program_builder import block, number, stack, text, workspace
from test_runner import step_through as step_through_code

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
    tree = ast.parse(run["code"])
    assert not [node for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))]
