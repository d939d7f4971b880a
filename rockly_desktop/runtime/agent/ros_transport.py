"""The agent's ROS transport: the same messages as over TCP (``agent.protocol``), on the agent's two topics on
the robot link ``kind``'s middleware (``ros1``: ``robot/ros1/agent_topics.py``, ``ros2``:
``robot/ros2/agent_topics.py``, reached through the robot-link registry). Why topics of standard types:
docs/decisions/031; why and how they are sealed: docs/decisions/036. ``where`` is the graph: a ROS 1 master URI, a
ROS 2 domain id (the agent: its connection's settings); None: this process's node's, or the environment's.

Every node on the graph can read and write the topics, so a paired client's line seals what it sends
(``agent.sealed``): ``{"client": ID, "line": LINE, "box": ...}``, with the pair's key, bound to the client, its line
(one per ``RosLine``: as one TCP connection), the direction, the namespace and the agent's session (one per run of
the agent), a counter inside that rises on each line. The agent opens it with ``agent.pairings.find(ID).key`` and
drops, unanswered, what does not open or comes again (``dropped`` counts them); it answers each line sealed the same
way, its answers and the run's events alike (events for several lines are sealed once per line), so only that
client can read them. Identity is the key: nobody can speak in another client's name.

In clear, with ``"from": NAME`` (a name unique to the line) and answered ``"to": NAME``, go only what comes before
a key: ``hello`` (its answer names the agent's ``session`` and its X25519 ``agent_key``: the line's first exchange,
the handshake) and ``pair``, whose code and answer (the pair's key) travel sealed with a one-time key agreed by
X25519 with ``agent_key`` (``sealed.PairingExchange``); anything else in clear gets the agent's refusal (not
paired), and a line that is not paired hears nothing but its answers and ``ALIVE``. A client from before pairing
(protocol format 1) began its line with a heartbeat with an id: it is answered, and its hello refused, so that it
says it must be updated and paired.

A topic has no "connection closed", so a ROS client says it is there with a heartbeat every
``HEARTBEAT_SECONDS`` (attached or not) and ``bye`` when it closes; the agent forgets a client not heard from for
``SILENT_CLIENT_SECONDS`` (it neither watches nor controls any more). A client hears a lost agent as its
incoming topic losing its publisher for ``LOST_AGENT_SECONDS`` (fast: a process that ends), or as the agent's
``ALIVE`` not heard for ``AGENT_SILENT_SECONDS`` (``AgentClient``: a hung or frozen agent, a cut network, which
leave the publisher in the graph: ROS 2 until the DDS lease ends, ROS 1 for ever).

``RosOffer`` is the agent's side, ``RosLine`` a client's; the middleware is reached only when one is made.
"""
import base64
import binascii
import collections
import os
import sys
import threading
import time
import uuid

from rockly_desktop import __version__
from rockly_desktop.core.app_texts import app_text
from rockly_desktop.core.errors import RocklyError
from rockly_desktop.runtime.agent.protocol import ALIVE, FORMAT, AgentError, client_before_pairing, refusal_text
from rockly_desktop.runtime.agent.robot_keys import ros_address
from rockly_desktop.runtime.agent.sealed import (
    FROM_AGENT,
    TO_AGENT,
    Binding,
    LineCounter,
    PairingExchange,
    Replays,
    Unsealable,
    new_line,
    new_session,
    seal,
    unseal,
)

SILENT_CLIENT_SECONDS = 5.0  # a ROS client not heard from this long is gone (it beats every 0.2 s)
LOST_AGENT_SECONDS = 1.0  # a client's incoming topic without the agent's publisher this long: the agent is gone
CLEAR_OPS = ("hello", "pair")  # the requests that come before a key
MAX_UNPAIRED = 64  # lines not paired yet (saying hello, pairing) the agent keeps: more are not heard
DROPPED_SAID_SECONDS = 60.0  # the agent says what it dropped at most this often (on standard error)


def _carrier(kind: str):
    from rockly_desktop.robot import links

    return links.agent_topics(kind)


