"""Recordings built to hurt: ``rockly replay`` opens each within bounded time and memory and says,
in the reader's language, what it left out; nothing a file holds gives a traceback."""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from hostile_recordings import MiB, RecordingBuilder, sparse, with_zero_chunks, zero_message_chunk
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from mcap.writer import CompressionType

from rockly_desktop.recording import channels, reading
from rockly_desktop.recording.mcap_records import Bounds
from rockly_desktop.recording.moments import Moments
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording
from rockly_desktop.recording.timeline import timeline_lines

REPO = Path(__file__).resolve().parents[2]
REPLAY_SECONDS = 60  # generous on a loaded machine: before the bounds, the sparse file took > 180 s
REPLAY_RSS_MB = 300  # before the bounds: 4.1 GB


def replay_measured(*args):
    """``rockly replay ARGS`` in a fresh parent process: (its result, the replay's peak RSS in MB)."""
    measure = ("import resource, subprocess, sys\n"
               "result = subprocess.run([sys.executable, '-m', 'rockly_desktop', 'replay', *sys.argv[1:]],"
               " capture_output=True, text=True)\n"
               "sys.stdout.write(result.stdout)\n"
               "sys.stderr.write(result.stderr)\n"
               "print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, file=sys.stderr)\n"
               "sys.exit(result.returncode)\n")
    result = subprocess.run([sys.executable, "-c", measure, *map(str, args)], capture_output=True, text=True,
                            timeout=REPLAY_SECONDS, cwd=REPO)
    *stderr, peak_kb = result.stderr.splitlines()
    result.stderr = "\n".join(stderr)
    return result, int(peak_kb) / 1024


def test_a_tiny_file_of_huge_zero_messages_opens_in_bounded_memory_and_says_what_it_left_out(tmp_path):
    hostile = tmp_path / "zeros.mcap"
    with_zero_chunks(hostile, 4, 800 * MiB)  # 104 KB on disk, 3.2 GB of messages
    lying = tmp_path / "lying.mcap"  # chunks that say they are small and inflate to 800 MB
    with_zero_chunks(lying, 2, 800 * MiB, stated_size=1000)
    assert hostile.stat().st_size < 200_000

    result, peak_mb = replay_measured(hostile, "--language", "en")
    assert result.returncode == 0, result.stderr
    assert peak_mb < REPLAY_RSS_MB
    assert "Traceback" not in result.stderr
    assert "rockly replay: warning: Parts too big to read were left out: 4." in result.stderr
    assert [line.split()[1:4] for line in result.stdout.splitlines()[1:]] == [
        ["start"], ["block", "look", "hobbit_head"], ["end", "finished"]]

    result, peak_mb = replay_measured(lying, "--language", "de")
    assert result.returncode == 0 and peak_mb < REPLAY_RSS_MB
    assert "rockly replay: Warnung: Beschädigte Teile wurden ausgelassen: 2." in result.stderr


def test_a_sparse_file_after_a_valid_start_opens_at_once_as_cut_short(tmp_path):
    hole = tmp_path / "hole.mcap"
    sparse(hole, 2 << 30)  # 2 GB of zeros after the metadata and a run's start
    result, peak_mb = replay_measured(hole, "--language", "en")
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines()[0].endswith("cut short, read to its end")
    assert peak_mb < REPLAY_RSS_MB

    no_start = tmp_path / "header only.mcap"
    with open(no_start, "wb") as stream:
        stream.write(b"\x89MCAP0\r\n\x01" + (10).to_bytes(8, "little") + bytes(10))
    with open(no_start, "r+b") as stream:
        stream.truncate(2 << 30)
    result, _peak = replay_measured(no_start, "--language", "de")
    assert result.returncode == 1 and not result.stdout
    assert result.stderr.strip() == f"rockly replay: {no_start} ist eine MCAP-Datei, aber keine Aufzeichnung " \
                                    "eines Rockly-Laufs"


def bad_events(path):
    """A run whose events include five that are not what their channels hold."""
    builder = RecordingBuilder(path)
    builder.event(0.0, channels.RUN, {"event": "start"})
    builder.event(0.1, channels.BLOCKS, {"block": "say", "type": "text_print"})
    builder.event(0.2, channels.BLOCKS, b"{not json")
    builder.event(0.3, channels.OUTPUT, [1, 2])
    builder.event(0.4, channels.COMMANDS, {"kind": 5, "name": "/cmd_vel"})
    builder.event(0.5, channels.RUN, {"event": "explode"})
    builder.event(0.6, channels.BLOCKS, {"type": "text_print"})
    builder.event(0.7, channels.OUTPUT, {"text": "hello"})
    builder.event(0.8, channels.COMMANDS, {"kind": "outcome", "name": "/move_base", "block": "say"})
    builder.event(1.0, channels.RUN, {"event": "end", "outcome": "finished", "block": None})
    builder.finish()


