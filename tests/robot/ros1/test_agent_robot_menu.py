"""The agent offering its programs on the robot's own UI (``rockly agent --offer-on-robot-ui hobbit``): HOBBIT's
tablet through ``/MMUI``, here the built-in simulator's (``rockly sim hobbit --ros`` with its window, in its own
process) on a real ROS master, a person answering in its window (tests/sim_window_harness.py), the agent in its
own process, an independent rospy node recording ``/cmd_vel``."""
import re
import struct

import pytest
from agent_tools import AgentProcess
from program_builder import block, number, rockly_document
from ros_helpers import RosMaster, ros_environment
from sim_window_harness import SimWindowProcess
from standalone_tools import export_standalone
from waiting import eventually
from wire_recorder import WireRecorder

from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.runtime.agent.library import Library

ZERO = (0.0,) * 6
PAIR_ITEM = "0. Pair a laptop with me (shows a code)\n"  # HOBBIT's manifest offers pairing on the tablet


@pytest.fixture(scope="module")
def own_master(tmp_path_factory):
    """A master of its own: the session's shared headless HOBBIT already serves /MMUI on the usual one."""
    master = RosMaster(tmp_path_factory.mktemp("ros-robot-menu")).start()
    yield master
    master.stop()


@pytest.fixture(scope="module")
def programs(tmp_path_factory):
    """``{name: standalone text}``: ``long`` waits ten minutes, ``wave`` shows an emotion and ends."""
    folder = tmp_path_factory.mktemp("menu-programs")
    made = {}
    for name, top in (("long", block("hobbit_wait", inputs={"seconds": number(600)}, id="long")),
                      ("wave", block("hobbit_emo", {"emotion": "HAPPY"}, id="wave"))):
        source = folder / f"{name}.rockly"
        source.write_text(rockly_document([top]))
        made[name] = export_standalone(source, folder / f"{name}.py", "--language", "en").read_text()
    return made


@pytest.fixture
def simulator(own_master, tmp_path):
    sim = SimWindowProcess(own_master, dict(ros_environment(own_master.uri, tmp_path / "ros"),
                                            QT_QPA_PLATFORM="offscreen"))
    yield sim
    sim.stop()


def test_the_simulators_tablet_lists_the_programs_and_a_person_starts_and_stops_one(own_master, programs, simulator,
                                                                                      tmp_path):
    Library(tmp_path / "library", ProfileRegistry.discover().profiles).keep("long", programs["long"])
    wire = WireRecorder(own_master, ["/cmd_vel"])
    agent = AgentProcess(tmp_path / "library", "--master", own_master.uri, "--offer-on-robot-ui", "hobbit",
                         backend="ros1", env=ros_environment(own_master.uri, own_master.home))
    events = []
    watcher = AgentClient("127.0.0.1", agent.port, on_event=events.append)
    try:
        said = [agent.process.stdout.readline() for _ in range(2)]  # on ROS 1 too; the programs offered
        assert said[0].startswith("rockly agent: on ROS 1 too, master ")
        assert said[1].startswith("rockly agent: the programs for hobbit are offered")
        watcher.attach(control=False)
        # the tablet lists what the robot keeps; the person types its number
        assert simulator.dialog(60) == ("text", "Which program shall I run?\n1. long\n" + PAIR_ITEM
                                                + "Type its number or its name.")
        simulator.send("type 1")
        simulator.send("click OK")
        eventually(lambda: {"event": "run", "state": "started", "program": "long"} in events, 60)
        # while it runs: a Stop; the person takes it, the robot's safe stop puts a zero velocity on the wire
        assert simulator.dialog(60) == ("yes_no", "“long” is running. Shall I stop it?")
        stops_before = sum(1 for _type, raw in wire.on("/cmd_vel") if struct.unpack("<6d", raw) == ZERO)
        simulator.send("click Yes")
        eventually(lambda: any(event.get("state") == "ended" for event in events), 60)
        assert next(event for event in events if event.get("event") == "finished")["outcome"] == "stopped"
        eventually(lambda: sum(1 for _type, raw in wire.on("/cmd_vel") if struct.unpack("<6d", raw) == ZERO)
                   > stops_before, 30)
        # after the run: the list again; a program that comes meanwhile is offered at once
        assert simulator.dialog(60) == ("text", "Which program shall I run?\n1. long\n" + PAIR_ITEM
                                                + "Type its number or its name.")
        watcher.send("wave", programs["wave"])
        assert simulator.dialog(60) == ("text", "Which program shall I run?\n1. long\n2. wave\n" + PAIR_ITEM
                                                + "Type its number or its name.")
    finally:
        watcher.close()
        agent.stop()
        wire.stop()
    assert agent.process.returncode == 0, agent.process.stderr


