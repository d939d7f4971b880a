"""The Preferences dialog's Teacher tab: toolbox level, maximum speeds and capabilities of the robot
on screen, a lock on the robot choice, and the robot's own limits (kept on the robot), behind a PIN."""
from PySide6.QtCore import QEvent, Qt
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QPushButton,
    QSpinBox,
    QStackedWidget,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.settings.teacher import MIN_PIN_LENGTH, wait_text
from rockly_desktop.ui.number_box import NumberBox
from rockly_desktop.ui.plain_text import mnemonic_free, plain_label
from rockly_desktop.ui.preferences.robot_limits_box import RobotLimitsBox
from rockly_desktop.ui.texts import tr


class TeacherTab(QStackedWidget):
    """Locked (asks for the PIN, or for a new one the first time) until the right PIN is given;
    then the settings for ``profile`` from ``teacher`` (TeacherSettings). ``apply()`` keeps them.
    ``unlocked``: the PIN was given just before (a kiosk asks it to open Preferences), not asked again.
    ``robot_limits``: how the robot's own limits are asked of its agent (``RobotLimitsBox``'s ``robot``)."""

    def __init__(self, profile, teacher, language: str, parent=None, unlocked: bool = False, robot_limits=None):
        super().__init__(parent)
        self.setObjectName("teacher_tab")
        self._profile, self._teacher, self._language = profile, teacher, language
        self._robot_limits = robot_limits
        self.addWidget(self._lock_page())
        self.addWidget(self._settings_page())
        if unlocked:
            self.setCurrentIndex(1)

    @property
    def unlocked(self) -> bool:
        """True once the right PIN was given (or a new one set)."""
        return self.currentIndex() == 1

    def _lock_page(self) -> QWidget:
        language, first_time = self._language, not self._teacher.has_pin
        page = QWidget(self)
        layout = QFormLayout(page)
        layout.addRow(QLabel(tr("teacher_new_pin" if first_time else "teacher_locked", language,
                                count=MIN_PIN_LENGTH), wordWrap=True))
        self.pin = QLineEdit(page, objectName="teacher_pin", echoMode=QLineEdit.EchoMode.Password)
        self.pin.installEventFilter(self)
        layout.addRow(tr("teacher_pin", language), self.pin)
        self.pin_again = None
        if first_time:
            self.pin_again = QLineEdit(page, objectName="teacher_pin_again", echoMode=QLineEdit.EchoMode.Password)
            self.pin_again.installEventFilter(self)
            layout.addRow(tr("teacher_pin_again", language), self.pin_again)
        self.unlock_button = QPushButton(tr("teacher_set_pin" if first_time else "teacher_unlock", language), page)
        self.unlock_button.setObjectName("teacher_unlock")
        self.unlock_button.setAutoDefault(False)
        self.unlock_button.clicked.connect(self.unlock)
        layout.addRow(self.unlock_button)
        self.problem = QLabel(page, objectName="teacher_problem", wordWrap=True)
        wait = 0 if first_time else self._teacher.pin_wait()
        if wait > 0:  # said at once, before anyone types in vain
            self.problem.setText(wait_text(wait, language))
        layout.addRow(self.problem)
        return page

    def eventFilter(self, watched, event):
        """Enter in a PIN field unlocks (the dialog's OK would close it, still locked)."""
        if event.type() == QEvent.Type.KeyPress and event.key() in (Qt.Key.Key_Return, Qt.Key.Key_Enter):
            self.unlock()
            return True
        return super().eventFilter(watched, event)

    def unlock(self):
        """Check the PIN typed (or set the new one) and show the settings when it is right."""
        pin = self.pin.text()
        if self.pin_again is not None:
            if len(pin) < MIN_PIN_LENGTH:
                self.problem.setText(tr("teacher_pin_short", self._language, count=MIN_PIN_LENGTH))
                return
            if pin != self.pin_again.text():
                self.problem.setText(tr("teacher_pin_mismatch", self._language))
                return
            self._teacher.set_pin(pin)
        else:
            answer = self._teacher.try_pin(pin)
            if not answer.right:
                self.problem.setText(answer.problem(self._language))
                self.pin.clear()
                return
        self.pin.clear()
        self.setCurrentIndex(1)

    def _settings_page(self) -> QWidget:
        profile, teacher, language = self._profile, self._teacher, self._language
        limits = teacher.limits(profile.id)
        page = QWidget(self)
        outer = QVBoxLayout(page)
        outer.addWidget(plain_label(tr("teacher_for", language, name=profile.display_name(language)), page,
                                    objectName="teacher_for"))
        if not teacher.has_own_limits(profile.id) and not limits.is_open:
            default = QLabel(tr("teacher_default_limits", language), page, objectName="teacher_default_limits")
            default.setWordWrap(True)
            default.setTextFormat(Qt.TextFormat.PlainText)
            outer.addWidget(default)
        form = QFormLayout()
        outer.addLayout(form)
        self.level_box = QComboBox(page, objectName="teacher_level")
        if not profile.levels:
            self.level_box.addItem(tr("teacher_all_blocks", language), None)
        for level in profile.levels:
            self.level_box.addItem(profile.localize(level["name"], language), level["id"])
        chosen = self.level_box.findData(teacher.level(profile.id))
        if chosen < 0:  # none chosen yet: the level with every category, as the editor shows then
            whole = next((level["id"] for level in profile.levels if level.get("categories") == "all"), None)
            chosen = max(0, self.level_box.findData(whole))
        self.level_box.setCurrentIndex(chosen)
        form.addRow(tr("teacher_level", language), self.level_box)
        self.max_speed = NumberBox(language, page, objectName="teacher_max_speed", decimals=2, singleStep=0.05,
                                   maximum=5.0, suffix=" m/s")
        self.max_speed.setSpecialValueText(tr("teacher_no_limit", language))
        self.max_speed.setValue(limits.max_speed or 0.0)
        form.addRow(tr("teacher_max_speed", language), self.max_speed)
        self.max_turn = QSpinBox(page, objectName="teacher_max_turn", maximum=720, singleStep=5, suffix=" °/s")
        self.max_turn.setSpecialValueText(tr("teacher_no_limit", language))
        self.max_turn.setValue(round(limits.max_turn or 0))
        form.addRow(tr("teacher_max_turn", language), self.max_turn)
        self.capability_boxes = {}
        for capability in profile.capabilities:
            box = QCheckBox(mnemonic_free(profile.localize(capability["name"], language)), page)
            box.setObjectName(f"teacher_capability_{capability['id']}")
            box.setChecked(capability["id"] not in limits.switched_off)
            self.capability_boxes[capability["id"]] = box
            form.addRow(tr("teacher_allowed", language) if len(self.capability_boxes) == 1 else "", box)
        self.lock_robot = QCheckBox(tr("teacher_lock_robot", language), page)
        self.lock_robot.setObjectName("teacher_lock_robot")
        self.lock_robot.setToolTip(tr("teacher_lock_robot_tip", language))
        self.lock_robot.setChecked(teacher.robot_locked)
        outer.addWidget(self.lock_robot)
        self.robot_limits_box = RobotLimitsBox(profile, language, self._robot_limits, page)
        outer.addWidget(self.robot_limits_box)
        outer.addStretch(1)
        return page

    def apply(self) -> bool:
        """Keep the settings shown (only when unlocked); True when the toolbox must change."""
        if not self.unlocked:
            return False
        profile_id, teacher = self._profile.id, self._teacher
        before = (teacher.level(profile_id), sorted(teacher.switched_off(profile_id)))
        switched_off = [name for name, box in self.capability_boxes.items() if not box.isChecked()]
        teacher.set_level(profile_id, self.level_box.currentData())
        teacher.set_limits(profile_id, self.max_speed.value() or None, self.max_turn.value() or None, switched_off)
        teacher.robot_locked = self.lock_robot.isChecked()
        return before != (teacher.level(profile_id), sorted(switched_off))
