"""Who controls a run under the agent (``rockly agent`` in a process of its own), with its clients in processes of
their own: the controlling client's breakpoints apply to the run (on attaching and when they change) and go with
it; a second client watches and is told, its Pause is refused but its STOP stops the robot; when the controlling
client is gone, the watching one takes control and is told."""
import json
import subprocess

import pytest
from agent_tools import REPO, AgentProcess
from program_builder import block, number, rockly_document, stack
from standalone_tools import environment, export_standalone
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient, AgentError


def two_drives():
    """Drive 1 m, print "half way", drive 1 m, print "done"."""
    return stack(block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": "half way"})}, id="half"),
                 block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="again"),
                 block("text_print", inputs={"TEXT": block("text", {"TEXT": "done"})}, id="tell"))


@pytest.fixture(scope="module")
def program(tmp_path_factory):
    folder = tmp_path_factory.mktemp("agent-control-program")
    source = folder / "drives.rockly"
    source.write_text(rockly_document([two_drives()]))
    env = environment(XDG_CONFIG_HOME=str(folder / "config"), XDG_DATA_HOME=str(folder / "data"))
    return export_standalone(source, folder / "drives.py", "--language", "en", env=env).read_text()


@pytest.fixture
def agent(tmp_path, program):
    """An agent whose simulated time runs at a quarter of real time (each drive takes 4 s), the program kept."""
    agent = AgentProcess(tmp_path / "library", "--speed", 0.25)
    client = AgentClient("127.0.0.1", agent.port)
    client.send("drives", program, on_lost_editor="keep_going")
    client.close()
    yield agent
    agent.stop()


class Client:
    """An ``AgentClient`` in this process, keeping every event it is sent."""

    def __init__(self, agent, language="en"):
        self.events = []
        self.client = AgentClient("127.0.0.1", agent.port, language, on_event=self.events.append)

    def wait_for(self, wanted, timeout=60):
        eventually(lambda: any(wanted(event) for event in list(self.events)), timeout)
        return next(event for event in list(self.events) if wanted(event))


def paused_at(block_id):
    return lambda event: event.get("event") == "paused" and event.get("block") == block_id


def ended(event):
    return event.get("event") == "run" and event.get("state") == "ended"


def test_the_controlling_clients_breakpoints_apply_on_attaching_and_when_they_change(agent):
    editor = Client(agent)
    try:
        editor.client.attach(control=True, breakpoints=["half"])
        editor.client.start("drives")
        assert editor.wait_for(paused_at("half"))["reason"] == "breakpoint"
        assert editor.client.programs()["run"]["breakpoints"] == ["half"]
        editor.client.breakpoints(["tell"])
        editor.client.control("continue")
        assert editor.wait_for(paused_at("tell"))["reason"] == "breakpoint"
        assert [event["text"] for event in editor.events if event.get("event") == "print"] == ["half way"]
        editor.client.control("continue")
        editor.wait_for(ended)
        assert next(event for event in editor.events if event.get("event") == "finished")["outcome"] == "finished"
    finally:
        editor.client.close()


def test_a_watchers_breakpoints_are_refused_and_the_editors_go_with_it(agent):
    editor, watcher = Client(agent), Client(agent, "de")
    try:
        editor.client.attach(control=True, breakpoints=["tell"])
        editor.client.start("drives")
        watcher.client.attach(control=False)
        with pytest.raises(AgentError) as refused:
            watcher.client.breakpoints(["half"])
        assert refused.value.key == "agent_not_controller"
        assert watcher.client.programs()["run"]["breakpoints"] == ["tell"]
        editor.client.close()  # the editor gone: a keep-going run must not stop at a breakpoint nobody watches
        eventually(lambda: watcher.client.programs()["run"]["breakpoints"] == [])
        watcher.wait_for(ended, 120)
        assert not any(event.get("event") == "paused" for event in watcher.events)
    finally:
        watcher.client.close()


def test_a_second_client_watches_is_refused_pause_takes_control_when_the_first_goes_and_its_stop_stops(agent):
    starter = AgentClient("127.0.0.1", agent.port)
    starter.start("drives")
    starter.close()
    editor = subprocess.Popen(agent.robot_command("attach"), cwd=REPO, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True)  # another process controls the run
    second = Client(agent, "de")
    try:
        attached = json.loads(editor.stdout.readline())
        assert attached["event"] == "attached" and attached["controller"]
        answer = second.client.attach(control=True)
        assert (answer["controller"], answer["controlled_elsewhere"]) == (False, True)
        with pytest.raises(AgentError) as refused:
            second.client.control("pause")
        assert refused.value.message == ("ein anderes Fenster steuert diesen Lauf: du kannst zusehen, aber nur jenes "
                                         "Fenster kann ihn anhalten, schrittweise ausführen oder fortsetzen")
        editor.kill()  # the controlling window's process gone, as when its laptop's Wi-Fi drops
        editor.wait(30)
        assert second.wait_for(lambda event: event.get("event") == "control")["controller"] is True
        assert second.client.controller
        second.client.control("pause")
        second.wait_for(lambda event: event.get("event") == "paused")
        assert second.client.stop()
        finished = second.wait_for(lambda event: event.get("event") == "finished")
        assert finished["outcome"] == "stopped"
    finally:
        if editor.poll() is None:
            editor.kill()
            editor.wait(30)
        editor.stdout.close()
        editor.stderr.close()
        second.client.close()

