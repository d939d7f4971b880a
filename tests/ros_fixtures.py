"""Fixtures: a real ROS master for this test run, and the ROS-level simulated HOBBIT on it."""
import pytest
from leak_check import shared_process
from ros_helpers import RocklyProcess, RosMaster, put_back_simulator


@pytest.fixture(scope="session")
def ros_master(tmp_path_factory):
    master = shared_process(RosMaster(tmp_path_factory.mktemp("ros")).start())  # tests may restart it
    yield master
    master.stop()


@pytest.fixture(scope="session")
def session_hobbit_on_ros(ros_master):
    """`rockly sim hobbit --ros` running against the session's master (fast simulated time), started once.

    Without its window: every question here is answered from --answer (one beyond them fails
    at once instead of waiting for a person), and no Qt redraws compete with timed tests for the
    whole session. The window has its own tests (robot/ros1/test_sim_window_on_ros.py)."""
    process = RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", ros_master.uri, "--speed", "20",
                             "--answer", "yes", "--answer", "Ada"], ros_master, ready_line="on ROS")
    yield process
    process.stop()


@pytest.fixture
def hobbit_on_ros(ros_master, session_hobbit_on_ros):
    """The session's ROS-level HOBBIT, put back as it started (its /rockly_sim/reset) before each test
    that uses it: a test before may have driven it away or left its arm out."""
    put_back_simulator(ros_master.uri)
    return session_hobbit_on_ros


@pytest.fixture(scope="session")
def session_ros_robot(ros_master, session_hobbit_on_ros, hobbit):
    from rockly_desktop.robot.ros1.link import RosRobot

    return RosRobot(hobbit, ros_master.uri)


@pytest.fixture
def ros_robot(session_ros_robot, hobbit_on_ros):
    """This test process as a Rockly node on the session's master, driving the ROS-level HOBBIT (put back
    at its start)."""
    return session_ros_robot
