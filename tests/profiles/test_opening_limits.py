"""Opening very large and very deep programs: up to the limit they open, past it they are refused clearly."""
import pytest
from program_builder import block, rockly_document, stack

from rockly_desktop.core.errors import ProgramFileError
from rockly_desktop.core.workspace_blocks import MAX_BLOCK_DEPTH
from rockly_desktop.profiles.opening import read_program_to_open


def print_stack(count):
    return stack(*[block("text_print", inputs={"TEXT": block("text", {"TEXT": f"line {i}"})}) for i in range(count)])


def deep_xml(count):
    return ('<xml xmlns="https://developers.google.com/blockly/xml">' + '<block type="hobbit_stop"><next>' * count
            + "</next></block>" * count + "</xml>")


def test_a_stack_of_600_blocks_opens(tmp_path, registry):
    path = tmp_path / "long.rockly"
    path.write_text(rockly_document([print_stack(600)]), encoding="utf-8")

    program = read_program_to_open(path, registry, registry.default())

    assert program.profile.id == "hobbit"


def test_a_stack_deeper_than_the_editor_takes_is_refused_with_the_limit(tmp_path, registry):
    path = tmp_path / "too-long.rockly"
    path.write_text(rockly_document([print_stack(MAX_BLOCK_DEPTH + 1)]), encoding="utf-8")

    with pytest.raises(ProgramFileError, match="takes up to 1,000"):
        read_program_to_open(path, registry, registry.default())


def test_first_rockly_xml_500_blocks_deep_imports(tmp_path, registry):
    path = tmp_path / "deep.xml"
    path.write_text(deep_xml(500), encoding="utf-8")

    program = read_program_to_open(path, registry, registry.default())

    assert program.xml.count('<block type="hobbit_stop">') == 500


@pytest.mark.parametrize("count", [MAX_BLOCK_DEPTH + 1, 70_000])
def test_first_rockly_xml_too_deep_is_refused_without_crashing(tmp_path, registry, count):
    path = tmp_path / "deeper.xml"
    path.write_text(deep_xml(count), encoding="utf-8")

    with pytest.raises(ProgramFileError, match=f"{count:,} blocks inside or under one another"):
        read_program_to_open(path, registry, registry.default())
