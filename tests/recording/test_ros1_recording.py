"""A run on ROS 1 (a real master, the ROS-level HOBBIT in its own process), recorded."""
from recorded_reading import channels_and_messages
from waiting import eventually

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.executor.run_to_mcap import RunRecording
from rockly_desktop.robot.ros1.message_values import from_message

PROGRAM = {"code": "\n".join([
    "__rockly__.block('look')", "robot.look('down_left')",
    "__rockly__.block('drive')", "robot.drive(0.2, 'forward')", ""]), "variables": {}}


def test_a_run_on_ros1_records_the_robots_topics_as_it_published_them(ros_robot, hobbit, tmp_path):
    ros_robot.follow_graph()
    eventually(lambda: ros_robot.state.latest("/odom") is not None and ros_robot.state.latest("/battery_state"))
    path = tmp_path / "ros.mcap"
    recording = RunRecording(path, hobbit, ros_robot, "ros.rockly", None, {"look": "hobbit_look",
                                                                         "drive": "hobbit_move"})
    result = make_runner(hobbit, ros_robot, PROGRAM, RunControl(), lambda event: None, recording=recording).run()
    assert result.outcome == "finished", result
    with ros_robot.state._lock:  # the feed's thread goes on adding /odom messages to the history
        history = list(ros_robot.state._topics["/odom"].history)
    published = {m["header"]["seq"]: m  # the ROS-level simulator leaves stamps at 0
                 for m in (from_message(raw) if not isinstance(raw, dict) else raw for _t, raw, _size in history)}

    found, messages = channels_and_messages(path)
    assert found["/odom"] == ("ros1", "nav_msgs/Odometry", "ros1msg")
    assert found["/battery_state"] == ("ros1", "sensor_msgs/BatteryState", "ros1msg")
    assert [(m["block"], m["type"]) for m in messages["/rockly/blocks"]] == [("look", "hobbit_look"),
                                                                             ("drive", "hobbit_move")]
    assert ("publish", "/DiscreteMotionCmd", "drive") in [(m["kind"], m["name"], m["block"])
                                                          for m in messages["/rockly/commands"]]
    assert messages["/odom"]
    for decoded in messages["/odom"]:  # mcap-ros1-support's message equals the one the robot sent
        assert from_message(decoded) == published[decoded.header.seq]
