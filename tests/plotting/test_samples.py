"""The Plot panel's data without Qt: sample buffers, reading new samples from the store, the CSV."""
import csv

from rockly_desktop.core.state_store import StateStore
from rockly_desktop.plotting.csv_export import write_tidy_csv
from rockly_desktop.plotting.samples import SampleBuffer, read_new_samples

X = "pose.pose.position.x"


class Clock:
    """The store's time, moved by the test."""

    def __init__(self):
        self.now = 1000.0

    def __call__(self):
        return self.now


def test_sample_buffer_keeps_order_across_wraps():
    buffer = SampleBuffer(10)
    everything = []
    for start in range(0, 200, 7):
        chunk = list(range(start, start + 7))
        buffer.extend(chunk, [v * 2 for v in chunk])
        everything += chunk
        assert buffer.times.tolist() == everything[-10:]
        assert buffer.values.tolist() == [v * 2 for v in everything[-10:]]
    buffer.extend(range(1000, 1025), range(25))  # more than the bound at once
    assert buffer.times.tolist() == list(range(1015, 1025))
    buffer.trim_before(1020)
    assert buffer.times.tolist() == list(range(1020, 1025))
    assert buffer.between(1021, 1023)[0].tolist() == [1021, 1022, 1023]
    buffer.clear()
    assert len(buffer) == 0 and buffer.last_time is None


def test_only_new_samples_are_read_even_with_equal_timestamps():
    clock = Clock()
    store = StateStore(clock=clock)
    buffer = SampleBuffer(100)
    for x in (1.0, 2.0):
        store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": x}}}})
    read_new_samples(store, "/odom", X, buffer)
    assert buffer.values.tolist() == [1.0, 2.0] and buffer.at_last_time == 2
    store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": 3.0}}}})  # the same time
    read_new_samples(store, "/odom", X, buffer)
    clock.now += 0.5
    store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": 4.0}}}})
    read_new_samples(store, "/odom", X, buffer)
    read_new_samples(store, "/odom", X, buffer)  # nothing new
    assert buffer.values.tolist() == [1.0, 2.0, 3.0, 4.0]
    assert buffer.times.tolist() == [1000.0, 1000.0, 1000.0, 1000.5]


def test_the_csv_is_long_ordered_by_time_then_curve(tmp_path):
    path = tmp_path / "plot.csv"
    curves = [("/odom", X, [10.0, 10.5], [0.1, 0.2]), ("/imu", "angular_velocity.z", [10.0, 10.25], [1.5, -0.5])]
    assert write_tidy_csv(path, curves) == 4
    with open(path, newline="", encoding="utf-8") as file:
        rows = list(csv.reader(file))
    assert rows == [["time", "topic", "field", "value"],
                    ["0.000000", "/odom", X, "0.1"], ["0.000000", "/imu", "angular_velocity.z", "1.5"],
                    ["0.250000", "/imu", "angular_velocity.z", "-0.5"], ["0.500000", "/odom", X, "0.2"]]
    assert write_tidy_csv(path, []) == 0
    assert path.read_text(encoding="utf-8").splitlines() == ["time,topic,field,value"]
