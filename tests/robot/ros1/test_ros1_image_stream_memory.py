"""A ROS 1 camera publishing 1 MB images at 60 Hz for 15 s: Rockly's memory stays bounded.

A plain rospy node in its own process (``ros1_camera_node.py``) is the camera; Rockly's link
follows the graph as the window does and a recorder listens to its state store, as every run
is recorded. The bounds are the ROS 2 test's (``robot/ros2/test_ros2_image_stream_memory.py``):
the store keeps at most 16 MB of a topic's history, the recorder's queue at most 64 MB. Before,
the store kept 2,000 images (2 GB). The state store and the recorder are shared with ROS 2, so
15 s of the real ROS 1 feed are enough here.
"""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from memory_watch import watch_growth
from ros_helpers import ros_environment
from waiting import eventually

from rockly_desktop.recording.recorder import Recorder

CAMERA_NODE = Path(__file__).parent / "ros1_camera_node.py"
IMAGE_BYTES = 1 << 20
RATE = 60
SECONDS = 15
ROCKLY_BOUND = 250 * 2 ** 20
TOPIC = "/camera/image_raw"


def _heard(store) -> int:
    return next((info.count for info in store.topics() if info.topic == TOPIC), 0)


@pytest.mark.long
def test_a_1mb_camera_at_60hz_on_ros1_keeps_memory_bounded(ros_master, ros_robot, tmp_path):
    camera = subprocess.Popen([sys.executable, str(CAMERA_NODE), str(IMAGE_BYTES), str(RATE)], stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, text=True, env=ros_environment(ros_master.uri, tmp_path / "ros"))
    recorder = Recorder(tmp_path / "run.mcap", ros_robot.recording_encoder())
    try:
        assert json.loads(camera.stdout.readline() or "{}").get("ready"), "the camera node did not start"
        recorder.start({"program": "camera"})
        ros_robot.state.add_listener(recorder.topic)
        ros_robot.follow_graph()
        eventually(lambda: _heard(ros_robot.state) > RATE, timeout=30)
        heard_before = _heard(ros_robot.state)
        watch_growth(SECONDS, {"self": ROCKLY_BOUND})
        assert _heard(ros_robot.state) - heard_before >= 10 * SECONDS  # the stream reached the store
        info = next(info for info in ros_robot.state.topics() if info.topic == TOPIC)
        assert info.cut and info.kept <= 16
        assert ros_robot.state.latest(TOPIC)["data"][:3] == b"\x00\x01\x02"  # shown as bytes, not a list
    finally:
        ros_robot.state.remove_listener(recorder.topic)
        recorder.close()
        camera.stdin.close()
        said = json.loads(camera.stdout.readline() or "{}")
        camera.wait(timeout=10)
    assert said.get("published", 0) >= 50 * SECONDS
