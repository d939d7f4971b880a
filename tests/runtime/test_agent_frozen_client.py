"""A client that takes nothing any more (a laptop gone to sleep, a cut network: TCP closes nothing), or takes the
run's events far slower than they come (bad Wi-Fi), is dropped by the agent (``rockly agent`` in a process of its
own): the run, the other clients and a STOP do not wait for it."""
import ssl
import threading
import time

import pytest
from agent_tools import AgentProcess
from agent_wire import hello, say, tls_connection
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


def watcher(agent):
    """A paired client that says hello and watches the run, over TLS, with a small receive buffer: it fills at once."""
    connection, nonce = tls_connection(agent.port, receive_buffer=4096)
    say(connection, hello(nonce, agent.key, client="asleep", id=1))
    say(connection, {"op": "attach", "id": 2, "control": False})
    return connection


class SlowReader:
    """Takes 4 kB of what ``connection`` holds every 20 ms (some 200 kB/s) until it ends."""

    def __init__(self, connection):
        self.connection = connection
        self.ended = threading.Event()
        self._thread = threading.Thread(target=self._read, daemon=True)
        self._thread.start()

    def _read(self):
        try:
            while self._take(4096):
                time.sleep(0.02)
        except OSError:
            pass
        self.ended.set()

    def _take(self, size: int) -> bool:
        """Take ``size`` bytes (TLS hands them out a record at a time); False once the connection has ended."""
        while size > 0:
            data = self.connection.recv(size)
            if not data:
                return False
            size -= len(data)
        return True

    def join(self):
        self._thread.join(10)


@pytest.mark.parametrize("kind", ["asleep", "slow"])
def test_a_client_that_cannot_keep_up_is_dropped_and_holds_up_neither_the_run_nor_a_stop(agent, kind):
    behind = watcher(agent)
    reader = SlowReader(behind) if kind == "slow" else None
    printed = []
    editor = AgentClient("127.0.0.1", agent.port, on_event=lambda event: event.get("event") == "print"
                         and printed.append(len(event.get("text", ""))))
    try:
        editor.attach(control=True)
        editor.start("chatty")
        # far more than the client behind can take meanwhile: before, every event waited for it, the program with
        # them, and the editor heard events only as fast as that client took them (asleep: no more at all)
        eventually(lambda: sum(printed) > 40_000_000, 120)
        assert editor.stop()
        eventually(lambda: editor.programs()["run"] is None, 4 * SEND_SECONDS + 10)
        # the agent shut the connection of the client behind: what it had taken is followed by the end
        if reader is not None:
            eventually(reader.ended.is_set, 120)  # after what the kernel's buffers held (megabytes)
        else:
            behind.settimeout(30)
            try:
                while behind.recv(1 << 20):
                    pass
            except ssl.SSLEOFError:  # shut without TLS's goodbye: ended all the same (a time-out is not)
                pass
    finally:
        editor.close()
        behind.close()
        if reader is not None:
            reader.join()