def agent_host(kind: str, connection: dict):
    """The host the robot link ``kind``'s agent runs on by its ``connection`` settings (the registry's
    ``agent_beside``: ROS 1's master), or None when its entry names none or the setting has no host."""
    from urllib.parse import urlsplit

    from rockly_desktop.robot import links

    beside = links.link_kind(kind).agent_beside
    return urlsplit(connection.get(beside) or "").hostname if beside is not None else None


def _texts(kind: str) -> tuple:
    """The texts naming ``kind``'s graph: (cannot reach it, no agent in the graph, the agent offers its calls
    there), from the robot-link registry."""
    from rockly_desktop.robot import links

    return links.link_kind(kind).agent_texts


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
        raise AgentError(_texts(kind)[0], app_text(_texts(kind)[0], language, reason=str(error))) from None
    return node, graph.in_language(language) if hasattr(graph, "in_language") else graph  # ROS 2's: "domain 7"


def _namespace(namespace: str) -> str:
    return "/" + namespace.strip("/")


def _short_text(value, longest: int = 200) -> bool:
    return isinstance(value, str) and 0 < len(value) <= longest


class _RosClient:
    """A line the agent hears over ROS (as a TCP connection): ``paired`` (a ``PairedClient``) and its ``line``
    for a sealed one, None and the line's clear name ``who`` for one that is not paired yet. ``send`` answers
    it (sealed for it alone when paired), ``deliver`` is its outlet for the run's events and ``ALIVE``."""

    def __init__(self, offer, who: str, paired=None, line: str = None):
        self.who = who
        self._sealed_for = self._paired = paired
        self.line = line
        self.language = "en"
        self.name = "?"
        self.attached = False
        self.wants_control = False
        self.heard = time.monotonic()
        self._offer = offer
        self.deliver = self.send if paired is not None else offer.say_to_unpaired  # each paired line its own
        if paired is not None:
            self._binding = Binding(offer.namespace, FROM_AGENT, paired.id, line, offer.session)
            self._counter = LineCounter()
            self._sending = threading.Lock()  # the counters go out in the order they rise

    @property
    def paired(self):
        return self._paired

    @paired.setter
    def paired(self, paired):
        """A line is paired by its key alone: the agent may take its pairing away (revoked) or renew it, never
        give one to a line that came without (its ``pair``, which makes a TCP connection paired, leaves a clear
        line as it was: anyone on the graph can write its clear name)."""
        if paired is None or (self._sealed_for is not None and paired.id == self._sealed_for.id):
            self._paired = paired

    def cut(self):
        """Its pairing was revoked: nothing it sends is taken any more (its key is not found), and what it is
        sent stays sealed for it alone."""
        self._paired = None

    def send(self, message: dict) -> bool:
        if self._sealed_for is None:
            return self._offer.topics.publish({**message, "to": self.who})
        with self._sending:
            box = seal(self._sealed_for.key, self._binding, self._counter.next(), message)
            return self._offer.topics.publish({"client": self._sealed_for.id, "line": self.line, "box": box})


