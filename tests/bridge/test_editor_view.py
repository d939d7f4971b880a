"""The Blockly page in QtWebEngine: start-up, toolbox, the JSON channel, offline, undo."""
import json

import pytest
from page_tools import add_block_as_user, block_types_on_page, run_js, toolbox_names
from program_builder import block, number, workspace
from PySide6.QtCore import QUrl
from PySide6.QtWebEngineCore import QWebEnginePage

from rockly_desktop.bridge.editor_view import EditorView, offline_web_profile


def call(qtbot, view, name, args=None):
    answers = []
    view.call(name, args, lambda result, error: answers.append((result, error)))
    qtbot.waitUntil(lambda: bool(answers), timeout=10000)
    return answers[0]


def test_editor_starts_with_the_hobbit_toolbox(qtbot, editor, hobbit):
    assert toolbox_names(qtbot, editor) == [
        "Drive", "Head", "Arm", "Tablet", "Sensors", "Time", "Expert", "ROS",
        "Logic", "Loops", "Math", "Text", "Lists", "Variables", "Functions"]
    assert hobbit.block_types <= editor.known_block_types


def test_every_toolbox_block_exists_in_the_page(qtbot, editor, hobbit):
    listed = run_js(qtbot, editor, """Blockly.getMainWorkspace().getToolbox().getToolboxItems()
        .flatMap(i => (i.getContents && Array.isArray(i.getContents())) ? i.getContents() : [])
        .filter(c => c.kind === 'block' || c.kind === 'BLOCK').map(c => c.type)""")
    assert len(listed) > 60
    assert set(listed) <= editor.known_block_types


def test_german_editor_shows_german_categories_and_blocks(qtbot, hobbit):
    view = EditorView()
    qtbot.addWidget(view)
    with qtbot.waitSignal(view.sig_ready, timeout=30000):
        view.start(hobbit.editor_config("de"), "de")
    assert toolbox_names(qtbot, view)[:4] == ["Fahren", "Kopf", "Arm", "Tablet"]
    view.load_workspace(workspace(block("hobbit_move", {"direction": "+"}, {"speed": number(1)}),
                                  block("controls_if", x=0, y=200)))
    texts = run_js(qtbot, view, "Blockly.getMainWorkspace().getTopBlocks(true).map(b => b.toString())")
    assert any("fahre" in text and "vorwärts" in text for text in texts)
    assert any(text.startswith("falls") for text in texts)  # Blockly's own messages in German


def test_calls_made_before_the_page_is_ready_are_queued_in_order(qtbot, hobbit):
    view = EditorView()
    qtbot.addWidget(view)
    answers = []
    view.start(hobbit.editor_config("en"), "en")
    view.load_workspace(workspace(block("hobbit_sos")), lambda r, e: answers.append(("load", r, e)))
    view.call("getState", None, lambda r, e: answers.append(("state", r, e)))
    assert not view.is_ready
    qtbot.waitUntil(lambda: len(answers) == 2, timeout=30000)
    assert [name for name, _, _ in answers] == ["load", "state"]
    assert answers[1][1]["python"] == "robot.call_sos()\n"


def test_edits_reach_python_with_workspace_and_code(qtbot, editor):
    with qtbot.waitSignal(editor.sig_changed, timeout=5000) as changed:
        add_block_as_user(qtbot, editor, "hobbit_sos")
    workspace_json, python, origin = changed.args
    assert origin == "user"
    assert python == "robot.call_sos()\n"
    assert workspace_json["blocks"]["blocks"][0]["type"] == "hobbit_sos"


def test_loading_a_program_is_not_a_user_edit(qtbot, editor):
    with qtbot.waitSignal(editor.sig_changed, timeout=5000) as changed:
        editor.load_workspace(workspace(block("hobbit_stop")))
    assert changed.args[2] == "load"
    assert changed.args[1] == "robot.stop()\n"


def test_undo_and_redo(qtbot, editor):
    add_block_as_user(qtbot, editor, "hobbit_sos")
    qtbot.waitUntil(lambda: block_types_on_page(qtbot, editor) == ["hobbit_sos"])
    # Blockly records the creation for undo when its event queue fires, a moment later.
    qtbot.waitUntil(lambda: run_js(qtbot, editor, "Blockly.getMainWorkspace().getUndoStack().length") > 0)
    editor.undo()
    qtbot.waitUntil(lambda: block_types_on_page(qtbot, editor) == [])
    editor.redo()
    qtbot.waitUntil(lambda: block_types_on_page(qtbot, editor) == ["hobbit_sos"])


def test_a_workspace_blockly_cannot_load_leaves_the_current_one(qtbot, editor):
    assert call(qtbot, editor, "load", {"workspace": workspace(block("hobbit_stop"))}) == ({"loaded": True}, None)
    broken = workspace(block("hobbit_move", inputs={"no_such_input": number(1)}))
    result, error = call(qtbot, editor, "load", {"workspace": broken})
    assert result is None and "no_such_input" in error
    state, _ = call(qtbot, editor, "getState")
    assert state["python"] == "robot.stop()\n"


