"""``AgentClient``: a Qt-free client of the robot's agent, for ``rockly robot ...`` and the window alike.

    client = AgentClient("robot.local", language="de", on_event=print)   # connects and says hello
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
and calls ``on_closed``; an agent that does not answer within ``timeout`` ends the call with
``AgentError("agent_no_answer")``.
"""
import itertools
import socket
import threading

from rockly_desktop import __version__
from rockly_desktop.core.app_texts import app_text
from rockly_desktop.runtime.agent.protocol import DEFAULT_PORT, FORMAT, HEARTBEAT_SECONDS, decode, encode


class AgentError(Exception):
    """The agent refused a request, or could not be reached: ``key`` and a ``message`` for people."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        self.key = key
        self.message = message


class AgentClient:
    """A connection to the agent at ``host``:``port``."""

    def __init__(self, host: str = "localhost", port: int = DEFAULT_PORT, language: str = "en",
                 on_event=None, on_closed=None, name: str = "rockly", timeout: float = 10.0):
        self.language = language
        self.on_event = on_event
        self.on_closed = on_closed
        self.timeout = timeout
        self.address = (host, port)
        self.controller = False
        self._ids = itertools.count(1)
        self._waiting = {}
        self._lock = threading.Lock()
        self._send_lock = threading.Lock()
        self._closed = threading.Event()
        self._attached = threading.Event()
        try:
            self._socket = socket.create_connection((host, port), timeout)
        except OSError as error:
            raise AgentError("agent_unreachable", app_text("agent_unreachable", language, host=host, port=port,
                                                           reason=error.strerror or str(error))) from None
        self._socket.settimeout(None)
        self._socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._reader = threading.Thread(target=self._read, daemon=True, name="agent-client")
        self._reader.start()
        self._heart = threading.Thread(target=self._beat, daemon=True, name="agent-heartbeat")
        self._heart.start()
        try:
            self.hello = self.request("hello", rockly=__version__, format=FORMAT, language=language, client=name)
        except AgentError:
            self.on_event = self.on_closed = None  # nobody was told of a client that never was
            self.close()  # an agent that never answers (or refuses) keeps no socket or thread of this client
            raise

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
            raise AgentError("agent_no_answer", app_text("agent_no_answer", self.language, host=self.address[0],
                                                         port=self.address[1], seconds=f"{self.timeout:g}"))
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
        answer = self.request("attach", control=control, breakpoints=list(breakpoints))
        self.controller = answer["controller"]
        self._attached.set()
        return answer

    def detach(self):
        """Stop watching (and controlling); the run goes on as its program's choice for a lost editor says."""
        self._attached.clear()
        self.request("detach")

    def control(self, what: str):
        """``pause``, ``step`` or ``continue`` the run (the controlling client only)."""
        self.request("control", what=what)

    def breakpoints(self, block_ids):
        """Pause the run before these blocks from now on (the controlling client only)."""
        self.request("breakpoints", blocks=list(block_ids))

    def close(self):
        """Close the connection (an attached client detaches)."""
        self._closed.set()
        try:
            self._socket.shutdown(socket.SHUT_RDWR)
        except OSError:
            pass
        self._socket.close()
        self._reader.join(5)
        self._heart.join(5)

    def _lost(self) -> AgentError:
        return AgentError("agent_connection_lost", app_text("agent_connection_lost", self.language))

    def _write(self, message: dict):
        try:
            with self._send_lock:
                self._socket.sendall(encode(message))
        except OSError:
            self._closed.set()

    def _beat(self):
        while not self._closed.wait(HEARTBEAT_SECONDS):
            if self._attached.is_set():
                self._write({"op": "heartbeat"})

    def _read(self):
        try:
            for line in self._socket.makefile("rb"):
                message = decode(line)
                if message is None:
                    continue
                if "event" in message:
                    if message["event"] == "control":
                        self.controller = bool(message.get("controller"))
                    if self.on_event is not None:
                        self.on_event(message)
                    continue
                with self._lock:
                    waiting = self._waiting.pop(message.get("reply"), None)
                if waiting is not None:
                    waiting[0].update(message)
                    waiting[1].set()
        except (OSError, ValueError):
            pass
        self._closed.set()
        with self._lock:
            waiting, self._waiting = list(self._waiting.values()), {}
        for _, done in waiting:
            done.set()
        if self.on_closed is not None:
            self.on_closed()