class RosOffer:
    """``agent``'s calls on the ``kind`` graph ``where`` in ``namespace``; AgentError when it cannot be reached.
    ``ready``: the line saying so, in ``language``. ``dropped`` counts, by reason, what it did not take."""

    def __init__(self, agent, kind: str, namespace: str, where=None, language: str = "en"):
        try:
            self._exchange = PairingExchange()  # this run's X25519 key: pairing over the topics
        except ImportError as missing:  # nothing can be sealed: nothing is offered in clear instead
            raise AgentError("agent_ros_needs_cryptography", app_text("agent_ros_needs_cryptography", language,
                                                                      reason=str(missing))) from None
        _, self.master = _node(kind, where, language)
        self.ready = app_text(_texts(kind)[2], language, master=self.master, namespace=namespace)
        self.agent = agent
        self.namespace = _namespace(namespace)
        self.session = new_session()
        self.dropped = collections.Counter()
        self._replays = Replays()
        self._language = language
        self._dropped_said = (0, None)  # (how many were said, when)
        self._clients = {}  # (paired client id, line) or ("", clear name) -> _RosClient
        self._lock = threading.Lock()
        self._stopped = threading.Event()
        self.topics = _carrier(kind).Topics(namespace, True, self._on_request)
        self._watch = threading.Thread(target=self._forget_silent, daemon=True, name="agent-ros-clients")
        self._watch.start()

    def say_to_unpaired(self, message: dict) -> bool:
        """The outlet of the lines not paired yet: ``ALIVE``, once for all of them; nothing else is theirs."""
        return self.topics.publish(message) if message == ALIVE else True

    def _on_request(self, message: dict):
        if "from" in message:  # what comes before a key (a pair request's code is in a box of its own)
            self._on_clear(message)
        else:
            self._on_sealed(message)

    def _on_sealed(self, message: dict):
        client_id, line, box = message.get("client"), message.get("line"), message.get("box")
        if not (_short_text(client_id) and _short_text(line) and isinstance(box, str)):
            self.dropped["malformed"] += 1
            return
        paired = self.agent.pairings.find(client_id)
        if paired is None:
            self.dropped["not_paired"] += 1
            return
        try:
            counter, request = unseal(paired.key, Binding(self.namespace, TO_AGENT, client_id, line, self.session),
                                      box)
        except Unsealable:
            self.dropped["not_opened"] += 1
            return
        with self._lock:
            if not self._replays.fresh(client_id, line, counter):
                self.dropped["replayed"] += 1
                return
            client = self._clients.get((client_id, line))
            if client is None:
                client = self._clients[(client_id, line)] = _RosClient(self, line, paired, line)
                self.agent.join(client)
        client.heard = time.monotonic()
        if request.get("op") == "bye":
            self._drop((client_id, line))
            return
        answer = self.agent.answer(client, request)
        if answer is not None:
            client.send(answer)

    def _on_clear(self, request: dict):
        who, op = request.get("from"), request.get("op")
        if not _short_text(who):
            self.dropped["malformed"] += 1
            return
        if op == "bye":
            self._drop(("", who))
            return
        with self._lock:
            client = self._clients.get(("", who))
            if client is None and op not in CLEAR_OPS:
                if op == "heartbeat":
                    if "id" in request:  # the handshake of a client from before pairing (format 1): it is told
                        self._tell_before_pairing(who, request)
                    return  # a line the agent does not know (any more): its hello comes first
                self.dropped["in_clear"] += 1
                client = _RosClient(self, who)  # told it is not paired; not kept
            elif client is None:
                if sum(1 for key in self._clients if not key[0]) >= MAX_UNPAIRED:
                    self.dropped["too_many"] += 1
                    return
                client = self._clients[("", who)] = _RosClient(self, who)
                self.agent.join(client)
        if client is None:
            return
        client.heard = time.monotonic()
        if op == "heartbeat" and "id" not in request:
            return  # a line not paired yet says it is there
        if op == "pair":
            answer = self._pair(client, request)
        else:
            answer = self.agent.answer(client, request)
            if op == "hello" and answer is not None:
                asked = request.get("paired_as")
                answer.update(session=self.session, agent_key=self._exchange.public_text,
                              known=_short_text(asked) and self.agent.pairings.find(asked) is not None)
        if answer is not None:
            client.send(answer)

    def _tell_before_pairing(self, who: str, request: dict):
        """Answer a format-1 client's handshake (a heartbeat with an id, answered as its line's first exchange) in
        clear: it must be updated and paired. Its hello, which follows, is refused so in its own language."""
        refusal = client_before_pairing("?")
        self.topics.publish({"reply": request["id"], "ok": False, "error": refusal.key,
                             "message": refusal_text(refusal, self._language), "to": who})

    def _pair(self, client, request: dict):
        """The agent's answer to a clear ``pair`` request: its code and name opened with the one-time key agreed
        with the line's ``public_key``, the answer (the pair's key) sealed with it."""
        try:
            once = self._exchange.key_with(request.get("public_key"), client_side=False)
            _, fields = unseal(once, Binding(self.namespace, TO_AGENT, "", client.who, self.session),
                               request.get("box"))
        except Unsealable:
            self.dropped["not_opened"] += 1
            return None
        answer = self.agent.answer(client, {"op": "pair", "id": request.get("id"), "code": fields.get("code"),
                                            "name": fields.get("name")})
        if answer is None:
            return None
        box = seal(once, Binding(self.namespace, FROM_AGENT, "", client.who, self.session), 0, answer)
        return {"reply": answer["reply"], "box": box}

    def _drop(self, key: tuple):
        with self._lock:
            client = self._clients.pop(key, None)
            if client is not None and key[0]:  # a sealed line (revoked or not): its counter is kept a while
                self._replays.ended(*key)
        if client is not None:
            self.agent.leave(client)

    def _forget_silent(self):
        while not self._stopped.wait(0.5):
            now = time.monotonic()
            for key, client in list(self._clients.items()):
                if now - client.heard > SILENT_CLIENT_SECONDS:
                    self._drop(key)
            self._say_dropped(now)

    def _say_dropped(self, now: float):
        """Say on standard error how many messages were dropped since it was last said (at most once a
        ``DROPPED_SAID_SECONDS``): someone on the graph may be trying the agent."""
        said, when = self._dropped_said
        count = sum(self.dropped.values())
        if count > said and (when is None or now - when >= DROPPED_SAID_SECONDS):
            self._dropped_said = (count, now)
            print(app_text("agent_ros_dropped", self._language, count=count - said), file=sys.stderr, flush=True)

    def close(self):
        """Stop offering the agent's calls."""
        self._stopped.set()
        self.topics.close()
        self._watch.join(5)


