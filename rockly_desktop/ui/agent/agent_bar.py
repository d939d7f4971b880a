"""``AgentBar``: in the status bar, what the chosen robot's agent runs now ("On the robot: square — running"), with
one click to attach. The agent is asked off the window's thread (``AgentCalls``, at most ``LOOK_TIMEOUT`` a look)
when the robot is chosen and every ``LOOK_MS`` while the window is not attached; when no agent answers (none
there, none reachable, nothing running) the bar shows nothing, and the window never waits for it."""
from urllib.parse import urlsplit

from PySide6.QtCore import QTimer
from PySide6.QtWidgets import QHBoxLayout, QLabel, QPushButton, QWidget

from rockly_desktop.runtime.agent.client import AgentClient
from rockly_desktop.runtime.agent.protocol import DEFAULT_PORT
from rockly_desktop.ui.agent.agent_calls import AgentCalls
from rockly_desktop.ui.texts import tr

LOOK_MS = 3000
LOOK_TIMEOUT = 2.0  # seconds an agent has to take the connection and answer a look


def agent_address(kind: str, connection: dict, remembered: str):
    """``(host, port)`` of the chosen robot's agent, or None when nowhere is known. ``kind``: the robot link's kind,
    ``connection``: its connection settings, ``remembered``: ``host:port`` where the Programs dialog last reached an
    agent. A robot over ROS 1 has its agent beside its master (at the remembered port); any other robot's agent is
    where the dialog last reached one."""
    host, _, port = (remembered or "").rpartition(":")
    port = int(port) if port.isdigit() else DEFAULT_PORT
    if kind == "ros1":
        host = urlsplit(connection.get("master") or "").hostname or host
    return (host, port) if host else None


class AgentBar(QWidget):
    """Says what the agent at ``address()`` (``agent_address``; None: no robot with an agent is chosen) runs; its
    Attach button attaches ``attached`` (the window's ``AttachedRun``). ``language()``: the window's, now."""

    def __init__(self, attached, language, address, parent=None):
        super().__init__(parent)
        self.setObjectName("agent_bar")
        self.attached, self._language, self._address = attached, language, address
        self.shown_at = None  # the address whose run is shown
        self.label = QLabel(self)
        self.attach_button = QPushButton(self)
        self.attach_button.setObjectName("agent_bar_attach")
        self.attach_button.clicked.connect(self.attach)
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
        address = self._address()
        if address is None or self.attached.active or self.attached.calls.busy:
            self._show(None, None)
            return
        if self.calls.busy:
            return
        host, port, language = *address, self._language()

        def ask():
            client = AgentClient(host, port, language, name="rockly window", timeout=LOOK_TIMEOUT)
            try:
                return client.programs()["run"]
            finally:
                client.close()

        self.calls.run(ask, lambda run, error: self._show(address, None if error is not None else run))

    def _show(self, address, run):
        runs = bool(run) and run["state"] != "ended" and address == self._address() and not self.attached.active
        self.shown_at = address if runs else None
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
        self.attached.attach(*self.shown_at, self._attached)

    def _attached(self, error):
        if error is not None:
            self.label.setText(error.message)
            self.attach_button.setEnabled(True)