def test_events_that_are_no_json_or_not_their_channels_are_left_out_and_said(tmp_path):
    recording = tmp_path / "bad events.mcap"
    bad_events(recording)
    result, _peak = replay_measured(recording, "--language", "en")
    assert result.returncode == 0, result.stderr
    assert result.stderr.strip() == "rockly replay: warning: Damaged parts were left out: 5."
    assert [line.split()[1:] for line in result.stdout.splitlines()[1:]] == [
        ["start"], ["block", "say", "text_print", "0.900", "s", "goal", "/move_base"], ["print", "hello"],
        ["end", "finished"]]
    result, _peak = replay_measured(recording, "--language", "de")
    assert result.stderr.strip() == "rockly replay: Warnung: Beschädigte Teile wurden ausgelassen: 5."


def test_records_bigger_than_their_bounds_are_skipped_unread(tmp_path):
    path = tmp_path / "big.mcap"
    builder = RecordingBuilder(path)
    builder.event(0.0, channels.RUN, {"event": "start"})
    builder.raw(zero_message_chunk(99, 70 * MiB))  # over the 64 MiB a chunk may hold
    builder.event(1.0, channels.OUTPUT, {"text": "x" * (2 * MiB)})  # over the 1 MiB an event may hold
    builder.event(2.0, channels.RUN, {"event": "end", "outcome": "finished"})
    builder.finish()
    recording = read_recording(path)
    assert (recording.too_big, recording.damaged, recording.complete) == (1, 1, True)
    assert [entry.data["event"] for entry in recording.entries] == ["start", "end"]


@pytest.fixture(scope="module")
def good_recording(tmp_path_factory):
    path = tmp_path_factory.mktemp("good") / "good.mcap"
    builder = RecordingBuilder(path, CompressionType.NONE)  # a flipped byte lands in an event's JSON
    for step in range(20):
        builder.event(step / 10, channels.BLOCKS, {"block": f"b{step}", "type": "text_print"})
        builder.event(step / 10 + 0.01, channels.OUTPUT, {"text": json.dumps(step)})
    builder.event(2.0, channels.RUN, {"event": "end", "outcome": "error", "message": "boom"})
    builder.finish()
    return path.read_bytes()


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(flips=st.lists(st.tuples(st.integers(min_value=0), st.integers(min_value=0, max_value=255)), max_size=8),
       cut=st.integers(min_value=0))
def test_a_damaged_recording_opens_or_is_refused_in_words_never_with_another_error(tmp_path, good_recording,
                                                                                 flips, cut):
    data = bytearray(good_recording[:cut % (len(good_recording) + 1)] if cut % 3 == 0 else good_recording)
    for where, value in flips:
        if data:
            data[where % len(data)] = value
    path = tmp_path / "damaged.mcap"
    path.write_bytes(bytes(data))
    try:
        recording = read_recording(path)
    except RecordingUnreadable as error:
        assert str(error.in_language("de"))
        return
    timeline_lines(recording)
    Moments(recording).markers()


def test_rockly_recordings_list_says_its_messages_in_the_language_asked_and_lists_a_hostile_file_as_it_is(tmp_path):
    folder = tmp_path / "recordings"
    folder.mkdir()
    listing = subprocess.run([sys.executable, "-m", "rockly_desktop", "recordings", "list", "--folder", str(folder),
                              "--language", "de"], capture_output=True, text=True, timeout=REPLAY_SECONDS, cwd=REPO)
    assert listing.returncode == 0 and listing.stdout.strip() == f"Keine Aufzeichnungen in {folder}."
    hole = folder / "2026-05-01_09-00-00_tour_sim.mcap"
    sparse(hole, 2 << 30)
    listing = subprocess.run([sys.executable, "-m", "rockly_desktop", "recordings", "list", "--folder", str(folder),
                              "--language", "de"], capture_output=True, text=True, timeout=REPLAY_SECONDS, cwd=REPO)
    assert listing.returncode == 0 and listing.stdout.split() == ["2097152.0", "KiB", str(hole)]


def test_reading_stops_at_its_bounds_on_everything_and_says_how_far_it_read(tmp_path, monkeypatch):
    path = tmp_path / "long.mcap"
    with_zero_chunks(path, 6, MiB)  # robot messages of 1 MiB each, between a start and an end
    whole = read_recording(path)
    assert whole.complete and whole.notes() == [] and len(whole.topic_data["/camera"]) == 6

    in_part = read_recording(path, Bounds(total_bytes=3 * MiB + 1000))
    assert in_part.read_in_part and not in_part.complete
    assert [str(note) for note in in_part.notes()] == [
        "This recording is too big to read whole: only its first 0.5 s were read."]
    assert timeline_lines(in_part)[0] == "# tour.rockly on sim (hobbit), started 2026-05-01T09:00:00+00:00"
    assert read_recording(path, Bounds(records=8)).read_in_part

    monkeypatch.setattr(reading, "ROBOT_BYTES", 2 * MiB + 100)
    kept = read_recording(path)
    assert len(kept.topic_data["/camera"]) == 2 and kept.on(channels.RUN)[-1].data["event"] == "end"
    assert [note.in_language("de") for note in kept.notes()] == [
        "Die Topics des Roboters sind zu groß, um sie ganz zu behalten: sie werden bis 0,0 s gezeigt."]
