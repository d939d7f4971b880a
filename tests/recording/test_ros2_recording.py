"""A run on ROS 2 (a plain rclpy robot in its own process, this run's own domain), recorded: its
topics in CDR with ros2msg schemas, as rosbag2 writes them."""
import logging

from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from waiting import eventually

from rockly_desktop.executor.events import RunFinished
from rockly_desktop.executor.run_to_mcap import RunRecording
from rockly_desktop.recording.reading import read_recording
from rockly_desktop.recording.topics import RecordedTopics, message_dict


def without_ros1_time(value):
    """A state store's ROS 2 message without the ROS 1 ``secs``/``nsecs`` a stamp also carries."""
    if isinstance(value, dict):
        return {key: without_ros1_time(item) for key, item in value.items() if key not in ("secs", "nsecs")}
    if isinstance(value, list):
        return [without_ros1_time(item) for item in value]
    return value


def test_a_run_on_ros2_records_the_robots_topics_in_cdr(ros2_robot, test_robot, turtlebot, tmp_path, caplog):
    ros2_robot.follow_graph()
    eventually(lambda: ros2_robot.state.latest("/odom") is not None)
    path = tmp_path / "ros2.mcap"
    recording = RunRecording(path, turtlebot, ros2_robot, "ros2.rockly", None, {})
    eventually(lambda: recording.recorder._file.counts.get("/odom", 0) >= 3)
    with caplog.at_level(logging.INFO, logger="rockly_desktop.recording.recorder"):
        for topic in ("/odd", "/odder"):  # a type ROS 2's environment has no definition of
            ros2_robot.state.record(topic, "rockly_test_msgs/Nothing", {"value": 1})
        eventually(lambda: recording.recorder._file.counts.get("/odder", 0) == 1)
    recording.emit(RunFinished("finished", None, ""))
    published = {m["twist"]["twist"]["linear"]["x"]: without_ros1_time(m)  # stamps are 0: the speeds differ
                 for _t, m, _size in ros2_robot.state._topics["/odom"].history}

    found, decoded = {}, {}
    with open(path, "rb") as stream:
        for schema, channel, _message, ros_message in make_reader(
                stream, decoder_factories=[DecoderFactory()]).iter_decoded_messages(topics=["/odom"]):
            found[channel.topic] = (channel.message_encoding, schema.name, schema.encoding)
            decoded.setdefault(channel.topic, []).append(message_dict(ros_message))
    assert found == {"/odom": ("cdr", "nav_msgs/msg/Odometry", "ros2msg")}
    assert len(decoded["/odom"]) >= 3
    for message in decoded["/odom"]:  # mcap-ros2-support's message equals the one the robot sent
        assert message == published[message["twist"]["twist"]["linear"]["x"]]
        assert message["pose"]["pose"]["position"]["x"] == 1.5 and message["header"]["frame_id"] == "odom"

    read = read_recording(path)
    assert read.channels["/odd"] == ("json", "rockly_test_msgs/Nothing", "jsonschema")
    topics = RecordedTopics(read)  # as the window's replay and `rockly replay` read them
    assert topics.messages("/odd") == [{"value": 1}] and topics.messages("/odder") == [{"value": 1}]
    assert topics.messages("/odom")[0]["pose"]["pose"]["position"]["x"] == 1.5
    said = [record.getMessage() for record in caplog.records if "cannot be encoded" in record.getMessage()]
    assert len(said) == 1 and "rockly_test_msgs/Nothing" in said[0]
