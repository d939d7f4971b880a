"""The agent (``rockly agent`` in a process of its own on 127.0.0.1) against a stranger who speaks its wire
protocol directly: ill-typed requests, a program text that would take gigabytes to parse, a line without end, a
slowloris, a connection that says nothing, more connections than it holds and a library filled to the brim. Each
is refused or cut, the agent stays small, and a paired editor's STOP still ends the run (issue 30)."""
import subprocess
import threading
import time

import pytest
from agent_tools import REPO, AgentProcess
from agent_wire import answers, closed_by_agent, plain_connection, say, tls_connection
from agent_wire import hello as hello_request
from program_builder import block, rockly_document, text
from standalone_tools import environment, export_standalone
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.runtime.agent.protocol import FORMAT, MAX_LINE_BYTES
from rockly_desktop.runtime.agent.tcp_transport import FIRST_LINE_SECONDS, MAX_CONNECTIONS_PER_ADDRESS


@pytest.fixture(scope="module")
def programs(tmp_path_factory):
    """``{name: (standalone text, .rockly text)}``: a program that waits for ever, and one 300 kB big."""
    folder = tmp_path_factory.mktemp("agent-bounds-programs")
    env = environment(XDG_CONFIG_HOME=str(folder / "config"), XDG_DATA_HOME=str(folder / "data"))
    made = {}
    for name, top in {"forever": block("controls_whileUntil", {"MODE": "WHILE"}, {
                          "BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
                          "DO": block("hobbit_wait", inputs={"seconds": block("math_number", {"NUM": 1})})}),
                      "big": block("text_print", inputs={"TEXT": text("x" * 300_000)})}.items():
        source = folder / f"{name}.rockly"
        source.write_text(rockly_document([top]))
        made[name] = (export_standalone(source, folder / f"{name}.py", "--language", "en", env=env).read_text(),
                      source.read_text())
    made["forever_path"] = folder / "forever.py"
    return made


@pytest.fixture
def agent(tmp_path):
    agent = AgentProcess(tmp_path / "library")
    yield agent
    agent.stop()


def stranger(agent, source_address: str = "127.0.0.1", hello: bool = True):
    """A TLS connection to ``agent`` from ``source_address``; with ``hello``, it says hello as the paired laptop
    (a paired client turned hostile: the bounds hold for it too)."""
    connection, nonce = tls_connection(agent.port, source_address)
    if hello:
        say(connection, hello_request(nonce, agent.key))
        assert answers(connection, 1)[0]["paired"]
    return connection


def peak_memory_bytes(pid: int) -> int:
    with open(f"/proc/{pid}/status") as status:
        line = next(line for line in status if line.startswith("VmHWM:"))
    return int(line.split()[1]) * 1024


ILL_TYPED = [
    {"op": ["list"]}, {"op": None}, {"op": 5}, {"op": "send", "name": ["x"], "standalone": "x"},
    {"op": "send", "name": "a", "standalone": 5}, {"op": "send", "name": "a", "standalone": "x", "source": 7},
    {"op": "send", "name": "a", "standalone": "x", "on_lost_editor": ["stop"]},
    {"op": "send", "name": "a", "standalone": "x", "decide_seconds": "2"},
    {"op": "send", "name": "a", "standalone": "x", "decide_seconds": {"a": 1}},
    {"op": "start", "name": 5}, {"op": "start", "name": "a", "answers": 5},
    {"op": "start", "name": "a", "answers": "ab"},
    {"op": "source", "name": {"a": 1}}, {"op": "delete", "name": None}, {"op": "delete", "name": ["a"]},
    {"op": "attach", "breakpoints": "x"}, {"op": "attach", "breakpoints": [1, 2]}, {"op": "attach", "control": {}},
    {"op": "control", "what": ["pause"]}, {"op": "breakpoints", "blocks": None},
    {"op": "hello", "language": ["en"], "client": {"a": 1}, "format": FORMAT}, {"op": "hello", "format": "1"},
    {"op": "send", "name": "a" * 10_000, "standalone": "x"}, {"op": "heartbeat", "id": [1]},
]


def test_ill_typed_requests_are_each_answered_and_the_connection_goes_on(agent):
    connection = stranger(agent)
    for number, request in enumerate(ILL_TYPED, start=1):
        say(connection, {**request, "id": request.get("id", number)})
        answer = answers(connection, 1)
        assert answer, f"the agent closed the connection on {request}"
        assert set(answer[0]) >= {"reply", "ok"}, (request, answer)
    say(connection, b"[" * 100_000 + b"\n")  # deeper than Python's JSON reader goes
    assert answers(connection, 1)[0]["error"] == "agent_bad_request"
    say(connection, {"op": "list", "id": 99})
    assert answers(connection, 1)[0] == {"reply": 99, "ok": True, "programs": [], "run": None}


