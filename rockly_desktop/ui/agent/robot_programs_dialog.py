"""Robot → "Programs on the robot…": the agent's address, the programs it keeps and what it runs now, with
Send (the open program, exported standalone as ``rockly export --standalone`` does), Start, Stop and Attach
(``AttachedRun``); once attached, whether the robot's program is the one open here; and, at a click, how to put
the agent on a robot; for the program chosen, whether its code is what its blocks make (the agent checks it).
While it is open the agent is asked again each second, so what it says stays true. A robot
this laptop is not paired with (or no longer: a revoked key, another certificate) is paired there
(``PairingPanel``)."""
import tempfile
from pathlib import Path

from PySide6.QtCore import Qt, QTimer
from PySide6.QtWidgets import (
    QCheckBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QInputDialog,
    QLabel,
    QLineEdit,
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QSpinBox,
    QStyle,
    QVBoxLayout,
)

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.program import Program, write_text_atomically
from rockly_desktop.core.workspace_blocks import block_types_by_id
from rockly_desktop.runtime.agent.client import AgentClient, AgentError, chosen_via
from rockly_desktop.runtime.agent.commands import code_state_text
from rockly_desktop.runtime.agent.protocol import DEFAULT_NAMESPACE, DEFAULT_PORT
from rockly_desktop.runtime.agent.robot_keys import RobotKeys, ros_address, tcp_address
from rockly_desktop.runtime.standalone_file import standalone_text
from rockly_desktop.ui.agent.agent_calls import AgentCalls
from rockly_desktop.ui.agent.pairing_panel import PAIRING_NEEDED, PairingPanel
from rockly_desktop.ui.agent.program_difference import same_program
from rockly_desktop.ui.texts import tr

POLL_MS = 1000  # the agent is asked again this often while the dialog is open