def test_unknown_block_types_are_refused_before_the_workspace_changes(qtbot, editor):
    call(qtbot, editor, "load", {"workspace": workspace(block("hobbit_stop"))})
    program = workspace(block("turtle_go", next_block=block("hobbit_sos")),
                        block("controls_if", inputs={"IF0": block("lidar_ok")}))
    assert call(qtbot, editor, "load", {"workspace": program}) == ({"unknownTypes": ["lidar_ok", "turtle_go"]}, None)
    xml = '<xml><block type="hobbit_sos"><next><block type="fly_away"></block></next></block></xml>'
    assert call(qtbot, editor, "importXml", {"xml": xml}) == ({"unknownTypes": ["fly_away"]}, None)
    assert call(qtbot, editor, "getState")[0]["python"] == "robot.stop()\n"


def test_setup_can_show_a_program_in_its_first_frame(qtbot, hobbit):
    view = EditorView()
    qtbot.addWidget(view)
    answers = []
    with qtbot.waitSignal(view.sig_changed, timeout=30000) as changed:
        view.start(hobbit.editor_config("en"), "en", ("load", {"workspace": workspace(block("hobbit_sos"))}),
                   lambda result, error: answers.append((result, error)))
    assert changed.args[1:] == ["robot.call_sos()\n", "load"]
    qtbot.waitUntil(lambda: bool(answers))
    assert answers == [({"loaded": True}, None)]


def workspace_shown(qtbot, view) -> str:
    """'none' before Blockly made the workspace, then 'hidden' or 'visible'."""
    return run_js(qtbot, view, """typeof Blockly === 'undefined' || !Blockly.getMainWorkspace() ? 'none'
        : document.getElementById('workspace').style.visibility || 'visible'""")


def shown_editor(qtbot):
    view = EditorView()
    qtbot.addWidget(view)
    view.resize(1000, 700)
    view.show()
    return view


def test_a_prepared_page_shows_its_workspace_with_the_program_once_started(qtbot, hobbit):
    view = shown_editor(qtbot)
    view.prepare(hobbit.editor_config("en"), "en", {"addBreakpoint": "Add", "removeBreakpoint": "Remove"})
    qtbot.waitUntil(lambda: workspace_shown(qtbot, view) == "hidden", timeout=30000)
    assert not view.is_ready
    answers = []
    with qtbot.waitSignal(view.sig_changed, timeout=30000) as changed:
        view.start(hobbit.editor_config("en"), "en", ("load", {"workspace": workspace(block("hobbit_sos"))}),
                   lambda result, error: answers.append((result, error)),
                   {"addBreakpoint": "Add", "removeBreakpoint": "Remove"})
    assert changed.args[1:] == ["robot.call_sos()\n", "load"]
    qtbot.waitUntil(lambda: bool(answers))
    assert answers == [({"loaded": True}, None)]
    assert view.is_ready and hobbit.block_types <= view.known_block_types
    qtbot.waitUntil(lambda: workspace_shown(qtbot, view) == "visible")


@pytest.mark.parametrize("language", ["en", "de"])  # German: the setup waits for its block texts to load
def test_a_prepared_page_gets_the_program_right_behind_its_setup_not_after_its_answer(qtbot, hobbit, language):
    view = shown_editor(qtbot)
    sent, answers, sent_by_start = [], [], []
    view.channel.toPage.connect(lambda message: sent.append(json.loads(message)["call"]))
    view.prepare(hobbit.editor_config(language), language)

    def start_while_the_setup_runs():  # the prepared setup has just gone to the page
        view.start(hobbit.editor_config(language), language, ("load", {"workspace": workspace(block("hobbit_sos"))}),
                   lambda result, error: answers.append((result, error)))
        sent_by_start.append(list(sent))

    view.channel.sig_hello.connect(start_while_the_setup_runs)
    with qtbot.waitSignal(view.sig_changed, timeout=30000) as changed:
        qtbot.waitUntil(lambda: bool(answers), timeout=30000)
    assert sent_by_start == [["setup", "load", "show"]]
    assert changed.args[1:] == ["robot.call_sos()\n", "load"]
    assert answers == [({"loaded": True}, None)]
    assert view.is_ready and hobbit.block_types <= view.known_block_types
    qtbot.waitUntil(lambda: workspace_shown(qtbot, view) == "visible")


def test_a_prepared_setup_that_fails_answers_the_start_once_and_a_later_start_works(qtbot, hobbit):
    view = shown_editor(qtbot)
    errors, answers, later = [], [], []
    view.sig_page_error.connect(errors.append)
    broken = {**hobbit.editor_config("en"), "blocks": None}
    view.prepare(broken, "en")
    view.start(broken, "en", ("load", {"workspace": workspace(block("hobbit_sos"))}),
               lambda result, error: answers.append((result, error)))
    qtbot.waitUntil(lambda: bool(answers), timeout=30000)
    assert answers[0][0] is None and answers[0][1]
    assert any(error.startswith("the editor could not start") for error in errors)
    assert not view.is_ready
    with qtbot.waitSignal(view.sig_ready, timeout=30000):
        view.start(hobbit.editor_config("de"), "de", ("load", {"workspace": workspace(block("hobbit_stop"))}),
                   lambda result, error: later.append((result, error)))
    qtbot.waitUntil(lambda: bool(later))
    assert len(answers) == 1 and later == [({"loaded": True}, None)]
    assert call(qtbot, view, "getState")[0]["python"] == "robot.stop()\n"


