"""Two runs recording to one file: the second is refused before its robot moves and the first one's
recording stays whole; the file's lock goes with a run killed by SIGKILL."""
import datetime
import signal
import subprocess
import sys
from pathlib import Path

from program_builder import block, number, rockly_document, stack, text
from waiting import eventually

from rockly_desktop.recording import channels
from rockly_desktop.recording.library import keep_last, new_recording_path, recordings_in
from rockly_desktop.recording.mcap_file import McapFile
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording

REPO = Path(__file__).resolve().parents[2]
LAPS = 200


def laps_program(tmp_path, name, laps):
    path = tmp_path / name
    path.write_text(rockly_document([stack(block("controls_repeat_ext", id="laps", inputs={
        "TIMES": number(laps), "DO": stack(block("text_print", inputs={"TEXT": text("lap")}, id="say"),
                                           block("hobbit_wait", inputs={"seconds": number(0.05)}, id="rest"))}))]))
    return path


def start_recording(program, out):
    return subprocess.Popen([sys.executable, "-m", "rockly_desktop", "run", str(program), "--record", str(out),
                             "--language", "en"], cwd=REPO, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def laps_on_disk(path):
    try:
        return len(read_recording(path).on(channels.OUTPUT))
    except RecordingUnreadable:
        return 0


def test_a_second_run_recording_to_a_held_file_is_refused_the_first_file_stays_whole_sigkill_lets_go(
        tmp_path):
    out = tmp_path / "out.mcap"
    first = start_recording(laps_program(tmp_path, "first.rockly", LAPS), out)
    try:
        eventually(lambda: laps_on_disk(out) >= 2, timeout=60)
        second = subprocess.run([sys.executable, "-m", "rockly_desktop", "run",
                                 str(laps_program(tmp_path, "second.rockly", 3)), "--record", str(out)],
                                cwd=REPO, text=True, capture_output=True, timeout=120)
        assert first.poll() is None, "the first run ended before the second one tried"
        stdout, stderr = first.communicate(timeout=120)
    finally:
        if first.poll() is None:
            first.kill()
            first.communicate()
    assert second.returncode == 1
    assert second.stderr.strip() == f"rockly run: cannot record to {out}: another run is recording to it right now"
    assert "block" not in second.stdout
    assert first.returncode == 0, stderr
    recording = read_recording(out)
    assert recording.complete and recording.notes() == []
    assert recording.metadata["program"] == "first.rockly"
    assert len(recording.on(channels.OUTPUT)) == LAPS

    killed = start_recording(laps_program(tmp_path, "killed.rockly", LAPS), out)
    try:
        eventually(lambda: laps_on_disk(out) >= 2, timeout=60)
    finally:
        killed.send_signal(signal.SIGKILL)
        killed.communicate()
    after = subprocess.run([sys.executable, "-m", "rockly_desktop", "run",
                            str(laps_program(tmp_path, "after.rockly", 3)), "--record", str(out)],
                           cwd=REPO, text=True, capture_output=True, timeout=120)
    assert after.returncode == 0, after.stderr
    recording = read_recording(out)
    assert recording.complete and recording.metadata["program"] == "after.rockly"


def test_the_last_n_kept_never_deletes_a_recording_a_run_is_writing(tmp_path):
    folder = tmp_path / "recordings"
    older = new_recording_path(folder, "a.rockly", "sim", datetime.datetime(2026, 5, 1, 9, 0))
    writing = new_recording_path(folder, "b.rockly", "sim", datetime.datetime(2026, 5, 1, 9, 1))
    older.write_bytes(b"")
    file = McapFile(writing)  # another window's run, recording
    try:
        assert keep_last(folder, 0) == [older]
        assert recordings_in(folder) == [writing]
    finally:
        file.close()
    assert keep_last(folder, 0) == [writing]