class RobotProgramsDialog(QDialog):
    """The programs on a robot's agent; ``attached``: the window's ``AttachedRun``. Every answer from the agent
    (or why it cannot be reached) is said in ``status``; ``open_copy(path, name)`` opens the robot's copy of
    its program (as an untitled copy) when it differs from the window's; ``reached(host, port)``: an agent answered
    there; Send sends the window's program
    (``document``: its file and profile) under ``limits()``, the teacher's limits in force. The agent is asked
    off the window's thread (``calls``): while an answer is on its way, ``status`` says so and the buttons that
    would ask again wait; answers that come after the dialog was closed are dropped. ``via`` is how the agent
    is reached (``AgentClient``'s: ``auto`` for a ROS robot: over ROS when its agent is in the graph of
    ``graph_kind``, the chosen robot's link kind). ``pair_as_student``: this laptop pairs as a student whatever
    the code says (a kiosk)."""

    def __init__(self, attached, language: str, parent=None, host: str = "localhost", port: int = DEFAULT_PORT,
                 open_copy=None, document=None, limits=None, reached=None, via: str = "tcp",
                 graph_kind: str = None, pair_as_student: bool = False):
        super().__init__(parent)
        self.via, self.graph_kind = via, graph_kind
        self.attached, self.language, self._open_copy = attached, language, open_copy
        self.document, self._limits, self._reached = document, limits, reached
        self._robot_source = None
        self._where = host  # where the window attached (the agent's host, or its ROS master and namespace)
        self.calls = AgentCalls(self)
        self._generation = 0  # of the dialog's showing: answers to an earlier one are dropped
        self._enabled_before = None  # the asking buttons' states while an answer is on its way
        self._runs = False  # whether the agent said a program runs
        self._copies = tempfile.TemporaryDirectory(prefix="rockly-robot-copy-")
        self.setWindowTitle(tr("robot_programs_title", language))
        self.host = QLineEdit(host)
        self.port = QSpinBox()
        self.port.setRange(1, 65535)
        self.port.setValue(port)
        self.refresh_button = QPushButton(tr("robot_programs_refresh", language))
        address = QHBoxLayout()
        address.addWidget(self.host, 1)
        address.addWidget(QLabel(tr("robot_programs_port", language)))
        address.addWidget(self.port)
        address.addWidget(self.refresh_button)
        form = QFormLayout()
        form.addRow(tr("robot_programs_host", language), address)
        if via != "tcp":
            note = QLabel(tr("robot_programs_via_ros", language))
            note.setWordWrap(True)
            form.addRow(note)
        self.pairing = PairingPanel(language, self._pairing_way, self, student_only=pair_as_student,
                                    paired=self.refresh)
        self.pairing.hide()  # until the agent says whether this laptop is paired
        self.pairing.sig_changed.connect(self._follow_pairing_panel)
        self.programs = QListWidget()
        self._abouts = {}  # name -> what the agent says of each program it keeps
        self.code_state = QLabel(objectName="robot_code_state", wordWrap=True)  # the chosen program's code
        self.code_state.setTextFormat(Qt.TextFormat.PlainText)
        self.code_warning = QLabel(objectName="robot_code_warning")
        self._warning_icon = self.style().standardIcon(QStyle.StandardPixmap.SP_MessageBoxWarning)
        self.code_warning.setPixmap(self._warning_icon.pixmap(24))
        self.code_warning.hide()
        code = QHBoxLayout()
        code.addWidget(self.code_warning, 0, Qt.AlignmentFlag.AlignTop)
        code.addWidget(self.code_state, 1)
        self.running = QLabel()
        self.status = QLabel()
        self.status.setWordWrap(True)
        self.difference = QLabel(tr("robot_program_differs", language))
        self.difference.setWordWrap(True)
        self.open_copy_button = QPushButton(tr("robot_programs_open_copy", language))
        self.open_copy_button.clicked.connect(self.open_robot_copy)
        differs = QHBoxLayout()
        differs.addWidget(self.difference, 1)
        differs.addWidget(self.open_copy_button)
        self.difference.hide()
        self.open_copy_button.hide()
        self.send_button = QPushButton(tr("robot_programs_send", language))
        self.send_button.setEnabled(document is not None)
        self.keep_going = QCheckBox(tr("robot_programs_keep_going", language))
        self.start_button = QPushButton(tr("robot_programs_start", language))
        self.stop_button = QPushButton(tr("robot_programs_stop", language))
        self.attach_button = QPushButton(tr("robot_programs_attach", language))
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        for button in (self.send_button, self.start_button, self.stop_button, self.attach_button):
            buttons.addButton(button, QDialogButtonBox.ButtonRole.ActionRole)
        buttons.rejected.connect(self.reject)
        self.help_button = QPushButton(tr("robot_programs_help", language))
        self.help_button.setCheckable(True)
        self.help = QLabel(tr("robot_programs_help_steps", language))
        self.help.setWordWrap(True)
        self.help.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.help.hide()
        self.help_button.toggled.connect(self._show_help)
        layout = QVBoxLayout(self)
        layout.addLayout(form)
        layout.addWidget(self.pairing)
        layout.addWidget(self.programs, 1)
        layout.addLayout(code)
        layout.addWidget(self.keep_going)
        layout.addWidget(self.running)
        layout.addWidget(self.status)
        layout.addLayout(differs)
        layout.addWidget(self.help_button)
        layout.addWidget(self.help)
        layout.addWidget(buttons)
        self.refresh_button.clicked.connect(self.refresh)
        self.start_button.clicked.connect(self.start_chosen)
        self.send_button.clicked.connect(self.send_open_program)
        self.stop_button.clicked.connect(lambda: self._with_client(lambda client: client.stop()))
        self.attach_button.clicked.connect(self.attach)
        attached.sig_state_changed.connect(self._follow_attachment)
        self.finished.connect(self._forget_calls)
        self.programs.itemSelectionChanged.connect(self._enable_start)
        self.programs.itemSelectionChanged.connect(self._show_code_state)
        self._enable_start()
        self._poll_timer = QTimer(self)
        self._poll_timer.setInterval(POLL_MS)
        self._poll_timer.timeout.connect(self._poll)
        self.finished.connect(self._poll_timer.stop)
        self.resize(520, 360)

    def showEvent(self, event):
        """Qt override: the agent is asked again each second while the dialog shows."""
        super().showEvent(event)
        self._poll_timer.start()

    def _show_help(self, shown: bool):
        """Show or hide the steps; the dialog grows to show them whole."""
        self.help.setVisible(shown)
        if shown:
            self._fit_height()

    def _fit_height(self):
        """Grow to show every wrapped text whole (a wrapped text's height is not in its layout's minimum), as far
        as the screen allows, moved up to stay on it."""
        self.layout().activate()
        area, frame = self.screen().availableGeometry(), self.frameGeometry()
        extra = frame.height() - self.height()  # the window's title bar and borders
        height = min(max(self.height(), self.layout().totalHeightForWidth(self.width())), area.height() - extra)
        self.resize(self.width(), height)
        self.move(frame.left(), max(area.top(), min(frame.top(), area.bottom() + 1 - height - extra)))  # on screen

    def _enable_start(self):
        self.start_button.setEnabled(not self._runs and self.chosen() is not None)

    def _poll(self):
        """Ask the agent quietly for its programs and what runs (not while another question is on its way)."""
        if self._enabled_before is not None or self.calls.busy:
            return
        work = self._on_a_client(lambda client: client.programs())

        def answered(answer, error):
            if self._enabled_before is None:  # a question asked meanwhile answers for itself
                self._show_programs(self._follow_pairing(answer, error), "")
                if error is not None:
                    self.status.setText("" if error.key in PAIRING_NEEDED else error.message)
        self.calls.run(work, answered)

    def refresh(self, said: str = ""):
        """Ask the agent for its programs and what runs; ``said``: what ``status`` says once they are shown."""
        self._with_client(lambda client: client.programs(), lambda answer: self._show_programs(answer, said),
                          refresh=False)

    def _show_programs(self, answer, said: str):
        """Show the agent's ``answer`` to ``programs()``; None (it was not reached): nothing is known, nothing shown."""
        if answer is None:
            self.programs.clear()
            self._abouts = {}
            self._show_code_state()
            self.running.setText("")
            self._runs = False
            self._enable_start()
            self.attach_button.setEnabled(False)
            return
        chosen = self.chosen()
        self.programs.clear()
        self._abouts = {about["name"]: about for about in answer["programs"]}
        for about in answer["programs"]:
            item = QListWidgetItem(tr("robot_programs_line", self.language, name=about["name"],
                                      profile=about["profile"], version=about["profile_version"]))
            item.setData(256, about["name"])
            if about.get("code") == "differs":  # seen in the list before it is chosen
                item.setIcon(self._warning_icon)
            self.programs.addItem(item)
            item.setSelected(about["name"] == chosen)
        self._show_code_state()
        if not answer["programs"]:
            self.status.setText(tr("robot_no_programs", self.language))
        run = answer["run"]
        runs = self._runs = bool(run) and run["state"] != "ended"
        self._enable_start()
        self.attach_button.setEnabled(runs and not self.attached.active)
        if runs:
            self.running.setText(tr("robot_programs_running", self.language, name=run["program"],
                                    state=tr("robot_programs_state_" + run["state"], self.language)))
        else:
            self.running.setText(tr("robot_programs_nothing", self.language))
        if said:
            self.status.setText(said)

    def _show_code_state(self):
        """Say whether the chosen program's code is what its blocks make (the agent checks it); a program whose
        code differs is warned of with an icon and in bold."""
        about = self._abouts.get(self.chosen())
        differs = about is not None and about.get("code") == "differs"
        said = code_state_text(about, self.language) if about is not None else ""
        self.code_state.setText(said[:1].upper() + said[1:])  # a sentence of its own here
        self.code_state.setVisible(about is not None)
        self.code_warning.setVisible(differs)
        font = self.code_state.font()
        font.setBold(differs)
        self.code_state.setFont(font)

    def _follow_attachment(self, state: str):
        if self._enabled_before is not None:  # asking: the button follows once the answer is in
            self._enabled_before[self.attach_button] = state == "idle"
        else:
            self.attach_button.setEnabled(state == "idle")

    def chosen(self):
        """The name of the program chosen in the list (None when none is)."""
        items = self.programs.selectedItems()
        return items[0].data(256) if items else None

    def send_open_program(self):
        """Send the window's program to the robot: the page's code and blocks, exported standalone, under its
        file's name (a program never saved: under the name the person gives it)."""
        if self.document.path:
            self._send_named(Path(self.document.path).stem)
            return
        ask = QInputDialog(self)
        ask.setObjectName("robot_program_name")
        ask.setWindowTitle(tr("robot_programs_send", self.language).replace("&", ""))
        ask.setLabelText(tr("robot_program_name", self.language))
        ask.textValueSelected.connect(lambda name: name.strip() and self._send_named(name.strip()))
        ask.finished.connect(ask.deleteLater)
        ask.open()

    def _send_named(self, name: str):
        self.attached.editor.call("getRunCode", {"values": False}, lambda run_code, error: self.attached.editor.call(
            "getState", None, lambda state, state_error: self._send(name, run_code, state, error or state_error)))

    def _send(self, name, run_code, state, error):
        if error:
            self.status.setText(str(error))
            return
        profile, workspace = self.document.profile, state["workspace"]
        standalone = standalone_text(f"{name}.rockly", profile, run_code, block_types_by_id(workspace),
                                     self._limits(), self.language)
        source = Program(profile.id, workspace, list(self.document.breakpoints),
                         profile.packs_used(workspace)).to_json()
        lost = "keep_going" if self.keep_going.isChecked() else "stop"
        self._with_client(lambda client: client.send(name, standalone, source, lost),
                          lambda answer: self._sent(name, answer), refresh=False)

    def _sent(self, name: str, answer):
        if answer is not None:
            self.refresh(tr("robot_sent", self.language, name=name))

    def start_chosen(self):
        name = self.chosen()
        if name is not None:
            self._with_client(lambda client: client.start(name))

    def attach(self):
        """Attach the window to what runs on the robot (``AttachedRun.attach``: off the window's thread)."""
        host, port = self.host.text().strip(), self.port.value()
        self._ask(lambda done: self.attached.attach(host, port, done, self.via, self.graph_kind), self._attached,
                  waits=True)

    def _attached(self, error):
        if error is not None:
            self.status.setText(error.message)
            return
        self._where = self.attached.client.where
        self.attach_button.setEnabled(False)
        name = self.attached.program
        self._with_client(lambda client: client.source(name), lambda source: self._got_source(name, source),
                          refresh=False)

    def _got_source(self, name: str, source):
        self._robot_source = source
        self.status.setText(tr("attached_to", self.language, name=name, host=self._where))
        if source is not None:
            self.attached.editor.call("getState", None, self._compare)

    def _compare(self, state, error):
        if error or not isinstance(state, dict):
            return
        try:
            differs = not same_program(self._robot_source, state.get("workspace") or {})
        except RocklyError:  # the robot keeps a copy that does not parse: not this program
            differs = True
        self.difference.setVisible(differs)
        self.open_copy_button.setVisible(differs and self._open_copy is not None)

    def open_robot_copy(self):
        """Open the robot's copy of the running program in the window (untitled: Save asks where to keep it)."""
        name = self.attached.program or "robot"
        path = Path(self._copies.name) / f"{name}.rockly"
        write_text_atomically(path, self._robot_source)
        self._open_copy(str(path), name)

    def _with_client(self, call, then=None, refresh=True):
        """``call(client)`` on a short connection to the agent, off the window's thread; on the window's thread
        ``then(answer)`` follows (None when refused: the refusal is said in ``status``), then a refresh."""
        host, port = self.host.text().strip(), self.port.value()
        work = self._on_a_client(call)

        def answered(answer, error):
            answer = self._follow_pairing(answer, error)
            self.status.setText(error.message if error is not None and error.key not in PAIRING_NEEDED else "")
            if error is None and self._reached is not None:
                self._reached(host, port)
            if then is not None:
                then(answer)
            if refresh:
                self.refresh()

        self._ask(work, answered)

    def _follow_pairing_panel(self):
        """While this laptop must pair, the robot's programs are not shown (it cannot see them); the dialog grows
        to show the panel's texts whole."""
        unpaired = self.pairing.pairing_needed and not self.pairing.isHidden()
        self.programs.setVisible(not unpaired)
        self.keep_going.setVisible(not unpaired)
        self.layout().setStretchFactor(self.pairing, 1 if unpaired else 0)  # it takes the list's room
        if unpaired:
            self.status.setText("")  # the panel says why
        self._fit_height()

    def _client_maker(self):
        """A function that makes a new client of the agent at the address shown now (called off the window's
        thread)."""
        host, port, language, via, graph_kind = (self.host.text().strip(), self.port.value(), self.language,
                                                 self.via, self.graph_kind)
        return lambda: AgentClient(host, port, language, name="rockly window", via=via, graph_kind=graph_kind)

    def _pairing_way(self):
        """``(make, also_for)`` for the pairing panel: pairing goes over TCP (TLS: the key never travels in clear),
        and on a robot reached over ROS the key serves its agent there too (the graph this window is on)."""
        host, port, language = self.host.text().strip(), self.port.value(), self.language
        also_for = []
        if self.via != "tcp":
            _via, kind, where = chosen_via("ros", graph_kind=self.graph_kind)
            if where is not None:
                also_for.append(ros_address(kind, where, DEFAULT_NAMESPACE))
        return lambda: AgentClient(host, port, language, name="rockly window"), also_for

    def _on_a_client(self, call):
        """The work of ``call(client)`` on a short connection to the agent: it returns ``(call's answer, the key
        the client used)``; an AgentError it raises carries ``robot_key`` too: the key this laptop holds for the
        agent (None when it holds none), which a refusal for lack of pairing makes worth forgetting."""
        make, tcp_key = self._client_maker(), tcp_address(self.host.text().strip(), self.port.value())

        def work():
            try:
                client = make()
            except AgentError as error:  # a certificate other than the one paired with is refused before hello
                error.robot_key = RobotKeys().get(tcp_key)
                raise
            try:
                return call(client), client.robot_key
            except AgentError as error:
                error.robot_key = client.robot_key
                raise
            finally:
                client.close()
        return work

    def _follow_pairing(self, answer, error):
        """The pairing panel follows an answer of ``_on_a_client``'s work (or the ``error`` that came instead):
        returns the call's own answer."""
        if error is not None:
            if error.key in PAIRING_NEEDED:
                key = getattr(error, "robot_key", None)
                reason = error.message
                if error.key == "agent_not_paired":  # the agent's words name the command line: here, the dialog's
                    # a key held all the same: revoked there, or a new agent
                    reason = tr("pairing_revoked" if key is not None else "pairing_not_yet", self.language)
                elif error.key == "agent_other_certificate":
                    reason += " " + tr("pairing_other_certificate", self.language)
                self.pairing.needed(reason, key)
            return None
        answer, key = answer
        self.pairing.show_paired(key)
        return answer

    def _forget_calls(self):
        """The dialog closed: answers on their way are dropped, and the buttons wait no more."""
        self.calls.forget()
        self._generation += 1
        enabled, self._enabled_before = self._enabled_before or {}, None
        for button, was in enabled.items():
            button.setEnabled(was)

    def _ask(self, work, answered, unused=None, waits=False):
        """``work()`` off the window's thread, ``answered(answer, error)`` on it; meanwhile ``status`` says the
        robot is being asked and the buttons that would ask again wait. ``waits``: ``work(done)`` asks by itself
        without waiting (``AttachedRun.attach``) and calls ``done(error)`` on the window's thread."""
        self.status.setText(tr("robot_programs_asking", self.language))
        asking = (self.refresh_button, self.send_button, self.start_button, self.stop_button, self.attach_button)
        self._enabled_before = {button: button.isEnabled() for button in asking}
        for button in asking:
            button.setEnabled(False)
        generation = self._generation

        def done(*answered_with):
            if generation != self._generation:  # the dialog was closed meanwhile
                return
            enabled, self._enabled_before = self._enabled_before, None
            for button, was in enabled.items():
                button.setEnabled(was)
            answered(*answered_with)

        if waits:
            work(done)
        else:
            self.calls.run(work, done, unused)
