"""Recording onto a full disk, on a real tiny tmpfs: the run goes on, says once that it is not (or no
longer) recorded, and what was written before replays."""
import signal
import subprocess
import sys
from pathlib import Path

from program_builder import block, number, rockly_document, stack, text
from tiny_disk import fill, tiny_disk
from waiting import eventually

from rockly_desktop.recording import channels
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording

REPO = Path(__file__).resolve().parents[2]
LAPS = 300


def rockly(*args, timeout=120):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=timeout, cwd=REPO)


def laps_program(tmp_path, laps=LAPS):
    """A program printing 'lap' ``laps`` times, 0.05 s apart."""
    path = tmp_path / "laps.rockly"
    path.write_text(rockly_document([stack(block("controls_repeat_ext", id="laps", inputs={
        "TIMES": number(laps), "DO": stack(block("text_print", inputs={"TEXT": text("lap")}, id="say"),
                                           block("hobbit_wait", inputs={"seconds": number(0.05)}, id="rest"))}))]))
    return path


def printed_laps(stdout):
    return sum(line.split()[1:] == ["lap"] for line in stdout.splitlines())


def laps_on_disk(path):
    try:
        return len(read_recording(path).on(channels.OUTPUT))
    except RecordingUnreadable:  # not even the metadata yet
        return 0


def test_a_run_started_on_a_full_disk_goes_on_unrecorded_and_says_so_once(tmp_path):
    with tiny_disk(tmp_path / "disk") as disk:
        fill(disk)
        result = rockly("run", laps_program(tmp_path, 3), "--record", disk / "out.mcap", "--language", "en")
        assert result.returncode == 0, result.stderr
        assert result.stderr.strip() == (f"rockly run: warning: This run is not recorded: {disk / 'out.mcap'}: "
                                         "the disk is full. The run goes on.")
        assert printed_laps(result.stdout) == 3
        assert not (disk / "out.mcap").exists()


def test_a_disk_filling_up_during_a_run_stops_the_recording_once_and_keeps_it_readable(tmp_path):
    with tiny_disk(tmp_path / "disk") as disk:
        out = disk / "out.mcap"
        process = subprocess.Popen([sys.executable, "-m", "rockly_desktop", "run", str(laps_program(tmp_path)),
                                    "--record", str(out), "--language", "de"], cwd=REPO, text=True,
                                   stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        try:
            eventually(lambda: laps_on_disk(out) >= 5, timeout=60)
            fill(disk)
            stdout, stderr = process.communicate(timeout=120)
        finally:
            if process.poll() is None:
                process.send_signal(signal.SIGKILL)
                process.communicate()
        assert process.returncode == 0, stderr
        assert printed_laps(stdout) == LAPS  # the run went on to its end
        assert stderr.strip() == (f"rockly run: Warnung: Die Aufzeichnung ist abgebrochen: {out}: der Datenträger "
                                  "ist voll. Der Lauf geht weiter; was bis dahin aufgezeichnet wurde, bleibt erhalten.")
        recording = read_recording(out)
        assert not recording.complete and recording.notes() == []
        assert 5 <= len(recording.on(channels.OUTPUT)) < LAPS
        replay = rockly("replay", out, "--language", "en")
        assert replay.returncode == 0 and not replay.stderr
        assert replay.stdout.splitlines()[0].endswith("cut short, read to its end")
