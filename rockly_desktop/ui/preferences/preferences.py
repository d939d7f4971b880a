"""The Preferences dialog: the language of the window and the blocks, putting the robot back before
each Run, high-contrast blocks and larger text on them; the teacher's settings."""
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLayout,
    QTabWidget,
    QVBoxLayout,
    QWidget,
)

from rockly_desktop.ui.preferences.kiosk_tab import KioskTab
from rockly_desktop.ui.preferences.teacher_tab import TeacherTab
from rockly_desktop.ui.texts import language_names, tr


class PreferencesDialog(QDialog):
    """Lets the user pick English or German (``language``), whether the simulated robot is put
    back before each Run (``reset_before_run``) and how the blocks look (``block_look``: high contrast,
    larger text).

    With a ``profile`` and the ``teacher`` settings it has a Teacher tab (``teacher_tab``)
    behind a PIN; the caller calls ``teacher_tab.apply()`` when the dialog is accepted. With the
    ``kiosk`` settings it has a Kiosk tab (``kiosk_tab``, ``apply()`` too), unlocked with the Teacher
    tab; in ``kiosk_mode`` the toolbox level cannot be changed. ``pin_given``: the teacher's PIN was
    checked just before opening (a kiosk's gate), so both tabs open unlocked. ``challenges``: the
    lessons the Kiosk tab offers as the challenge of the day, [(id, title)]. ``robot_limits``: how the
    Teacher tab asks the robot's agent for the robot's own limits (``RobotLimitsBox``).
    """

    def __init__(self, language: str, parent=None, profile=None, teacher=None, reset_before_run: bool = False,
                 kiosk=None, kiosk_mode: bool = False, block_look=None, pin_given: bool = False,
                 challenges=(), robot_limits=None):
        super().__init__(parent)
        self.setWindowTitle(tr("preferences_title", language))
        self.language_box = QComboBox(self)
        for code, name in language_names().items():
            self.language_box.addItem(name, code)
        self.language_box.setCurrentIndex(self.language_box.findData(language))
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        general = QWidget(self)
        layout = QFormLayout(general)
        layout.addRow(tr("language", language), self.language_box)
        self.reset_box = QCheckBox(tr("reset_before_run", language), self)
        self.reset_box.setObjectName("reset_before_run")
        self.reset_box.setChecked(reset_before_run)
        layout.addRow(self.reset_box)
        look = block_look or {}
        self.contrast_box = QCheckBox(tr("high_contrast_blocks", language), self)
        self.contrast_box.setObjectName("high_contrast_blocks")
        self.contrast_box.setChecked(bool(look.get("highContrast")))
        layout.addRow(self.contrast_box)
        self.large_text_box = QCheckBox(tr("large_block_text", language), self)
        self.large_text_box.setObjectName("large_block_text")
        self.large_text_box.setChecked(bool(look.get("largeText")))
        layout.addRow(self.large_text_box)
        self.tabs = QTabWidget(self)
        self.tabs.addTab(general, tr("preferences_general", language))
        self.teacher_tab = None
        if profile is not None and teacher is not None and (teacher.has_pin or not kiosk_mode):
            # (a visitor must not set the first PIN: with it they could leave the kiosk)
            self.teacher_tab = TeacherTab(profile, teacher, language, self, unlocked=pin_given,
                                          robot_limits=robot_limits)
            self.tabs.addTab(self.teacher_tab, tr("teacher_tab", language))
            if kiosk_mode:
                self.teacher_tab.level_box.setEnabled(False)
                self.teacher_tab.level_box.setToolTip(tr("kiosk_level_fixed", language))
        self.kiosk_tab = None
        if kiosk is not None and self.teacher_tab is not None:
            self.kiosk_tab = KioskTab(kiosk, self.teacher_tab, language, self, challenges)
            self.tabs.addTab(self.kiosk_tab, tr("kiosk_tab", language))
        outer = QVBoxLayout(self)
        outer.addWidget(self.tabs)
        outer.addWidget(buttons)
        # as big as its content, no bigger: no empty band or resize grip under the buttons; it grows when
        # the Teacher tab shows its settings
        outer.setSizeConstraint(QLayout.SizeConstraint.SetFixedSize)

    @property
    def language(self) -> str:
        """The language code chosen in the dialog."""
        return self.language_box.currentData()

    @property
    def block_look(self) -> dict:
        """How the blocks are to look: {"highContrast": bool, "largeText": bool}."""
        return {"highContrast": self.contrast_box.isChecked(), "largeText": self.large_text_box.isChecked()}

    @property
    def reset_before_run(self) -> bool:
        """True when the robot is to be put back before each Run."""
        return self.reset_box.isChecked()
