"""``AgentClient``: a Qt-free client of the robot's agent, for ``rockly robot ...`` and the window alike.

    client = AgentClient("robot.local", language="de", on_event=print)   # connects and says hello
    client = AgentClient(via="ros", master="http://robot:11311")          # the same over ROS 1
    client = AgentClient(via="ros", domain=7)                             # the same over ROS 2
    client.send("square", standalone_text, source_text, on_lost_editor="keep_going", decide_seconds=2.0)
    client.programs(); client.start("square")
    state = client.attach(control=True)      # the run so far; events then arrive on ``on_event`` (its thread)
    client.control("pause"); client.control("step"); client.control("continue"); client.stop()
    client.close()

Each call waits for the agent's answer and returns it as a dict; a refusal raises ``AgentError`` whose
``message`` is already in the client's language. ``on_event`` is called from the client's reader thread (a
window hands it on to its own thread). While attached, the client sends a heartbeat every
``HEARTBEAT_SECONDS``: that is what "the editor is there" means to a program that stops the robot when the
editor is lost. A connection that breaks ends the calls waiting with ``AgentError("agent_connection_lost")``
and calls ``on_closed``; so does an agent that said it beats (its ``hello``) and then is not heard from for
``AGENT_SILENT_SECONDS`` (hung, frozen, or the network cut: no transport says so soon, see ``agent.protocol``).
An agent that does not answer within ``timeout`` ends the call with ``AgentError("agent_no_answer")``.

A client proves it is paired with the key this laptop keeps for the agent's address (``RobotKeys``; over TCP in
its ``hello``, over ROS by sealing every message); without one it can say hello and ``pair(code)``, which keeps the key.
Anything else an agent refuses with ``AgentError("agent_not_paired", ...)``, saying how to pair.

``via`` picks the transport (one module each): ``tcp`` (``agent.tcp_transport``: ``host``:``port``), ``ros``
(``agent.ros_transport``: the agent's topics in ``namespace`` on ROS 2 domain ``domain`` when it is given, through
this process's ROS 2 helper; else on ROS 1 ``master``, this process's one ROS 1 node), or ``auto``: ROS when that
graph is given (or this process already has its ROS 1 node or ROS 2 helper) and an agent is in it, TCP otherwise.
"""
import base64
import getpass
import itertools
import socket
import threading
import time

from rockly_desktop import __version__
from rockly_desktop.core.app_texts import app_text
from rockly_desktop.runtime.agent.pairings import hello_data, proof_of_key
from rockly_desktop.runtime.agent.protocol import (
    AGENT_SILENT_SECONDS,
    DEFAULT_NAMESPACE,
    DEFAULT_PORT,
    FORMAT,
    HEARTBEAT_SECONDS,
    AgentError,
)
from rockly_desktop.runtime.agent.robot_keys import RobotKey, RobotKeys, tcp_address

VIAS = ("auto", "tcp", "ros")


def chosen_via(via: str, master: str = None, namespace: str = DEFAULT_NAMESPACE, domain=None,
               graph_kind: str = None) -> tuple:
    """``("tcp", None, None)`` or ``("ros", "ros1" or "ros2", the graph)`` for ``via`` (see above); without a
    ``master`` or ``domain``, only the graph of ``graph_kind`` (the chosen robot's) this process is on, if given."""
    if via == "tcp":
        return "tcp", None, None
    from rockly_desktop.robot.links import agent_graph_kinds
    from rockly_desktop.runtime.agent.ros_transport import agent_in_graph, master_at_hand

    if domain is not None:
        graphs = [("ros2", domain)]
    elif master:
        graphs = [("ros1", master)]
    else:
        kinds = [graph_kind] if graph_kind else agent_graph_kinds()
        graphs = [(kind, where) for kind, where in ((kind, master_at_hand(kind)) for kind in kinds) if where]
    if via == "ros":
        return ("ros", *graphs[0]) if graphs else ("ros", "ros1", None)
    return next((("ros", kind, where) for kind, where in graphs if agent_in_graph(kind, where, namespace)),
                ("tcp", None, None))


