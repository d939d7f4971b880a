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