def test_a_program_text_that_takes_gigabytes_to_parse_is_refused_and_the_agent_stays_small(agent):
    connection = stranger(agent)
    say(connection, {"op": "send", "id": 1, "name": "lines", "standalone": "a\n" * 2_000_000})
    answer = answers(connection, 1)[0]
    assert (answer["ok"], answer["error"]) == (False, "agent_not_standalone")
    assert peak_memory_bytes(agent.process.pid) < 400 * 2**20  # parsed in the agent, it took 3.5 GB


def test_a_program_of_profile_version_none_is_refused(agent, programs):
    standalone = programs["forever"][0]
    assert "'version': '1.0.0'" in standalone
    connection = stranger(agent)
    say(connection, {"op": "send", "id": 1, "name": "none", "standalone": standalone.replace(
        "'version': '1.0.0'", "'version': None")})
    assert answers(connection, 1)[0]["error"] == "agent_not_standalone"


def test_a_line_longer_than_the_agent_takes_is_refused_and_the_connection_closed(agent):
    connection = stranger(agent)
    heard = []
    reader = threading.Thread(target=lambda: heard.extend(answers(connection, 1)) or closed_by_agent(connection))
    reader.start()  # as a client reads: on a thread of its own, while it sends
    chunk = b"x" * (1 << 20)
    try:
        for _ in range(MAX_LINE_BYTES // len(chunk) + 2):
            connection.sendall(chunk)
    except OSError:
        pass  # the agent closed it while the rest was still being sent
    reader.join(60)
    assert not reader.is_alive()  # the agent closed the connection
    assert heard and heard[0]["error"] == "agent_line_too_long"


def test_a_line_sent_a_byte_at_a_time_is_cut(agent):
    """A slowloris: one byte every half second, a line that never ends."""
    connection = stranger(agent)
    started = time.monotonic()
    try:
        for _ in range(200):
            connection.sendall(b"{")
            time.sleep(0.5)
    except OSError:
        pass
    answer = answers(connection, 1)
    assert answer and answer[0]["error"] == "agent_line_too_slow"
    assert closed_by_agent(connection)
    assert time.monotonic() - started < 60  # it was held for ever


def test_a_connection_that_says_nothing_is_closed(agent):
    connection = stranger(agent, hello=False)
    connection.settimeout(FIRST_LINE_SECONDS + 30)
    assert answers(connection, 1)[0]["error"] == "agent_line_too_slow"
    assert closed_by_agent(connection)


def test_connections_are_capped_per_address_and_an_editor_from_another_still_stops_the_run(agent, programs):
    editor = AgentClient("127.0.0.1", agent.port)
    crowd = []
    try:
        editor.send("forever", programs["forever"][0])
        editor.start("forever")
        crowd = [stranger(agent, "127.0.0.2") for _ in range(MAX_CONNECTIONS_PER_ADDRESS)]
        one_more = plain_connection(agent.port, "127.0.0.2")  # told before TLS, which it does not wait for
        assert answers(one_more, 1)[0]["error"] == "agent_too_many_connections"
        assert closed_by_agent(one_more)
        assert editor.stop()
        eventually(lambda: editor.programs()["run"] is None, 30)
        late = AgentClient("127.0.0.1", agent.port)  # the editor's address still gets in
        late.close()
    finally:
        editor.close()
        for connection in crowd:
            connection.close()


def test_the_library_keeps_to_its_quota(tmp_path, programs):
    agent = AgentProcess(tmp_path / "library", "--library-quota", "1")
    client = AgentClient("127.0.0.1", agent.port)
    try:
        standalone, source = programs["big"]
        client.send("first", standalone, source)
        with pytest.raises(AgentError) as refused:
            client.send("second", standalone, source)
        assert refused.value.key == "agent_library_full" and "1 MB" in refused.value.message
        client.send("first", standalone, source)  # replacing a program counts it once
        assert [entry["name"] for entry in client.programs()["programs"]] == ["first"]
    finally:
        client.close()
        agent.stop()


def test_a_program_sent_again_by_another_says_whose_it_replaced_and_a_padded_name_is_refused(agent, programs):
    standalone = programs["forever"][0]
    teacher = AgentClient("127.0.0.1", agent.port, name="teacher's window")
    try:
        teacher.send("demo", standalone)
        with pytest.raises(AgentError) as padded:
            teacher.send("demo ", standalone)  # it would be listed beside "demo" as if it were that one
        assert padded.value.key == "agent_bad_name"
    finally:
        teacher.close()
    replaced = subprocess.run(AgentProcess.robot_command(agent, "send", programs["forever_path"], "--name", "demo"),
                              capture_output=True, text=True, timeout=120, cwd=REPO)
    assert replaced.returncode == 0, replaced.stderr
    assert "it replaces the 'demo' that teacher's window (" in replaced.stdout
    lister = AgentClient("127.0.0.1", agent.port)
    try:
        assert [entry["name"] for entry in lister.programs()["programs"]] == ["demo"]
    finally:
        lister.close()
