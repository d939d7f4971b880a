"""The agent's ROS transport (``agent.ros_transport``) with the real ``Agent`` and ``Pairings``, its topics carried
by an in-memory bus that hands every message to every other end, as a ROS graph does (and keeps what went by, as a
stranger listening would): a line pairs with a code and then works sealed; what a stranger writes, in clear, forged or
recorded, is not taken; nothing the agent says to a paired line can be read off the bus. The real middlewares:
tests/robot/ros1/test_agent_ros_strangers.py and tests/robot/ros2/test_agent_ros2_strangers.py."""
import base64
import json
import queue
import threading
import types

import pytest
from waiting import eventually

from rockly_desktop.runtime.agent import ros_transport
from rockly_desktop.runtime.agent.library import Library
from rockly_desktop.runtime.agent.pairings import Pairings
from rockly_desktop.runtime.agent.protocol import AgentError
from rockly_desktop.runtime.agent.robot_keys import RobotKey, RobotKeys
from rockly_desktop.runtime.agent.server import Agent


class Bus:
    """One graph: every message published by one side reaches every end of the other, in order, on the bus's own
    thread (as a middleware's); ``went_by``: (topic, message) of all of them."""

    def __init__(self):
        self.ends = []
        self.went_by = []
        self._queue = queue.Queue()
        self._thread = threading.Thread(target=self._carry, daemon=True)
        self._thread.start()

    def _carry(self):
        while True:
            sender, text = self._queue.get()
            if sender is None:
                return
            self.went_by.append(("to_agent" if not sender.agent_side else "from_agent", json.loads(text)))
            for end in list(self.ends):
                if end.agent_side != sender.agent_side:
                    end.on_message(json.loads(text))

    def put(self, sender, message: dict):
        self._queue.put((sender, json.dumps(message)))

    def stop(self):
        self._queue.put((None, None))
        self._thread.join(10)

    def carrier(self):
        bus = self

        class Topics:
            def __init__(self, namespace, agent_side, on_message):
                self.agent_side, self.on_message = agent_side, on_message
                bus.ends.append(self)

            def publish(self, message):
                bus.put(self, message)
                return True

            def connected(self):
                return True

            def heard_from(self):
                return True

            def close(self):
                if self in bus.ends:
                    bus.ends.remove(self)
        return types.SimpleNamespace(Topics=Topics, node_name=lambda where=None: ("/laptop", "the test bus"),
                                     agent_in_graph=lambda where, namespace: True, master_at_hand=lambda: "bus")


class Stranger:
    """A node on the bus that is no Rockly: it publishes what it is given, as a client would."""

    agent_side = False

    def __init__(self, bus):
        self.bus = bus

    def write(self, *messages):
        for message in messages:
            self.bus.put(self, message)


@pytest.fixture
def graph(tmp_path, monkeypatch):
    """``(bus, agent, offer, pairings)``: an agent offered on the bus (its library and folder in ``tmp_path``)."""
    bus = Bus()
    monkeypatch.setattr(ros_transport, "_carrier", lambda kind: bus.carrier())
    pairings = Pairings(tmp_path / "agent")
    agent = Agent(Library(tmp_path / "library", {}, 2**20), "sim", [], pairings)
    offer = ros_transport.RosOffer(agent, "ros1", "/rockly_agent")
    yield bus, agent, offer, pairings
    offer.close()
    bus.stop()


class Client:
    """A line to the agent as ``AgentClient`` uses it: ``ask(op, **fields)`` waits for the answer."""

    def __init__(self, keys):
        self.taken, self.ids, self.gone = [], iter(range(1, 10**6)), threading.Event()
        self.line = ros_transport.RosLine("ros1", None, "/rockly_agent", "en", 10, self.taken.append, self.gone.set,
                                          keys)

    def ask(self, op, **fields):
        number = next(self.ids)
        self.line.write({"op": op, "id": number, **fields})
        eventually(lambda: any(message.get("reply") == number for message in list(self.taken)), 10)
        return next(message for message in self.taken if message.get("reply") == number)

    def close(self):
        self.line.close()


def paired_client(tmp_path, pairings) -> tuple:
    """``(client, keys, code, answer)``: a line that paired over the bus with a fresh ``code``, its key kept in
    ``keys``."""
    keys = RobotKeys(tmp_path / "robot-keys.json")
    client = Client(keys)
    code = pairings.new_code().code
    answer = client.ask("pair", code=code, name="ada@laptop")
    assert answer["ok"] is True, answer
    keys.save(RobotKey(client.line.address, answer["agent"], answer["client"], base64.b64decode(answer["key"]),
                       answer["role"], ""))  # as AgentClient.pair keeps it
    return client, keys, code, answer


def test_a_line_pairs_over_the_topics_and_then_works_sealed(graph, tmp_path):
    bus, agent, _, pairings = graph
    client, _, code, answer = paired_client(tmp_path, pairings)
    assert pairings.find(answer["client"]).key == base64.b64decode(answer["key"])
    assert client.ask("list") == {"reply": 2, "ok": True, "programs": [], "run": None}
    client.close()
    text = json.dumps(bus.went_by)
    assert answer["key"] not in text and code not in text and "ada@laptop" not in text  # nothing in clear
    assert '"programs"' not in text


