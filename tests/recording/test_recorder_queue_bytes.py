"""The recorder's queue holds at most QUEUE_BYTES of robot messages while its writer is behind
(a slow disk, a slow encoder): a camera's images beyond that are dropped and counted per topic."""
import threading

from recorded_reading import channels_and_messages

from rockly_desktop.recording.recorder import QUEUE_BYTES, Recorder


class HeldEncoder:
    """A ROS encoder whose first message waits until ``go`` is set: the writer thread is behind."""

    message_encoding, schema_encoding = "json", "jsonschema"

    def __init__(self):
        self.go = threading.Event()
        self.started = threading.Event()

    def schema_name(self, msg_type):
        return msg_type

    def __call__(self, msg_type, message):
        self.started.set()
        self.go.wait(30)
        raise ValueError("written as JSON instead")


def test_a_camera_behind_a_stuck_writer_fills_at_most_the_queues_bytes_and_the_drops_are_counted(tmp_path):
    clock = iter(range(10**9, 10**12, 10**9))  # a second between messages: no rate cap applies
    encoder = HeldEncoder()
    recorder = Recorder(tmp_path / "camera.mcap", encoder, topic_rate=10, clock=lambda: next(clock))
    recorder.start({"program": "camera.rockly"})
    try:
        recorder.topic("/first", "sensor_msgs/Image", {"data": "x"})
        assert encoder.started.wait(10)  # the writer is now stuck on that one
        images = 3 * QUEUE_BYTES // 2 ** 20
        for number in range(images):
            recorder.topic("/camera", "sensor_msgs/Image", {"seq": number, "data": bytes(2 ** 20)})
        dropped = recorder.stats()["dropped"]["/camera"]
        assert images - QUEUE_BYTES // 2 ** 20 <= dropped < images - QUEUE_BYTES // 2 ** 20 + 2
    finally:
        encoder.go.set()
        recorder.close()
    _found, messages = channels_and_messages(tmp_path / "camera.mcap")
    assert messages["/rockly/recording"][-1]["dropped"] == {"/camera": dropped}
