"""A client that takes nothing any more (a laptop gone to sleep, a cut network: TCP closes nothing) is dropped by the
agent (``rockly agent`` in a process of its own): the run, the other clients and a STOP do not wait for it."""
import json
import socket

import pytest
from agent_tools import AgentProcess
from program_builder import block, rockly_document, text
from standalone_tools import environment, export_standalone
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.runtime.agent.tcp_transport import SEND_SECONDS

LONG_LINE = "a robot that talks a lot " * 80  # 2,000 characters a print: megabytes of events within seconds


@pytest.fixture(scope="module")
def chatty_program(tmp_path_factory):
    """Print a long line for ever."""
    folder = tmp_path_factory.mktemp("agent-chatty-program")
    source = folder / "chatty.rockly"
    source.write_text(rockly_document([block("controls_whileUntil", {"MODE": "WHILE"}, {
        "BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
        "DO": block("text_print", inputs={"TEXT": text(LONG_LINE)}, id="talk")})]))
    env = environment(XDG_CONFIG_HOME=str(folder / "config"), XDG_DATA_HOME=str(folder / "data"))
    return export_standalone(source, folder / "chatty.py", "--language", "en", env=env).read_text()


@pytest.fixture
def agent(tmp_path, chatty_program):
    agent = AgentProcess(tmp_path / "library")
    client = AgentClient("127.0.0.1", agent.port)
    client.send("chatty", chatty_program, on_lost_editor="stop")
    client.close()
    yield agent
    agent.stop()


def asleep_watcher(port: int) -> socket.socket:
    """A client that says hello, watches the run, and then reads nothing (with a small receive buffer: it is full
    at once)."""
    connection = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    connection.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    connection.connect(("127.0.0.1", port))
    for request in ({"op": "hello", "id": 1, "format": 1, "language": "en", "client": "asleep"},
                    {"op": "attach", "id": 2, "control": False}):
        connection.sendall((json.dumps(request) + "\n").encode())
    return connection


def test_a_client_that_takes_nothing_is_dropped_and_holds_up_neither_the_run_nor_a_stop(agent):
    asleep = asleep_watcher(agent.port)
    printed = []
    editor = AgentClient("127.0.0.1", agent.port, on_event=lambda event: event.get("event") == "print"
                         and printed.append(len(event.get("text", ""))))
    try:
        editor.attach(control=True)
        editor.start("chatty")
        # far more than the asleep client's connection holds (its buffer and the agent's, 4 MB at most): before,
        # every event then waited for it, the program with them, and the editor heard nothing more
        eventually(lambda: sum(printed) > 40_000_000, 120)
        assert editor.stop()
        eventually(lambda: editor.programs()["run"] is None, 4 * SEND_SECONDS + 10)
        # the agent shut the asleep client's connection: what it had taken is followed by the end
        asleep.settimeout(30)
        while asleep.recv(1 << 20):
            pass
    finally:
        editor.close()
        asleep.close()
