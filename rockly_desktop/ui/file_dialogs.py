"""Asking for a file: the usual dialogs, or dialogs that never leave one folder (kiosk mode)."""
from pathlib import Path

from PySide6.QtCore import QUrl
from PySide6.QtWidgets import QDialog, QFileDialog


class FileDialogs:
    """The system's file dialogs. ``open_file``/``save_file`` return the chosen path, or "" when cancelled."""

    def open_file(self, parent, title: str, folder: str, name_filter: str) -> str:
        """Ask for an existing file, starting in ``folder``."""
        return QFileDialog.getOpenFileName(parent, title, folder, name_filter)[0]

    def save_file(self, parent, title: str, suggestion: str, name_filter: str) -> str:
        """Ask where to write a file, suggesting the path ``suggestion``."""
        return QFileDialog.getSaveFileName(parent, title, suggestion, name_filter)[0]


class ConfinedFileDialogs(FileDialogs):
    """File dialogs that show only ``folder`` and what is inside it, and accept no file outside it."""

    def __init__(self, folder):
        self.folder = Path(folder).resolve()

    def open_file(self, parent, title: str, folder: str, name_filter: str) -> str:
        """Ask for an existing file inside the folder (``folder`` is ignored)."""
        return self._ask(ConfinedFileDialog(self.folder, parent, title, name_filter, saving=False))

    def save_file(self, parent, title: str, suggestion: str, name_filter: str) -> str:
        """Ask where to write a file inside the folder; only the name of ``suggestion`` is kept."""
        dialog = ConfinedFileDialog(self.folder, parent, title, name_filter, saving=True)
        dialog.selectFile(Path(suggestion).name)
        return self._ask(dialog)

    @staticmethod
    def _ask(dialog) -> str:
        try:
            return dialog.selectedFiles()[0] if dialog.exec() == QDialog.DialogCode.Accepted else ""
        finally:
            dialog.deleteLater()


class ConfinedFileDialog(QFileDialog):
    """Qt's own file dialog (never the desktop's, which could go anywhere) kept inside ``folder``:
    entering a folder outside it goes back to it, a file outside it is not accepted, and files
    cannot be deleted or renamed."""

    def __init__(self, folder: Path, parent, title: str, name_filter: str, saving: bool):
        folder.mkdir(parents=True, exist_ok=True)
        super().__init__(parent, title, str(folder), name_filter)
        self.setObjectName("confined_file_dialog")
        self._folder = folder
        self.setOption(QFileDialog.Option.DontUseNativeDialog)
        self.setOption(QFileDialog.Option.ReadOnly)
        if saving:
            self.setAcceptMode(QFileDialog.AcceptMode.AcceptSave)
        else:
            self.setFileMode(QFileDialog.FileMode.ExistingFile)
        self.setSidebarUrls([QUrl.fromLocalFile(str(folder))])
        self.setHistory([])
        self.directoryEntered.connect(self._stay_inside)

    def inside(self, path) -> bool:
        """True when ``path`` (links followed) is the folder or inside it."""
        resolved = Path(path).resolve()
        return resolved == self._folder or self._folder in resolved.parents

    def _stay_inside(self, directory: str):
        if not self.inside(directory):
            self.setDirectory(str(self._folder))

    def accept(self):
        """Qt override: accept only files (and enter only folders) inside the folder."""
        chosen = self.selectedFiles()
        if chosen and all(self.inside(path) for path in chosen):
            super().accept()
        else:
            self.setDirectory(str(self._folder))
            self.selectFile("")
