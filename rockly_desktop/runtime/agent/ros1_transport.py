"""The agent's ROS 1 transport: the same messages as over TCP (``agent.protocol``), on the agent's two topics
(``robot/ros1/agent_topics.py``, reached through the robot-link registry): requests go to the agent with
``"from": CLIENT`` (a name unique to the client), answers come back with ``"to": CLIENT``, the run's events
without (one topic out keeps a client's answers and events in the order the agent sent them, as one TCP
connection does). Why topics of standard types: docs/decisions/031.

A topic has no "connection closed", so a ROS client says it is there with a heartbeat every
``HEARTBEAT_SECONDS`` (attached or not) and ``bye`` when it closes; the agent forgets a client not heard from for
``SILENT_CLIENT_SECONDS`` (it neither watches nor controls any more). A client hears a lost agent as its
incoming topic losing its publisher for ``LOST_AGENT_SECONDS``.

``RosOffer`` is the agent's side, ``RosLine`` a client's; rospy is imported only when one is made.
"""
import os
import threading
import time
import uuid

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.robot.link import RobotUnavailable
from rockly_desktop.runtime.agent.protocol import AgentError

KIND = "ros1"  # the robot link whose middleware carries these topics
SILENT_CLIENT_SECONDS = 5.0  # a ROS client not heard from this long is gone (it beats every 0.2 s)
LOST_AGENT_SECONDS = 1.0  # a client's incoming topic without the agent's publisher this long: the agent is gone


def _carrier():
    from rockly_desktop.robot import links

    return links.agent_topics(KIND)


def agent_in_graph(master: str, namespace: str) -> bool:
    """True when the ROS 1 master at ``master`` lists an agent in ``namespace``."""
    return _carrier().agent_in_graph(master, namespace)


def master_at_hand():
    """The master of this process's ROS 1 node, None when it has none."""
    return _carrier().master_at_hand()


def _node(master, language: str) -> tuple:
    """``(node name, master URI)`` of this process's ROS 1 node; AgentError when it cannot be had."""
    try:
        return _carrier().node_name(master)
    except (RobotUnavailable, ImportError) as error:
        raise AgentError("agent_no_ros", app_text("agent_no_ros", language, reason=str(error))) from None


class _RosClient:
    """A client the agent has heard over ROS: ``send`` answers it, ``deliver`` is the transport's one outlet
    for the run's events (every ROS client gets them from the same topic)."""

    def __init__(self, offer, who: str):
        self.who = who
        self.language = "en"
        self.name = "?"
        self.attached = False
        self.wants_control = False
        self.heard = time.monotonic()
        self.deliver = offer.broadcast
        self._offer = offer

    def send(self, message: dict) -> bool:
        return self._offer.topics.publish({**message, "to": self.who})


class RosOffer:
    """``agent``'s calls on ROS 1 ``master`` (None: ``ROS_MASTER_URI``) in ``namespace``; AgentError when ROS 1
    cannot be reached."""

    def __init__(self, agent, namespace: str, master: str = None, language: str = "en"):
        _, self.master = _node(master, language)
        self.agent = agent
        self._clients = {}
        self._lock = threading.Lock()
        self._stopped = threading.Event()
        self.topics = _carrier().Topics(namespace, True, self._on_request)
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
    """A client's line to the agent in ``namespace`` on ROS 1 ``master`` (None: this process's node's master, or
    ``ROS_MASTER_URI``): ``take(message)`` gets the agent's messages for this client and its events, in order
    (on rospy's thread); ``gone()`` is called once when the line has ended (closed, or the agent lost)."""

    beats_always = True  # the agent has no closed connection to hear: a client falling silent is gone

    def __init__(self, master, namespace: str, language: str, timeout: float, take, gone):
        node, master = _node(master, language)
        not_there = AgentError("agent_not_in_graph", app_text("agent_not_in_graph", language, namespace=namespace,
                                                              master=master))
        if not agent_in_graph(master, namespace):
            raise not_there
        self.who = f"{node}/{os.getpid()}-{uuid.uuid4().hex[:8]}"
        self.where = f"{master} ({namespace})"  # what a window names
        self._take, self._gone = take, gone
        self._ready = threading.Event()
        self._ended = threading.Event()
        self._ending = threading.Lock()
        self.topics = _carrier().Topics(namespace, False, self._on_message)
        if not self._handshake(timeout):
            self.topics.close()
            raise not_there
        self._watch = threading.Thread(target=self._watch_agent, daemon=True, name="agent-client")
        self._watch.start()

    def _handshake(self, timeout: float) -> bool:
        """Ask until the agent answers: rospy drops what is published before a subscriber is connected, and a
        publisher lists a subscriber only after the subscriber sees the connection up; an answer that came back
        means both ways work. True when it came within ``timeout``."""
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.topics.connected():
                self.write({"op": "heartbeat", "id": self.who})  # answered {"reply": its id} as any request
            if self._ready.wait(0.05):
                return True
        return False

    def write(self, message: dict) -> bool:
        """Send ``message`` to the agent; False once the line has ended."""
        return not self._ended.is_set() and self.topics.publish({**message, "from": self.who})

    def close(self):
        """Say goodbye to the agent and end the line (``gone`` follows)."""
        self.write({"op": "bye"})
        self._end()
        self._watch.join(5)

    def _on_message(self, message: dict):
        if self._ended.is_set():
            return
        to = message.pop("to", None)
        if to == self.who and message.get("reply") == self.who:
            self._ready.set()
        elif to == self.who or (to is None and "event" in message):
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
