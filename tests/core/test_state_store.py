"""The state store: latest values, history bounded by count and bytes, rates, field paths, many writers."""
import array
import threading

import pytest

from rockly_desktop.core.message_size import message_bytes
from rockly_desktop.core.state_store import TOPIC_BYTES, StateStore, field_value


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


def image(number, size=1 << 20):
    """A camera image as the ROS 2 helper sends it: its pixels compact (here bytes), 1 MB."""
    return {"header": {"frame_id": "camera", "seq": number}, "height": 1024, "width": 1024,
            "encoding": "mono8", "data": bytes([number % 256]) * size}


def test_a_camera_topic_keeps_at_most_its_byte_budget_and_says_its_history_was_cut():
    store = StateStore()
    for number in range(100):
        store.record("/camera", "sensor_msgs/Image", image(number))
        store.record("/odom", "nav_msgs/Odometry", odometry(float(number)))
    assert store.held_bytes() <= TOPIC_BYTES + 2 ** 20  # the camera's budget, and the odometry's few KB
    camera, odom = (next(info for info in store.topics() if info.topic == topic) for topic in ("/camera", "/odom"))
    assert camera.cut and 10 <= camera.kept <= 16 and camera.count == 100
    assert not odom.cut and odom.kept == 100
    assert store.latest("/camera")["header"]["seq"] == 99  # the newest stays, the oldest went
    assert store.series("/camera", "header.seq")[-1][1] == 99.0


def test_topics_share_the_total_budget_and_a_new_topic_makes_the_shares_smaller():
    store = StateStore(topic_bytes=8 * 2 ** 20, total_bytes=12 * 2 ** 20)
    for number in range(20):
        store.record("/front", "sensor_msgs/Image", image(number))
    assert 7 * 2 ** 20 <= store.held_bytes() <= 8 * 2 ** 20 + 4096
    for number in range(20):
        store.record("/back", "sensor_msgs/Image", image(number))
    assert store.held_bytes() <= 12 * 2 ** 20 + 4096  # 6 MB each
    assert {info.topic: info.kept for info in store.topics()} == {"/back": 5, "/front": 5}
    assert store.topic_budget() == 6 * 2 ** 20


def test_a_message_larger_than_the_budget_is_still_kept_as_the_newest():
    store = StateStore(topic_bytes=2 ** 20, total_bytes=2 ** 20)
    store.record("/cloud", "sensor_msgs/PointCloud2", image(1, size=4 << 20))
    store.record("/cloud", "sensor_msgs/PointCloud2", image(2, size=4 << 20))
    (info,) = store.topics()
    assert info.kept == 1 and info.cut
    assert store.latest("/cloud")["header"]["seq"] == 2


def test_the_count_bound_alone_is_no_cut_history():
    store = StateStore(history=10)
    for number in range(30):
        store.record("/odom", "nav_msgs/Odometry", odometry(float(number)))
    (info,) = store.topics()
    assert info.kept == 10 and not info.cut


def test_message_bytes_counts_compact_arrays_by_their_bytes_and_lists_by_their_items():
    one_mb = 2 ** 20
    assert one_mb <= message_bytes({"data": bytes(one_mb)}) <= one_mb + 1024
    assert 4 * one_mb <= message_bytes({"ranges": array.array("f", bytes(4 * one_mb))}) <= 4 * one_mb + 1024
    assert message_bytes({"data": list(range(one_mb))}) >= 8 * one_mb  # a list: a pointer and an object per item
    poses = [{"position": {"x": 1.0, "y": 2.0}}] * 1000
    assert 100_000 <= message_bytes({"poses": poses}) <= 1_000_000


def test_decoded_messages_are_read_once_and_stay_the_same_object():
    decoded = []
    store = StateStore(decode=lambda message: decoded.append(message) or {"data": message})
    store.record("/raw", "std_msgs/String", "first")
    assert store.latest("/raw") is store.latest("/raw")
    store.record("/raw", "std_msgs/String", "second")
    assert store.latest("/raw") == {"data": "second"} and decoded == ["first", "second"]
