"""``AttachedRun``: the window attached to the program that runs on the robot under its agent.

While attached, the running block glows in the editor, the Variables dock and the Console fill from the run's
events, and the run toolbar's Pause/Step/Continue/STOP act on the robot's run (``pause``, ``step``, ``resume``,
``stop``, as ``RunSession`` has them). The client's callbacks come on its reader thread; two Qt signals bring
them to the window's thread. Detaching (or closing the window, or a lost connection) never stops the run: the
program's own choice for a lost editor decides.
"""
from PySide6.QtCore import QObject, Signal

from rockly_desktop.runtime.agent.client import AgentClient, AgentError
from rockly_desktop.ui.texts import tr


class AttachedRun(QObject):
    """The window's attachment to the run on a robot (at most one at a time)."""

    sig_state_changed = Signal(str)  # 'idle' (not attached, or the run ended), 'running' or 'paused'
    _sig_event = Signal(dict)
    _sig_closed = Signal()

    def __init__(self, editor, console, variables, language, parent=None):
        super().__init__(parent)
        self.editor, self.console, self.variables = editor, console, variables
        self.language = language
        self.client = None
        self.program = None
        self.state = "idle"
        self._sig_event.connect(self._on_event)
        self._sig_closed.connect(self._on_closed)

    @property
    def active(self) -> bool:
        """True while attached to a run that has not ended."""
        return self.client is not None and self.state != "idle"

    def attach(self, host: str, port: int, via: str = "tcp") -> dict:
        """Attach to what runs on the agent at ``host``:``port`` (or over ROS: ``via``, as ``AgentClient`` has it)
        and show its state so far; returns the agent's answer. Raises ``AgentError`` (its message for people)
        when it cannot. Waits for the agent: a window calls ``reach`` off its thread and ``adopt`` on it instead."""
        self.detach()
        reached = self.reach(host, port, via)
        return self.adopt(reached, reached[0].where)

    def reach(self, host: str, port: int, via: str = "tcp") -> tuple:
        """Connect to the agent at ``host``:``port`` (or over ROS, ``via``) and attach to its run: ``(client,
        answer)`` for ``adopt``. Touches nothing of the window, so it may run on any thread. Raises
        ``AgentError`` when it cannot."""
        client = AgentClient(host, port, self.language(), on_event=self._sig_event.emit,
                             on_closed=self._sig_closed.emit, name="rockly window", via=via)
        try:
            answer = client.attach(control=True)
        except AgentError:
            client.close()
            raise
        run = answer["run"]
        if run is None or run["state"] == "ended":
            client.close()
            raise AgentError("nothing_runs", tr("attach_nothing_runs", self.language()))
        return client, answer

    def adopt(self, reached: tuple, host: str) -> dict:
        """Become attached through ``reached`` (``reach``'s answer) and show the run so far; returns the agent's
        answer."""
        self.detach()
        client, answer = reached
        run = answer["run"]
        self.client, self.program = client, run["program"]
        self.console.append(tr("attached_to", self.language(), name=self.program, host=host), "info")
        if answer["controlled_elsewhere"]:
            self.console.append(tr("robot_watch_only", self.language()), "info")
        self.console.append_lines(line for line in run["prints"] if line is not None)
        self.variables.show_values(run["variables"])
        self._highlight(run["block"])
        self._set_state(run["state"])
        return answer

    def detach(self):
        """Stop watching; the run on the robot goes on (or stops) as its program chose for a lost editor."""
        client, self.client = self.client, None
        if client is None:
            return
        try:
            client.detach()
        except AgentError:
            pass  # the connection is gone already: that detaches too
        client.close()
        self._highlight(None)
        self.console.append(tr("attach_detached", self.language()), "info")
        self._set_state("idle")

    def pause(self):
        self._control("pause")

    def step(self):
        self._control("step")

    def resume(self):
        self._control("continue")

    def stop(self):
        """STOP the run on the robot (its safe stop runs there)."""
        if self.client is not None:
            self._ask(self.client.stop)

    def _control(self, what: str):
        if self.client is not None:
            self._ask(lambda: self.client.control(what))

    def _ask(self, call):
        try:
            call()
        except AgentError as error:
            self.console.append(error.message, "error")

    def _highlight(self, block_id):
        self.editor.call("highlight", {"id": block_id})

    def _set_state(self, state: str):
        self.state = "idle" if state == "ended" else state
        self.sig_state_changed.emit(self.state)

    def _on_event(self, event: dict):
        if self.client is None:
            return
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
        elif kind == "resumed":
            self._set_state("running")
        elif kind == "finished" and event.get("message"):
            self.console.append(str(event["message"]), "error")
        elif kind == "run" and event.get("state") == "ended":
            self.console.append(tr("attached_run_ended", self.language(), name=self.program), "info")
            self.detach()

    def _on_closed(self):
        if self.client is not None:
            self.console.append(tr("attach_connection_lost", self.language()), "error")
            self.detach()
