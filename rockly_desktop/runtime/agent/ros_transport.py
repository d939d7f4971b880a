"""The agent's ROS transport: the same messages as over TCP (``agent.protocol``), on the agent's two topics on
the robot link ``kind``'s middleware (``ros1``: ``robot/ros1/agent_topics.py``, ``ros2``:
``robot/ros2/agent_topics.py``, reached through the robot-link registry): requests go to the agent with
``"from": CLIENT`` (a name unique to the client), answers come back with ``"to": CLIENT``, the run's events
without (one topic out keeps a client's answers and events in the order the agent sent them, as one TCP
connection does). Why topics of standard types: docs/decisions/031. ``where`` is the graph: a ROS 1 master
URI, a ROS 2 domain id (the agent: its connection's settings); None: this process's node's, or the environment's.

A topic has no "connection closed", so a ROS client says it is there with a heartbeat every
``HEARTBEAT_SECONDS`` (attached or not) and ``bye`` when it closes; the agent forgets a client not heard from for
``SILENT_CLIENT_SECONDS`` (it neither watches nor controls any more). A client hears a lost agent as its
incoming topic losing its publisher for ``LOST_AGENT_SECONDS`` (fast: a process that ends), or as the agent's
``ALIVE`` (broadcast to all clients) not heard for ``AGENT_SILENT_SECONDS`` (``AgentClient``: a hung or frozen
agent, a cut network, which leave the publisher in the graph: ROS 2 until the DDS lease ends, ROS 1 for ever).

A paired client proves every message: ``client_id`` and ``proof`` (``pairings.proof_of_key`` of
``pairings.message_data``); the agent takes the message as that client's, or as an unpaired client's. (Not yet:
replay protection, and pairing over ROS itself: ``pair`` and ``pairing_code`` would carry the key or a code in
clear, so they are refused here; a laptop pairs over TCP and keeps the key for the ROS address too.)

``RosOffer`` is the agent's side, ``RosLine`` a client's; the middleware is reached only when one is made.
"""
import os
import threading
import time
import uuid

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.runtime.agent.pairings import message_data, proof_of_key
from rockly_desktop.runtime.agent.protocol import AgentError, AgentRefusal, refusal_text

KINDS = ("ros1", "ros2")  # the robot links whose middleware carries these topics
# the texts naming each: (cannot reach it, no agent in the graph, the agent offers its calls there)
TEXTS = {"ros1": ("agent_no_ros", "agent_not_in_graph", "agent_ready_ros"),
         "ros2": ("agent_no_ros2", "agent_not_in_graph_ros2", "agent_ready_ros2")}
NOT_OVER_ROS = ("pair", "pairing_code")  # their answers carry a key or a code: over TLS only (see above)
SILENT_CLIENT_SECONDS = 5.0  # a ROS client not heard from this long is gone (it beats every 0.2 s)
LOST_AGENT_SECONDS = 1.0  # a client's incoming topic without the agent's publisher this long: the agent is gone


def _carrier(kind: str):
    from rockly_desktop.robot import links

    return links.agent_topics(kind)


def agent_in_graph(kind: str, where, namespace: str) -> bool:
    """True when the ``kind`` graph ``where`` names lists an agent in ``namespace``."""
    return _carrier(kind).agent_in_graph(where, namespace)


def master_at_hand(kind: str):
    """The graph of this process's ``kind`` node (a master URI, a domain id), None when it has none (or the
    middleware is not installed here)."""
    try:
        return _carrier(kind).master_at_hand()
    except ImportError:
        return None


def _node(kind: str, where, language: str) -> tuple:
    """``(node name, the graph as a person reads it)`` of this process's ``kind`` node; AgentError when it
    cannot be had."""
    try:
        node, graph = _carrier(kind).node_name(where)
    except (RocklyError, ImportError) as error:
        raise AgentError(TEXTS[kind][0], app_text(TEXTS[kind][0], language, reason=str(error))) from None
    return node, graph.in_language(language) if hasattr(graph, "in_language") else graph  # ROS 2's: "domain 7"


class _RosClient:
    """A client the agent has heard over ROS: ``send`` answers it, ``deliver`` is the transport's one outlet
    for the run's events (every ROS client gets them from the same topic)."""

    def __init__(self, offer, who: str):
        self.who = who
        self.language = "en"
        self.name = "?"
        self.attached = False
        self.wants_control = False
        self.paired = None  # the PairedClient its latest message proved
        self.heard = time.monotonic()
        self.deliver = offer.broadcast
        self._offer = offer

    def send(self, message: dict) -> bool:
        return self._offer.topics.publish({**message, "to": self.who})

    def cut(self):
        """Its pairing was revoked: its messages are an unpaired client's from now (each proves itself anew)."""
        self.paired = None