def test_a_person_at_the_tablet_asks_for_a_pairing_code_and_one_laptop_pairs_with_it(own_master, simulator,
                                                                                      tmp_path):
    """A fresh agent (no laptop paired, no programs): the tablet offers pairing alone; the code it shows pairs the
    first laptop as a teacher, once. The code is on the tablet only: not in the agent's output; and nobody on the
    network can ask for one (a laptop not paired is refused ``pairing_code``)."""
    agent = AgentProcess(tmp_path / "library", "--master", own_master.uri, "--offer-on-robot-ui", "hobbit",
                         backend="ros1", env=ros_environment(own_master.uri, own_master.home), paired=False)
    laptop = AgentClient("127.0.0.1", agent.port)
    try:
        with pytest.raises(AgentError) as refused:
            laptop.pairing_code()
        assert refused.value.key == "agent_not_paired"
        assert simulator.dialog(60) == ("text", "No programs are kept for me yet.\nTo pair a laptop with me, type 0.")
        simulator.send("type 0")
        simulator.send("click OK")
        kind, shown = simulator.dialog(60)
        found = re.fullmatch(r"To pair a laptop with me, type this code in Rockly on it \(Robot → Programs on the "
                             r"robot…\):\n([A-Z2-9]{3}-[A-Z2-9]{3})\nIt works once, for 2 minutes\.", shown)
        assert kind == "ok" and found, shown
        code = found.group(1)
        assert laptop.pair(code, "teacher's laptop").role == "teacher"
        other = AgentClient("127.0.0.1", agent.port)
        try:
            with pytest.raises(AgentError) as used:
                other.pair(code, "another laptop")
            assert used.value.key == "agent_pair_code_used"
        finally:
            other.close()
        simulator.send("click OK")  # the person confirms: the tablet offers pairing again
        assert simulator.dialog(60) == ("text", "No programs are kept for me yet.\nTo pair a laptop with me, type 0.")
    finally:
        laptop.close()
        agent.process.terminate()
        out, err = agent.process.communicate(timeout=60)
        agent.stop()
    assert agent.process.returncode == 0, err
    assert "rockly agent: a pairing code was shown on the robot's own UI, as a person there asked (valid 2 minutes, " \
           "once; the laptop pairs as teacher)\n" in err
    assert code not in out + err and code.replace("-", "") not in out + err


def test_with_no_pairing_on_robot_ui_the_tablet_offers_the_programs_only(own_master, programs, simulator, tmp_path):
    """A fair, where visitors use the tablet: no code is offered there."""
    Library(tmp_path / "library", ProfileRegistry.discover().profiles).keep("long", programs["long"])
    agent = AgentProcess(tmp_path / "library", "--master", own_master.uri, "--offer-on-robot-ui", "hobbit",
                         "--no-pairing-on-robot-ui", backend="ros1", env=ros_environment(own_master.uri,
                                                                                          own_master.home))
    try:
        assert simulator.dialog(60) == ("text", "Which program shall I run?\n1. long\nType its number or its name.")
        simulator.send("type 0")  # not a program: asked anew, nothing shown
        simulator.send("click OK")
        assert simulator.dialog(60) == ("text", "Which program shall I run?\n1. long\nType its number or its name.")
    finally:
        agent.stop()
    assert agent.process.returncode == 0
