"""The window's texts: Rockly's catalogue (``resources/locale``), looked up by key (block texts come from the profiles).

A new text is one entry in ``resources/locale/messages.pot`` (English) and one in each
``LANG.po`` (``scripts/move-texts.py`` writes both from ``"key": ("English", "German")`` pairs).
"""
from rockly_desktop.core.app_texts import app_catalogue, app_text, language_name, languages
from rockly_desktop.core.numbers import number_text


def tr(key: str, language: str, **values) -> str:
    """The text ``key`` in ``language`` (English where it has no translation), with ``values`` filled in."""
    return app_text(key, language, **values)


def said_in(text, language: str) -> str:
    """A catalogue text (``LocalText``) in ``language``, or anything else as it is (a topic's name, a URI)."""
    return text.in_language(language) if hasattr(text, "in_language") else str(text)


def language_names() -> dict:
    """{code: the language's name in itself} of every language Rockly speaks."""
    return {code: language_name(code) for code in languages()}


# Blockly's keyboard hints (its German messages leave them English): Blockly's message name -> text key
_NAVIGATION_HINTS = {f"KEYBOARD_NAV_{name.upper()}_HINT": f"nav_hint_{name}" for name in (
    "block_navigation", "constrained_move", "copied", "cut", "flyout_label", "unconstrained_move",
    "workspace_navigation")}

# More of Blockly's words its German messages leave English (key names in its menus, its shortcuts) and the
# repeat block's title (its "%1-mal" showed as "4 -mal": a field stands apart from the text after it)
_BLOCKLY_WORDS = {name: f"blockly_{name.lower()}" for name in (
    "BACKSPACE_KEY", "COMMAND_KEY", "CONTROL_KEY", "DELETE_KEY", "END_KEY", "ENTER_KEY", "ESCAPE",
    "HOME_KEY", "INSERT_KEY", "OPTION_KEY", "PAGE_DOWN_KEY", "PAGE_UP_KEY", "SHIFT_KEY", "SPACE_KEY", "TAB_KEY",
    "COPY_SHORTCUT", "CUT_SHORTCUT", "PASTE_SHORTCUT", "EDIT_BLOCK_CONTENTS", "MOVE_BLOCK", "SHORTCUTS_DELETE",
    "SHORTCUTS_DUPLICATE", "SHORTCUTS_ESCAPE", "SHORTCUTS_CLEANUP", "SHORTCUTS_SHOW_CONTEXT_MENU", "RESET_ZOOM",
    "ZOOM_IN", "ZOOM_OUT", "OPEN_TRASH", "CLOSE", "CONTROLS_REPEAT_TITLE", "ROCKLY_PYTHON_BLOCK_TOOLTIP")}


def editor_page_texts(language: str) -> dict:
    """The editor page's own texts in ``language`` (``EditorView.start``'s ``texts``): its menu, its
    hint, a number field's refusal, and ``blocklyMsg``, Blockly's keyboard hints and the words of its own it leaves
    untranslated."""
    return {"addBreakpoint": tr("add_breakpoint", language), "removeBreakpoint": tr("remove_breakpoint", language),
            "editMadeBlock": tr("edit_made_block_here", language),
            "emptyHint": tr("empty_hint", language, run=tr("run", language)),
            "numberRefused": tr("number_refused", language, example=number_text(2.5, language)),
            "blocklyMsg": {name: tr(key, language) for name, key in {**_NAVIGATION_HINTS, **_BLOCKLY_WORDS}.items()}}


def robot_problem(error, language: str) -> tuple:
    """(what went wrong, what to try next) for an error reaching the robot, in ``language``.

    An error that names its ``reason`` (like RosUnavailable's 'no_master') is said with
    the texts ``ros_REASON`` and ``ros_REASON_hint``; any other is shown as it is, with no hint.
    """
    key = f"ros_{getattr(error, 'reason', None)}"
    catalogue = app_catalogue()
    if key not in catalogue:
        return str(error), ""
    values = getattr(error, "values", {})
    hint = f"{key}_hint"
    return tr(key, language, **values), tr(hint, language, **values) if hint in catalogue else ""
