"""`rockly sim hobbit --ros` with its window, on a real master: a program's process asks on
/MMUI, a person (the test, through tests/sim_window_harness.py) answers in the window.

These tests use a master of their own: the session's master already has the shared
headless HOBBIT (tests/ros_fixtures.py) serving /MMUI, and a second HOBBIT there would
take over its topics and service.
"""
import signal

import pytest
from ros_helpers import RosMaster, ros_environment
from sim_window_harness import RosCaller, SimWindowProcess
from waiting import eventually


@pytest.fixture(scope="module")
def own_master(tmp_path_factory):
    master = RosMaster(tmp_path_factory.mktemp("ros-sim-window")).start()
    yield master
    master.stop()


@pytest.fixture
def env(own_master, tmp_path):
    return dict(ros_environment(own_master.uri, tmp_path / "ros"), QT_QPA_PLATFORM="offscreen")


@pytest.fixture
def caller(own_master, env):
    process = RosCaller(own_master, env)
    yield process
    process.stop()


@pytest.fixture
def started(own_master, env):
    processes = []

    def start(*answers):
        process = SimWindowProcess(own_master, env, *(f"--answer={answer}" for answer in answers))
        processes.append(process)
        return process

    yield start
    for process in processes:
        process.stop()


def node_registrations(master_uri):
    """Every node that publishes /odom or serves /MMUI on the master."""
    import rosgraph

    publishers, _subscribers, services = rosgraph.Master("/test", master_uri=master_uri).getSystemState()
    return {node for name, nodes in publishers + services if name in ("/odom", "/MMUI") for node in nodes}


def test_the_window_shows_the_robot_live_and_the_person_answers_mmui_questions(own_master, started, caller, tmp_path):
    sim = started()
    described = sim.describe()
    assert described["view"] == "HobbitSimView"
    assert "HOBBIT" in described["title"] and own_master.uri in described["title"]

    caller.start("ask_yes_no", "Would you like some tea?")
    assert sim.dialog() == ("yes_no", "Would you like some tea?")
    eventually(lambda: sim.describe()["tablet"] == {"kind": "D_YES_NO", "text": "Would you like some tea?"})
    sim.send(f"shot {tmp_path / 'sim_window.png'}")
    sim.out.expect("shot ")
    assert (tmp_path / "sim_window.png").stat().st_size > 10_000
    sim.send("click Yes")
    assert caller.result() == {"value": True}

    caller.start("ask_text", "What is your name?")
    assert sim.dialog() == ("text", "What is your name?")
    sim.send("type Ada Lovelace")
    sim.send("click OK")
    assert caller.result() == {"value": "Ada Lovelace"}

    assert caller.call("drive", 0.5, "forward") == {"value": None}
    eventually(lambda: sim.describe()["x"] == pytest.approx(0.5, abs=0.05))  # the view follows the robot
    assert caller.call("call_sos") == {"value": None}
    eventually(lambda: "SOS call started" in sim.describe()["status"])

    sim.send("close")
    assert sim.wait() == 0, sim.stderr()
    assert node_registrations(own_master.uri) == set()  # the node's publishers and service are gone


def test_answers_from_the_command_line_come_first_then_the_window_asks(started, caller):
    sim = started("no", "Bob")
    assert caller.call("ask_yes_no", "Tea?") == {"value": False}
    assert caller.call("ask_text", "Name?") == {"value": "Bob"}
    caller.start("ask_yes_no", "More tea?")
    assert sim.dialog() == ("yes_no", "More tea?")
    sim.send("click Yes")
    assert caller.result() == {"value": True}
    assert [line for line in sim.out.seen if line.startswith("dialog ")] == ['dialog yes_no "More tea?"']
    sim.send("close")
    assert sim.wait() == 0


@pytest.mark.parametrize("how", ["close", "Ctrl+C", "SIGTERM"])
def test_ending_with_a_question_open_answers_the_caller_and_exits_0(own_master, started, caller, how):
    sim = started()
    caller.start("ask_yes_no", "Still there?")
    assert sim.dialog() == ("yes_no", "Still there?")
    if how == "close":
        sim.send("close")
    else:
        sim.process.send_signal(signal.SIGINT if how == "Ctrl+C" else signal.SIGTERM)
    assert sim.wait() == 0, sim.stderr()
    result = caller.result()
    assert result["error"] == "RobotCommandError" and "shut down" in result["message"]
    assert node_registrations(own_master.uri) == set()
