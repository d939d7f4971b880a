"""What blocks cannot say stays as it was, in a Python block the real editor writes back as it is."""
from rockly_desktop.profiles.opening import read_program_to_open
from rockly_desktop.python_blocks.convert import python_to_program
from rockly_desktop.python_blocks.source import parse_source

TEXT = """import os

robot.show_emotion('HAPPY')
# ask first
with open(os.devnull) as stream:
  stream.read()
robot.drive(1, 'forward')
"""


def test_python_blocks_keep_their_text_and_the_rest_becomes_blocks(headless_editor, registry, tmp_path):
    conversion = python_to_program(parse_source(TEXT), registry.get("hobbit"))
    assert [(part.first_line, part.last_line) for part in conversion.kept_python] == [(1, 1), (5, 6)]
    path = tmp_path / "kept.rockly"
    path.write_text(conversion.program.to_json())
    python = headless_editor.python_for(read_program_to_open(path, registry, registry.default()))
    assert python == TEXT.replace("import os\n\n", "import os\n")  # blank lines between blocks go


def test_a_python_block_runs_as_one_step(headless_editor, registry, tmp_path):
    conversion = python_to_program(parse_source("for i in range(1, 3):\n  robot.stop()\n"), registry.get("hobbit"))
    path = tmp_path / "step.rockly"
    path.write_text(conversion.program.to_json())
    headless_editor.python_for(read_program_to_open(path, registry, registry.default()))
    code = headless_editor.call_and_wait("getRunCode", {"values": False})["code"]
    kept = conversion.program.workspace["blocks"]["blocks"][0]
    assert kept["type"] == "rockly_python"
    assert code.strip().splitlines()[-3:] == [f"__rockly__.block('{kept['id']}')", "for i in range(1, 3):",
                                              "  robot.stop()"]


def test_comments_become_block_comments_and_those_that_cannot_stay_python(registry):
    text = ("# Say hello.\nrobot.show_emotion('HAPPY')\nrobot.stop()  # now\n"
            "if True:\n  robot.stop()\n  # inside, at the end\nrobot.stop()\n# the end\n")
    conversion = python_to_program(parse_source(text), registry.get("hobbit"))
    first = conversion.program.workspace["blocks"]["blocks"][0]
    assert first["icons"]["comment"]["text"] == "Say hello."
    second = first["next"]["block"]
    assert (second["type"], second["extraState"]["code"]) == ("rockly_python", "robot.stop()  # now")
    assert [(part.first_line, part.last_line) for part in conversion.kept_python] == [(3, 3), (8, 8)]
    last = second["next"]["block"]["next"]["block"]
    assert last["icons"]["comment"]["text"] == "inside, at the end"  # moved to the next statement, kept
    assert last["next"]["block"]["extraState"]["code"] == "# the end"
