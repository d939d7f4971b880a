"""A program printing in a tight loop: its output reaches the console in batches, and STOP ends it."""
from program_builder import block, text
from test_running import load

from rockly_desktop.executor.events import OutputPrinted
from rockly_desktop.ui.docks.console_dock import MAX_LINES


def endless_print():
    return block("controls_whileUntil", {"MODE": "WHILE"}, {"BOOL": block("logic_boolean", {"BOOL": "TRUE"}),
                                                             "DO": block("text_print", inputs={"TEXT": text("tick")})})


def test_endless_printing_arrives_in_batches_and_stop_ends_it(qtbot, window):
    load(qtbot, window, endless_print())
    events = []
    window.runs.run()
    qtbot.waitUntil(lambda: window.runs.thread is not None)
    window.runs.thread.sig_event.connect(events.append)

    qtbot.waitUntil(lambda: window.console.lines().count("tick") > 1000, timeout=20000)
    with qtbot.waitSignal(window.runs.sig_finished, timeout=20000) as finished:
        window.runs.stop()

    assert finished.args[0].outcome == "stopped"
    assert not [event for event in events if isinstance(event, OutputPrinted)]  # lines come from the buffer
    lines = window.console.lines()
    assert len(lines) <= MAX_LINES
    assert lines[-1] == "Program stopped"


def test_the_console_shows_a_batch_in_order_after_what_came_before(qtbot, window):
    window.console.append("before", "info")
    window.console.append_lines(["one", "two", "three"])

    assert window.console.lines()[-4:] == ["before", "one", "two", "three"]


def test_lines_printed_too_fast_to_keep_are_counted(qtbot, window):
    from rockly_desktop.executor.output_buffer import OutputBuffer

    buffer = OutputBuffer(limit=3)
    for number in range(10):
        buffer.add(str(number))

    assert buffer.take() == (["7", "8", "9"], 7)
    assert buffer.take() == ([], 0)


def test_the_window_takes_a_batch_at_a_time_oldest_first():
    from rockly_desktop.executor.output_buffer import OutputBuffer

    buffer = OutputBuffer(limit=100, batch=4)
    for number in range(10):
        buffer.add(str(number))

    assert buffer.take() == (["0", "1", "2", "3"], 0)
    assert buffer.take(everything=True) == (["4", "5", "6", "7", "8", "9"], 0)
