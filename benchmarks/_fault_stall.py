"""The window's longest event-loop stall after STOP for runs of 10 s, 2 min and 10 min (aim <= 100 ms for all),
against the stall after a 1 s run of the driving program in the same window (issue 19, item 7).

After STOP the window opens the run's recording for its replay, and the recording grows with the
run. Two programs: HOBBIT driving on the simulator (forever drive, turn, count, print: ~50
messages a second recorded) and a tight loop (forever count and print: the recorder's budgets
full, ~3,400 messages a second, the most a run records). Each runs 1 s and 10 s for real. The
longer runs are made faster than real time, because what grows is the recording: the 10 s run's
recording is tiled (its messages again and again, each copy 10 s later, one start and one end)
into files of 2 and 10 minutes, holding what a run repeating those 10 s records (the same
channels, rates and sizes). For those the program runs 1 s and the window's ``runs.last_recording``
is pointed at the long file before STOP, so the window opens it after STOP as it opens its own.
Each stall is the longest lateness of a 10 ms timer from STOP until the replay bar shows (and
0.5 s more); "idle" is STOP until the run has ended, "ready" STOP until the bar shows.

    python benchmarks/_fault_stall.py   (or run() from benchmarks/faults.py)
"""
import json
import sys
import tempfile
import time
from pathlib import Path

from _paths import REPO

sys.path.insert(0, str(REPO / "benchmarks"))
from executor import event_loop_delays
from program_builder import block, number, stack, text, workspace

AIM_MS = 100
SLICE_SECONDS = 0.1
LONGEST_WAIT_SECONDS = 120


def forever(*body):
    return block("controls_whileUntil", {"MODE": "WHILE"}, {"BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
                                                             "DO": stack(*body)})


def counted(*body):
    program = workspace(forever(*body, block("math_change", {"VAR": {"id": "laps"}}, {"DELTA": number(1)}),
                                block("text_print", inputs={"TEXT": text("lap")})))
    program["variables"] = [{"name": "laps", "id": "laps"}]
    return program


PROGRAMS = {  # name: the program; a tight loop fills the recorder's budgets (100 blocks and 100 lines a tick)
    "driving": counted(block("hobbit_move", {"direction": "+"}, {"speed": number(0.3)}),
                       block("hobbit_turn", {"direction": "+"}, {"angle": number(90)})),
    "tight loop": counted(),
}


def tiled(source: Path, target: Path, copies: int) -> float:
    """Write ``copies`` of the recording ``source`` one after the other into ``target``; its length in seconds."""
    from mcap.records import Attachment, Channel, Message, Metadata, Schema
    from mcap.stream_reader import StreamReader
    from mcap.writer import CompressionType, Writer

    from rockly_desktop.recording import channels
    from rockly_desktop.recording.mcap_file import CHUNK_BYTES

    schemas, topics, messages, extras = {}, {}, [], []
    with open(source, "rb") as stream:
        for record in StreamReader(stream).records:
            if isinstance(record, Schema):
                schemas[record.id] = record
            elif isinstance(record, Channel):
                topics[record.id] = record
            elif isinstance(record, Message):
                messages.append(record)
            elif isinstance(record, (Metadata, Attachment)):
                extras.append(record)
    first, last = min(m.log_time for m in messages), max(m.log_time for m in messages)
    span = last - first + 10**6
    with open(target, "wb") as stream:
        writer = Writer(stream, chunk_size=CHUNK_BYTES, compression=CompressionType.ZSTD)
        writer.start(profile="", library="rockly")
        schema_ids = {old: writer.register_schema(s.name, s.encoding, s.data) for old, s in schemas.items()}
        channel_ids = {old: writer.register_channel(c.topic, c.message_encoding, schema_ids.get(c.schema_id, 0))
                       for old, c in topics.items()}
        for extra in extras:
            if isinstance(extra, Metadata):
                writer.add_metadata(extra.name, dict(extra.metadata))
            else:
                writer.add_attachment(extra.create_time, extra.log_time, extra.name, extra.media_type, extra.data)
        for copy in range(copies):
            for message in messages:
                if topics[message.channel_id].topic == channels.RUN:
                    event = json.loads(message.data)["event"]
                    if (event == "start" and copy) or (event in ("safe_stop", "end") and copy < copies - 1):
                        continue
                stamp = message.log_time + copy * span
                writer.add_message(channel_ids[message.channel_id], stamp, message.data, stamp)
        writer.finish()
    return copies * span / 1e9