def test_a_prepared_page_started_for_another_language_is_loaded_afresh(qtbot, hobbit):
    view = shown_editor(qtbot)
    view.prepare(hobbit.editor_config("en"), "en")
    qtbot.waitUntil(lambda: workspace_shown(qtbot, view) == "hidden", timeout=30000)
    with qtbot.waitSignal(view.sig_ready, timeout=30000):
        view.start(hobbit.editor_config("de"), "de")
    assert toolbox_names(qtbot, view)[:2] == ["Fahren", "Kopf"]
    assert workspace_shown(qtbot, view) == "visible"


def test_a_page_started_before_its_prepared_setup_was_sent_starts_as_asked(qtbot, hobbit):
    view = shown_editor(qtbot)
    view.prepare(hobbit.editor_config("en"), "en")
    with qtbot.waitSignal(view.sig_changed, timeout=30000) as changed:
        view.start(hobbit.editor_config("en"), "en", ("load", {"workspace": workspace(block("hobbit_stop"))}))
    assert changed.args[1] == "robot.stop()\n"
    assert workspace_shown(qtbot, view) == "visible"


def test_a_first_program_blockly_cannot_load_leaves_the_editor_working(qtbot, hobbit):
    view = shown_editor(qtbot)
    broken = workspace(block("hobbit_move", inputs={"no_such_input": number(1)}))
    answers = []
    view.start(hobbit.editor_config("en"), "en", ("load", {"workspace": broken}),
               lambda result, error: answers.append((result, error)))
    qtbot.waitUntil(lambda: bool(answers), timeout=30000)
    assert answers[0][0] is None and "no_such_input" in answers[0][1]
    assert call(qtbot, view, "load", {"workspace": workspace(block("hobbit_stop"))}) == ({"loaded": True}, None)


def test_unknown_page_call_is_an_error_not_a_hang(qtbot, editor):
    result, error = call(qtbot, editor, "formatDisk")
    assert result is None and "unknown call" in error


def test_nothing_is_fetched_from_the_network(qtbot, editor):
    interceptor = editor.interceptor
    editor.load_workspace(workspace(block("hobbit_move", {"direction": "+"}, {"speed": number(1)})))
    run_js(qtbot, editor, "Blockly.getMainWorkspace().getToolbox().selectItemByPosition(0)")
    qtbot.waitUntil(lambda: any("sprites.svg" in url or "media" in url for url in interceptor.requested), timeout=5000)
    assert any(url.endswith("blockly_compressed.js") for url in interceptor.requested)
    assert interceptor.blocked == []
    # The guard is real: anything using the editor's web profile cannot reach the network.
    probe = QWebEnginePage(offline_web_profile())
    probe.load(QUrl("http://example.invalid/blockly.js"))
    qtbot.waitUntil(lambda: "http://example.invalid/blockly.js" in interceptor.blocked, timeout=5000)
    probe.deleteLater()
    local = [url for url in interceptor.requested if url not in interceptor.blocked]
    assert all(url.startswith(("file:", "qrc:", "data:")) for url in local)


def test_the_silent_editor_starts_no_audio(qtbot, editor):
    # Blockly makes an AudioContext for each workspace the browser could play sounds in; Rockly plays none,
    # and starting Chromium's audio for them was most of the page's start-up work.
    workspaces = """(() => { const ws = Blockly.getMainWorkspace();
        return [ws, ws.getToolbox().getFlyout().getWorkspace(), ws.trashcan.flyout.getWorkspace()]; })()"""
    assert run_js(qtbot, editor, f"{workspaces}.map(w => Boolean(w.getAudioManager().context))") == [False] * 3
    assert run_js(qtbot, editor, "typeof window.AudioContext") == "undefined"


def test_numbers_too_big_for_64_bits_still_reach_python(qtbot, editor):
    # A child types 99999999999999999999: every later edit must still arrive (the app tracks changes by them).
    with qtbot.waitSignal(editor.sig_changed, timeout=10000) as loaded:
        editor.load_workspace(workspace(block("hobbit_move", {"direction": "+"}, {"speed": number(10 ** 20)}, id="m")))
    assert "robot.drive(100000000000000000000, 'forward')" in loaded.args[1]
    assert loaded.args[0]["blocks"]["blocks"][0]["inputs"]["speed"]["block"]["fields"]["NUM"] == 10 ** 20
    with qtbot.waitSignal(editor.sig_changed, timeout=10000) as edited:
        run_js(qtbot, editor, "Blockly.getMainWorkspace().getBlockById('m').setFieldValue('-', 'direction') || true")
    assert edited.args[2] == "user" and "robot.drive(100000000000000000000, 'backward')" in edited.args[1]
