"""Blockly's own prompts (a new variable's name) in the real editor page: styled as the app, in its language."""
from page_tools import run_js

OPEN_PROMPT = "(Blockly.Variables.createVariableButtonHandler(Blockly.getMainWorkspace()), true)"
DIALOG = "document.querySelector('dialog.blocklyDialog[open]')"


def _open_prompt(qtbot, window) -> dict:
    run_js(qtbot, window.editor, OPEN_PROMPT)
    qtbot.waitUntil(lambda: run_js(qtbot, window.editor, f"!!{DIALOG}"), timeout=5000)
    return run_js(qtbot, window.editor, f"""(() => {{
        const dialog = {DIALOG}, ok = dialog.querySelector('.blocklyDialogConfirmButton');
        const style = element => getComputedStyle(element);
        return {{prompt: dialog.querySelector('.blocklyDialogPrompt').textContent,
                 buttons: [...dialog.querySelectorAll('button')].map(b => b.textContent),
                 buttonFont: style(ok).fontFamily, bodyFont: style(document.body).fontFamily,
                 okColour: style(ok).backgroundColor, radius: style(dialog).borderRadius}}; }})()""")


def _variables(qtbot, window) -> list:
    return run_js(qtbot, window.editor, "Blockly.getMainWorkspace().getVariableMap().getAllVariables()"
                                        ".map(v => v.getName())")


def test_the_new_variable_prompt_is_styled_and_german_in_a_german_window(qtbot, german_window):
    shown = _open_prompt(qtbot, german_window)
    assert shown["prompt"] == "Name der neuen Variable:" and shown["buttons"] == ["Okay", "Abbrechen"]
    assert shown["buttonFont"] == shown["bodyFont"] == "sans-serif"     # not the browser's serif form font
    assert shown["okColour"] == "rgb(77, 141, 255)" and shown["radius"] == "12px"
    run_js(qtbot, german_window.editor, f"""(() => {{ const dialog = {DIALOG};
        dialog.querySelector('input').value = 'Mia';
        dialog.querySelector('.blocklyDialogConfirmButton').click(); return true; }})()""")
    qtbot.waitUntil(lambda: "Mia" in _variables(qtbot, german_window), timeout=5000)
    assert not run_js(qtbot, german_window.editor, f"!!{DIALOG}")


def test_cancel_creates_no_variable(qtbot, window):
    shown = _open_prompt(qtbot, window)
    assert shown["prompt"] == "New variable name:" and shown["buttons"] == ["OK", "Cancel"]
    run_js(qtbot, window.editor, f"({DIALOG}.querySelector('.blocklyDialogCancelButton').click(), true)")
    qtbot.waitUntil(lambda: not run_js(qtbot, window.editor, f"!!{DIALOG}"), timeout=5000)
    assert _variables(qtbot, window) == []
