"""``AgentBar``: in the status bar, what the chosen robot's agent runs now ("On the robot: square — running"), with
one click to attach. The agent is asked off the window's thread (``AgentCalls``, at most ``LOOK_TIMEOUT`` a look)
when the robot is chosen and every ``LOOK_MS`` while the window is not attached; when no agent answers (none
there, none reachable, nothing running) the bar shows nothing, and the window never waits for it. A robot over
ROS has its agent asked as the Programs dialog asks it (``AgentWay``): over ROS when the window's own node or
helper is on the robot's graph and an agent is in it (one look at the graph; no node or helper is started for a
look), else over TCP; Attach goes the way the look went."""
from typing import NamedTuple

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QHBoxLayout, QLabel, QPushButton, QWidget

from rockly_desktop.runtime.agent.client import AgentClient, chosen_via
from rockly_desktop.runtime.agent.protocol import DEFAULT_PORT
from rockly_desktop.runtime.agent.ros_transport import agent_host
from rockly_desktop.ui.agent.agent_calls import AgentCalls
from rockly_desktop.ui.texts import tr

LOOK_MS = 3000
LOOK_TIMEOUT = 2.0  # seconds an agent has to take the connection and answer a look


def agent_address(kind: str, connection: dict, remembered: str):
    """``(host, port)`` of the chosen robot's agent, or None when nowhere is known. ``kind``: the robot link's kind,
    ``connection``: its connection settings, ``remembered``: ``host:port`` where the Programs dialog last reached an
    agent. A robot whose registry entry names ``agent_beside`` (ROS 1: its master) has its agent on that setting's
    host (at the remembered port); any other robot's agent is where the dialog last reached one."""
    host, _, port = (remembered or "").rpartition(":")
    port = int(port) if port.isdigit() else DEFAULT_PORT
    host = agent_host(kind, connection) or host
    return (host, port) if host else None


class AgentWay(NamedTuple):
    """How the chosen robot's agent is asked: at ``host``:``port`` over TCP (``host`` None: no address known, so
    not over TCP) and, with ``via`` "auto", first over ROS on the graph of the robot link ``graph_kind``."""

    host: str | None
    port: int
    via: str = "tcp"
    graph_kind: str | None = None


def _ask_run(way: AgentWay, language: str) -> tuple:
    """``(the way the agent answered: "tcp" or "ros", what it runs)``; ``(None, None)`` when there is no way to
    try. Raises AgentError when the agent cannot be reached."""
    via = way.via
    if way.host is None:  # only the robot's graph is known: a look that finds no agent there tries no TCP
        via = chosen_via(via, graph_kind=way.graph_kind)[0]
        if via == "tcp":
            return None, None
    client = AgentClient(way.host or "", way.port, language, name="rockly window", timeout=LOOK_TIMEOUT, via=via,
                         graph_kind=way.graph_kind)
    try:
        return client.via, client.programs()["run"]
    finally:
        client.close()


class AgentBar(QWidget):
    """Says what the agent that ``way()`` names (an ``AgentWay``; None: no robot with an agent is chosen) runs; its
    Attach button attaches ``attached`` (the window's ``AttachedRun``) once ``gate(command)`` runs the command (a
    kiosk asks for the teacher's PIN first). ``language()``: the window's, now."""

    def __init__(self, attached, language, way, parent=None, gate=lambda command: command()):
        super().__init__(parent)
        self.setObjectName("agent_bar")
        self.attached, self._language, self._way = attached, language, way
        self.shown_at = None  # the way whose run is shown, and the transport it answered on
        self.label = QLabel(self)
        self.attach_button = QPushButton(self)
        self.attach_button.setObjectName("agent_bar_attach")
        self.attach_button.clicked.connect(lambda: gate(self.attach))
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.label)
        layout.addWidget(self.attach_button)
        self.calls = AgentCalls(self)
        self._timer = QTimer(self)
        self._timer.setInterval(LOOK_MS)
        self._timer.timeout.connect(self.look)
        attached.sig_state_changed.connect(lambda _state: self.look())
        self.hide()

    def start(self):
        """Look now and every ``LOOK_MS``."""
        self._timer.start()
        self.look()

    def stop(self):
        """Look no more (the window is closing); an answer on its way is dropped."""
        self._timer.stop()
        self.calls.forget()

    def look(self):
        """Ask the chosen robot's agent what runs there (unless an answer is on its way, or the window is attached)."""
        way = self._way()
        if way is None or self.attached.active or self.attached.calls.busy:
            self._show(None, None, None)
            return
        if self.calls.busy:
            return
        language = self._language()
        self.calls.run(lambda: _ask_run(way, language),
                       lambda answer, error: self._show(way, *((None, None) if error is not None else answer)))

    def _show(self, way, via, run):
        runs = bool(run) and run["state"] != "ended" and way == self._way() and not self.attached.active
        self.shown_at = (way, via) if runs else None
        if runs:
            language = self._language()
            self.label.setText(tr("agent_bar_running", language, name=run["program"],
                                  state=tr("robot_programs_state_" + run["state"], language)))
            self.attach_button.setText(tr("agent_bar_attach", language))
            self.attach_button.setEnabled(True)
        self.setVisible(runs)

    def attach(self):
        """Attach the window to the run shown."""
        if self.shown_at is None:
            return
        self.attach_button.setEnabled(False)
        way, via = self.shown_at
        self.attached.attach(way.host or "", way.port, self._attached, via, way.graph_kind)

    def _attached(self, error):
        if error is not None:
            self.label.setText(error.message)
            self.attach_button.setEnabled(True)
