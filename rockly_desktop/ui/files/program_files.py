"""The File menu's work: new, open, open a copy (an example), save, save as, recent files,
import XML, export Python, and restoring a program a crash left unsaved.

Every failure is shown as a plain message; a failed open or import leaves the program
on screen untouched, and a failed save leaves the file on disk untouched. A program that
opens with changes (its profile is not installed, or its blocks could not take some of
its values) is opened as changed, with a message saying what changed.

A file another window or program changed since this window opened or saved it (its
``core.file_stamp`` differs) is never written over unasked: Save asks whether to save as
another file, overwrite or reload it; when the window comes back to the front, a program
without changes of its own is reloaded and one with changes asks.
"""
import json
from pathlib import Path

from PySide6.QtCore import QObject, Signal
from PySide6.QtWidgets import QMessageBox

from rockly_desktop.bridge.editor_view import ANSWER_TIMEOUT_MS
from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ProgramFileError, RocklyError
from rockly_desktop.core.export import python_module_text
from rockly_desktop.core.file_stamp import stamp_file
from rockly_desktop.core.program import PROGRAM_SUFFIX, Program, save_program, write_text_atomically
from rockly_desktop.profiles.opening import read_program_to_open, unknown_blocks_error
from rockly_desktop.ui.files.disk_changes import OVERWRITE, RELOAD, SAVE_AS, changed_on_disk_box
from rockly_desktop.ui.files.file_dialogs import FileDialogs
from rockly_desktop.ui.message_boxes import plain_message_box
from rockly_desktop.ui.texts import tr