def stop_and_measure(app, window, seconds: float, recording=None) -> tuple:
    """Run the program ``seconds``, STOP (the window opening ``recording`` if given, else its own) and measure:
    (longest stall in s, STOP until idle in s, STOP until the replay shows in s, the recording it opened)."""
    from PySide6.QtCore import QEventLoop, QTimer

    loop = QEventLoop()
    def running(state):
        if state == "running":
            loop.quit()

    window.runs.sig_state_changed.connect(running)
    window.runs.run()
    loop.exec()
    window.runs.sig_state_changed.disconnect(running)  # only this one: the window's own stay
    QTimer.singleShot(int(seconds * 1000), loop.quit)
    loop.exec()
    if recording is not None:
        window.runs.last_recording = str(recording)
    opened = window.runs.last_recording
    marks = {}
    def idle(_result):
        marks.setdefault("idle", time.perf_counter())

    window.runs.sig_finished.connect(idle)
    asked = time.perf_counter()
    window.runs.stop()
    delays = []
    while time.perf_counter() - asked < LONGEST_WAIT_SECONDS and not window.replay_bar.isVisible():
        delays += event_loop_delays(app, SLICE_SECONDS)
    marks["ready"] = time.perf_counter() if window.replay_bar.isVisible() else float("nan")
    delays += event_loop_delays(app, 0.5)
    window.runs.sig_finished.disconnect(idle)
    return max(delays), marks.get("idle", float("nan")) - asked, marks["ready"] - asked, Path(opened)


def describe(name, figures, base) -> str:
    """One case's figures as text."""
    from rockly_desktop.recording.reading import read_recording

    stall, idle, ready, opened = figures
    recording = read_recording(opened)
    return (f"{name} ({recording.duration:.0f} s recorded, {opened.stat().st_size / 1e6:.1f} MB, "
            f"{sum(recording.counts.values()):,} messages): stall {stall * 1000:.0f} ms "
            f"(ratio {stall / max(base, 1e-4):.2f}), idle {idle * 1000:.0f} ms, ready {ready * 1000:.0f} ms")


def run():
    """Measure and print the stalls after STOP (see the module's docstring)."""
    from PySide6.QtCore import QCoreApplication, QEvent, QEventLoop

    from rockly_desktop.app import build_main_window, create_application

    with tempfile.TemporaryDirectory() as folder:
        app = create_application()
        window = build_main_window(str(Path(folder) / "settings.ini"))
        window.settings.recordings_folder = str(Path(folder) / "recordings")
        window.show()
        loop = QEventLoop()
        window.editor.sig_ready.connect(loop.quit)
        window.start()
        loop.exec()
        lines, base = [], None
        for program, source in PROGRAMS.items():
            window.editor.call("load", {"workspace": source}, lambda _result, _error: loop.quit())
            loop.exec()
            short = stop_and_measure(app, window, 1.0)
            base = short[0] if base is None else base
            ten_seconds = stop_and_measure(app, window, 10.0)
            cases = [describe("1 s", short, base), describe("10 s", ten_seconds, base)]
            for name, copies in (("2 min", 12), ("10 min", 60)):
                long_file = Path(folder) / f"{program}-{name}.mcap".replace(" ", "")
                tiled(ten_seconds[3], long_file, copies)
                cases.append(describe(name, stop_and_measure(app, window, 1.0, long_file), base))
                long_file.unlink()  # a 10-minute tight loop's file is large
            lines.append(f"{program}: " + "; ".join(cases))
        window.document.modified = False
        window.close()
        window.deleteLater()
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    print("(e) window stall after STOP (aim <= 100 ms each), against the driving program's 1 s run:\n    "
          + "\n    ".join(lines))


if __name__ == "__main__":
    run()
