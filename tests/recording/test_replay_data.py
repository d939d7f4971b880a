"""Preparing a replay in a thread of its own without holding the GIL for long: the collector is paused while a
recording is read and what was read is kept out of its later passes; a replay let go is emptied a slice at a time."""
import gc
import threading

from test_printed_lines import printed_fast  # noqa: F401 - the fixture

from rockly_desktop.ui.replay import recording_reader


def test_reading_pauses_the_collector_and_keeps_what_it_read_out_of_its_passes(printed_fast):  # noqa: F811
    frozen = gc.get_freeze_count()
    enabled = []
    original = recording_reader.replay_data

    def noted(*args):
        enabled.append(gc.isenabled())
        return original(*args)

    recording_reader.replay_data = noted
    try:
        reader = recording_reader.RecordingReader(printed_fast, str)
        reader.start()
        assert reader.wait(30000)
    finally:
        recording_reader.replay_data = original
    assert enabled == [False] and gc.isenabled()
    assert gc.get_freeze_count() > frozen
    assert reader.data.moments.recording.entries


def test_a_replay_let_go_is_emptied_in_another_thread(printed_fast, monkeypatch):  # noqa: F811
    data = recording_reader.replay_data(printed_fast, str)
    threads = []
    empty = recording_reader._empty
    monkeypatch.setattr(recording_reader, "_empty", lambda *args: (threads.append(threading.current_thread()),
                                                                   empty(*args)))
    recording_reader.release(data)
    threads_started = [thread for thread in threading.enumerate() if thread.name == "rockly-replay-release"]
    for thread in threads_started:
        thread.join(30)
    assert threads and threading.main_thread() not in threads
    assert data.moments.recording.entries == [] and data.printed == [] and data.markers == []


def test_rocklys_events_written_out_of_time_order_are_read_in_time_order(tmp_path):
    from rockly_desktop.recording import channels
    from rockly_desktop.recording.mcap_file import McapFile
    from rockly_desktop.recording.reading import read_recording

    written = McapFile(tmp_path / "shuffled.mcap")
    written.metadata(channels.METADATA, {"program": "shuffled.rockly"})
    for stamp in (1_000, 3_000, 2_000, 4_000, 0):
        written.write_json(channels.OUTPUT, *channels.SCHEMAS[channels.OUTPUT], stamp, {"text": str(stamp)})
    written.close()
    entries = read_recording(tmp_path / "shuffled.mcap").entries
    assert [entry.data["text"] for entry in entries] == ["0", "1000", "2000", "3000", "4000"]
    assert [entry.time for entry in entries] == [0.0, 1e-6, 2e-6, 3e-6, 4e-6]
