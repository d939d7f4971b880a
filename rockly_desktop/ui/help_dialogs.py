"""Help → First Steps and Keyboard Shortcuts: short pages inside the app, made from the window's
texts and its actions (so a shortcut shown is the one that works)."""
from html import escape

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QDialog, QDialogButtonBox, QMenu, QTextBrowser, QVBoxLayout

from rockly_desktop.ui.run.run_toolbar import RUN_KEYS
from rockly_desktop.ui.texts import tr

_STEPS = ("first_steps_robot", "first_steps_blocks", "first_steps_run", "first_steps_glow", "first_steps_loose",
          "first_steps_put_back", "first_steps_examples")
_TEACHERS_STEPS = {"first_steps_robot"}  # what they point to asks for the teacher's PIN in a kiosk: not told there

_STYLE = "<style>body { font-size: 11pt; } li { margin-bottom: 8px; } p { margin-bottom: 10px; }</style>"


def action_shortcuts(window) -> list:
    """(command, keys) of every action of ``window`` that has a shortcut now, in the order they were made."""
    rows, seen = [], set()
    for action in window.findChildren(QAction):
        if not _in_menu_bar_or_window(action, window):
            continue
        keys = ", ".join(sequence.toString(QKeySequence.SequenceFormat.NativeText) for sequence in action.shortcuts())
        command = _plain(action.text())
        if keys and (command, keys) not in seen:
            seen.add((command, keys))
            rows.append((command, keys))
    return rows


def _in_menu_bar_or_window(action, window) -> bool:
    """Whether ``action`` is the window's own or in a menu the menu bar shows (not one that a language
    switch replaced and that is still waiting to be deleted)."""
    top, parent = None, action.parent()
    while isinstance(parent, QMenu):
        top, parent = parent, parent.parent()
    return top is None or top.menuAction() in window.menuBar().actions()


def first_steps_html(window, language: str) -> str:
    """The First Steps page: the texts, with the window's own names and shortcuts filled in (in a kiosk, only
    the steps a visitor can take)."""
    def keys(name):
        action = window.findChild(QAction, name)
        shortcut = action.shortcut() if action is not None else QKeySequence()
        return shortcut.toString(QKeySequence.SequenceFormat.NativeText) or tr("no_shortcut", language)

    # Run's key belongs to Continue while a program is paused: the page names the key Run has when idle.
    run_keys = QKeySequence(RUN_KEYS).toString(QKeySequence.SequenceFormat.NativeText)
    values = {
        "robot_menu": _plain(tr("menu_robot", language)), "run": _plain(tr("run", language)), "run_keys": run_keys,
        "stop": _plain(tr("stop", language)), "stop_keys": keys("action_stop"),
        "put_back": _plain(tr("reset_robot", language)), "put_back_keys": keys("action_reset_robot"),
        "examples": _plain(tr("menu_examples", language)), "file_menu": _plain(tr("menu_file", language)),
        "save": _plain(tr("save", language)),
    }
    names = {name: f"<b>{escape(value)}</b>" for name, value in values.items()}
    shown = [key for key in _STEPS if not (window.settings.kiosk_mode and key in _TEACHERS_STEPS)]
    steps = "".join(f"<li>{escape(tr(key, language)).format(**names)}</li>" for key in shown)
    return (f"{_STYLE}<h2>{escape(tr('first_steps_title', language))}</h2>"
            f"<p>{escape(tr('first_steps_intro', language))}</p><ol>{steps}</ol>")


# The keys of the window's Tab order and of Blockly's own keyboard navigation (in the block editor):
# (the keys' name, a text key for them or None when the name is the same in every language, what they do)
_EDITOR_KEYS = (("", "keys_tab_name", "keys_tab"), ("T", None, "keys_t"), ("W", None, "keys_w"),
                ("", "keys_arrows_name", "keys_arrows"), ("", "keys_enter_name", "keys_enter"), ("M", None, "keys_m"),
                ("", "keys_delete_name", "keys_delete"), ("", "keys_copy_name", "keys_copy"),
                ("", "keys_menu_name", "keys_menu"), ("", "keys_escape_name", "keys_escape"))


def shortcuts_html(window, language: str) -> str:
    """The Keyboard Shortcuts page: a table made from the window's actions, then the block editor's keys."""
    def table(rows):
        cells = "".join(f"<tr><td>{escape(command)}</td><td><b>{escape(keys)}</b></td></tr>" for command, keys in rows)
        return (f"<table cellpadding='6'><tr><th align='left'>{escape(tr('shortcut_command', language))}</th>"
                f"<th align='left'>{escape(tr('shortcut_keys', language))}</th></tr>{cells}</table>")

    editor_rows = [(tr(what, language), tr(name_key, language) if name_key else name)
                   for name, name_key, what in _EDITOR_KEYS]
    return (f"{_STYLE}<h2>{escape(tr('shortcuts_title', language))}</h2>{table(action_shortcuts(window))}"
            f"<h3>{escape(tr('editor_keys_title', language))}</h3>{table(editor_rows)}")


class HelpPage(QDialog):
    """A small window showing one help page (HTML made here, nothing from the web); ``page(language)``
    makes its (title, HTML), again when the window's language changes."""

    def __init__(self, page, language: str, parent=None):
        super().__init__(parent)
        self._page = page
        self.browser = QTextBrowser(self)
        self.browser.setOpenLinks(False)
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close, self)
        buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        layout.addWidget(self.browser)
        layout.addWidget(buttons)
        self.set_language(language)
        self.resize(560, 480)

    def set_language(self, language: str):
        """Show the page in ``language``."""
        title, html = self._page(language)
        self.setWindowTitle(title)
        self.browser.setHtml(html)


def show_first_steps(window, language: str) -> HelpPage:
    """Open the First Steps page over ``window`` (not modal: the person can try the steps meanwhile)."""
    return _show(window, "first_steps_dialog", language,
                 lambda lang: (tr("first_steps_title", lang), first_steps_html(window, lang)))


def show_shortcuts(window, language: str) -> HelpPage:
    """Open the Keyboard Shortcuts page over ``window``."""
    return _show(window, "shortcuts_dialog", language,
                 lambda lang: (tr("shortcuts_title", lang), shortcuts_html(window, lang)))


def retitle_help_pages(window, language: str):
    """Say the help pages open over ``window`` in ``language`` (after a language switch)."""
    for page in window.findChildren(HelpPage):
        page.set_language(language)


def _show(window, name: str, language: str, page) -> HelpPage:
    page = HelpPage(page, language, window)
    page.setObjectName(name)
    page.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
    page.show()
    return page


def _plain(text: str) -> str:
    """A menu text without its mnemonic marks and trailing dots ("&Open…" is "Open")."""
    return text.replace("&&", "\0").replace("&", "").replace("\0", "&").rstrip("…").rstrip(".")
