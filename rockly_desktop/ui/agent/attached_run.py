"""``AttachedRun``: the window attached to the program that runs on the robot under its agent.

While attached, the running block glows in the editor, the Variables dock and the Console fill from the run's
events, the window's breakpoints apply to the run (sent on attaching and whenever they change), and the run
toolbar's Pause/Step/Continue/STOP act on the robot's run (``pause``, ``step``, ``resume``, ``stop``, as
``RunSession`` has them). What the window sees is recorded (``attached_recording``) and given to the replay when
it detaches. Nothing here waits for the agent on the window's thread: attaching and every request go through
``AgentCalls``. The client's callbacks come on its reader thread; two Qt signals bring them to the window's
thread. Detaching (or closing the window, or a lost connection) never stops the run: the program's own choice for
a lost editor decides.

Two windows may attach at once: the first controls the run, the other watches and is told so; a watching
window's Pause, Step and Continue are off, but its STOP stops the robot (a STOP is a safety control: the agent
never refuses one). When the controlling window goes, a watching one takes control and is told.
"""
import threading

from PySide6.QtCore import QObject, Signal

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.ui.agent.agent_calls import AgentCalls
from rockly_desktop.ui.texts import tr

ATTACH_TIMEOUT = 5.0  # seconds the agent has to answer a request of the attached window


