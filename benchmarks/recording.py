"""Recording figures, recording on vs off, measured in the same run.

(a) per-block cost: a 100,000-iteration loop shaped like the generated code
    (``__rockly__.check()``, ``__rockly__.block(ID)``, one statement), run without and
    with a recording (blocks beyond the recorder's budget are sampled, so a tight loop
    costs one extra test per block);
(b) a 1 kHz topic: the cost per message of the state store taking it, without and with
    a recording listening (rate cap 10 per second: most messages are counted and left out).

    python benchmarks/recording.py
"""
import statistics
import sys
import tempfile
import time
from numbers import Number
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

ITERATIONS = 100_000
MESSAGES = 100_000
AIM = 1.2
CODE = f"""n = 0
for count in range({ITERATIONS}):
    __rockly__.check()
    __rockly__.block('change')
    n = (n if isinstance(n, Number) else 0) + 1
"""


def run_once(recorder=None) -> float:
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.runner import ProgramRunner

    runner = ProgramRunner(CODE, {"Number": Number}, RunControl(), lambda event: None, {"n": "n"},
                           entered=None if recorder is None else recorder.blocks)
    if recorder is not None:
        recorder.follow(runner.hooks, runner.variables_snapshot)
    started = time.perf_counter()
    result = runner.run()
    elapsed = time.perf_counter() - started
    assert result.outcome == "finished", result
    return elapsed


def per_block(folder: Path):
    from rockly_desktop.recording.recorder import Recorder

    off, on = [], []
    for trial in range(7):  # interleaved, so both see the same machine
        off.append(run_once())
        recorder = Recorder(folder / f"blocks{trial}.mcap")
        recorder.start({"program": "benchmark"})
        try:
            on.append(run_once(recorder))
        finally:
            recorder.close()
    plain, recorded = statistics.median(off), statistics.median(on)
    print(f"(a) {ITERATIONS:,}-iteration loop: per block {plain / ITERATIONS * 1e9:.0f} ns without a recording, "
          f"{recorded / ITERATIONS * 1e9:.0f} ns with one, ratio {recorded / plain:.2f} (aim <= {AIM})")


def per_message(folder: Path):
    from rockly_desktop.core.state_store import StateStore
    from rockly_desktop.recording.recorder import Recorder

    def feed(store):
        message = {"data": 1.0}
        started = time.perf_counter()
        for _ in range(MESSAGES):
            store.record("/fast", "std_msgs/Float64", message)
        return time.perf_counter() - started

    off, on = [], []
    for trial in range(7):
        off.append(feed(StateStore()))
        store, recorder = StateStore(), Recorder(folder / f"topic{trial}.mcap", topic_rate=10)
        recorder.start({"program": "benchmark"})
        store.add_listener(recorder.topic)
        try:
            on.append(feed(store))
        finally:
            recorder.close()
    plain, recorded = statistics.median(off), statistics.median(on)
    print(f"(b) 1 kHz topic: {plain / MESSAGES * 1e6:.2f} µs a message without a recording, "
          f"{recorded / MESSAGES * 1e6:.2f} µs with one, ratio {recorded / plain:.2f}; "
          f"at 1 kHz that is {recorded * 1000 / MESSAGES * 100:.2f}% of one core")


if __name__ == "__main__":
    with tempfile.TemporaryDirectory() as folder:
        per_block(Path(folder))
        per_message(Path(folder))
