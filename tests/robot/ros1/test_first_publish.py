"""A new publisher's first message on ROS 1 reaches a robot node that connects slowly (a busy robot or computer:
rospy drops what is published before a subscriber is connected), heard by an independent rospy node
(tests/wire_recorder.py); a subscriber that never connects holds up only the first message. The recorder itself
is ready only once the publishers have its connection: its own count says so before the connection is up."""
import time

import pytest
from ros_helpers import connected_subscription
from waiting import eventually
from wire_recorder import WireRecorder

from rockly_desktop.robot.interrupt import Interrupt


@pytest.fixture
def slow_recorder(ros_master):
    made = []

    def start(topic, connect_after):
        made.append(WireRecorder(ros_master, [topic], connect_after=connect_after))
        return made[-1]

    yield start
    for recorder in made:
        recorder.stop()


def test_the_first_message_waits_for_a_robot_node_that_connects_two_seconds_late(ros_robot, slow_recorder):
    wire = slow_recorder("/busy/chatter", connect_after=2.0)
    ros_robot.backend(Interrupt()).publish("/busy/chatter", "std_msgs/String", {"data": "first"})
    eventually(lambda: wire.on("/busy/chatter"))
    assert [data[4:] for _type, data in wire.on("/busy/chatter")] == [b"first"]


def test_a_subscriber_that_never_connects_holds_up_only_the_first_message(ros_robot, slow_recorder):
    slow_recorder("/unreached/chatter", connect_after=600.0)
    backend = ros_robot.backend(Interrupt())
    backend.publish("/unreached/chatter", "std_msgs/String", {"data": "first"})  # waited for it, in vain
    started = time.monotonic()
    for number in range(10):
        backend.publish("/unreached/chatter", "std_msgs/String", {"data": str(number)})
    assert time.monotonic() - started < 5.0  # not a wait for the same subscriber per message


def test_the_recorder_is_ready_once_a_publisher_already_sending_has_its_late_connection(ros_robot, slow_recorder):
    connected_subscription(ros_robot, "/busy/status", "std_msgs/String")  # this node hears itself: connected
    backend = ros_robot.backend(Interrupt())
    backend.publish("/busy/status", "std_msgs/String", {"data": "before"})
    wire = slow_recorder("/busy/status", connect_after=2.0)
    backend.publish("/busy/status", "std_msgs/String", {"data": "after"})  # no wait: not its first message
    eventually(lambda: wire.on("/busy/status"))
    assert [data[4:] for _type, data in wire.on("/busy/status")] == [b"after"]
