"""The File menu's work: new, open, save, save as, recent files, import XML, export Python.

Every failure is shown as a plain message; a failed open or import leaves the program
on screen untouched, and a failed save leaves the file on disk untouched. A program that
opens with changes (its profile is not installed, or its blocks could not take some of
its values) is opened as changed, with a message saying what changed.
"""
import json
from pathlib import Path

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QFileDialog, QMessageBox

from rockly_desktop.core.errors import RocklyError
from rockly_desktop.core.export import python_module_text
from rockly_desktop.core.program import PROGRAM_SUFFIX, Program, save_program, write_text_atomically
from rockly_desktop.profiles.opening import read_program_to_open, unknown_blocks_error
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import tr


class ProgramFiles(QObject):
    """Owns which file is open and whether it has unsaved changes."""

    sig_document_changed = Signal()  # path or modified flag changed
    sig_status = Signal(str)

    def __init__(self, window):
        super().__init__(window)
        self.window = window
        self.path = None
        self.modified = False

    # --- state --------------------------------------------------------------------------

    def display_name(self) -> str:
        """The file name for the title bar and prompts."""
        return Path(self.path).name if self.path else tr("untitled", self.window.language)

    def mark_modified(self):
        """The user changed the program."""
        if not self.modified:
            self.modified = True
            self.sig_document_changed.emit()

    def _set_document(self, path, modified: bool):
        self.path = str(path) if path else None
        self.modified = modified
        if self.path:
            self.window.settings.add_recent_file(self.path)
        self.sig_document_changed.emit()

    # --- commands -----------------------------------------------------------------------

    def new(self):
        """Start an empty program for the active robot."""
        if self.maybe_save():
            self.window.breakpoints = []
            self.window.editor.clear()
            self._set_document(None, False)
            self.window.settings.last_file = None

    def open(self, path=None) -> bool:
        """Open a ``.rockly`` (or first-Rockly ``.xml``) program; ask for the file when ``path`` is None."""
        if not self.maybe_save():
            return False
        if path is None:
            path, _ = QFileDialog.getOpenFileName(self.window, tr("open", self.window.language).replace("&", ""),
                                                  self._start_folder(), tr("filter_open", self.window.language))
            if not path:
                return False
        return self._open_checked(path)

    def import_xml(self, path=None) -> bool:
        """Import a program the first Rockly saved as Blockly XML."""
        if not self.maybe_save():
            return False
        if path is None:
            path, _ = QFileDialog.getOpenFileName(self.window, tr("import_xml", self.window.language).replace("&", ""),
                                                  self._start_folder(), tr("filter_xml", self.window.language))
            if not path:
                return False
        return self._open_checked(path)

    def save(self) -> bool:
        """Save to the current file, or ask for one."""
        if self.path is None:
            return self.save_as()
        return self._write(self.path)

    def save_as(self, path=None) -> bool:
        """Save under a new name."""
        if path is None:
            suggestion = self.path or str(Path(self._start_folder()) / (self.display_name() + PROGRAM_SUFFIX))
            path, _ = QFileDialog.getSaveFileName(self.window, tr("save_as", self.window.language).replace("&", ""),
                                                  suggestion, tr("filter_program", self.window.language))
            if not path:
                return False
        if not path.endswith(PROGRAM_SUFFIX):
            path += PROGRAM_SUFFIX
        return self._write(path)

    def export_python(self, path=None) -> bool:
        """Write the generated Python to a ``.py`` file."""
        language = self.window.language
        if path is None:
            stem = Path(self.path).stem if self.path else tr("untitled", language)
            path, _ = QFileDialog.getSaveFileName(self.window, tr("export_python", language).replace("&", ""),
                                                  str(Path(self._start_folder()) / f"{stem}.py"), tr("filter_python", language))
            if not path:
                return False
        try:
            state = self.window.editor.call_blocking("getState")
            text = python_module_text(state["python"], self.window.profile.id, self.path and Path(self.path).name)
            write_text_atomically(path, text)
        except (RocklyError, RuntimeError) as error:
            self._show_error("cannot_export", error, untouched=False)
            return False
        self.sig_status.emit(tr("exported", language, path=path))
        return True

    def maybe_save(self) -> bool:
        """Ask to save unsaved changes; False when the user cancels (or saving failed)."""
        if not self.modified:
            return True
        language = self.window.language
        box = plain_message_box(self.window, QMessageBox.Icon.Warning, tr("save_changes_title", language),
                                tr("save_changes", language, name=self.display_name()),
                                QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard
                                | QMessageBox.StandardButton.Cancel)
        box.setInformativeText(tr("save_changes_detail", language))
        box.setDefaultButton(QMessageBox.StandardButton.Save)
        answer = box.exec()
        if answer == QMessageBox.StandardButton.Save:
            return self.save()
        return answer == QMessageBox.StandardButton.Discard

    # --- helpers ------------------------------------------------------------------------

    def _start_folder(self) -> str:
        recent = self.window.settings.recent_files
        return str(Path(recent[0]).parent) if recent else str(Path.home())

    def _open_checked(self, path) -> bool:
        window = self.window
        try:
            program = read_program_to_open(path, window.registry, window.profile)
        except RocklyError as error:
            self._show_error("cannot_open", error)
            return False

        def on_shown(result, error):
            if error:
                self._show_error("cannot_open", f"{path}: the editor could not show this program ({error})")
            elif result.get("untypedBlock"):
                self._show_error("cannot_open", f"{path}: the file is broken: block {result['untypedBlock']} has no type")
            elif result.get("unknownTypes"):
                self._show_error("cannot_open", unknown_blocks_error(program, result["unknownTypes"], window.registry))
            else:
                # What is shown differs from the file when the page replaced values or another
                # profile stands in: the program counts as changed, and the person is told.
                program.take_load_result(result)
                changed = bool(program.missing_profile or program.replaced_fields)
                if program.is_import:
                    window.breakpoints = []
                    self._set_document(None, True)
                    self.sig_status.emit(tr("imported", window.language, path=path))
                else:
                    window.breakpoints = list(program.breakpoints)
                    self._set_document(path, changed)
                    self.sig_status.emit(tr("opened", window.language, path=path))
                if changed:
                    self._show_opening_changes(program)

        window.show_program(program, on_shown)
        return True

    def _show_opening_changes(self, program):
        """Say what opening ``program`` changed: a stand-in profile, replaced field values."""
        language = self.window.language
        parts = []
        if program.missing_profile:
            parts.append(tr("missing_profile", language, declared=program.missing_profile,
                            installed=", ".join(program.installed_profiles), name=program.profile.display_name(language)))
        if program.replaced_fields:
            lines = [tr("replaced_fields", language)]
            for entry in program.replaced_fields:
                values = {"number": entry.get("number"), "type": entry.get("type"), "field": entry.get("field"),
                          "requested": _shown(entry.get("requested")), "now": _shown(entry.get("now"))}
                key = "field_left_out" if entry.get("missing") else "replaced_field"
                lines.append("• " + tr(key, language, **values))
            parts.append("\n".join(lines))
        box = plain_message_box(self.window, QMessageBox.Icon.Warning, tr("opened_with_changes", language),
                                "\n\n".join(parts))
        box.setInformativeText(tr("opened_with_changes_detail", language))
        box.setObjectName("opening_changes_box")
        box.open()

    def _write(self, path) -> bool:
        try:
            state = self.window.editor.call_blocking("getState")
            save_program(path, Program(self.window.profile.id, state["workspace"], self.window.breakpoints))
        except (RocklyError, RuntimeError) as error:
            self._show_error("cannot_save", error, untouched=False)
            return False
        self._set_document(path, False)
        self.sig_status.emit(tr("saved", self.window.language, path=path))
        return True

    def _show_error(self, title_key: str, error, untouched: bool = True):
        language = self.window.language
        box = plain_message_box(self.window, QMessageBox.Icon.Critical, tr(title_key, language), str(error))
        if untouched:
            box.setInformativeText(tr("nothing_changed", language))
        box.setObjectName("error_box")
        box.open()


def _shown(value) -> str:
    """A field value as a person reads it (text as it is, anything else as JSON would write it)."""
    if isinstance(value, str):
        return value
    return json.dumps(value, ensure_ascii=False)
