"""An address the robot's nodes cannot connect back to (ROS_IP=::1 without ROS_IPV6) is named at once."""
import pytest

from rockly_desktop.robot.ros1.connection import address_problem, address_problem_text


@pytest.mark.parametrize(("environment", "problem"), [
    ({"ROS_IP": "::1"}, ("ipv6", "::1")),
    ({"ROS_IP": "192.0.2.77"}, ("not_local", "192.0.2.77")),  # TEST-NET-1: never this computer's
    ({"ROS_IP": "127.0.0.1"}, None),
    ({"ROS_IP": "::1", "ROS_IPV6": "on"}, None),
    ({}, None),
])
def test_address_problems_are_found(environment, problem):
    assert address_problem(environment) == problem


def test_the_problem_says_what_to_do():
    text = address_problem_text(("ipv6", "::1"))
    assert "ROS_IP is ::1" in text and "127.0.0.1" in text and "never arrive" in text


def test_rockly_run_warns_before_the_program_starts(tmp_path):
    import subprocess
    import sys

    from program_builder import block, rockly_document
    from ros_helpers import REPO, RosMaster, ros_environment

    master = RosMaster(tmp_path / "ros").start()
    source = tmp_path / "hello.rockly"
    source.write_text(rockly_document([block("ros_log", {"level": "info"})]))
    environment = {**ros_environment(master.uri, master.home), "ROS_IP": "::1"}
    try:
        result = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(source), "--backend", "ros1",
                                 "--master", master.uri], cwd=REPO, env=environment, capture_output=True, text=True,
                                timeout=60)
    finally:
        master.stop()
    assert "rockly run: warning: ROS_IP is ::1, an IPv6 address" in result.stderr
