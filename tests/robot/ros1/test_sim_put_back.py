"""The ROS-level simulator's put-back service (``/rockly_sim/reset``, std_srvs/Trigger): HOBBIT back at its
start pose as a plain rospy node hears it on /odom; and the session's shared simulator handed to each test
that uses it put back, whatever was done to it before (here: by this test's own first fixture)."""
import math

import pytest
from ros_helpers import put_back_simulator
from waiting import eventually
from wire_recorder import WireRecorder

from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros1.message_classes import MessageTypes


@pytest.fixture
def odometry_heard(ros_master, hobbit):
    """A plain rospy node (its own process, nothing of Rockly in it) on /odom: a function that gives the
    last pose it heard as ``(x, y, heading in degrees)``."""
    odometry = MessageTypes(hobbit.message_folders).message_class("nav_msgs/Odometry")
    wire = WireRecorder(ros_master, ["/odom"])

    def last_pose():
        eventually(lambda: wire.on("/odom"))
        message = odometry().deserialize(wire.on("/odom")[-1][1])
        position, q = message.pose.pose.position, message.pose.pose.orientation
        return position.x, position.y, math.degrees(math.atan2(2 * q.w * q.z, 1 - 2 * q.z ** 2))

    yield last_pose
    wire.stop()


def drive_away(ros_robot, hobbit):
    hobbit.load_object("api")(ros_robot.backend(Interrupt())).drive(0.5, "forward")


def test_a_reset_puts_hobbit_back_at_its_start_pose_on_the_wire(ros_master, ros_robot, hobbit, odometry_heard):
    drive_away(ros_robot, hobbit)
    eventually(lambda: odometry_heard()[0] == pytest.approx(0.5, abs=0.05))
    put_back_simulator(ros_master.uri)
    eventually(lambda: odometry_heard() == (0.0, 0.0, 0.0))


@pytest.fixture
def hobbit_driven_away(session_ros_robot, hobbit, odometry_heard):
    """The session's simulated HOBBIT driven 0.5 m away, as a test before might have left it. Requested
    before ``ros_robot`` (pytest sets up a test's fixtures of one scope in the order it names them)."""
    drive_away(session_ros_robot, hobbit)
    eventually(lambda: odometry_heard()[0] == pytest.approx(0.5, abs=0.05))


def test_a_test_finds_the_shared_hobbit_at_its_start_pose_whatever_was_done_before(
        hobbit_driven_away, ros_robot, odometry_heard):
    eventually(lambda: odometry_heard() == (0.0, 0.0, 0.0))