def test_a_stranger_in_clear_is_told_to_pair_and_nothing_it_asks_is_done(graph):
    bus, agent, offer, _ = graph
    stranger = Stranger(bus)
    stranger.write({"op": "send", "id": 1, "from": "evil", "name": "x", "standalone": "RUN_CODE = ''"},
                   {"op": "start", "id": 2, "from": "evil", "name": "x"}, {"op": "list", "id": 3, "from": "evil"})
    eventually(lambda: len([m for topic, m in bus.went_by if m.get("to") == "evil"]) == 3)
    answers = [m for topic, m in bus.went_by if m.get("to") == "evil"]
    assert {m["error"] for m in answers} == {"agent_not_paired"} and agent.library.entries() == []
    assert agent.run is None


def test_recorded_boxes_are_not_taken_again(graph, tmp_path):
    bus, agent, offer, pairings = graph
    client, _, _, _ = paired_client(tmp_path, pairings)
    client.ask("list")
    recorded = [m for topic, m in bus.went_by if topic == "to_agent" and "box" in m and "client" in m]
    answered = len([m for topic, m in bus.went_by if topic == "from_agent"])
    before = offer.dropped["replayed"]
    Stranger(bus).write(*recorded)
    eventually(lambda: offer.dropped["replayed"] == before + len(recorded))
    assert len([m for topic, m in bus.went_by if topic == "from_agent" and "alive" not in json.dumps(m)]) <= answered
    client.close()


def test_a_forged_box_or_a_bye_in_a_paired_lines_name_has_no_effect(graph, tmp_path):
    bus, agent, offer, pairings = graph
    client, _, _, answer = paired_client(tmp_path, pairings)
    client.ask("attach", control=True)
    assert agent.controller is not None
    line = client.line.line
    Stranger(bus).write({"op": "bye", "from": line}, {"op": "detach", "id": 1, "from": line},
                        {"client": answer["client"], "line": line, "box": base64.b64encode(b"x" * 40).decode()})
    eventually(lambda: offer.dropped["not_opened"] >= 1)
    assert agent.controller is not None and agent.controller.line == line
    client.close()


def test_a_line_whose_key_the_agent_no_longer_knows_is_told_to_pair(graph, tmp_path):
    bus, agent, offer, pairings = graph
    client, keys, _, answer = paired_client(tmp_path, pairings)
    client.close()
    again = Client(keys)  # the key kept works for a new line
    assert again.ask("list")["ok"] is True
    again.close()
    pairings.revoke(answer["client"])
    with pytest.raises(AgentError) as refused:
        Client(keys)
    assert refused.value.key == "agent_not_paired"


def test_an_agent_that_does_not_seal_is_told_apart_before_anything_is_sent(tmp_path, monkeypatch):
    """An agent from before sealing answers the clear hello without a session: a paired laptop must not send its
    requests in clear to it, so the line ends, saying the two do not speak the same language."""
    bus = Bus()
    monkeypatch.setattr(ros_transport, "_carrier", lambda kind: bus.carrier())
    old = bus.carrier().Topics("/rockly_agent", True, lambda message: old.publish(
        {"reply": message.get("id"), "ok": True, "agent": "0.0.9", "to": message.get("from")}))
    try:
        with pytest.raises(AgentError) as refused:
            Client(RobotKeys(tmp_path / "robot-keys.json"))
        assert refused.value.key == "agent_other_format" and "0.0.9" in refused.value.message
        assert [message for topic, message in bus.went_by if topic == "to_agent" and message.get("op") != "hello"] == []
    finally:
        bus.stop()


def test_a_line_that_paired_is_not_paired_under_its_clear_name(graph, tmp_path):
    """The agent's ``pair`` makes the client it answers paired (a TCP connection stays so); over ROS the clear name
    that paired is anyone's to write: a request in that name is still refused."""
    bus, agent, _, pairings = graph
    client, _, _, _ = paired_client(tmp_path, pairings)
    Stranger(bus).write({"op": "list", "id": "x", "from": client.line.who})
    eventually(lambda: any(m.get("reply") == "x" for topic, m in bus.went_by if topic == "from_agent"))
    (answer,) = [m for topic, m in bus.went_by if topic == "from_agent" and m.get("reply") == "x"]
    assert answer["error"] == "agent_not_paired"
    client.close()


def test_a_forged_answer_to_a_pair_request_does_not_keep_the_line_from_pairing(graph, tmp_path, monkeypatch):
    """A stranger answers the pair request first, with a box of its own: the line waits for the agent's."""
    bus, agent, _, pairings = graph
    client = Client(RobotKeys(tmp_path / "robot-keys.json"))
    stranger = Stranger(bus)
    stranger.agent_side = True  # it speaks to the clients, as the agent does
    answer_pair = agent.answer

    def forged_first(line, request):  # the stranger's answer goes out before the agent's
        if request.get("op") == "pair":
            stranger.write({"to": client.line.who, "reply": request["id"], "box": base64.b64encode(b"y" * 48).decode()})
        return answer_pair(line, request)
    monkeypatch.setattr(agent, "answer", forged_first)
    answer = client.ask("pair", code=pairings.new_code().code, name="ada@laptop")
    assert answer["ok"] is True and client.ask("list")["ok"] is True  # paired, and sealing with the key
    client.close()