class RosOffer:
    """``agent``'s calls on the ``kind`` graph ``where`` in ``namespace``; AgentError when it cannot be reached.
    ``ready``: the line saying so, in ``language``."""

    def __init__(self, agent, kind: str, namespace: str, where=None, language: str = "en"):
        _, self.master = _node(kind, where, language)
        self.ready = app_text(TEXTS[kind][2], language, master=self.master, namespace=namespace)
        self.agent = agent
        self._clients = {}
        self._lock = threading.Lock()
        self._stopped = threading.Event()
        self.topics = _carrier(kind).Topics(namespace, True, self._on_request)
        self._watch = threading.Thread(target=self._forget_silent, daemon=True, name="agent-ros-clients")
        self._watch.start()

    def broadcast(self, event: dict) -> bool:
        """Publish one of the run's events once for every attached ROS client."""
        return self.topics.publish(event)

    def _on_request(self, request: dict):
        who = request.get("from")
        if not isinstance(who, str) or not who:
            return  # nobody to answer
        if request.get("op") == "bye":
            self._drop(who)
            return
        with self._lock:
            client = self._clients.get(who)
            if client is None:
                client = self._clients[who] = _RosClient(self, who)
                self.agent.join(client)
        client.heard = time.monotonic()
        client.paired = self.agent.pairings.verify(request.get("client_id"), request.get("proof"),
                                                   message_data(request))
        if request.get("op") in NOT_OVER_ROS:
            refusal = AgentRefusal("agent_pair_over_tcp")
            client.send({"reply": request.get("id"), "ok": False, "error": refusal.key,
                         "message": refusal_text(refusal, client.language)})
            return
        answer = self.agent.answer(client, request)
        if answer is not None:
            client.send(answer)

    def _drop(self, who: str):
        with self._lock:
            client = self._clients.pop(who, None)
        if client is not None:
            self.agent.leave(client)

    def _forget_silent(self):
        while not self._stopped.wait(0.5):
            now = time.monotonic()
            for who, client in list(self._clients.items()):
                if now - client.heard > SILENT_CLIENT_SECONDS:
                    self._drop(who)

    def close(self):
        """Stop offering the agent's calls."""
        self._stopped.set()
        self.topics.close()
        self._watch.join(5)


class RosLine:
    """A client's line to the agent in ``namespace`` on the ``kind`` graph ``where`` (None: this process's node's,
    or the environment's): ``take(message)`` gets the agent's messages for this client and its events, in order
    (on the middleware's thread); ``gone()`` is called once when the line has ended (closed, or the agent lost)."""

    beats_always = True  # the agent has no closed connection to hear: a client falling silent is gone

    def __init__(self, kind: str, where, namespace: str, language: str, timeout: float, take, gone, key=None):
        self.key = key  # the RobotKey whose proof every message carries (None: not paired)
        node, master = _node(kind, where, language)
        not_there = AgentError(TEXTS[kind][1], app_text(TEXTS[kind][1], language, namespace=namespace,
                                                        master=master))
        if not agent_in_graph(kind, where, namespace):
            raise not_there
        self.who = f"{node}/{os.getpid()}-{uuid.uuid4().hex[:8]}"
        self.where = f"{master} ({namespace})"  # what a window names
        self._take, self._gone = take, gone
        self._ready = threading.Event()
        self._ended = threading.Event()
        self._ending = threading.Lock()
        self.topics = _carrier(kind).Topics(namespace, False, self._on_message)
        if not self._handshake(timeout):
            self.topics.close()
            raise not_there
        self._watch = threading.Thread(target=self._watch_agent, daemon=True, name="agent-client")
        self._watch.start()

    def _handshake(self, timeout: float) -> bool:
        """Ask until the agent answers: ROS drops what is published before a subscriber is connected (ROS 2's
        discovery is gradual), and a publisher lists a subscriber only after the subscriber sees the connection
        up; an answer that came back means both ways work. True when it came within ``timeout``."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.topics.connected():
                self.write({"op": "heartbeat", "id": self.who})  # answered {"reply": its id} as any request
            if self._ready.wait(0.05):
                return True
        return False

    def write(self, message: dict) -> bool:
        """Send ``message`` to the agent; False once the line has ended."""
        message = {**message, "from": self.who}
        if self.key is not None:
            message["client_id"] = self.key.client
            message["proof"] = proof_of_key(self.key.key, message_data(message))
        return not self._ended.is_set() and self.topics.publish(message)

    def close(self):
        """Say goodbye to the agent and end the line (``gone`` follows)."""
        self.write({"op": "bye"})
        self._end()
        self._watch.join(5)

    def lose(self):
        """End the line as lost (the agent fell silent; ``gone`` follows)."""
        self._end()

    def _on_message(self, message: dict):
        if self._ended.is_set():
            return
        to = message.pop("to", None)
        if to == self.who and message.get("reply") == self.who:
            self._ready.set()
        elif to == self.who or to is None:  # an answer to this client; an event or ``ALIVE`` to all
            self._take(message)

    def _watch_agent(self):
        alone_since = None
        while not self._ended.wait(0.1):
            if self.topics.heard_from():
                alone_since = None
            elif alone_since is None:
                alone_since = time.monotonic()
            elif time.monotonic() - alone_since > LOST_AGENT_SECONDS:
                self._end()

    def _end(self):
        with self._ending:
            if self._ended.is_set():
                return
            self._ended.set()
        self.topics.close()
        self._gone()
