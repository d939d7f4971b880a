"""Asking for a file: the usual dialogs, or dialogs that never leave their folders (kiosk mode)."""
from pathlib import Path

from PySide6.QtCore import QSortFilterProxyModel, Qt, QUrl
from PySide6.QtWidgets import QAbstractItemView, QDialog, QFileDialog, QMessageBox, QWidget

from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import tr


class FileDialogs:
    """The system's file dialogs. ``open_file``/``save_file`` return the chosen path, or "" when cancelled."""

    def open_file(self, parent, title: str, folder: str, name_filter: str) -> str:
        """Ask for an existing file, starting in ``folder``."""
        return QFileDialog.getOpenFileName(parent, title, folder, name_filter)[0]

    def save_file(self, parent, title: str, suggestion: str, name_filter: str) -> str:
        """Ask where to write a file, suggesting the path ``suggestion``."""
        return QFileDialog.getSaveFileName(parent, title, suggestion, name_filter)[0]


class ConfinedFileDialogs(FileDialogs):
    """File dialogs that show only their folders and what is inside them and accept no file outside:
    opening from ``open_folders``, saving (only under a new name) into ``save_folder`` (None: nothing
    is saved with them). ``language()`` is the language their messages are said in."""

    def __init__(self, open_folders, save_folder=None, language=lambda: "en"):
        self.open_folders = [Path(folder).resolve() for folder in open_folders]
        self.save_folder = Path(save_folder).resolve() if save_folder is not None else None
        self.language = language

    def open_file(self, parent, title: str, folder: str, name_filter: str) -> str:
        """Ask for an existing file inside the open folders (``folder`` is ignored)."""
        return self._ask(ConfinedFileDialog(self.open_folders, parent, title, name_filter, False, self.language()))

    def save_file(self, parent, title: str, suggestion: str, name_filter: str) -> str:
        """Ask for a new file inside the save folder; only the name of ``suggestion`` is kept."""
        if self.save_folder is None:
            return ""
        dialog = ConfinedFileDialog([self.save_folder], parent, title, name_filter, True, self.language())
        dialog.selectFile(Path(suggestion).name)
        return self._ask(dialog)

    @staticmethod
    def _ask(dialog) -> str:
        try:
            return dialog.selectedFiles()[0] if dialog.exec() == QDialog.DialogCode.Accepted else ""
        finally:
            dialog.deleteLater()


def inside(path, folders) -> bool:
    """True when ``path`` (links followed) is one of ``folders`` (resolved paths) or inside one."""
    resolved = Path(path).resolve()
    return any(resolved == folder or folder in resolved.parents for folder in folders)


class InsideFolders(QSortFilterProxyModel):
    """A view of the dialog's file system model without anything outside ``folders``: only the folders,
    what is inside them and the folders on the way to them (the model's tree must reach them), so
    neither the dialog's list nor its completer ever shows what lies elsewhere."""

    def __init__(self, folders, parent=None):
        super().__init__(parent)
        self._folders = folders

    def filterAcceptsRow(self, row: int, parent) -> bool:
        """Qt override: keep the row when its path is inside a folder or on the way to one."""
        source = self.sourceModel()
        path = Path(source.filePath(source.index(row, 0, parent)))
        return inside(path, self._folders) or any(path in folder.parents for folder in self._folders)


class ConfinedFileDialog(QFileDialog):
    """Qt's own file dialog (never the desktop's, which could go anywhere) kept inside ``folders``:
    it lists nothing outside them, entering a folder outside goes back with a message, a file outside
    (or, ``saving``, one that exists: saves never write over a file) is refused with a message, and
    nothing can be renamed, deleted or made."""

    def __init__(self, folders, parent, title: str, name_filter: str, saving: bool, language: str):
        for folder in folders:
            folder.mkdir(parents=True, exist_ok=True)
        super().__init__(parent, title, str(folders[0]), name_filter)
        self.setObjectName("confined_file_dialog")
        self._folders, self._saving, self._language = list(folders), saving, language
        self.problem_box = None
        self.setOption(QFileDialog.Option.DontUseNativeDialog)
        self.setOption(QFileDialog.Option.ReadOnly)
        self.setOption(QFileDialog.Option.DontConfirmOverwrite)  # an existing file is refused anyway
        self.setProxyModel(InsideFolders(self._folders, self))
        if saving:
            self.setAcceptMode(QFileDialog.AcceptMode.AcceptSave)
        else:
            self.setFileMode(QFileDialog.FileMode.ExistingFile)
        self.setSidebarUrls([QUrl.fromLocalFile(str(folder)) for folder in self._folders])
        self.setHistory([])
        for name in ("newFolderButton", "toParentButton", "backButton", "forwardButton"):
            button = self.findChild(QWidget, name)
            if button is not None:
                button.hide()
        for view in self.findChildren(QAbstractItemView):  # its menu would offer New Folder
            view.setContextMenuPolicy(Qt.ContextMenuPolicy.PreventContextMenu)
        self.directoryEntered.connect(self._stay_inside)

    def _stay_inside(self, directory: str):
        if not inside(directory, self._folders):
            self.setDirectory(str(self._folders[0]))
            self._refuse("kiosk_outside", directory)

    def accept(self):
        """Qt override: accept only files inside the folders (saving: only new ones); say why otherwise."""
        chosen = self.selectedFiles()
        outside = [path for path in chosen if not inside(path, self._folders)]
        if not chosen or outside:
            self.setDirectory(str(self._folders[0]))
            self._refuse("kiosk_outside", outside[0] if outside else "")
        elif self._saving and Path(chosen[0]).exists() and not Path(chosen[0]).is_dir():
            self._refuse("kiosk_name_taken", chosen[0])
        else:
            super().accept()  # a folder inside is entered; a file is taken

    def _refuse(self, key: str, path: str):
        language = self._language
        folders = ", ".join(f"“{folder.name}”" for folder in self._folders)  # the sidebar's names
        if self.problem_box is not None:
            self.problem_box.deleteLater()
        self.problem_box = plain_message_box(self, QMessageBox.Icon.Information, tr("kiosk_refused_title", language),
                                             tr(key, language, path=path, name=Path(path).name, folders=folders))
        self.problem_box.setObjectName("confined_problem_box")
        self.problem_box.open()
        for view in self.findChildren(QAbstractItemView):  # the refused file must not stay chosen
            if view.selectionModel() is not None:
                view.selectionModel().clearSelection()
        self.selectFile("")
