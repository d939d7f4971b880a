"""The connection dialog: how to reach a robot over a kind of robot link (for ROS 1: which ROS
master, and this computer's address for the robot). Its fields are the link's connection
settings in the robot-link registry (``robot/links.py``)."""
from PySide6.QtWidgets import QDialog, QDialogButtonBox, QFormLayout, QLabel, QLineEdit

from rockly_desktop.ui.texts import tr


def edit_hint(edit: QLineEdit) -> str:
    """The longer of a line edit's text and its placeholder."""
    return max(edit.text(), edit.placeholderText(), key=len)


class ConnectionDialog(QDialog):
    """Asks for ``link_kind``'s connection settings, starting from ``remembered`` ({name: value})
    or this computer's environment; ``values`` holds the answers. ``edits`` are the fields by name."""

    def __init__(self, language: str, robot_name: str, link_kind, remembered: dict = None, parent=None):
        super().__init__(parent)
        remembered = remembered or {}
        self.setWindowTitle(tr("connect_title", language, robot=robot_name))
        self.edits = {}
        layout = QFormLayout(self)
        if link_kind.explanation:
            explanation = QLabel(tr(link_kind.explanation, language), self)
            explanation.setWordWrap(True)
            layout.addRow(explanation)
        for setting in link_kind.settings:
            edit = QLineEdit(remembered.get(setting.name) or setting.default_value(), self)
            edit.setObjectName(f"connect_{setting.name}")
            if setting.hint:
                edit.setPlaceholderText(tr(setting.hint, language))
            longest = max(edit_hint(edit), setting.example, key=len)
            edit.setMinimumWidth(edit.fontMetrics().horizontalAdvance(longest) + 24)  # the whole address shows
            layout.addRow(tr(setting.label, language), edit)
            self.edits[setting.name] = edit
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout.addRow(buttons)

    @property
    def values(self) -> dict:
        """The settings typed in, by name (stripped; an empty one is None)."""
        return {name: edit.text().strip() or None for name, edit in self.edits.items()}
