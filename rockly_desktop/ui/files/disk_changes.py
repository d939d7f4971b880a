"""The question when the program's file was changed on disk by another window or program since
this window opened or saved it: keep both (save as another file), overwrite, or reload from disk."""
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import tr

SAVE_AS = QMessageBox.StandardButton.Save
OVERWRITE = QMessageBox.StandardButton.Yes
RELOAD = QMessageBox.StandardButton.Reset
CANCEL = QMessageBox.StandardButton.Cancel


def changed_on_disk_box(name: str, language: str, parent, may_reload: bool) -> QMessageBox:
    """The box asking about the file ``name``; its ``exec()`` answers SAVE_AS (the default), OVERWRITE,
    RELOAD (offered only when ``may_reload``: not while a program runs) or CANCEL."""
    buttons = SAVE_AS | OVERWRITE | CANCEL | (RELOAD if may_reload else QMessageBox.StandardButton.NoButton)
    box = plain_message_box(parent, QMessageBox.Icon.Warning, tr("changed_on_disk_title", language),
                            tr("changed_on_disk", language, name=name), buttons)
    detail = [tr("changed_on_disk_keep_both", language), tr("changed_on_disk_overwrite", language)]
    if may_reload:
        detail.append(tr("changed_on_disk_reload", language))
    box.setInformativeText("\n".join(detail))
    box.button(SAVE_AS).setText(tr("changed_save_as", language))
    box.button(OVERWRITE).setText(tr("changed_overwrite", language))
    if may_reload:
        box.button(RELOAD).setText(tr("changed_reload", language))
    box.setDefaultButton(SAVE_AS)
    box.setEscapeButton(CANCEL)
    box.setObjectName("changed_on_disk_box")
    return box
