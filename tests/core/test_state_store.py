"""The state store: latest values, bounded history, rates, field paths, many writers."""
import threading

import pytest

from rockly_desktop.core.state_store import StateStore, field_value


class FakeClock:
    """A clock the test moves by hand (time itself is what is being tested here)."""

    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def odometry(x):
    return {"pose": {"pose": {"position": {"x": x, "y": 0.0}}}, "ranges": [1.0, 2.5]}


def test_latest_and_field_values():
    store = StateStore()
    store.record("/odom", "nav_msgs/Odometry", odometry(1.5))
    store.record("/odom", "nav_msgs/Odometry", odometry(2.0))
    assert store.value("/odom", "pose.pose.position.x") == 2.0
    assert store.value("/odom", "ranges[1]") == 2.5
    assert store.value("/odom", "pose.nothing", default="-") == "-"
    assert store.value("/missing", "data") is None


def test_field_paths_refuse_what_is_not_there():
    with pytest.raises(KeyError):
        field_value({"ranges": [1]}, "ranges[3]")
    with pytest.raises(KeyError):
        field_value({"a": 1}, "a.b")


def test_history_is_bounded_and_series_keep_numbers_only():
    store = StateStore(history=10)
    for i in range(25):
        store.record("/odom", "nav_msgs/Odometry", odometry(float(i)))
    store.record("/odom", "nav_msgs/Odometry", {"pose": {"pose": {"position": {"x": "far"}}}})
    series = store.series("/odom", "pose.pose.position.x")
    assert [value for _, value in series] == [float(i) for i in range(16, 25)]


def test_rate_age_and_count_per_topic():
    clock = FakeClock()
    store = StateStore(rate_window=2.0, clock=clock)
    for _ in range(101):
        store.record("/odom", "nav_msgs/Odometry", odometry(0.0))
        clock.now += 0.01  # 100 Hz
    clock.now += 0.5
    (info,) = store.topics()
    assert (info.topic, info.msg_type, info.count) == ("/odom", "nav_msgs/Odometry", 101)
    assert info.rate == pytest.approx(100.0, rel=0.01)
    assert info.age == pytest.approx(0.51, abs=1e-6)


def test_many_writers_lose_nothing():
    store = StateStore(history=100_000)

    def write(topic):
        for i in range(5000):
            store.record(topic, "std_msgs/Float64", {"data": i})

    threads = [threading.Thread(target=write, args=(f"/t{n}",)) for n in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert [info.count for info in store.topics()] == [5000] * 4
    assert store.version == 20000
