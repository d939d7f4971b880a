"""The agent on the robot (``rockly agent``) in a process of its own, on the built-in simulator, with
``rockly robot`` and ``AgentClient`` as its clients: send, list, start, attach, pause/step, stop, delete, the
checks of what is sent, and what a lost editor means."""
import json
import os
import signal
import socket
import subprocess

import pytest
from agent_tools import REPO, AgentProcess, AttachedClient, seconds_until_ended_while_frozen
from agent_wire import answers, say, tls_connection
from program_builder import block, number, rockly_document, stack
from standalone_tools import environment, exported_program
from tiny_disk import fill, tiny_disk
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.runtime.agent.protocol import AGENT_SILENT_SECONDS, FORMAT
from rockly_desktop.runtime.agent.robot_keys import RobotKeys


def drive_and_tell():
    """Drive 1 m, then print "done"."""
    return stack(block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": "done"})}, id="tell"))


@pytest.fixture(scope="module")
def program(tmp_path_factory):
    """``(standalone .py, .rockly)`` of the drive-and-tell program (exported once, as ``rockly export`` does)."""
    return exported_program(tmp_path_factory.mktemp("agent-program"), drive_and_tell())


@pytest.fixture
def agent_at(tmp_path):
    """Start agents with the given simulated-time speed; each is ended (SIGTERM) after the test."""
    started = []

    def start(speed=20.0):
        started.append(AgentProcess(tmp_path / f"library-{len(started)}", "--speed", speed))
        return started[-1]
    yield start
    for agent in started:
        agent.stop()


class Watcher:
    """An ``AgentClient`` in this process, keeping every event it is sent."""

    def __init__(self, agent, **options):
        self.events = []
        self.client = AgentClient("127.0.0.1", agent.port, on_event=self.events.append, **options)

    def wait_for(self, wanted, timeout=60):
        eventually(lambda: any(wanted(event) for event in list(self.events)), timeout)
        return next(event for event in self.events if wanted(event))

    def start_driving(self, standalone):
        """Send ``standalone`` (a file) as "drive", attach, start it; return once its drive block runs."""
        self.client.send("drive", standalone.read_text())
        self.client.attach()
        self.client.start("drive")
        return self.wait_for(lambda event: event.get("id") == "drive")

    def close(self):
        self.client.close()


def ended(event):
    return event.get("event") == "run" and event.get("state") == "ended"


def test_send_list_start_attach_and_the_run_finishes_on_the_robot(agent_at, program):
    agent = agent_at()
    standalone, _ = program
    sent = agent.robot("send", standalone, "--name", "drive", "--keep-going")
    assert sent.returncode == 0 and sent.stdout == "'drive' is on the robot now\n", sent.stderr
    listed = agent.robot("list")
    assert listed.returncode == 0
    assert listed.stdout.startswith("drive  hobbit 1.0.0  came 20") and "lost editor: keep going" in listed.stdout
    watcher = Watcher(agent)
    try:
        watcher.client.attach()
        assert agent.robot("start", "drive").stdout == "'drive' started on the robot\n"
        watcher.wait_for(ended)
        blocks = [event["id"] for event in watcher.events if event.get("event") == "block"]
        assert blocks == ["drive", "tell"]
        assert [event["text"] for event in watcher.events if event.get("event") == "print"] == ["done"]
        finished = next(event for event in watcher.events if event.get("event") == "finished")
        assert finished["outcome"] == "finished"
        assert watcher.wait_for(ended)["status"] == 0
    finally:
        watcher.close()
    assert "running:" not in agent.robot("list").stdout


def test_a_cli_attaching_mid_run_gets_the_state_then_the_events_and_a_stop_stops_the_robot(agent_at, program):
    agent = agent_at(speed=0.05)  # slow simulated time: the drive is under way for 20 s
    client = AgentClient("127.0.0.1", agent.port)
    try:
        client.send("drive", program[0].read_text(), program[1].read_text())
        client.start("drive")
        eventually(lambda: (client.programs()["run"] or {}).get("block") == "drive", 60)
    finally:
        client.close()
    attach = subprocess.Popen(agent.robot_command("attach", "--watch-only"), cwd=REPO, text=True,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        first = json.loads(attach.stdout.readline())
        assert first["event"] == "attached" and first["run"]["program"] == "drive"
        assert first["run"]["block"] == "drive" and first["controller"] is False
        stopped = agent.robot("stop")
        assert stopped.stdout == "the program was stopped (the robot stops safely)\n"
        out, _ = attach.communicate(timeout=60)
    finally:
        if attach.poll() is None:
            attach.kill()
            attach.communicate()
    events = [json.loads(line) for line in out.splitlines()]
    finished = next(event for event in events if event.get("event") == "finished")
    assert (finished["outcome"], finished["block"]) == ("stopped", "drive")  # after the robot's safe stop ran
    assert events[-1]["event"] == "run" and events[-1]["state"] == "ended" and events[-1]["status"] == 130
    assert attach.returncode == 0  # a stop asked for ends the run as Ctrl+C does (130)


def test_pause_step_and_continue_from_the_controlling_client_only(agent_at, program):
    agent = agent_at(speed=0.05)
    controller, other = Watcher(agent), Watcher(agent, language="de")
    try:
        controller.client.send("drive", program[0].read_text())
        assert controller.client.attach()["controller"] is True
        controller.client.start("drive")
        answer = other.client.attach()
        assert answer["controller"] is False and answer["controlled_elsewhere"] is True
        with pytest.raises(AgentError) as refused:
            other.client.control("pause")
        assert refused.value.message.startswith("ein anderes Fenster steuert diesen Lauf: du kannst zusehen")
        controller.client.control("pause")
        paused = other.wait_for(lambda event: event.get("event") == "paused")  # the watcher sees it too
        assert paused["reason"] == "pause"
        controller.client.control("continue")
        controller.wait_for(lambda event: event.get("event") == "resumed")
        assert other.client.stop() is True  # a STOP is never refused
        assert controller.wait_for(lambda event: event.get("event") == "finished")["outcome"] == "stopped"
    finally:
        controller.close()
        other.close()


@pytest.mark.parametrize("language", ["en", "de"])
def test_what_is_sent_is_checked_and_a_refusal_says_why(agent_at, program, tmp_path, language):
    agent = agent_at()
    standalone = program[0].read_text()
    client = AgentClient("127.0.0.1", agent.port, language=language)
    try:
        def refusal(**fields):
            with pytest.raises(AgentError) as refused:
                client.send(**{"name": "p", "standalone": standalone, **fields})
            return refused.value.message
        texts = {
            "other profile": refusal(standalone=standalone.replace("'id': 'hobbit'", "'id': 'nobody'")),
            "newer version": refusal(standalone=standalone.replace("'version': '1.0.0'", "'version': '2.0.0'")),
            "not a program": refusal(standalone="print('hello')"),
            "broken source": refusal(source='{"format": "rockly", "version": 1, "profile": "hobbit", '),
            "source of another profile": refusal(source=rockly_document([drive_and_tell()], profile="turtlebot")),
            "name": refusal(name="../escape"),
        }
        assert client.programs()["programs"] == []  # nothing refused was kept
    finally:
        client.close()
    if language == "en":
        assert texts["other profile"].startswith("this program was made for the robot profile 'nobody' 1.0.0, "
                                                 "which this robot does not have (it has: ")
        assert texts["newer version"] == ("this program was made for hobbit 2.0.0, but the robot has hobbit 1.0.0: "
                                          "update the robot's profile, or open the program with the robot's version")
        assert texts["not a program"].startswith("what was sent is not a program Rockly exported")
        assert texts["broken source"].startswith("the program's file cannot be read: program.rockly: ")
        assert texts["source of another profile"].startswith("the program says it is for 'turtlebot'")
        assert texts["name"].startswith("'../escape' cannot be a program's name on the robot")
    else:
        assert texts["other profile"].startswith("dieses Programm wurde für das Roboterprofil 'nobody' 1.0.0 gemacht")
        assert texts["newer version"].startswith("dieses Programm wurde für hobbit 2.0.0 gemacht, der Roboter hat")
        assert texts["not a program"].startswith("was geschickt wurde, ist kein Programm")
        assert texts["broken source"].startswith("die Programmdatei lässt sich nicht lesen: program.rockly: ")
        assert texts["source of another profile"].startswith("das Programm sagt, es sei für 'turtlebot'")
        assert texts["name"].startswith("'../escape' kann kein Programmname auf dem Roboter sein")


def test_delete_and_what_cannot_be_done_while_a_program_runs(agent_at, program):
    agent = agent_at(speed=0.05)
    client = AgentClient("127.0.0.1", agent.port)
    try:
        client.send("drive", program[0].read_text(), program[1].read_text())
        client.send("other", program[0].read_text())
        assert client.source("drive") == program[1].read_text() and client.source("other") is None
        client.start("drive")
        for call in (lambda: client.start("other"), lambda: client.delete("drive"),
                     lambda: client.send("drive", program[0].read_text())):
            with pytest.raises(AgentError) as refused:
                call()
            assert "stop it first" in refused.value.message
        client.stop()
        eventually(lambda: client.programs()["run"] is None, 60)
    finally:
        client.close()
    deleted = agent.robot("delete", "drive")
    assert deleted.stdout == "'drive' was deleted from the robot\n"
    assert [line.split()[0] for line in agent.robot("list").stdout.splitlines() if not line.startswith(" ")] == [
        "other"]
    again = agent.robot("delete", "drive", language="de")
    assert again.returncode == 1 and again.stderr == "rockly robot: der Roboter hat kein Programm namens 'drive'\n"


def test_an_unreachable_agent_is_said(tmp_path):
    result = subprocess.run(AgentProcess.robot_command(type("A", (), {"port": 9})(), "list"), cwd=REPO,
                            capture_output=True, text=True, timeout=60)
    assert result.returncode == 1
    assert result.stderr.startswith("rockly robot: the robot's agent at 127.0.0.1:9 cannot be reached")


def test_a_host_that_never_answers_hello_is_said_and_the_client_keeps_no_thread(tmp_path):
    """A port that takes the connection but never answers: the client gives up after its timeout, closes,
    and tells nobody of a connection that never was."""
    import threading

    silent = socket.socket()
    silent.bind(("127.0.0.1", 0))
    silent.listen(1)
    closed = []
    try:
        with pytest.raises(AgentError) as raised:
            AgentClient("127.0.0.1", silent.getsockname()[1], "de", on_closed=lambda: closed.append(1), timeout=0.5)
        assert raised.value.key == "agent_no_answer"
        port = silent.getsockname()[1]
        assert raised.value.message == (f"der Agent des Roboters unter 127.0.0.1:{port} hat nicht innerhalb von 0.5 s "
                                        "geantwortet (ist das Netz zum Roboter langsam oder unterbrochen?)")
        eventually(lambda: not [thread for thread in threading.enumerate()
                                if thread.name in ("agent-client", "agent-heartbeat")])
        assert closed == []
    finally:
        silent.close()


@pytest.mark.parametrize("choice", ["keep_going", "stop"])
def test_a_lost_editor_keeps_the_run_going_or_stops_the_robot_as_the_program_says(agent_at, program, choice):
    """The editor (an attached ``rockly robot attach``) is killed while the program drives."""
    agent = agent_at(speed=0.25)  # the 1 m drive takes 4 s of real time
    watcher = Watcher(agent)
    try:
        watcher.client.send("drive", program[0].read_text(), on_lost_editor=choice, decide_seconds=0.5)
        watcher.client.attach(control=False)
        watcher.client.start("drive")
        watcher.wait_for(lambda event: event.get("id") == "drive")
        editor = subprocess.Popen(agent.robot_command("attach"), cwd=REPO, text=True, stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL)
        assert json.loads(editor.stdout.readline())["controller"] is True  # the watcher here is not the editor
        editor.kill()  # the laptop's side is gone: no more heartbeats
        editor.communicate()
        end = watcher.wait_for(ended)
        finished = next(event for event in watcher.events if event.get("event") == "finished")
    finally:
        watcher.close()
    if choice == "keep_going":
        assert finished["outcome"] == "finished" and end["status"] == 0 and not end["stopped_for_lost_editor"]
    else:
        assert finished["outcome"] == "stopped" and finished["block"] == "drive" and end["stopped_for_lost_editor"]
        assert any(event.get("state") == "editor_lost" for event in watcher.events)


def test_the_agent_killed_mid_run_leaves_the_robot_stopped(agent_at, program):
    """SIGKILL gives the agent no chance to stop anything: the program's own process sees its requests end
    and stops the robot itself."""
    agent = agent_at(speed=0.01)  # the drive would take 100 s
    watcher = Watcher(agent)
    try:
        watcher.start_driving(program[0])
        started = watcher.wait_for(lambda event: event.get("event") == "started")
    finally:
        watcher.close()
    agent.process.send_signal(signal.SIGKILL)
    agent.process.wait(10)

    def gone():
        try:
            os.kill(started["pid"], 0)
        except ProcessLookupError:
            return True
        return False
    eventually(gone, 60)  # it ended (after its safe stop), not killed by anyone


def test_a_frozen_agent_is_heard_lost_and_its_run_goes_on(agent_at, program):
    """SIGSTOP closes nothing (the TCP connection stays open): the attached ``rockly robot attach`` (the editor)
    hears the agent fall silent and ends as for a closed connection; the run's own process goes on, and the agent,
    woken, still runs it (a keep-going program: the editor's loss is the agent's to judge, as before)."""
    agent = agent_at(speed=0.01)  # the drive would take 100 s
    watcher = Watcher(agent)
    try:
        watcher.client.send("drive", program[0].read_text(), on_lost_editor="keep_going")
        watcher.client.attach(control=False)
        watcher.client.start("drive")
        started = watcher.wait_for(lambda event: event.get("event") == "started")
    finally:
        watcher.close()
    editor = AttachedClient(agent.robot_command("attach"), None)
    try:
        assert editor.first["controller"] is True and editor.first["run"]["state"] == "running"
        # the run's own process was not touched
        took = seconds_until_ended_while_frozen(agent.process, editor.process, lambda: os.kill(started["pid"], 0))
    finally:
        editor.end()
    assert editor.process.returncode == 0 and not editor.seen(ended)
    # the product's promise: a few seconds, with room for a loaded machine
    assert took < AGENT_SILENT_SECONDS + 10
    listed = agent.robot("list")
    assert listed.returncode == 0 and "running: drive" in listed.stdout, listed.stderr


def test_events_reach_every_watcher_while_many_attach(agent_at, program):
    agent = agent_at(speed=2)
    watchers = [Watcher(agent) for _ in range(3)]
    try:
        watchers[0].client.send("drive", program[0].read_text())
        for watcher in watchers:
            watcher.client.attach()
        watchers[0].client.start("drive")
        for watcher in watchers:
            watcher.wait_for(ended)
            assert [event["id"] for event in watcher.events if event.get("event") == "block"] == ["drive", "tell"]
    finally:
        for watcher in watchers:
            watcher.close()


@pytest.mark.parametrize("language, expected", [
    ("en", "the robot's disk is full: 'second' was not kept (the programs already there are unchanged)"),
    ("de", "die Festplatte des Roboters ist voll: 'second' wurde nicht aufbewahrt (die Programme dort sind "
           "unverändert)"),
])
def test_a_full_disk_on_the_robot_is_said_and_loses_nothing(program, tmp_path, language, expected):
    with tiny_disk(tmp_path / "disk") as disk:
        agent = AgentProcess(disk / "library", "--speed", "20")
        client = AgentClient("127.0.0.1", agent.port, language=language)
        try:
            client.send("first", program[0].read_text(), program[1].read_text())
            kept = (disk / "library" / "first" / "program.py").read_text()
            fill(disk)
            with pytest.raises(AgentError) as refused:
                client.send("second", program[0].read_text(), program[1].read_text())
            assert refused.value.message.startswith(expected)
            with pytest.raises(AgentError):  # replacing a kept one on a full disk keeps the one there
                client.send("first", program[0].read_text().replace("drive.rockly", "other.rockly"))
            assert [about["name"] for about in client.programs()["programs"]] == ["first"]
            assert (disk / "library" / "first" / "program.py").read_text() == kept
            assert client.source("first") == program[1].read_text()
        finally:
            client.close()
            agent.stop()


@pytest.mark.parametrize("language, expected", [
    ("en", "the robot's agent (Rockly 0.1.0) and this Rockly (9.0.0) do not speak the same language"),
    ("de", "der Agent des Roboters (Rockly 0.1.0) und dieses Rockly (9.0.0) sprechen nicht dieselbe Sprache"),
])
def test_a_client_of_another_rockly_version_is_told(agent_at, language, expected):
    agent = agent_at()
    connection, _ = tls_connection(agent.port)
    with connection:
        say(connection, {"op": "hello", "id": 1, "rockly": "9.0.0", "format": FORMAT + 1, "language": language})
        answer = answers(connection, 1)[0]
    assert answer["reply"] == 1 and answer["ok"] is False and answer["error"] == "agent_other_format"
    assert answer["message"].startswith(expected)


@pytest.mark.parametrize("language, expected", [
    ("en", "this Rockly (0.0.9) is older than the robot's agent (Rockly 0.1.0), which answers only laptops paired "
           "with it, over encrypted or sealed messages: update Rockly on this laptop, then pair it"),
    ("de", "dieses Rockly (0.0.9) ist älter als der Agent des Roboters (Rockly 0.1.0), der nur mit ihm gekoppelte "
           "Laptops beantwortet, über verschlüsselte oder versiegelte Nachrichten: aktualisiere Rockly auf diesem "
           "Laptop und kopple ihn dann"),
])
def test_a_client_of_the_format_before_pairing_is_told_to_update_and_pair(agent_at, language, expected):
    """A format-1 hello inside TLS (a hand-made client; a format-1 Rockly speaks plain TCP:
    tests/runtime/test_agent_pairing.py)."""
    assert FORMAT == 2
    agent = agent_at()
    connection, _ = tls_connection(agent.port)
    with connection:
        say(connection, {"op": "hello", "id": 1, "rockly": "0.0.9", "format": 1, "language": language})
        answer = answers(connection, 1)[0]
    assert (answer["reply"], answer["ok"], answer["error"]) == (1, False, "agent_client_before_pairing")
    assert answer["message"].startswith(expected)


def test_sigterm_to_the_agent_mid_run_stops_the_program_with_the_safe_stop_first(agent_at, program):
    """As systemd or a launch file ends the agent: the run ends stopped, then the agent exits 0."""
    agent = agent_at(speed=0.01)
    watcher = Watcher(agent)
    try:
        watcher.start_driving(program[0])
        agent.process.terminate()
        assert agent.process.wait(60) == 0
        finished = next(event for event in watcher.events if event.get("event") == "finished")
    finally:
        watcher.close()
    assert (finished["outcome"], finished["block"]) == ("stopped", "drive")


def test_rockly_robot_sends_a_rockly_file_exported_and_checked(agent_at, program, tmp_path):
    """The laptop's ``rockly robot send PROGRAM.rockly`` exports it as ``--standalone`` does and sends both texts."""
    agent = agent_at()
    env = environment(XDG_CONFIG_HOME=str(tmp_path / "config"), XDG_DATA_HOME=str(tmp_path / "data"))
    RobotKeys(tmp_path / "config" / "rockly" / "robot-keys.json").save(agent.key)  # the laptop's key, in its config
    sent = agent.robot("send", program[1], "--decide-seconds", "3", env=env)
    assert sent.returncode == 0 and sent.stdout == "'drive' is on the robot now\n", sent.stderr
    listed = agent.robot("list", language="de")
    assert "Editor verloren: Roboter nach 3,0 s anhalten" in listed.stdout
    client = AgentClient("127.0.0.1", agent.port)
    try:
        assert client.source("drive") == program[1].read_text()
    finally:
        client.close()
    broken = tmp_path / "broken.rockly"
    broken.write_text("{")
    refused = agent.robot("send", broken, env=env)
    assert refused.returncode == 1 and refused.stderr.startswith("rockly robot: ")


def test_a_paused_run_steps_block_by_block(agent_at, program):
    """Paused during the drive, a step ends that block and holds before the next; another step runs it."""
    agent = agent_at(speed=0.5)
    watcher = Watcher(agent)
    try:
        watcher.start_driving(program[0])
        watcher.client.control("pause")
        paused = watcher.wait_for(lambda event: event.get("event") == "paused")
        assert (paused["block"], paused["reason"]) == ("drive", "pause")
        assert watcher.client.programs()["run"]["state"] == "paused"
        watcher.client.control("step")
        held = watcher.wait_for(lambda event: event.get("event") == "paused" and event["block"] == "tell")
        assert held["reason"] == "step"
        assert not any(event.get("event") == "print" for event in watcher.events)  # held before "tell"
        watcher.client.control("step")
        assert watcher.wait_for(lambda event: event.get("event") == "print")["text"] == "done"
        assert watcher.wait_for(ended)["status"] == 0
    finally:
        watcher.close()
