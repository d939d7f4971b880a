"""The Programs dialog's pairing: why this laptop cannot use the robot yet (no key for it, a key the robot no
longer knows, a certificate other than the one paired with), a field for the one-time code the robot shows
(``rockly agent pair`` prints one; a robot's own screen may show one) and Pair; once paired, the robot's name, this
laptop's role there and the certificate's short fingerprint; a teacher makes a code for another laptop; and Forget
this robot deletes the key. The agent is asked off the window's thread (``AgentCalls``); a wrong, expired or
over-guessed code is said and the code typed stays."""
from PySide6.QtCore import Qt, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.runtime.agent.robot_keys import RobotKeys
from rockly_desktop.runtime.agent.tls import short_fingerprint
from rockly_desktop.ui.agent.agent_calls import AgentCalls
from rockly_desktop.ui.texts import tr

# what pairing (again) mends: no key the agent knows (none, or revoked), a certificate other than the one paired with
PAIRING_NEEDED = frozenset({"agent_not_paired", "agent_other_certificate"})
ROLES = ("student", "teacher")


class PairingPanel(QGroupBox):
    """Pairing with the robot whose agent ``connect()`` reaches (called on the window's thread, it returns
    ``(make, also_for)``: ``make()`` makes a new ``AgentClient`` off it, over TCP, and ``also_for`` the addresses
    of the same agent over ROS the key serves too). ``student_only``: this laptop pairs as a student whatever the
    code says (a kiosk). ``paired()`` is called on the window's thread once a pairing succeeded or a key was
    forgotten (the dialog asks again). ``sig_changed``: what it shows changed (texts, rows shown)."""

    sig_changed = Signal()

    def __init__(self, language: str, connect, parent=None, student_only: bool = False, paired=None,
                 keys: RobotKeys = None):
        super().__init__(tr("pairing_title", language), parent)
        self.setObjectName("pairing_panel")
        self._language, self._connect, self._student_only, self._paired = language, connect, student_only, paired
        self._keys = keys if keys is not None else RobotKeys()
        self.key = None  # the RobotKey this laptop holds for the robot, when known
        self.calls = AgentCalls(self)
        self.reason = self._label("pairing_reason")
        self.how = self._label("pairing_how")
        self.how.setText(tr("pairing_how", language) + (" " + tr("pairing_kiosk_student", language)
                                                         if student_only else ""))
        self.code = QLineEdit(self, objectName="pairing_code")
        self.code.setPlaceholderText(tr("pairing_code_hint", language, example="K7Q-M2X"))
        self.code.returnPressed.connect(self.pair)
        self.code.textChanged.connect(lambda text: self.pair_button.setEnabled(bool(text.strip())))
        self.pair_button = QPushButton(tr("pairing_pair", language), self, objectName="pairing_pair")
        self.pair_button.setAutoDefault(False)
        self.pair_button.setEnabled(False)
        self.pair_button.clicked.connect(self.pair)
        self.asking = QWidget(self)
        entry = QHBoxLayout(self.asking)
        entry.setContentsMargins(0, 0, 0, 0)
        entry.addWidget(QLabel(tr("pairing_code_label", language), self))
        entry.addWidget(self.code, 1)
        entry.addWidget(self.pair_button)
        self.about = self._label("pairing_about")
        self.another_button = QPushButton(tr("pairing_another", language), self, objectName="pairing_another")
        self.another_role = QComboBox(self, objectName="pairing_another_role")
        for role in ROLES:
            self.another_role.addItem(tr(f"pairing_as_{role}", language), role)
        self.forget_button = QPushButton(tr("pairing_forget", language), self, objectName="pairing_forget")
        for button in (self.another_button, self.forget_button):
            button.setAutoDefault(False)
        self.another_button.clicked.connect(self.make_code)
        self.forget_button.clicked.connect(self.forget)
        self.actions = QWidget(self)
        row = QHBoxLayout(self.actions)
        row.setContentsMargins(0, 0, 0, 0)
        row.addWidget(self.another_button)
        row.addWidget(self.another_role)
        row.addStretch(1)
        row.addWidget(self.forget_button)
        self.other_code_hint = self._label("pairing_other_code_hint")
        self.other_code = self._label("pairing_other_code")
        self.other_code.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        big = self.other_code.font()
        big.setPointSizeF(big.pointSizeF() * 2)
        big.setBold(True)
        self.other_code.setFont(big)
        self.other = QWidget(self)
        other = QVBoxLayout(self.other)
        other.setContentsMargins(0, 0, 0, 0)
        other.addWidget(self.other_code_hint)
        other.addWidget(self.other_code)
        self.problem = self._label("pairing_problem")
        self.problem.hide()
        layout = QVBoxLayout(self)
        for widget in (self.reason, self.how, self.asking, self.about, self.actions, self.other, self.problem):
            layout.addWidget(widget)
        layout.addStretch(1)  # room the dialog gives it stays below its rows
        self.needed("")

    def _tell(self, text: str):
        """``text`` under the panel's rows (how a pairing or a code went); no row at all when there is none."""
        self.problem.setText(text)
        self.problem.setVisible(bool(text))

    def _label(self, name: str) -> QLabel:
        label = QLabel(self, objectName=name, wordWrap=True)
        label.setTextFormat(Qt.TextFormat.PlainText)
        return label

    @property
    def pairing_needed(self) -> bool:
        """True while the panel asks for a code."""
        return not self.asking.isHidden()

    def needed(self, reason: str, key=None):
        """This laptop cannot use the robot without pairing: ``reason`` says why (the agent's or the client's
        words); ``key``: the key it holds all the same (one the robot no longer knows), which Forget deletes."""
        self.show()
        self.key = key
        self.reason.setText(reason)
        self.reason.setVisible(bool(reason))
        for widget in (self.how, self.asking):
            widget.show()
        self.about.hide()
        self.another_button.hide()
        self.another_role.hide()
        self.forget_button.setVisible(key is not None)
        self.actions.setVisible(key is not None)
        self.other.hide()
        self.sig_changed.emit()

    def show_paired(self, key):
        """The robot answered this laptop, which holds ``key`` for it (a ``RobotKey``; None: none is needed)."""
        if key is None:
            self.hide()
            self.sig_changed.emit()
            return
        self.show()
        changed = key != self.key
        self.key = key
        self.about.setText(tr("pairing_about", self._language, agent=key.agent,
                              role=tr(f"pairing_role_{key.role}", self._language),
                              fingerprint=short_fingerprint(key.fingerprint) if key.fingerprint
                              else tr("pairing_no_certificate", self._language)))
        for widget in (self.reason, self.how, self.asking):
            widget.hide()
        self.about.show()
        self.actions.show()
        teacher = key.role == "teacher"
        self.another_button.setVisible(teacher)
        self.another_role.setVisible(teacher)
        self.forget_button.show()
        if changed:
            self.other.hide()
            self._tell("")
        self.sig_changed.emit()

    def pair(self):
        """Pair with the code typed (off the window's thread); the code stays when it is refused."""
        code = self.code.text().strip()
        if not code or self.calls.busy:
            return
        role = "student" if self._student_only else None
        make, also_for = self._connect()

        def work():
            client = make()
            try:
                return client.pair(code, also_for=also_for, role=role)
            finally:
                client.close()

        self.pair_button.setEnabled(False)
        self._tell(tr("robot_programs_asking", self._language))
        self.calls.run(work, self._pair_answered)

    def _pair_answered(self, key, error):
        self.pair_button.setEnabled(bool(self.code.text().strip()))
        if error is not None:
            self._tell(error.message)
            self.sig_changed.emit()
            return
        self.code.clear()
        self._tell(tr("pairing_done", self._language, agent=key.agent))
        self.show_paired(key)
        if self._paired is not None:
            self._paired()

    def make_code(self):
        """Ask the robot for a one-time code another laptop pairs with, in the role chosen (a teacher only)."""
        role, (make, _also_for) = self.another_role.currentData(), self._connect()

        def work():
            client = make()
            try:
                return client.pairing_code(role)
            finally:
                client.close()

        self.another_button.setEnabled(False)
        self._tell(tr("robot_programs_asking", self._language))
        self.calls.run(work, self._code_answered)

    def _code_answered(self, answer, error):
        self.another_button.setEnabled(True)
        if error is not None:
            self._tell(error.message)
            return
        self._tell("")
        self.other_code_hint.setText(tr("pairing_other_code", self._language, seconds=answer["seconds"],
                                        role=tr(f"pairing_role_{answer['role']}", self._language)))
        self.other_code.setText(answer["code"])
        self.other.show()
        self.sig_changed.emit()

    def forget(self):
        """Delete this laptop's key for the robot (for each way it is reached: TCP, its ROS graph): it must pair
        again to use it."""
        if self.key is not None:
            for kept in self._keys.all():
                if kept.address == self.key.address or kept.client == self.key.client:
                    self._keys.forget(kept.address)
        self.needed(tr("pairing_forgotten", self._language))
        self._tell("")
        if self._paired is not None:
            self._paired()
