"""Recording files as people meet them: rockly run --record and rockly replay, a run killed
with SIGKILL, files that are no recording, the recordings folder."""
import datetime
import signal
import subprocess
import sys
from pathlib import Path

import pytest
from mcap.writer import Writer
from program_builder import block, number, rockly_document, stack, text
from waiting import eventually

from rockly_desktop.recording import channels
from rockly_desktop.recording.library import keep_last, new_recording_path, recordings_in
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording

REPO = Path(__file__).resolve().parents[2]


def rockly(*args, timeout=120):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def drive(block_id, metres=1):
    return block("hobbit_move", {"direction": "+"}, {"speed": number(metres)}, id=block_id)


def program_file(tmp_path, *blocks):
    path = tmp_path / "tour.rockly"
    path.write_text(rockly_document([stack(*blocks)]))
    return path


def test_rockly_run_records_and_rockly_replay_prints_the_timeline(tmp_path):
    program = program_file(tmp_path, drive("there"), block("text_print", inputs={"TEXT": text("arrived")}, id="say"),
                           block("hobbit_emo", {"emotion": "HAPPY"}, id="smile"))
    out = tmp_path / "out.mcap"
    result = rockly("run", program, "--speed", "20", "--record", out)
    assert result.returncode == 0, result.stderr
    replay = rockly("replay", out)
    assert replay.returncode == 0, replay.stderr
    lines = replay.stdout.splitlines()
    assert lines[0].startswith("# tour.rockly on sim (hobbit)")
    assert [line.split()[2:4] for line in lines if line.split()[1:2] == ["block"]] == [
        ["there", "hobbit_move"], ["say", "text_print"], ["smile", "hobbit_emo"]]
    assert any(line.split()[1:] == ["print", "arrived"] for line in lines)
    assert lines[-1].split()[1:] == ["end", "finished"]


def test_a_recording_killed_with_sigkill_reads_up_to_its_last_flushed_chunk(tmp_path):
    program = program_file(tmp_path, block("controls_repeat_ext", id="laps", inputs={
        "TIMES": number(1000), "DO": drive("lap", 0.2)}))
    out = tmp_path / "killed.mcap"
    process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", "run", str(program), "--record", str(out)],
                               cwd=REPO, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        def laps_on_disk():
            try:
                return len(read_recording(out).on(channels.BLOCKS))
            except RecordingUnreadable:  # not even the metadata yet
                return 0

        eventually(lambda: laps_on_disk() >= 4, timeout=60)
    finally:
        process.send_signal(signal.SIGKILL)
        process.wait(10)
    recording = read_recording(out)
    assert not recording.complete
    assert recording.metadata["program"] == "tour.rockly"
    assert [entry.data["block"] for entry in recording.on(channels.BLOCKS)][:4] == ["laps", "lap", "laps", "lap"]
    assert rockly("replay", out).returncode == 0


def test_a_file_that_is_no_recording_is_refused_with_a_clear_message(tmp_path):
    text_file = tmp_path / "notes.mcap"
    text_file.write_text("shopping list\n")
    with pytest.raises(RecordingUnreadable, match="is not an MCAP recording"):
        read_recording(text_file)
    foreign = tmp_path / "foreign.mcap"
    with open(foreign, "wb") as stream:
        writer = Writer(stream)
        writer.start(profile="", library="someone else")
        writer.finish()
    with pytest.raises(RecordingUnreadable, match="no recording of a Rockly run"):
        read_recording(foreign)
    result = rockly("replay", text_file)
    assert result.returncode == 1 and "is not an MCAP recording" in result.stderr and not result.stdout
    assert text_file.read_text() == "shopping list\n"


def test_recordings_are_named_by_date_program_and_robot_and_the_last_n_are_kept(tmp_path):
    folder = tmp_path / "recordings"
    made = []
    for minute in range(5):
        path = new_recording_path(folder, "My square.rockly", "simulator", datetime.datetime(2026, 5, 1, 9, minute))
        path.write_bytes(b"")
        made.append(path)
    assert made[0].name == "2026-05-01_09-00-00_My-square_simulator.mcap"
    (folder / "keep-me.mcap").write_bytes(b"")
    assert keep_last(folder, 3) == made[:2]
    assert recordings_in(folder) == made[2:]
    assert (folder / "keep-me.mcap").exists()
    listing = rockly("recordings", "list", "--folder", folder)
    assert listing.returncode == 0 and [line.split()[-1] for line in listing.stdout.splitlines()] == [
        str(path) for path in reversed(made[2:])]


def test_a_recording_that_cannot_be_written_stops_rockly_run_before_the_robot_moves(tmp_path):
    program = program_file(tmp_path, drive("there"))
    result = rockly("run", program, "--record", tmp_path / "no such folder" / "out.mcap")
    assert result.returncode == 1
    assert "cannot record to" in result.stderr and "No such file or directory" in result.stderr
    assert "block" not in result.stdout
