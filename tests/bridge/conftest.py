"""A shown editor page with the HOBBIT profile, checked for page errors."""
import pytest

from rockly_desktop.bridge.editor_view import EditorView


@pytest.fixture
def editor(qtbot, hobbit):
    """The editor page, shown (a hidden page runs its timers too rarely for Blockly)."""
    view = EditorView()
    qtbot.addWidget(view)
    view.resize(1000, 700)
    view.show()
    errors = []
    view.sig_page_error.connect(errors.append)
    with qtbot.waitSignal(view.sig_ready, timeout=30000):
        view.start(hobbit.editor_config("en"), "en")
    yield view
    assert errors == [], f"the page reported errors: {errors}"
