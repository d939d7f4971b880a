"""The Preferences dialog: the language of the window and the blocks."""
from PySide6.QtWidgets import QComboBox, QDialog, QDialogButtonBox, QFormLayout

from rockly_desktop.ui.texts import LANGUAGE_NAMES, tr


class PreferencesDialog(QDialog):
    """Lets the user pick English or German; ``language`` holds the choice."""

    def __init__(self, language: str, parent=None):
        super().__init__(parent)
        self.setWindowTitle(tr("preferences_title", language))
        self.language_box = QComboBox(self)
        for code, name in LANGUAGE_NAMES.items():
            self.language_box.addItem(name, code)
        self.language_box.setCurrentIndex(self.language_box.findData(language))
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout = QFormLayout(self)
        layout.addRow(tr("language", language), self.language_box)
        layout.addRow(buttons)

    @property
    def language(self) -> str:
        """The language code chosen in the dialog."""
        return self.language_box.currentData()
