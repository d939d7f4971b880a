"""The timeline bar on its own: ▶ at the end plays again from the start, and play/pause show glyphs that are there."""
from types import SimpleNamespace

from PySide6.QtCore import Qt
from PySide6.QtGui import QFontMetrics

from rockly_desktop.ui.replay.replay_bar import ReplayBar

DURATION = 1.2345  # s: not a whole number of the slider's milliseconds


def a_bar(qtbot):
    bar = ReplayBar(SimpleNamespace(code="en"))
    qtbot.addWidget(bar)
    bar.show_timeline(DURATION, [])
    return bar


def test_play_at_the_end_of_a_recording_starts_again_from_the_beginning(qtbot):
    bar = a_bar(qtbot)
    bar.jump_to(DURATION)  # the last moment (a marker there, the scrubber dragged to the end)
    with qtbot.waitSignal(bar.sig_moment, timeout=2000, check_params_cb=lambda seconds: seconds == 0.0):
        qtbot.mouseClick(bar.play_button, Qt.MouseButton.LeftButton)
    assert bar.playing


def test_playing_stops_at_the_end_and_play_then_starts_again(qtbot):
    bar = a_bar(qtbot)
    bar.speed.setCurrentIndex(bar.speed.count() - 1)  # 4×
    bar.jump_to(DURATION - 0.1)
    qtbot.mouseClick(bar.play_button, Qt.MouseButton.LeftButton)
    qtbot.waitUntil(lambda: not bar.playing, timeout=5000)
    assert bar.position == DURATION
    with qtbot.waitSignal(bar.sig_moment, timeout=2000, check_params_cb=lambda seconds: seconds == 0.0):
        qtbot.mouseClick(bar.play_button, Qt.MouseButton.LeftButton)


def shows_what_the_font_has(button) -> bool:
    """The button shows an icon, or text whose every character the button's font has."""
    if not button.icon().isNull():
        return True
    metrics = QFontMetrics(button.font())
    return bool(button.text()) and all(metrics.inFont(character) for character in button.text())


def test_play_and_pause_show_glyphs_the_font_has(qtbot):
    bar = a_bar(qtbot)
    bar.jump_to(0.0)
    assert shows_what_the_font_has(bar.play_button)
    qtbot.mouseClick(bar.play_button, Qt.MouseButton.LeftButton)
    assert bar.playing and shows_what_the_font_has(bar.play_button)
    bar.pause()
    assert shows_what_the_font_has(bar.play_button)
