"""Ten simulated minutes of a 1 kHz topic: memory stays flat and the file holds what the rate cap lets in.

Simulated time comes from a fake clock that the store and the recorder share (as a run at
--speed 10 would see it, without waiting a minute of real time): every message moves it 1 ms.
"""
import resource

from recorded_reading import channels_and_messages

from rockly_desktop.core.state_store import StateStore
from rockly_desktop.recording.recorder import Recorder
from rockly_desktop.robot.ros1.recording_codec import Ros1Encoder
from rockly_desktop.robot.sim.sim_world import SimWorld

MINUTES = 10
RATE_CAP = 10


class SimulatedClock:
    def __init__(self):
        self.ns = 1_700_000_000 * 10**9

    def seconds(self):
        return self.ns / 1e9

    def nanoseconds(self):
        return self.ns


def test_ten_minutes_of_a_1khz_topic_keep_memory_flat_and_the_file_within_the_cap(tmp_path):
    clock = SimulatedClock()
    world, store = SimWorld(), StateStore(clock=clock.seconds)
    world.tap(store.record)
    recorder = Recorder(tmp_path / "long.mcap", Ros1Encoder(), topic_rate=RATE_CAP, clock=clock.nanoseconds)
    recorder.start({"program": "long.rockly"})
    store.add_listener(recorder.topic)
    try:
        peak_kib = []
        for minute in range(MINUTES):
            for millisecond in range(60_000):
                clock.ns += 1_000_000
                world.publish("/fast", "std_msgs/Float64", {"data": minute * 60 + millisecond / 1000})
            peak_kib.append(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
    finally:
        recorder.close()
    assert peak_kib[-1] - peak_kib[1] < 4 * 1024, peak_kib  # flat after the first minute (the store's history full)

    found, messages = channels_and_messages(tmp_path / "long.mcap")
    assert found["/fast"] == ("ros1", "std_msgs/Float64", "ros1msg")
    values = [message.data for message in messages["/fast"]]
    assert MINUTES * 60 * RATE_CAP - 1 <= len(values) <= MINUTES * 60 * RATE_CAP + 1
    assert values == sorted(values) and values[-1] > MINUTES * 60 - 1
    stats = messages["/rockly/recording"][-1]
    assert stats["overflow"] == 0 and stats["capped"]["/fast"] == MINUTES * 60_000 - len(values)
    assert (tmp_path / "long.mcap").stat().st_size < 1024 * 1024
