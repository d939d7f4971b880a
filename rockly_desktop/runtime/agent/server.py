"""The agent (``rockly agent``): its library and its one run, offered to clients through its transports (TCP:
``agent.tcp_transport``; ROS 1 and 2: ``agent.ros_transport``), which all pass requests to ``Agent.answer``.

Requests (each answered; refusals say why in the client's language):

    hello    {"rockly", "format", "language", "client", "client_id"?, "proof"?}
                                                                  -> {"agent", "format", "backend", "profiles",
                                                                     "alive_seconds", "paired", "name"}
    pair     {"code", "name", "role"?}                            -> {"client", "key", "role", "agent"}
                                                                     ("role": "student" asks for less than the code)
    pairing_code {"role"?}  (a teacher)                           -> {"code", "seconds", "role"}
    list                                                          -> {"programs": [about...], "run": snapshot|null}
    send     {"name", "standalone", "source"?, "on_lost_editor"?, "decide_seconds"?} -> {"program": about}
    source   {"name"}                                             -> {"source": .rockly text|null}
    start    {"name", "answers"?}                                 -> {"run": snapshot}
    stop                                                          -> {"stopped": bool}   (any client: a STOP is
                                                                     never refused)
    delete   {"name"}                                             -> {}
    attach   {"control": bool, "breakpoints"?: [block id...]}     -> {"run", "controller", "controlled_elsewhere"}
                                                                     (the breakpoints apply once it controls)
    detach                                                        -> {}
    control  {"what": "pause"|"step"|"continue"}                  -> {}  (the controlling client only)
    breakpoints {"blocks": [block id...]}                         -> {}  (the controlling client only: the run,
                                                                     and one it starts, pause before these blocks)
    heartbeat                                                     (no answer without an "id"); the controlling
                                                                     client's say the editor is there
    robot_limits {"set"?: {"max_speed", "max_turn", "switched_off"}}  -> {"limits": {...}} (a paired teacher only:
                                                                     the robot's own limits, ``runtime.robot_limits``;
                                                                     with ``set`` they are kept first)

Before a client is paired (``client.paired``: a ``PairedClient``, set by its transport: over TCP by a ``hello``
that proves the key, ``pairings.hello_data``; over ROS by the key each line seals with) only ``hello`` and ``pair`` are
answered; anything else is refused with ``agent_not_paired``. A teacher may do everything; a student may send,
replace and delete its own programs, start its own and the teacher's, attach and watch, control a run it started,
and stop any run (``agent_teacher_only``, ``agent_not_yours``). Who may do what: docs/agent.md.

An attached client gets every event of the run as it happens (see ``agent.protocol``). One attached client
controls the run (the first that asked to); when it goes, the next attached client that asked to control takes
over and is told ``{"event": "control", "controller": true}``. The breakpoints are the controlling client's: they
are cleared when it goes (a run must not pause where nobody watches), and the next controller sends its own.
"""
import base64
import socket
import threading

from rockly_desktop import __version__
from rockly_desktop.runtime.agent.library import Library
from rockly_desktop.runtime.agent.pairings import CODE_SECONDS, ROLES, TEACHER, PairedClient, Pairings, hello_data
from rockly_desktop.runtime.agent.protocol import (
    ALIVE,
    ALIVE_SECONDS,
    FORMAT,
    AgentRefusal,
    client_before_pairing,
    older_format,
    refusal_text,
)
from rockly_desktop.runtime.agent.running import ProgramRun
from rockly_desktop.runtime.robot_limits import (
    RobotLimitsError,
    read_robot_limits,
    robot_limits_data,
    robot_limits_from_data,
    write_robot_limits,
)


class _OnTheRobot:
    """Whoever uses the robot's own UI (``robot_menu``): a person at the robot, who may start and stop any program
    as a teacher may (the robot's owner put that UI there); never a network client."""

    paired = PairedClient("on-the-robot", "the robot's own UI", TEACHER, b"", "")
    name = "the robot's own UI"
    language = "en"
    attached = wants_control = False


ON_THE_ROBOT = _OnTheRobot()
OPEN_BEFORE_PAIRING = ("hello", "pair")
TEACHER_ONLY = ("pairing_code", "robot_limits")  # pairing others, changing the robot's limits


