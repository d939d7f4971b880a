"""Programs are what their blocks say: the robot's agent (in a process of its own) generates each kept program's
code from its ``.rockly`` source with the window's Rockly, and says whether it is the code that runs
(``agent.source_match``), in ``rockly robot list`` and in what a client is sent."""
import pytest
from agent_tools import AgentProcess
from program_builder import block, number, stack
from standalone_tools import exported_program
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient


@pytest.fixture(scope="module")
def program(tmp_path_factory):
    """``(standalone .py, .rockly)`` of a short program, exported as ``rockly export --standalone`` does."""
    drive = stack(block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                  block("text_print", inputs={"TEXT": block("text", {"TEXT": "done"})}, id="tell"))
    return exported_program(tmp_path_factory.mktemp("checked-program"), drive)


@pytest.fixture
def agent(tmp_path):
    started = []

    def start(*options):
        started.append(AgentProcess(tmp_path / f"library-{len(started)}", *options))
        return started[-1]
    yield start
    for each in started:
        each.stop()


def checked(client, name: str) -> dict:
    """Program ``name``'s entry once its check has ended."""
    def entry():
        found = [about for about in client.programs()["programs"] if about["name"] == name]
        return found[0] if found and found[0].get("code") != "checking" else None
    eventually(entry, 120)
    return entry()


def test_the_code_its_blocks_make_is_same_and_changed_code_differs(agent, program):
    standalone, source = program[0].read_text(), program[1].read_text()
    # code a sender put in beside the blocks: the standalone file still reads, and runs it
    changed = standalone.replace('RUN_CODE = """', 'RUN_CODE = """import os\nos.system("true")\n', 1)
    assert changed != standalone
    running = agent("--speed", "20")
    client = AgentClient("127.0.0.1", running.port)
    try:
        client.send("honest", standalone, source)
        client.send("changed", changed, source)
        client.send("bare", standalone)
        assert [about["code"] for about in client.programs()["programs"] if about["name"] == "honest"] in (
            ["checking"], ["same"])  # a send never waits for the check
        assert checked(client, "honest")["code"] == "same"
        assert (checked(client, "changed")["code"], checked(client, "changed")["code_part"]) == ("differs", "code")
        assert checked(client, "bare")["code"] == "no_source"
    finally:
        client.close()
    listed = running.robot("list").stdout
    assert "its code is what its blocks make (checked on the robot)" in listed
    assert "its code is NOT what its blocks make (the code differs)" in listed
    assert "sein Code ist NICHT das, was seine Blöcke ergeben (der Code anders)" in running.robot(
        "list", language="de").stdout


def test_a_newer_program_of_the_same_name_is_checked_itself(agent, program):
    """A program replaced while its check runs keeps the check of what it is now, not of what it was."""
    standalone, source = program[0].read_text(), program[1].read_text()
    changed = standalone.replace('RUN_CODE = """', 'RUN_CODE = """print(1)\n', 1)
    running = agent("--speed", "20")
    client = AgentClient("127.0.0.1", running.port)
    try:
        client.send("demo", changed, source)
        client.send("demo", standalone, source)
        assert checked(client, "demo")["code"] == "same"
    finally:
        client.close()


def test_an_agent_told_not_to_check_says_so(agent, program):
    running = agent("--no-source-check")
    client = AgentClient("127.0.0.1", running.port)
    try:
        client.send("honest", program[0].read_text(), program[1].read_text())
        assert (checked(client, "honest")["code"], checked(client, "honest")["code_reason"]) == ("unchecked", "off")
    finally:
        client.close()
    assert "not known here (the agent's check is switched off)" in running.robot("list").stdout