class AttachedRun(QObject):
    """The window's attachment to the run on a robot (at most one at a time). ``breakpoints()``: the window's
    breakpoints now; ``record(snapshot)``: an ``AttachedRecording`` of the run (None: not recorded)."""

    sig_state_changed = Signal(str)  # 'idle' (not attached, or the run ended), 'running' or 'paused'
    sig_control_changed = Signal(bool)  # whether this window controls the run (False: it watches)
    sig_attached = Signal(str)  # attached to the run of this program
    sig_attach_failed = Signal(str)  # why attaching failed, for people
    sig_status = Signal(str)  # a status-bar message; empty: clear it
    sig_recorded = Signal(str)  # the path of what the window saw of the run, once finished
    _sig_event = Signal(dict)
    _sig_closed = Signal()

    def __init__(self, editor, console, variables, language, parent=None, breakpoints=lambda: (), record=None):
        super().__init__(parent)
        self.editor, self.console, self.variables = editor, console, variables
        self.language = language
        self.client = None
        self.program = None
        self.controller = False
        self.state = "idle"
        self.recording = None
        self.calls = AgentCalls(self)
        self._breakpoints = breakpoints
        self._record = record
        self._sig_event.connect(self._on_event)
        self._sig_closed.connect(self._on_closed)

    @property
    def active(self) -> bool:
        """True while attached to a run that has not ended."""
        return self.client is not None and self.state != "idle"

    def attach(self, host: str, port: int, then=None, via: str = "tcp", graph_kind: str = None):
        """Attach to what runs on the agent at ``host``:``port`` (or over ROS: ``via``, as ``AgentClient`` has it),
        off the window's thread: returns at once. Once the
        agent has answered (within ``ATTACH_TIMEOUT``), the run so far is shown and ``sig_attached`` said, or
        ``sig_attach_failed`` says why not; ``then(error)`` follows on the window's thread (``error``: None or the
        ``AgentError``). A later ``attach`` or ``detach`` drops this one."""
        self.detach()
        self.calls.forget()  # an attach still on its way is dropped (its connection closed)
        breakpoints, language = list(self._breakpoints()), self.language()

        def reached(answer, error):
            if error is None:
                self._adopt(answer, answer[0].where)
            else:
                self.sig_attach_failed.emit(error.message)
            if then is not None:
                then(error)

        self.calls.run(lambda: self._reach(host, port, breakpoints, language, via, graph_kind), reached,
                       unused=lambda answer: answer[0].close())

    def _reach(self, host: str, port: int, breakpoints: list, language: str, via: str, graph_kind: str) -> tuple:
        """Connect and attach (on a call's thread): ``(client, answer)``; raises ``AgentError`` when it cannot."""
        client = AgentClient(host, port, language, on_event=self._sig_event.emit, on_closed=self._sig_closed.emit,
                             name="rockly window", timeout=ATTACH_TIMEOUT, via=via,
                             graph_kind=graph_kind)
        try:
            answer = client.attach(control=True, breakpoints=breakpoints)
        except AgentError:
            client.close()
            raise
        run = answer["run"]
        if run is None or run["state"] == "ended":
            client.close()
            raise AgentError("nothing_runs", tr("attach_nothing_runs", language))
        return client, answer

    def _adopt(self, reached: tuple, where: str):
        """Become attached through ``reached`` and show the run so far."""
        self.detach()
        client, answer = reached
        run = answer["run"]
        self.client, self.program, self.controller = client, run["program"], client.controller
        self.recording = self._record(run) if self._record is not None else None  # first: it closes a replay
        self.console.append(tr("attached_to", self.language(), name=self.program, host=where), "info")
        if not self.controller:
            self.console.append(tr("attach_watching", self.language()), "info")
        self.console.append_lines(line for line in run["prints"] if line is not None)
        self.variables.show_values(run["variables"])
        self._highlight(run["block"])
        self._set_state(run["state"])
        self.sig_control_changed.emit(self.controller)
        self.sig_attached.emit(self.program)

    def detach(self, ended: bool = False):
        """Stop watching; the run on the robot goes on (or stops) as its program chose for a lost editor. What the
        window saw goes to ``sig_recorded``. ``ended``: the run ended (or its connection was lost) and the Console
        said so already: nothing is said of it going on."""
        self.calls.forget()
        client, self.client = self.client, None
        if client is None:
            return
        client.on_event = client.on_closed = None
        if self.calls.busy:  # a STOP (or another request) on its way is sent before the connection closes
            threading.Thread(target=self._close_after_calls, args=(client,), daemon=True, name="agent-detach").start()
        else:
            client.close()  # the agent takes a closed connection as a detach (no answer to wait for)
        self._highlight(None)
        if not ended:
            self.console.append(tr("attach_detached", self.language()), "info")
        self.sig_status.emit("")  # a pause it said is no longer this window's to say
        self.controller = False
        self._set_state("idle")
        recording, self.recording = self.recording, None
        if recording is not None:
            recording.close()
            self.sig_recorded.emit(str(recording.path))

    def _close_after_calls(self, client):
        self.calls.wait(ATTACH_TIMEOUT)
        client.close()

    def set_breakpoints(self, block_ids):
        """The window's breakpoints changed: the run on the robot pauses before these blocks from now on."""
        if self.client is not None and self.controller:
            client, blocks = self.client, list(block_ids)
            self._ask(lambda: client.breakpoints(blocks))

    def pause(self):
        self._control("pause")

    def step(self):
        self._control("step")

    def resume(self):
        self._control("continue")

    def stop(self):
        """STOP the run on the robot (its safe stop runs there), from a controlling or a watching window alike."""
        if self.client is not None:
            self._ask(self.client.stop)

    def _control(self, what: str):
        if self.client is not None:
            client = self.client
            self._ask(lambda: client.control(what))

    def _ask(self, call):
        """``call()`` off the window's thread; a refusal is said in the Console."""
        self.calls.run(call, lambda _answer, error: error is not None and self.console.append(error.message, "error"))

    def _highlight(self, block_id):
        self.editor.call("highlight", {"id": block_id})

    def _set_state(self, state: str):
        self.state = "idle" if state == "ended" else state
        self.sig_state_changed.emit(self.state)

    def _on_event(self, event: dict):
        if self.client is None:
            return
        if self.recording is not None:
            self.recording.take(event)
        kind = event.get("event")
        if kind == "block":
            self._highlight(event.get("id"))
        elif kind == "print" and event.get("text") is not None:
            self.console.append(str(event["text"]))
        elif kind == "variables":
            self.variables.show_values(event.get("values") or {})
        elif kind == "paused":
            self._highlight(event.get("block"))
            self._set_state("paused")
            key = "paused_breakpoint" if event.get("reason") == "breakpoint" else "paused"
            self.sig_status.emit(tr(key, self.language()))
        elif kind == "resumed":
            self._set_state("running")
            self.sig_status.emit("")
        elif kind == "finished" and event.get("message"):
            self.console.append(str(event["message"]), "error")
        elif kind == "control" and event.get("controller"):
            self._take_control()
        elif kind == "run" and event.get("state") == "ended":
            self.console.append(tr("attached_run_ended", self.language(), name=self.program), "info")
            self.detach(ended=True)

    def _take_control(self):
        """The window that controlled the run has gone: this one controls it now, with its own breakpoints."""
        self.controller = True
        self.console.append(tr("attach_now_controlling", self.language()), "info")
        self.set_breakpoints(self._breakpoints())
        self.sig_control_changed.emit(True)

    def _on_closed(self):
        if self.client is not None:
            self.console.append(tr("attach_connection_lost", self.language()), "error")
            self.detach(ended=True)