class Agent:
    """The agent: ``library`` (a Library), programs run with ``backend`` and the child's ``options``
    (connection options, ``--speed``), for the clients paired in ``pairings``."""

    def __init__(self, library: Library, backend: str, options: list, pairings: Pairings):
        self.library = library
        self.backend = backend
        self.options = options
        self.pairings = pairings
        self.name = socket.gethostname()  # what a laptop calls this agent
        self.run = None
        self.started_by = None  # the id of the client that started the run
        self._pairings_version = None  # of the paired clients, when revoked ones were last looked for
        self.controller = None
        self.breakpoints = []  # the controlling client's: a run started while it is attached pauses there too
        self.clients = []
        self.listeners = []  # called (no arguments) when the library changes or a run starts or ends
        self.robot_limits_path = None  # the robot's own limits file (None: ``robot_limits.default_path()``)
        self.source_checks = None  # agent.source_match's SourceChecks: whether a kept program's code is its blocks'
        self._lock = threading.RLock()

    # -- requests

    def handle(self, client, request: dict) -> dict:
        """The answer to one ``request`` from ``client`` (without its ``reply`` id); refusals raise AgentRefusal."""
        op = request.get("op")
        if op not in OPEN_BEFORE_PAIRING:
            paired = self._still_paired(client)
            if paired is None:
                raise AgentRefusal("agent_not_paired")
            if op in TEACHER_ONLY and paired.role != TEACHER:
                raise AgentRefusal("agent_teacher_only")
        handler = getattr(self, "_op_" + op, None) if isinstance(op, str) and op.isidentifier() else None
        if handler is None:
            raise AgentRefusal("agent_unknown_request", op=str(op)[:40])
        return handler(client, request)

    def _op_hello(self, client, request):
        client.language = request.get("language") if request.get("language") in ("en", "de") else "en"
        client.name = str(request.get("client", "?"))[:80]
        if older_format(request.get("format")):
            raise client_before_pairing(request.get("rockly", "?"))
        if request.get("format") != FORMAT:
            raise AgentRefusal("agent_other_format", agent=__version__, client=request.get("rockly", "?"))
        nonce, client_id = getattr(client, "nonce", None), request.get("client_id")
        if nonce is not None and isinstance(client_id, str):  # TCP: a hello proves the key over the connection's
            # nonce (ROS: every message proves itself); a hello naming no client changes nothing
            client.paired = self.pairings.verify(client_id, request.get("proof"), hello_data(nonce, client_id))
        paired = client.paired
        return {"agent": __version__, "format": FORMAT, "backend": self.backend,
                "profiles": {p.id: p.version for p in self.library.profiles.values()}, "alive_seconds": ALIVE_SECONDS,
                "name": self.name, "paired": None if paired is None else {"client": paired.id, "role": paired.role}}

    def _op_pair(self, client, request):
        name = request.get("name")
        paired = self.pairings.pair(request.get("code"), name if isinstance(name, str) and name else client.name,
                                    request.get("role"))
        client.paired = paired
        return {"client": paired.id, "key": base64.b64encode(paired.key).decode("ascii"), "role": paired.role,
                "agent": self.name}

    def _op_pairing_code(self, client, request):
        role = request.get("role")
        if role is not None and role not in ROLES:
            raise AgentRefusal("agent_bad_request")
        code = self.pairings.new_code(role)
        return {"code": code.shown, "seconds": int(CODE_SECONDS), "role": code.role}

    def _op_list(self, client, request):
        return {"programs": self.library.entries(), "run": self._snapshot()}

    def _op_send(self, client, request):
        name = request.get("name")
        # checked before the lock (the text is read in a child process): a STOP or another client never waits for it
        checked = self.library.check(name, _text(request.get("standalone")), request.get("source"),
                                     request.get("on_lost_editor", "stop"), request.get("decide_seconds", 2.0))
        with self._lock:
            if self.run is not None and self.run.about["name"] == name:
                raise AgentRefusal("agent_program_running", name=name)
            self._may_change(client, name)
            about = self.library.store(checked, client.name, {"client": client.paired.id, "role": client.paired.role})
        if self.source_checks is not None:
            self.source_checks.check_later(about)
        self.changed()
        return {"program": about}

    def _op_source(self, client, request):
        return {"source": self.library.source(request.get("name"))}

    def _op_start(self, client, request):
        name = request.get("name")
        answers = [str(answer) for answer in request.get("answers") or []]
        with self._lock:
            if self.run is not None:
                raise AgentRefusal("agent_busy", name=self.run.about["name"])
            about = self.library.about(name)
            if not self._is_teacher(client) and _owner(about) not in (client.paired.id, TEACHER):
                raise AgentRefusal("agent_not_yours", name=name)
            path = self.library.standalone_path(name)
            options = ["--backend", self.backend, *self.options, "--any-profile-version"]
            for answer in answers:
                options += ["--answer", answer]
            self.run = ProgramRun(about, path, options, self.publish, self._ended, self.breakpoints)
            self.started_by = client.paired.id
            if self.controller is not None and not self._may_control(self.controller):
                self._hand_control_on()
            self.publish({"event": "run", "state": "started", "program": name})
            self.changed()
            return {"run": self.run.snapshot()}

    def _op_stop(self, client, request):
        run = self.run
        if run is None:
            return {"stopped": False}
        run.request("stop")
        return {"stopped": True}

    def _op_delete(self, client, request):
        name = request.get("name")
        with self._lock:
            if self.run is not None and self.run.about["name"] == name:
                raise AgentRefusal("agent_program_running", name=name)
            self._may_change(client, name)
            self.library.delete(name)
        self.changed()
        return {}

    def _op_attach(self, client, request):
        breakpoints = _block_ids(request.get("breakpoints", []))
        with self._lock:
            client.attached = True
            client.wants_control = bool(request.get("control", True))
            if client.wants_control and self.controller is None and self._may_control(client):
                self.controller = client
            if self.controller is client:
                self._set_breakpoints(breakpoints)
            if self.run is not None and self.controller is client:
                self.run.heartbeat()
            return {"run": self._snapshot(), "controller": self.controller is client,
                    "controlled_elsewhere": self.controller is not None and self.controller is not client}

    def _op_detach(self, client, request):
        self._forget(client)
        return {}

    def _op_control(self, client, request):
        what = request.get("what")
        if what not in ("pause", "step", "continue"):
            raise AgentRefusal("agent_unknown_request", op=str(what)[:40])
        run = self.run
        if run is None:
            raise AgentRefusal("agent_nothing_running")
        if not self._may_control(client):
            raise AgentRefusal("agent_not_yours", name=run.about["name"])
        if self.controller is not client:
            raise AgentRefusal("agent_not_controller")
        run.request(what)
        return {}

    def _op_breakpoints(self, client, request):
        blocks = _block_ids(request.get("blocks"))
        with self._lock:
            if not self._may_control(client):
                raise AgentRefusal("agent_not_yours", name=self.run.about["name"] if self.run else "?")
            if self.controller is not client:
                raise AgentRefusal("agent_not_controller")
            self._set_breakpoints(blocks)
        return {}

    def _set_breakpoints(self, blocks: list):
        self.breakpoints = list(blocks)
        if self.run is not None and self.run.breakpoints != self.breakpoints:
            self.run.set_breakpoints(self.breakpoints)

    def _op_heartbeat(self, client, request):
        run = self.run
        if client is self.controller and run is not None:  # the editor is the controlling client; watchers are not
            run.heartbeat()
        return {}

    def _op_robot_limits(self, client, request):
        wanted = request.get("set")
        try:
            if wanted is not None:
                try:
                    limits = robot_limits_from_data(wanted, "set")
                except RobotLimitsError:
                    raise AgentRefusal("agent_bad_request") from None
                write_robot_limits(limits, self.robot_limits_path)
            return {"limits": robot_limits_data(read_robot_limits(self.robot_limits_path))}
        except RobotLimitsError as error:  # the file on the robot is broken: said as the robot says it
            raise AgentRefusal(error.text.key, **error.text.values) from None
        except OSError as error:
            raise AgentRefusal("agent_limits_cannot_write", reason=error.strerror or str(error)) from None

    # -- who may do what

    def _still_paired(self, client):
        """``client``'s pairing, None when it has none or it was revoked since (``rockly agent revoke``)."""
        if client.paired is not None and client is not ON_THE_ROBOT:
            client.paired = self.pairings.find(client.paired.id)
        return client.paired

    @staticmethod
    def _is_teacher(client) -> bool:
        return client.paired is not None and client.paired.role == TEACHER

    def _may_change(self, client, name: str):
        """Refuse a student replacing or deleting program ``name`` that it did not send."""
        if self._is_teacher(client):
            return
        try:
            about = self.library.about(name)
        except AgentRefusal:
            return  # a new name
        if _owner(about) != client.paired.id:
            raise AgentRefusal("agent_not_yours", name=name)

    def _may_control(self, client) -> bool:
        """A teacher controls any run, a student only one it started (or whatever it starts next)."""
        return self._is_teacher(client) or self.run is None or (
            client.paired is not None and self.started_by == client.paired.id)

    def check_pairings(self):
        """Close the connections of clients revoked since the last look (call it now and then: the alive beat)."""
        version = self.pairings.version()
        if version == self._pairings_version:
            return
        self._pairings_version = version
        for client in list(self.clients):
            if client.paired is not None and self._still_paired(client) is None:
                self._forget(client)
                client.cut()

    # -- events and clients

    def publish(self, record: dict):
        """Give ``record`` to every attached client (a client that cannot take it is dropped). Clients that share
        an outlet (``client.deliver``: the ROS 1 transport's one events topic) get it through it once."""
        delivered = {}
        for client in [client for client in list(self.clients) if client.attached]:
            outlet = client.deliver
            if outlet not in delivered:
                delivered[outlet] = outlet(record)
            if not delivered[outlet]:
                self._forget(client)

    def say_alive(self):
        """Tell every client the agent is there (``agent.protocol``'s ``ALIVE``; call it every ``ALIVE_SECONDS``),
        once per outlet; a client that cannot take it is left to its transport."""
        said = set()
        for client in list(self.clients):
            if client.deliver not in said:
                said.add(client.deliver)
                client.deliver(ALIVE)

    def _snapshot(self):
        run = self.run
        return run.snapshot() if run is not None else None

    def _ended(self, run):
        with self._lock:
            if self.run is run:
                self.run = None
                self.started_by = None
        self.changed()

    def changed(self):
        """Tell the listeners the library, the run or a program's check changed."""
        for listener in list(self.listeners):
            listener()

    def _forget(self, client):
        with self._lock:
            client.attached = False
            if self.controller is not client:
                return
            self._hand_control_on()

    def _hand_control_on(self):
        """(holding the lock) Control passes to the next attached client that asked for it and may have it; it is
        told."""
        self.controller = next((other for other in self.clients if other.attached and other.wants_control
                                and other is not self.controller and self._may_control(other)), None)
        self._set_breakpoints([])  # the next controller sends its own
        if self.controller is not None:
            self.controller.send({"event": "control", "controller": True})

    def join(self, client):
        """A transport's new ``client`` (``language``, ``name``, ``attached``, ``wants_control``, ``paired``,
        ``send(message)``, ``deliver(event)``, ``cut()``: end it, revoked; over TCP ``nonce``)."""
        with self._lock:
            self.clients.append(client)

    def leave(self, client):
        """``client`` is gone (its connection closed, or it fell silent): it neither watches nor controls."""
        self._forget(client)
        with self._lock:
            if client in self.clients:
                self.clients.remove(client)

    def answer(self, client, request: dict):
        """The message that answers ``request`` from ``client``: None for a request without an ``id`` that
        succeeded (a heartbeat)."""
        try:
            answer = {"ok": True, **self.handle(client, request)}
        except AgentRefusal as refusal:
            answer = {"ok": False, "error": refusal.key, "message": refusal_text(refusal, client.language)}
        except (TypeError, ValueError, AttributeError, KeyError, IndexError, RecursionError):
            # a field of the wrong kind (a list for a name, a number for answers): no request Rockly sends
            refusal = AgentRefusal("agent_bad_request")
            answer = {"ok": False, "error": refusal.key, "message": refusal_text(refusal, client.language)}
        if "id" not in request:
            return None if answer["ok"] else {"reply": None, **answer}
        return {"reply": request["id"], **answer}

    def shut_down(self):
        """Stop a running program (its safe stop runs) and wait for it."""
        run = self.run
        if run is not None:
            run.end()
        if self.source_checks is not None:
            self.source_checks.close()


def _owner(about: dict) -> str:
    """The id of the client that sent a kept program; ``TEACHER`` for a teacher's, and for one kept before
    pairing existed (put there by whoever ran the robot)."""
    owner = about.get("owner") or {}
    return TEACHER if owner.get("role", TEACHER) == TEACHER else owner.get("client")


def _block_ids(value) -> list:
    """The block ids of a request's breakpoints; refused when they are not a list of texts."""
    if not isinstance(value, list) or not all(isinstance(block, str) for block in value):
        raise AgentRefusal("agent_bad_request")
    return value


def _text(value) -> str:
    if not isinstance(value, str):
        raise AgentRefusal("agent_not_standalone")
    return value
