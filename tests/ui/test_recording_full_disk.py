"""A window whose recordings folder is on a full disk (a real tiny tmpfs): the run goes on, the console
says once that it is not (or no longer) recorded, and the cut recording replays."""
from page_tools import call_page
from program_builder import block, number, stack, text, workspace
from tiny_disk import fill, tiny_disk

from rockly_desktop.recording import channels
from rockly_desktop.recording.reading import RecordingUnreadable, read_recording


def laps(count):
    return stack(block("controls_repeat_ext", id="laps", inputs={
        "TIMES": number(count), "DO": stack(block("text_print", inputs={"TEXT": text("lap")}, id="say"),
                                            block("hobbit_wait", inputs={"seconds": number(0.05)}, id="rest"))}))


def console_lines(window, starting):
    return [line for line in window.console.view.toPlainText().splitlines() if starting in line]


def laps_on_disk(path):
    try:
        return len(read_recording(path).on(channels.OUTPUT))
    except RecordingUnreadable:
        return 0


def test_a_run_started_on_a_full_disk_goes_on_and_the_console_says_it_is_not_recorded(qtbot, window, tmp_path):
    with tiny_disk(tmp_path / "disk") as disk:
        fill(disk)
        window.settings.recordings_folder = str(disk)
        call_page(qtbot, window.editor, "load", {"workspace": workspace(laps(3))})
        with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as finished:
            assert window.runs.run()
        assert finished.args[0].outcome == "finished"
        said = console_lines(window, "This run is not recorded: ")
        assert len(said) == 1 and said[0].endswith(": the disk is full. The run goes on.")
        assert len(console_lines(window, "lap")) == 3
        assert window.runs.last_recording is None and sorted(path.name for path in disk.iterdir()) == ["filler"]


def test_a_disk_filling_up_during_a_run_is_said_once_in_german_and_the_cut_recording_replays(qtbot, german_window,
                                                                                             tmp_path):
    window = german_window
    window.simulator_speed = 1.0  # the laps' waits take their time: the disk fills while they run
    with tiny_disk(tmp_path / "disk") as disk:
        window.settings.recordings_folder = str(disk)
        call_page(qtbot, window.editor, "load", {"workspace": workspace(laps(300))})
        with qtbot.waitSignal(window.runs.sig_finished, timeout=120000) as finished:
            assert window.runs.run()
            qtbot.waitUntil(lambda: window.runs.last_recording is not None
                            and laps_on_disk(window.runs.last_recording) >= 3, timeout=60000)
            fill(disk)
        assert finished.args[0].outcome == "finished"
        said = console_lines(window, "Die Aufzeichnung ist abgebrochen: ")
        assert said and said[0].endswith(": der Datenträger ist voll. Der Lauf geht weiter; was bis dahin "
                                         "aufgezeichnet wurde, bleibt erhalten.")
        assert len(said) == 1
        assert len(console_lines(window, "lap")) == 300
        qtbot.waitUntil(window.replay_bar.isVisible, timeout=10000)
        assert window.replay_bar.time_label.text().endswith("(abgebrochen)")
        assert 3 <= len(window.replay.moments.recording.on(channels.OUTPUT)) < 300
