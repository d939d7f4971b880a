"""Opening a recording built to hurt in the window (File → Open Recording…): it opens with what was
left out said in a box and the replay bar's note, in the window's language, or is refused in words."""
from hostile_recordings import MiB, RecordingBuilder, with_zero_chunks
from PySide6.QtWidgets import QMessageBox
from window_tools import opened_recording

from rockly_desktop.recording import channels


def shown_box(qtbot, window, name):
    qtbot.waitUntil(lambda: window.findChild(QMessageBox, name) is not None, timeout=5000)
    return window.findChild(QMessageBox, name)


def test_events_that_are_no_json_are_left_out_and_said_in_the_window(qtbot, window, tmp_path):
    path = tmp_path / "bad events.mcap"
    builder = RecordingBuilder(path)
    builder.event(0.0, channels.RUN, {"event": "start"})
    builder.event(0.1, channels.BLOCKS, {"block": "say", "type": "text_print"})
    builder.event(0.2, channels.BLOCKS, b"{not json")
    builder.event(0.3, channels.OUTPUT, [1, 2])
    builder.event(1.0, channels.RUN, {"event": "end", "outcome": "error", "message": "boom"})
    builder.finish()

    assert opened_recording(qtbot, window, path)
    assert window.replay_bar.isVisible()
    assert window.replay_bar.time_label.text().endswith("(parts left out)")
    assert window.replay_bar.time_label.toolTip() == "Damaged parts were left out: 2."
    assert [marker.kind for marker in window.replay_bar.markers.markers] == ["error"]
    assert shown_box(qtbot, window, "recording_partly_read_box").text() == "Damaged parts were left out: 2."


def test_a_tiny_file_of_huge_zero_messages_opens_in_german_saying_what_was_left_out(qtbot, german_window, tmp_path):
    path = tmp_path / "zeros.mcap"
    with_zero_chunks(path, 4, 800 * MiB)
    assert opened_recording(qtbot, german_window, path)
    assert german_window.replay_bar.time_label.text().endswith("(Teile ausgelassen)")
    box = shown_box(qtbot, german_window, "recording_partly_read_box")
    assert box.text() == "Zu große Teile wurden ausgelassen: 4."
    box.close()

    not_a_recording = tmp_path / "photo.mcap"
    not_a_recording.write_bytes(b"\x89PNG not a recording")
    assert not opened_recording(qtbot, german_window, not_a_recording)
    assert shown_box(qtbot, german_window, "recording_unreadable_box").text() == \
        f"{not_a_recording} ist keine MCAP-Aufzeichnung"
