"""A speed that is no number never reaches the ROS 2 wire, seen by the plain rclpy test robot
(ros2_test_node.py): under a teacher's limit the limit refuses it, without one the robot's side does,
as rclpy itself would (a boolean is no 1.0)."""
import pytest
from waiting import eventually

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.wrappers.limits import Limits


def speeds(test_robot):
    return [line["message"]["linear"]["x"] for line in test_robot.received("/cmd_vel")]


def failure_of(call):
    try:
        call()
    except RobotCommandError as error:
        return str(error)
    return None


def heard_again(ros2_robot, test_robot, speed):
    """Publish ``speed`` and wait until the test robot has it: what came before has come."""
    ros2_robot.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": speed}})
    eventually(lambda: speed in speeds(test_robot))


@pytest.mark.parametrize("value", [True, "1.0"])
def test_under_a_limit_a_speed_that_is_no_number_never_reaches_the_ros_2_wire(ros2_robot, test_robot, turtlebot,
                                                                              value):
    code = f"robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {{'linear': {{'x': {value!r}}}}})\n"
    result = make_runner(turtlebot, ros2_robot, {"code": code, "variables": {}}, RunControl(), lambda event: None,
                         "en", Limits(max_speed=0.1)).run()
    assert result.outcome == "error"
    assert result.message.endswith(f"the teacher's speed limit needs real numbers on /cmd_vel: linear.x is {value!r}")
    heard_again(ros2_robot, test_robot, 0.05)
    assert 1.0 not in speeds(test_robot)


def test_without_a_limit_a_boolean_speed_is_refused_not_sent_as_1(ros2_robot, test_robot):
    backend = ros2_robot.backend(Interrupt())
    backend.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": True}})
    # the helper's refusal is told by whichever request comes next (it may be the graph's): not waited for here
    for _ in range(2):
        failure_of(lambda: backend.topic_types("/cmd_vel"))
    heard_again(ros2_robot, test_robot, 0.04)
    assert 1.0 not in speeds(test_robot)
