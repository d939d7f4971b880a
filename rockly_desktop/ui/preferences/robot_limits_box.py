"""The Teacher tab's "This robot's own limits": the limits the robot keeps itself, for every program it runs
whoever sent it (what ``rockly agent limits`` sets on the robot), read from its agent and set there by a laptop
paired with it as a teacher. The window's own limits above them stay the window's."""
from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QCheckBox,
    QFormLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.ui.number_box import NumberBox
from rockly_desktop.ui.plain_text import mnemonic_free
from rockly_desktop.ui.texts import tr


class RobotLimitsBox(QGroupBox):
    """The robot's own limits for ``profile``'s capabilities, asked through ``robot(owner)`` (which makes a
    ``RobotLimitsOnRobot``: ``read(then)``, ``keep(limits, then)``; None when no agent is known). Read from the
    robot when first shown (its values show once it has said them); nothing changes on the robot until "Set on
    the robot" is clicked, and what the robot then keeps is shown."""

    def __init__(self, profile, language: str, robot, parent=None):
        super().__init__(tr("teacher_robot_limits_title", language), parent)
        self.setObjectName("robot_limits_box")
        self._language = language
        self._robot = robot(self) if robot is not None else None
        self._capability_ids = [capability["id"] for capability in profile.capabilities]
        self._other_switched_off = []  # capabilities the robot switches off that this profile does not name
        self._read_once = False
        outer = QVBoxLayout(self)
        note = QLabel(tr("teacher_robot_limits_note", language), self, wordWrap=True)
        note.setTextFormat(Qt.TextFormat.PlainText)
        outer.addWidget(note)
        self.values = QWidget(self, objectName="robot_limits_values")  # shown once the robot has said them
        form = QFormLayout(self.values)
        form.setContentsMargins(0, 0, 0, 0)
        outer.addWidget(self.values)
        self.max_speed = NumberBox(language, self.values, objectName="robot_max_speed", decimals=2, singleStep=0.05,
                                   maximum=5.0, suffix=" m/s")
        self.max_speed.setSpecialValueText(tr("teacher_no_limit", language))
        form.addRow(tr("teacher_max_speed", language), self.max_speed)
        self.max_turn = QSpinBox(self.values, objectName="robot_max_turn", maximum=720, singleStep=5, suffix=" °/s")
        self.max_turn.setSpecialValueText(tr("teacher_no_limit", language))
        form.addRow(tr("teacher_max_turn", language), self.max_turn)
        self.capability_boxes = {}
        for capability in profile.capabilities:
            box = QCheckBox(mnemonic_free(profile.localize(capability["name"], language)), self.values)
            box.setObjectName(f"robot_capability_{capability['id']}")
            self.capability_boxes[capability["id"]] = box
            form.addRow(tr("teacher_allowed", language) if len(self.capability_boxes) == 1 else "", box)
        self.values.hide()
        self._showing = False  # while the robot's answer is put into the boxes (no edit of the teacher's)
        self.max_speed.valueChanged.connect(self._edited)
        self.max_turn.valueChanged.connect(self._edited)
        for box in self.capability_boxes.values():
            box.toggled.connect(self._edited)
        self.read_button = QPushButton(tr("teacher_robot_limits_read", language), self, objectName="robot_limits_read")
        self.keep_button = QPushButton(tr("teacher_robot_limits_keep", language), self, objectName="robot_limits_keep")
        for button in (self.read_button, self.keep_button):
            button.setAutoDefault(False)  # Enter in a box must not set the robot's limits
        self.read_button.clicked.connect(self.read)
        self.keep_button.clicked.connect(self.keep)
        buttons = QHBoxLayout()
        buttons.addWidget(self.read_button)
        buttons.addWidget(self.keep_button)
        buttons.addStretch(1)
        outer.addLayout(buttons)
        self.status = QLabel(self, objectName="robot_limits_status", wordWrap=True)
        self.status.setTextFormat(Qt.TextFormat.PlainText)
        outer.addWidget(self.status)
        self._set_enabled(False)
        if self._robot is None:
            self.read_button.setEnabled(False)
            self._say(tr("teacher_robot_limits_no_agent", language))

    def showEvent(self, event):
        """Qt override: the robot is asked for its limits the first time they show (after the PIN)."""
        super().showEvent(event)
        if not self._read_once and self._robot is not None:
            self._read_once = True
            self.read()

    def _set_enabled(self, enabled: bool):
        self.values.setEnabled(enabled)
        self.keep_button.setEnabled(enabled)

    def read(self):
        """Ask the robot for the limits it keeps (off the window's thread) and show them."""
        self._asking()
        self._robot.read(lambda limits, problem: self._answered(limits, problem, "teacher_robot_limits_shown"))

    def keep(self):
        """Set the limits shown as the robot's own."""
        self._asking()
        self._robot.keep(self.limits(), lambda limits, problem: self._answered(limits, problem,
                                                                               "teacher_robot_limits_kept"))

    def limits(self) -> dict:
        """The limits shown, as the agent takes them (0 shows "no limit": none)."""
        off = [capability for capability, box in self.capability_boxes.items() if not box.isChecked()]
        return {"max_speed": self.max_speed.value() or None, "max_turn": self.max_turn.value() or None,
                "switched_off": sorted(set(off) | set(self._other_switched_off))}

    def _asking(self):
        self.read_button.setEnabled(False)
        self._set_enabled(False)
        self._say(tr("robot_programs_asking", self._language))

    def _answered(self, limits, problem, said: str):
        self.read_button.setEnabled(True)
        if limits is None:
            self._say(problem or "")
            return
        self._showing = True
        self.max_speed.setValue(limits.get("max_speed") or 0.0)
        self.max_turn.setValue(round(limits.get("max_turn") or 0))
        off = limits.get("switched_off") or []
        for capability, box in self.capability_boxes.items():
            box.setChecked(capability not in off)
        self._showing = False
        self._other_switched_off = [capability for capability in off if capability not in self.capability_boxes]
        self._set_enabled(True)
        self.values.show()
        self._say(tr(said, self._language))

    def _edited(self):
        """The teacher changed a value: the robot does not keep it yet."""
        if not self._showing:
            self._say(tr("teacher_robot_limits_not_kept", self._language))

    def _say(self, text: str):
        """``text`` in the status line, whole: the Preferences dialog takes its size from its contents' hints,
        in which a wrapped text's height is not."""
        self.status.setText(text)
        width = self.status.width() if self.isVisible() else self.sizeHint().width()
        self.status.setMinimumHeight(self.status.heightForWidth(width) if text else 0)