class ProgramFiles(QObject):
    """The File menu's commands on the window's Document.

    Commands that need the page's answer (save, export, and whatever asks to save
    first) carry on when it comes: they take ``then(ok)``, called once the command has
    ended (at once when nothing had to wait; False when it failed or was cancelled).
    ``parent`` is the widget the dialogs belong to; ``file_dialogs`` asks for files (kiosk mode
    puts dialogs confined to one folder in its place); ``may_reload()`` says whether the program on
    screen may be replaced now (not while it runs); ``keep_changes(then)``, when set, keeps unsaved
    changes without asking and then calls ``then()`` (a kiosk keeps a visitor's program in its own folder).
    """

    sig_status = Signal(str)
    sig_show_program = Signal(object, object)  # ProgramToOpen, callback(result, error) with the page's answer
    sig_program_replaced = Signal()  # New, Open, Import or Restore put another program on screen

    def __init__(self, document, editor, settings, registry, parent):
        super().__init__(parent)
        self.document = document
        self.editor = editor
        self.settings = settings
        self.registry = registry
        self._saves_waiting = 0
        self._after_saves = []  # continuations waiting until no save waits for the page
        self.file_dialogs = FileDialogs()
        self.may_reload = lambda: True
        self.keep_changes = None
        self._asked_about = None  # the change on disk last asked about (asked once, until Save)

    @property
    def saving(self) -> bool:
        """True while a save waits for the page's answer."""
        return self._saves_waiting > 0

    # --- commands -----------------------------------------------------------------------

    def new(self, *, ask: bool = True):
        """Start an empty program for the active robot (after asking to save changes, unless not ``ask``)."""
        if ask:
            self.maybe_save(then=lambda ok: ok and self.new(ask=False))
            return
        self.document.breakpoints = []
        self.editor.clear()
        self._set_file(None, False)
        self.settings.last_file = None
        self.sig_program_replaced.emit()

    def open(self, path=None, then=None):
        """Open a ``.rockly`` (or first-Rockly ``.xml``) program; ask for the file when ``path`` is None."""
        self._open_after_asking(path, "open", "filter_open", then)

    def open_copy(self, path, name: str, then=None):
        """Open a copy of the program at ``path`` (a shipped example called ``name``): untitled, so
        Save asks where to keep it and the file itself is never written."""
        self.maybe_save(then=lambda ok: self._open_checked(path, then, copy_of=name) if ok else _report(then, False))

    def import_xml(self, path=None, then=None):
        """Import a program the first Rockly saved as Blockly XML."""
        self._open_after_asking(path, "import_xml", "filter_xml", then)

    def restore(self, recovery, then=None):
        """Show the program a recovery file kept (core.recovery.Recovery) as unsaved changes
        to the file it belongs to (after asking to save the program on screen)."""
        def go_on(may_replace: bool):
            if may_replace:
                self._open_checked(recovery.path, then, recovery)
            else:
                _report(then, False)

        self.maybe_save(then=go_on)

    def save(self, then=None):
        """Save to the current file (asking first when it changed on disk), or ask for one."""
        if self.document.path is None:
            self.save_as(then=then)
            return
        changed = self.document.changed_on_disk()
        if changed is None:
            self._write(self.document.path, then, guard=True)
        else:
            self._settle_disk_change(changed, then)

    def follow_disk(self):
        """Take in a change another window or program made to the file (the window came back to the
        front): a program without changes here is reloaded; with changes, the person is asked once."""
        if self._saves_waiting:
            return
        changed = self.document.changed_on_disk()
        if changed is None or changed == self._asked_about:
            return
        if self.document.modified or not self.may_reload():
            self._settle_disk_change(changed, None)
        else:
            self._reload(None)

    def save_as(self, path=None, then=None):
        """Save under a new name."""
        if path is None:
            language = self.settings.language
            suggestion = self.document.path or str(Path(self._start_folder()) / (self.document.display_name(language)
                                                                               + PROGRAM_SUFFIX))
            path = self.file_dialogs.save_file(self.parent(), tr("save_as", language).replace("&", ""),
                                               suggestion, tr("filter_program", language))
            if not path:
                _report(then, False)
                return
        if not path.endswith(PROGRAM_SUFFIX):
            path += PROGRAM_SUFFIX
        self._write(path, then)

    def export_python(self, path=None, then=None):
        """Write the generated Python to a ``.py`` file (a name without a suffix gets ``.py``)."""
        language = self.settings.language
        if path is None:
            stem = Path(self.document.path).stem if self.document.path else tr("untitled", language)
            path = self.file_dialogs.save_file(self.parent(), tr("export_python", language).replace("&", ""),
                                               str(Path(self._start_folder()) / f"{stem}.py"),
                                               tr("filter_python", language))
            if not path:
                _report(then, False)
                return
        if not Path(path).suffix:
            path += ".py"
        source = self.document.path and Path(self.document.path).name

        def write(state):
            write_text_atomically(path, python_module_text(state["python"], self.document.profile.id, source))
            self.sig_status.emit(tr("exported", self.settings.language, path=path))

        self._with_page_state(write, "cannot_export", then)

    def maybe_save(self, then):
        """Ask to save unsaved changes, then ``then(ok)``: False when the person cancelled or saving failed.

        A save still waiting for the page is waited for first, so nothing is lost.
        """
        if self._saves_waiting:
            self._after_saves.append(lambda: self.maybe_save(then))
            return
        if not self.document.modified:
            then(True)
            return
        if self.keep_changes is not None:
            self.keep_changes(lambda: then(True))
            return
        language = self.settings.language
        box = plain_message_box(self.parent(), QMessageBox.Icon.Warning, tr("save_changes_title", language),
                                tr("save_changes", language, name=self.document.display_name(language)),
                                QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard
                                | QMessageBox.StandardButton.Cancel)
        box.setInformativeText(tr("save_changes_detail", language))
        box.setDefaultButton(QMessageBox.StandardButton.Save)
        answer = box.exec()
        if answer == QMessageBox.StandardButton.Save:
            self.save(then=then)
        else:
            then(answer == QMessageBox.StandardButton.Discard)

    # --- helpers ------------------------------------------------------------------------

    def _set_file(self, path, modified: bool, disk_stamp=None):
        self._asked_about = None
        self.document.set_file(path, modified, disk_stamp)
        if path:
            self.settings.add_recent_file(str(path))

    def _start_folder(self) -> str:
        recent = self.settings.recent_files
        return str(Path(recent[0]).parent) if recent else str(Path.home())

    def _open_after_asking(self, path, title_key: str, filter_key: str, then):
        def go_on(may_replace: bool):
            chosen = path
            if may_replace and chosen is None:
                language = self.settings.language
                chosen = self.file_dialogs.open_file(self.parent(), tr(title_key, language).replace("&", ""),
                                                     self._start_folder(), tr(filter_key, language))
            if may_replace and chosen:
                self._open_checked(chosen, then)
            else:
                _report(then, False)

        self.maybe_save(then=go_on)

    def _settle_disk_change(self, changed, then):
        """Ask what to do with the file ``changed`` on disk (its FileStamp now), then do it."""
        self._asked_about = changed
        language, may_reload = self.settings.language, self.may_reload()
        answer = changed_on_disk_box(self.document.display_name(language), language, self.parent(), may_reload).exec()
        if answer == OVERWRITE:
            self._write(self.document.path, then, guard=True, accepted=changed)
        elif answer == SAVE_AS:
            self.save_as(then=then)
        elif answer == RELOAD and may_reload:
            self._reload(then)
        else:
            _report(then, False)

    def _reload(self, then):
        """Show the file as it is on disk now; ``then(False)``: nothing of this window's was saved."""
        name = self.document.display_name(self.settings.language)

        def reloaded(ok):
            if ok:
                self.sig_status.emit(tr("reloaded", self.settings.language, name=name))
            _report(then, False)

        self._open_checked(self.document.path, reloaded)

    def _open_checked(self, path, then, recovery=None, copy_of=None):
        disk_stamp = stamp_file(path)  # before reading: a change made while reading is noticed, not missed
        try:
            program = read_program_to_open(path, self.registry, self.document.profile)
        except RocklyError as error:
            self._show_error("cannot_open", error)
            _report(then, False)
            return

        def on_shown(result, error):
            language = self.settings.language
            if error:
                self._show_error("cannot_open", tr("editor_could_not_show", language, path=path, error=error))
            elif result.get("untypedBlock"):
                self._show_error("cannot_open", f"{path}: " + tr("file_broken_no_type", language,
                                                                  number=result["untypedBlock"]))
            elif result.get("unknownTypes"):
                self._show_error("cannot_open", unknown_blocks_error(program, result["unknownTypes"], self.registry))
            else:
                # What is shown differs from the file when the page replaced values or another
                # profile stands in: the program counts as changed, and the person is told.
                program.take_load_result(result)
                changed = bool(program.missing_profile or program.replaced_fields)
                if recovery is not None:
                    self.document.breakpoints = list(program.breakpoints)
                    # the file as the crashed window knew it: changed since, Save asks before writing
                    self._set_file(recovery.program_path, True,
                                   recovery.file_stamp or (recovery.program_path and stamp_file(recovery.program_path)))
                    self.sig_status.emit(tr("restored", language))
                elif copy_of is not None:
                    self.document.breakpoints = list(program.breakpoints)
                    self._set_file(None, changed)
                    self.sig_status.emit(tr("example_opened", language, name=copy_of))
                elif program.is_import:
                    self.document.breakpoints = []
                    self._set_file(None, True)
                    self.sig_status.emit(tr("imported", language, path=path))
                else:
                    self.document.breakpoints = list(program.breakpoints)
                    self._set_file(path, changed, disk_stamp)
                    self.sig_status.emit(tr("opened", language, path=path))
                if changed:
                    self._show_opening_changes(program)
                self.sig_program_replaced.emit()
                _report(then, True)
                return
            _report(then, False)

        self.sig_show_program.emit(program, on_shown)

    def _show_opening_changes(self, program):
        """Say what opening ``program`` changed: a stand-in profile, replaced field values."""
        language = self.settings.language
        parts = []
        if program.missing_profile:
            parts.append(tr("missing_profile", language, declared=program.missing_profile,
                            installed=", ".join(program.installed_profiles),
                            name=program.profile.display_name(language)))
        if program.replaced_fields:
            lines = [tr("replaced_fields", language)]
            for entry in program.replaced_fields:
                values = {"number": entry.get("number"), "type": entry.get("type"), "field": entry.get("field"),
                          "requested": _shown(entry.get("requested")), "now": _shown(entry.get("now"))}
                key = "field_left_out" if entry.get("missing") else "replaced_field"
                lines.append("• " + tr(key, language, **values))
            parts.append("\n".join(lines))
        box = plain_message_box(self.parent(), QMessageBox.Icon.Warning, tr("opened_with_changes", language),
                                "\n\n".join(parts))
        box.setInformativeText(tr("opened_with_changes_detail", language))
        box.setObjectName("opening_changes_box")
        box.open()

    def _write(self, path, then, guard=False, accepted=None):
        """Save to ``path``; with ``guard`` (the document's own file) only while the file on disk is
        as this window knew it, or is ``accepted``, the change the person chose to overwrite."""
        def write(state):
            if guard:
                now = self.document.changed_on_disk()
                if now is not None and now != accepted:
                    raise ProgramFileError(path, app_local_text("file_changed_meanwhile"))
            disk_stamp = save_program(path, Program(self.document.profile.id, state["workspace"],
                                                    self.document.breakpoints,
                                                    self.document.profile.packs_used(state["workspace"])))
            self._set_file(path, False, disk_stamp)
            self.sig_status.emit(tr("saved", self.settings.language, path=path))

        self._saves_waiting += 1
        self._with_page_state(write, "cannot_save", lambda ok: self._save_ended(ok, then))

    def _save_ended(self, ok: bool, then):
        self._saves_waiting -= 1
        _report(then, ok)
        if not self._saves_waiting:
            waiting, self._after_saves = self._after_saves, []
            for go_on in waiting:
                go_on()

    def _with_page_state(self, use, error_key: str, then):
        """Ask the page for its state; ``use(state)`` when it comes, then ``then(ok)``."""
        def answered(state, error):
            if not error:
                try:
                    use(state)
                except RocklyError as problem:
                    error = problem
            if error:
                self._show_error(error_key, error, untouched=False)
            _report(then, not error)

        self.editor.call("getState", None, answered, timeout_ms=ANSWER_TIMEOUT_MS)

    def _show_error(self, title_key: str, error, untouched: bool = True):
        language = self.settings.language
        text = error.in_language(language) if isinstance(error, RocklyError) else str(error)
        box = plain_message_box(self.parent(), QMessageBox.Icon.Critical, tr(title_key, language), text)
        if untouched:
            box.setInformativeText(tr("nothing_changed", language))
        box.setObjectName("error_box")
        box.open()


def _report(then, ok: bool):
    """Tell a command's continuation how it ended (if it has one)."""
    if then is not None:
        then(ok)


def _shown(value) -> str:
    """A field value as a person reads it (text as it is, anything else as JSON would write it)."""
    if isinstance(value, str):
        return value
    return json.dumps(value, ensure_ascii=False)
