"""Real Blockly-generated, instrumented programs: stepping order through loops, functions, if/else."""
import ast
import threading

from program_builder import block, number, stack, text, workspace
from test_runner import Recorder

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.events import OutputPrinted, RunFinished, RunPaused
from rockly_desktop.executor.runner import ProgramRunner


def run_code(editor, ws):
    editor.view.call_blocking("load", {"workspace": ws})
    return editor.view.call_blocking("getRunCode")


def step_through(run):
    """Run the program one block at a time on a thread; return the block ids in order."""
    control = RunControl()
    control.step()
    recorder = Recorder()
    runner = ProgramRunner(run["code"], {}, control, recorder, run["variables"])
    thread = threading.Thread(target=runner.run)
    thread.start()
    visited = []
    while True:
        recorder.wait_for(lambda e: isinstance(e, (RunPaused, RunFinished)) and
                          len(recorder.of(RunPaused)) + len(recorder.of(RunFinished)) > len(visited))
        if recorder.of(RunFinished):
            break
        visited.append(recorder.of(RunPaused)[-1].block_id)
        control.step()
    thread.join(5)
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