class RosLine:
    """A client's line to the agent in ``namespace`` on the ``kind`` graph ``where`` (None: this process's node's,
    or the environment's): ``take(message)`` gets the agent's messages for this client and its events, in order
    (on the middleware's thread); ``gone()`` is called once when the line has ended (closed, or the agent lost).
    ``address`` names the agent as ``RobotKeys`` does; with a key for it in ``keys`` (``key``), everything but
    the handshake travels sealed. A line that pairs (a ``pair`` request) seals with the new key from then on."""

    beats_always = True  # the agent has no closed connection to hear: a client falling silent is gone

    def __init__(self, kind: str, where, namespace: str, language: str, timeout: float, take, gone, keys=None):
        node, master = _node(kind, where, language)
        not_there = AgentError(_texts(kind)[1], app_text(_texts(kind)[1], language, namespace=namespace,
                                                        master=master))
        if not agent_in_graph(kind, where, namespace):
            raise not_there
        self.namespace = _namespace(namespace)
        self.address = ros_address(kind, _carrier(kind).master_at_hand(), self.namespace)
        self.key = keys.get(self.address) if keys is not None else None  # a RobotKey
        self.who = f"{node}/{os.getpid()}-{uuid.uuid4().hex[:8]}"
        self.line = new_line()
        self.where = f"{master} ({namespace})"  # what a window names
        self._take, self._gone = take, gone
        self._language = language
        self._sealing = None  # (client id, key) once paired
        self._counter = LineCounter()
        self._writing = threading.Lock()  # the counters go out in the order they rise
        self._agent = None  # the handshake's answer: the agent's session, its X25519 key, whether it knows the key
        self._pairing = {}  # request id -> the one-time key of a pair request
        self._ready = threading.Event()
        self._ended = threading.Event()
        self._ending = threading.Lock()
        self.topics = _carrier(kind).Topics(namespace, False, self._on_message)
        if not self._handshake(timeout):
            self.topics.close()
            raise not_there
        if not isinstance(self._agent.get("session"), str):  # an agent from before sealing: nothing safe to say
            self.topics.close()
            raise AgentError("agent_other_format", app_text("agent_other_format", language,
                                                            agent=self._agent.get("agent", "?"), client=__version__))
        if self.key is not None:
            if not self._agent.get("known"):
                self.topics.close()
                raise AgentError("agent_not_paired", app_text("agent_not_paired", language))  # revoked
            self._sealing = (self.key.client, self.key.key)
        self._watch = threading.Thread(target=self._watch_agent, daemon=True, name="agent-client")
        self._watch.start()

    def _handshake(self, timeout: float) -> bool:
        """Say a clear hello until the agent answers: ROS drops what is published before a subscriber is
        connected (ROS 2's discovery is gradual), and a publisher lists a subscriber only after the subscriber
        sees the connection up; an answer that came back means both ways work. It names the agent's session
        and X25519 key. True when it came within ``timeout``."""
        hello = {"op": "hello", "id": self.who, "from": self.who, "format": FORMAT, "language": self._language}
        if self.key is not None:
            hello["paired_as"] = self.key.client
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.topics.connected():
                self.topics.publish(hello)
            if self._ready.wait(0.05):
                return True
        return False

    def write(self, message: dict) -> bool:
        """Send ``message`` to the agent (sealed once the line has a key); False once the line has ended."""
        if self._ended.is_set():
            return False
        if self._sealing is None:
            if message.get("op") == "pair":
                message = self._pair_request(message)
            return self.topics.publish({**message, "from": self.who})
        client, key = self._sealing
        binding = Binding(self.namespace, TO_AGENT, client, self.line, self._agent["session"])
        with self._writing:
            box = seal(key, binding, self._counter.next(), message)
            return self.topics.publish({"client": client, "line": self.line, "box": box})

    def _pair_request(self, request: dict) -> dict:
        """A ``pair`` request whose code and name are sealed with a one-time key agreed with the agent's."""
        exchange = PairingExchange()
        try:
            once = exchange.key_with(self._agent.get("agent_key"), client_side=True)
        except Unsealable:  # an agent that offers no pairing over ROS: it refuses a request without the code
            return {"op": "pair", "id": request.get("id")}
        self._pairing[request.get("id")] = once
        fields = {"code": request.get("code"), "name": request.get("name")}
        box = seal(once, Binding(self.namespace, TO_AGENT, "", self.who, self._agent["session"]), 0, fields)
        return {"op": "pair", "id": request.get("id"), "public_key": exchange.public_text, "box": box}

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
        if "box" in message and "to" not in message:
            self._on_sealed(message)
            return
        to = message.pop("to", None)
        if to == self.who and message.get("reply") == self.who:
            if not self._ready.is_set():
                self._agent = message
                self._ready.set()
        elif self._sealing is not None:
            return  # a paired line believes only what is sealed for it
        elif to == self.who and message.get("reply") in self._pairing:
            self._on_paired(message)
        elif to == self.who or message == ALIVE:  # an answer to this line; the agent saying it is there
            self._take(message)

    def _on_sealed(self, message: dict):
        if self._sealing is None or message.get("client") != self._sealing[0] or message.get("line") != self.line:
            return
        binding = Binding(self.namespace, FROM_AGENT, self._sealing[0], self.line, self._agent["session"])
        try:
            counter, inside = unseal(self._sealing[1], binding, message.get("box"))
        except Unsealable:
            return
        if self._counter.heard(counter):
            self._take(inside)

    def _on_paired(self, message: dict):
        """The agent's answer to this line's ``pair``: opened with its one-time key; a line that paired seals
        with the pair's key from now on."""
        once = self._pairing[message["reply"]]
        try:
            _, answer = unseal(once, Binding(self.namespace, FROM_AGENT, "", self.who, self._agent["session"]),
                               message.get("box"))
        except Unsealable:
            return  # not the agent's: its answer may still come
        del self._pairing[message["reply"]]
        if answer.get("ok") and answer.get("client") and answer.get("key"):
            try:
                self._sealing = (str(answer["client"]), base64.b64decode(answer["key"], validate=True))
            except (binascii.Error, ValueError, TypeError):
                pass
        self._take(answer)

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
