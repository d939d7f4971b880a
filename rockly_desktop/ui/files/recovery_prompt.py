"""Offering, at start, the unsaved program a Rockly left behind when it did not close cleanly."""
from pathlib import Path

from PySide6.QtCore import QDateTime, QLocale, QObject
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import tr


def recovery_box(recovery, language: str, parent) -> QMessageBox:
    """The question for a claimed Recovery: what was found, from when, for which file; Restore or Discard."""
    name = Path(recovery.program_path).name if recovery.program_path else tr("untitled", language)
    box = plain_message_box(parent, QMessageBox.Icon.Question, tr("recovery_title", language),
                            tr("recovery_found", language, name=name), QMessageBox.StandardButton.NoButton)
    file_line = (tr("recovery_file", language, path=recovery.program_path) if recovery.program_path
                 else tr("recovery_no_file", language))
    box.setInformativeText("\n".join((file_line, tr("recovery_when", language, **_when(recovery.saved_at, language)),
                                      "", tr("recovery_choice", language))))
    box.setObjectName("recovery_box")
    restore = box.addButton(tr("recovery_restore", language), QMessageBox.ButtonRole.AcceptRole)
    restore.setObjectName("recovery_restore")
    discard = box.addButton(tr("recovery_discard", language), QMessageBox.ButtonRole.DestructiveRole)
    discard.setObjectName("recovery_discard")
    box.setDefaultButton(restore)
    return box


def _when(saved_at, language: str) -> dict:
    """The date and time of ``saved_at`` in the person's time zone, written the way ``language`` does."""
    moment = QDateTime.fromSecsSinceEpoch(int(saved_at.timestamp())).toLocalTime()
    locale = QLocale(language)
    return {"date": locale.toString(moment.date(), QLocale.FormatType.LongFormat),
            "time": locale.toString(moment.time(), QLocale.FormatType.ShortFormat)}


class RecoveryPrompt(QObject):
    """Asks about a claimed ``recovery`` (window-modal, not waiting): Restore shows it through
    ``files`` as unsaved changes and hands it to ``autosave``; Discard deletes it. A box closed
    without an answer leaves the file for the next start."""

    def __init__(self, recovery, files, autosave, language: str, parent):
        super().__init__(parent)
        self.recovery = recovery
        self.files = files
        self.autosave = autosave
        self.box = recovery_box(recovery, language, parent)
        self.box.finished.connect(self._answered)
        self.box.open()

    def _answered(self):
        clicked = self.box.clickedButton()
        choice = clicked.objectName() if clicked is not None else None
        if choice == "recovery_restore":
            self.files.restore(self.recovery, then=self._restored)
        elif choice == "recovery_discard":
            self.recovery.discard()
        else:
            self.recovery.release()

    def _restored(self, ok: bool):
        if ok:
            self.autosave.adopt(self.recovery)
        else:
            self.recovery.release()
