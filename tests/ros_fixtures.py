"""Fixtures: a real ROS master for this test run, and the ROS-level simulated HOBBIT on it."""
import pytest
from leak_check import shared_process
from ros_helpers import RocklyProcess, RosMaster


@pytest.fixture(scope="session")
def ros_master(tmp_path_factory):
    master = shared_process(RosMaster(tmp_path_factory.mktemp("ros")).start())  # tests may restart it
    yield master
    master.stop()


@pytest.fixture(scope="session")
def hobbit_on_ros(ros_master):
    """`rockly sim hobbit --ros` running against the session's master (fast simulated time).

    Without its window: every question here is answered from --answer (one beyond them fails
    at once instead of waiting for a person), and no Qt redraws compete with timed tests for the
    whole session. The window has its own tests (robot/ros1/test_sim_window_on_ros.py)."""
    process = RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", ros_master.uri, "--speed", "20",
                             "--answer", "yes", "--answer", "Ada"], ros_master, ready_line="on ROS")
    yield process
    process.stop()


@pytest.fixture(scope="session")
def ros_robot(ros_master, hobbit_on_ros, hobbit):
    """This test process as a Rockly node on the session's master, driving the ROS-level HOBBIT."""
    from rockly_desktop.robot.ros1.link import RosRobot

    return RosRobot(hobbit, ros_master.uri)