class AgentClient:
    """A connection to the agent: at ``host``:``port`` over TCP, or in ``namespace`` on ROS 1 ``master`` or ROS 2
    ``domain`` (``via``, see above; ``self.via`` says which was taken, ``self.kind`` which ROS), paired with the
    key ``keys`` (this laptop's ``RobotKeys`` when None) holds for its ``address``: ``self.robot_key``, None when
    it has none; ``self.paired``: the agent's word on it (``{"client", "role"}`` or None)."""

    def __init__(self, host: str = "localhost", port: int = DEFAULT_PORT, language: str = "en",
                 on_event=None, on_closed=None, name: str = "rockly", timeout: float = 10.0, via: str = "tcp",
                 master: str = None, namespace: str = DEFAULT_NAMESPACE, domain=None, graph_kind: str = None,
                 keys: RobotKeys = None):
        self.language = language
        self.on_event = on_event
        self.on_closed = on_closed
        self.timeout = timeout
        self.keys = keys if keys is not None else RobotKeys()
        self.controller = False
        self._ids = itertools.count(1)
        self._waiting = {}
        self._lock = threading.Lock()
        self._closed = threading.Event()
        self._attached = threading.Event()
        self._watching = threading.Event()  # from the attach request on: the run's events are wanted
        self._heard = time.monotonic()  # when the agent last said anything
        self._agent_beats = False  # its hello said it says it is there: its silence means it is lost
        self.via, self.kind, where = chosen_via(via, master, namespace, domain, graph_kind)
        if self.via == "ros":
            from rockly_desktop.runtime.agent.ros_transport import RosLine

            self._line = RosLine(self.kind, where, namespace, language, timeout, self._take, self._gone, self.keys)
            self.address, self.robot_key = self._line.address, self._line.key  # of the graph the line found
        else:
            from rockly_desktop.runtime.agent.tcp_transport import TcpLine

            self.address = tcp_address(host, port)
            self.robot_key = self.keys.get(self.address)
            self._line = TcpLine(host, port, language, timeout, self._take, self._gone,
                                 self.robot_key.fingerprint if self.robot_key else None)
        self.where = self._line.where  # the agent's host, or its ROS graph and namespace: what a window names
        self._heart = threading.Thread(target=self._beat, daemon=True, name="agent-heartbeat")
        self._heart.start()
        proof = {}
        if self.robot_key is not None and getattr(self._line, "nonce", None):
            proof = {"client_id": self.robot_key.client, "proof": proof_of_key(
                self.robot_key.key, hello_data(self._line.nonce, self.robot_key.client))}
        try:
            self.hello = self.request("hello", rockly=__version__, format=FORMAT, language=language,
                                      client=f"{name} ({_who()})", **proof)
        except AgentError:
            self.on_event = self.on_closed = None  # nobody was told of a client that never was
            self.close()  # an agent that never answers (or refuses) keeps no socket or thread of this client
            raise
        if self.hello.get("format") != FORMAT:  # an agent that did not check (it is older than the check)
            self.on_event = self.on_closed = None
            self.close()
            raise AgentError("agent_other_format", app_text("agent_other_format", language,
                                                            agent=self.hello.get("agent", "?"), client=__version__))
        self._agent_beats = bool(self.hello.get("alive_seconds"))
        self.paired = self.hello.get("paired")

    def pair(self, code: str, name: str = None, also_for=(), role: str = None) -> RobotKey:
        """Pair this laptop with the agent with the one-time ``code`` the robot showed, as ``name`` (``user@host``
        when None) and in the code's role (``role="student"``: as a student whatever the code gives, a kiosk);
        keeps the key (for this address, and for the addresses ``also_for``: the same agent over ROS) and returns
        it. AgentError when the agent refuses the code."""
        answer = self.request("pair", code=code, name=name or _who(), **({"role": role} if role else {}))
        key = RobotKey(self.address, str(answer["agent"]), str(answer["client"]), base64.b64decode(answer["key"]),
                       str(answer["role"]), getattr(self._line, "fingerprint", "") or "")
        self.keys.save(key)
        for address in also_for:
            self.keys.save(RobotKey(address, key.agent, key.client, key.key, key.role, ""))
        self.robot_key = key
        self._line.key = key  # (a ROS line seals with it already: it opened the answer)
        self.paired = {"client": key.client, "role": key.role}
        return key

    def pairing_code(self, role: str = None) -> dict:
        """A one-time code pairing another laptop (as ``role``: "student" or "teacher"; a teacher's client only):
        ``{"code", "seconds", "role"}``."""
        return self.request("pairing_code", **({"role": role} if role else {}))

    def request(self, op: str, **fields) -> dict:
        """Send request ``op`` and return the agent's answer (its fields, without ``reply`` and ``ok``); raises
        AgentError on a refusal or a lost connection."""
        number = next(self._ids)
        answer, done = {}, threading.Event()
        with self._lock:
            if self._closed.is_set():
                raise self._lost()
            self._waiting[number] = (answer, done)
        self._write({"op": op, "id": number, **fields})
        answered = done.wait(self.timeout)
        if not answered or not answer:
            with self._lock:
                self._waiting.pop(number, None)
            if answered or self._closed.is_set():
                raise self._lost()
            raise AgentError("agent_no_answer", app_text("agent_no_answer", self.language, where=self.where,
                                                         seconds=f"{self.timeout:g}"))
        if not answer.get("ok"):
            raise AgentError(answer.get("error", "?"), answer.get("message", "?"))
        return {key: value for key, value in answer.items() if key not in ("reply", "ok")}

    def programs(self) -> dict:
        """``{"programs": [...], "run": snapshot or None}``: the robot's library and what runs."""
        return self.request("list")

    def send(self, name: str, standalone: str, source: str = None, on_lost_editor: str = "stop",
             decide_seconds: float = 2.0) -> dict:
        """Keep a program on the robot (``standalone``: its ``rockly export --standalone`` text)."""
        return self.request("send", name=name, standalone=standalone, source=source, on_lost_editor=on_lost_editor,
                            decide_seconds=decide_seconds)["program"]

    def start(self, name: str, answers=()) -> dict:
        """Start program ``name``; returns the run's first snapshot."""
        return self.request("start", name=name, answers=list(answers))["run"]

    def stop(self) -> bool:
        """Stop the running program (the robot's safe stop runs on the robot); False when nothing ran."""
        return self.request("stop")["stopped"]

    def delete(self, name: str):
        """Remove program ``name`` from the robot."""
        self.request("delete", name=name)

    def source(self, name: str):
        """The ``.rockly`` text the robot keeps of program ``name`` (None when it came without one)."""
        return self.request("source", name=name)["source"]

    def attach(self, control: bool = True, breakpoints=()) -> dict:
        """Watch the run (and control it when ``control`` and no other client does, pausing it before the blocks
        ``breakpoints``): returns ``{"run": snapshot or None, "controller": bool, "controlled_elsewhere": bool}``;
        heartbeats start. Control that comes later (the controlling client went) is said by the event
        ``{"event": "control", "controller": true}``."""
        self._watching.set()
        try:
            answer = self.request("attach", control=control, breakpoints=list(breakpoints))
        except AgentError:
            self._watching.clear()
            raise
        self.controller = answer["controller"]
        self._attached.set()
        return answer

    def detach(self):
        """Stop watching (and controlling); the run goes on as its program's choice for a lost editor says."""
        self._attached.clear()
        self._watching.clear()
        self.request("detach")

    def control(self, what: str):
        """``pause``, ``step`` or ``continue`` the run (the controlling client only)."""
        self.request("control", what=what)

    def breakpoints(self, block_ids):
        """Pause the run before these blocks from now on (the controlling client only)."""
        self.request("breakpoints", blocks=list(block_ids))

    def robot_limits(self, wanted: dict = None) -> dict:
        """The robot's own limits (``{"max_speed", "max_turn", "switched_off"}``, as ``runtime.robot_limits``
        keeps them), after keeping ``wanted`` as them when given (a paired teacher only)."""
        fields = {} if wanted is None else {"set": wanted}
        return self.request("robot_limits", **fields)["limits"]

    def close(self):
        """Close the connection (an attached client detaches)."""
        self._closed.set()
        self._line.close()
        self._heart.join(5)

    def _lost(self) -> AgentError:
        return AgentError("agent_connection_lost", app_text("agent_connection_lost", self.language))

    def _write(self, message: dict):
        if not self._line.write(message):
            self._closed.set()

    def _beat(self):
        while not self._closed.wait(HEARTBEAT_SECONDS):
            if self._agent_beats and time.monotonic() - self._heard > AGENT_SILENT_SECONDS:
                self._line.lose()  # as if the connection had closed: ``_gone`` follows
                return
            if self._attached.is_set() or self._line.beats_always:
                self._write({"op": "heartbeat"})

    def _take(self, message: dict):
        """One message from the agent (on the transport's reader thread): an event, an answer, or ``ALIVE`` (none
        of them)."""
        self._heard = time.monotonic()
        if "event" in message:
            if message["event"] == "control":
                self.controller = bool(message.get("controller"))
            if self.on_event is not None and self._watching.is_set():
                self.on_event(message)
            return
        with self._lock:
            waiting = self._waiting.pop(message.get("reply"), None)
        if waiting is not None:
            waiting[0].update(message)
            waiting[1].set()

    def _gone(self):
        """The transport has ended (once): the calls waiting are told, then ``on_closed``."""
        self._closed.set()
        with self._lock:
            waiting, self._waiting = list(self._waiting.values()), {}
        for _, done in waiting:
            done.set()
        if self.on_closed is not None:
            self.on_closed()


def _who() -> str:
    """``user@computer`` of this client, what the agent says of whoever sent a program (said, not proven)."""
    try:
        user = getpass.getuser()
    except (KeyError, OSError):  # a user id without a name (a container)
        user = "?"
    return f"{user}@{socket.gethostname()}"

