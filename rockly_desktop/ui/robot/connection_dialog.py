"""The connection dialog: how to reach a robot over a kind of robot link (for ROS 1: which ROS
master, and this computer's address for the robot). Its fields are the link's connection
settings in the robot-link registry (``robot/links.py``)."""
from PySide6.QtWidgets import QComboBox, QDialog, QDialogButtonBox, QFormLayout, QLabel, QLayout, QLineEdit

from rockly_desktop.ui.texts import tr


def edit_hint(edit: QLineEdit) -> str:
    """The longer of a line edit's text and its placeholder."""
    return max(edit.text(), edit.placeholderText(), key=len)


class ConnectionDialog(QDialog):
    """Asks for ``link_kind``'s connection settings, starting from ``remembered`` ({name: value})
    or this computer's environment; ``values`` holds the answers. ``fields`` are its line edits
    (and choice boxes) by setting name."""

    def __init__(self, language: str, robot_name: str, link_kind, remembered: dict = None, parent=None):
        super().__init__(parent)
        remembered = remembered or {}
        self.setWindowTitle(tr("connect_title", language, robot=robot_name))
        self.fields = {}
        layout = QFormLayout(self)
        if link_kind.explanation:
            explanation = QLabel(tr(link_kind.explanation, language), self)
            explanation.setWordWrap(True)
            layout.addRow(explanation)
        for setting in link_kind.settings:
            value = remembered.get(setting.name) or setting.default_value()
            field = self._choice(setting, value, language) if setting.choices else self._text(setting, value, language)
            field.setObjectName(f"connect_{setting.name}")
            layout.addRow(tr(setting.label, language), field)
            self.fields[setting.name] = field
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout.addRow(buttons)
        layout.setSizeConstraint(QLayout.SizeConstraint.SetFixedSize)  # no empty band or resize grip under the buttons

    def _text(self, setting, value: str, language: str) -> QLineEdit:
        edit = QLineEdit(value, self)
        if setting.hint:
            edit.setPlaceholderText(tr(setting.hint, language))
        longest = max(edit_hint(edit), setting.example, key=len)
        edit.setMinimumWidth(edit.fontMetrics().horizontalAdvance(longest) + 24)  # the whole address shows
        return edit

    def _choice(self, setting, value: str, language: str) -> QComboBox:
        box = QComboBox(self)
        for choice, text in setting.choices:
            box.addItem(tr(text, language) if text else choice.capitalize(), choice)
        box.setCurrentIndex(max(box.findData(value), 0))
        if setting.hint:
            box.setToolTip(tr(setting.hint, language))
        return box

    @property
    def values(self) -> dict:
        """The settings given, by name (a text stripped; an empty one is None)."""
        return {name: (field.currentData() if isinstance(field, QComboBox) else field.text().strip()) or None
                for name, field in self.fields.items()}
