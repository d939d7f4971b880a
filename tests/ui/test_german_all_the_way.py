"""German all the way: numbers with a decimal comma wherever Rockly writes them for people, every
text following a live language switch, and toolbar labels that fit a 1280 px wide window."""
import re

import pytest
from PySide6.QtWidgets import QToolButton

from rockly_desktop.core.app_texts import app_text
from rockly_desktop.ui.help_dialogs import show_shortcuts
from rockly_desktop.ui.run.block_badges import badge_texts

DECIMAL_COMMA = re.compile(r"\d,\d")
DECIMAL_POINT = re.compile(r"\d\.\d")


def test_the_replay_bar_writes_seconds_with_a_decimal_comma_in_german(qtbot, german_window):
    german_window.replay_bar.show_timeline(2.0, [])
    assert german_window.replay_bar.time_label.text() == "2,0 s von 2,0 s"


def test_the_health_lights_details_use_a_decimal_comma_in_german(qtbot, german_window):
    health = german_window.health
    qtbot.waitUntil(lambda: "Hz" in health.toolTip(), timeout=5000)
    details = health.toolTip()
    assert DECIMAL_COMMA.search(details) and not DECIMAL_POINT.search(details), details


def test_the_state_panel_shows_decimal_commas_in_german(qtbot, german_window):
    panels = german_window.state_dock.widget()
    qtbot.waitUntil(lambda: bool(DECIMAL_COMMA.search(panels.values().get("Position x", ""))), timeout=5000)
    assert not any(DECIMAL_POINT.search(text) for text in panels.values().values())


def test_catalogue_texts_write_their_numbers_the_readers_way():
    assert app_text("replay_time", "de", now=0.25, total=12.0) == "0,2 s von 12,0 s"
    assert app_text("replay_time", "en", now=0.25, total=12.0) == "0.2 s of 12.0 s"
    assert "0,15 m/s" in app_text("limit_speed_clamped", "de", speed=0.15)
    assert "0.15 m/s" in app_text("limit_speed_clamped", "en", speed=0.15)


def test_a_blocks_badge_says_its_seconds_with_a_decimal_comma_in_german():
    badges = badge_texts({"b1": ("succeeded", 1.25)}, "de")
    assert "1,2 s" in badges["b1"]["text"] or "1,3 s" in badges["b1"]["text"]


def test_after_a_live_switch_the_shortcut_list_and_the_replay_bar_are_german(qtbot, window):
    window.replay_bar.show_timeline(2.0, [])
    english_page = show_shortcuts(window, "en")
    window.set_language("de")
    qtbot.waitUntil(lambda: window.language == "de", timeout=10000)
    bar = window.replay_bar
    assert bar.time_label.text() == "2,0 s von 2,0 s"
    assert bar.play_button.toolTip() == app_text("replay_play", "de")
    assert bar.speed.toolTip() == app_text("replay_speed", "de")
    assert bar.findChild(QToolButton, "replay_close").toolTip() == app_text("replay_close", "de")
    german_page = show_shortcuts(window, "de")
    for page in (german_page, english_page):    # a new page, and the one open during the switch
        text = page.browser.toPlainText()
        assert app_text("save", "de").replace("&", "") in text
        assert app_text("save", "en").replace("&", "") not in text, text
        assert "Save" not in text and "Undo" not in text, text
        assert page.windowTitle() == app_text("shortcuts_title", "de")


def overflowing(toolbar) -> list:
    """The toolbar's visible actions that do not fit (their buttons hidden behind its » button)."""
    extension = toolbar.findChild(QToolButton, "qt_toolbar_ext_button")
    hidden = [action.text() or action.objectName() for action in toolbar.actions()
              if action.isVisible() and not action.isSeparator() and not toolbar.widgetForAction(action).isVisible()]
    return hidden + (["»"] if extension is not None and extension.isVisible() else [])


# 1280 px screens: maximised, and the first window less a window frame's borders
@pytest.mark.parametrize("width", [1280, 1260])
@pytest.mark.parametrize("language", ["en", "de"])
def test_no_toolbar_action_overflows_at_1280_px(qtbot, window, language, width):
    window.set_language(language)
    qtbot.waitUntil(lambda: window.language == language, timeout=10000)
    window.resize(width, 800)
    qtbot.waitUntil(lambda: window.width() == width and window.run_toolbar.width() >= width - 20, timeout=3000)
    toolbar = window.run_toolbar
    for state in ("idle", "running", "paused"):
        toolbar.set_state(state)
        qtbot.waitUntil(lambda: overflowing(toolbar) == [], timeout=2000)
    toolbar.set_state("idle")
