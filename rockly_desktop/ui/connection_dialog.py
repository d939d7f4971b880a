"""The ROS connection dialog: which ROS master, and this computer's address for the robot."""
import os

from PySide6.QtWidgets import QDialog, QDialogButtonBox, QFormLayout, QLabel, QLayout, QLineEdit

from rockly_desktop.ui.texts import tr

DEFAULT_MASTER = "http://localhost:11311"


def edit_hint(edit: QLineEdit) -> str:
    """The longer of a line edit's text and its placeholder."""
    return max(edit.text(), edit.placeholderText(), key=len)


class ConnectionDialog(QDialog):
    """Asks for ROS_MASTER_URI and ROS_IP/ROS_HOSTNAME; ``master_uri`` and ``host`` hold the answers."""

    def __init__(self, language: str, robot_name: str, master_uri: str = None, host: str = None, parent=None):
        super().__init__(parent)
        self.setWindowTitle(tr("connect_title", language, robot=robot_name))
        self.master_edit = QLineEdit(master_uri or os.environ.get("ROS_MASTER_URI") or DEFAULT_MASTER, self)
        self.host_edit = QLineEdit(host or os.environ.get("ROS_IP") or os.environ.get("ROS_HOSTNAME") or "", self)
        self.host_edit.setPlaceholderText(tr("connect_host_hint", language))
        widest = (self.master_edit, "http://192.168.100.100:11311"), (self.host_edit, edit_hint(self.host_edit))
        for edit, longest in widest:
            edit.setMinimumWidth(edit.fontMetrics().horizontalAdvance(longest) + 24)  # the whole address shows
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok | QDialogButtonBox.StandardButton.Cancel, self)
        buttons.accepted.connect(self.accept)
        buttons.rejected.connect(self.reject)
        layout = QFormLayout(self)
        explanation = QLabel(tr("connect_explanation", language), self)
        explanation.setWordWrap(True)
        layout.addRow(explanation)
        layout.addRow(tr("connect_master", language), self.master_edit)
        layout.addRow(tr("connect_host", language), self.host_edit)
        layout.addRow(buttons)
        layout.setSizeConstraint(QLayout.SizeConstraint.SetFixedSize)  # no empty band or resize grip under the buttons

    @property
    def master_uri(self) -> str:
        """The ROS master URI typed in."""
        return self.master_edit.text().strip()

    @property
    def host(self) -> str:
        """This computer's IP or host name as the robot should see it (may be empty)."""
        return self.host_edit.text().strip()
