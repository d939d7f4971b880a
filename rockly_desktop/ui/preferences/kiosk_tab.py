"""The Preferences dialog's Kiosk tab: folders, idle minutes, the key chord that leaves kiosk mode and the
lesson every visitor gets as the challenge of the day.
It can be changed only once the Teacher tab is unlocked with the PIN."""
from PySide6.QtWidgets import (
    QComboBox,
    QFileDialog,
    QFormLayout,
    QHBoxLayout,
    QKeySequenceEdit,
    QLabel,
    QLineEdit,
    QPushButton,
    QSpinBox,
    QWidget,
)

from rockly_desktop.ui.texts import tr


class KioskTab(QWidget):
    """The ``kiosk`` settings (KioskSettings), enabled while ``teacher_tab`` is unlocked; ``apply()`` keeps them.
    ``challenges``: the lessons offered as the challenge of the day, [(id, title)]."""

    def __init__(self, kiosk, teacher_tab, language: str, parent=None, challenges=()):
        super().__init__(parent)
        self.setObjectName("kiosk_tab")
        self._kiosk, self._teacher_tab, self._language = kiosk, teacher_tab, language
        form = QFormLayout(self)
        self.note = QLabel(tr("kiosk_locked", language), self, wordWrap=True)
        form.addRow(self.note)
        self.programs_folder = self._folder_row(form, "kiosk_programs_folder", str(kiosk.programs_folder))
        self.visitors_folder = self._folder_row(form, "kiosk_visitors_folder", str(kiosk.visitors_folder))
        self.idle_minutes = QSpinBox(self, objectName="kiosk_idle_minutes", minimum=1, maximum=120,
                                     suffix=tr("kiosk_minutes_suffix", language))
        self.idle_minutes.setValue(round(kiosk.idle_minutes))
        form.addRow(tr("kiosk_idle", language), self.idle_minutes)
        self.quit_chord = QKeySequenceEdit(self, objectName="kiosk_quit_chord", maximumSequenceLength=1)
        self.quit_chord.setClearButtonEnabled(True)
        self.quit_chord.setKeySequence(kiosk.quit_chord)
        form.addRow(tr("kiosk_chord", language), self.quit_chord)
        self.challenge = QComboBox(self, objectName="kiosk_challenge")
        self.challenge.addItem(tr("kiosk_no_challenge", language), "")
        for lesson_id, title in challenges:
            self.challenge.addItem(title, lesson_id)
        if self.challenge.findData(kiosk.challenge) < 0:  # a lesson of another robot: kept, shown by its id
            self.challenge.addItem(kiosk.challenge, kiosk.challenge)
        self.challenge.setCurrentIndex(self.challenge.findData(kiosk.challenge))
        form.addRow(tr("kiosk_challenge", language), self.challenge)
        teacher_tab.currentChanged.connect(lambda _page: self._follow_lock())
        self._follow_lock()

    def _folder_row(self, form, key: str, folder: str) -> QLineEdit:
        field = QLineEdit(folder, self, objectName=key)
        field.setMinimumWidth(min(field.fontMetrics().horizontalAdvance(folder) + 24, 480))  # the path readable
        choose = QPushButton(tr("kiosk_choose", self._language), self)
        choose.setAutoDefault(False)
        choose.clicked.connect(lambda: self._choose_folder(field))
        row = QHBoxLayout()
        row.addWidget(field, 1)
        row.addWidget(choose)
        form.addRow(tr(key, self._language), row)
        return field

    def _choose_folder(self, field: QLineEdit):
        folder = QFileDialog.getExistingDirectory(self, tr("kiosk_choose", self._language), field.text())
        if folder:
            field.setText(folder)

    def _follow_lock(self):
        unlocked = self._teacher_tab.unlocked
        for child in self.findChildren(QWidget):
            if child is not self.note:
                child.setEnabled(unlocked)
        self.note.setVisible(not unlocked)

    def apply(self):
        """Keep the settings shown (only when the Teacher tab is unlocked)."""
        if not self._teacher_tab.unlocked:
            return
        kiosk = self._kiosk
        kiosk.programs_folder = self.programs_folder.text().strip()
        kiosk.visitors_folder = self.visitors_folder.text().strip()
        kiosk.idle_minutes = self.idle_minutes.value()
        kiosk.quit_chord = self.quit_chord.keySequence().toString()
        kiosk.challenge = self.challenge.currentData()
