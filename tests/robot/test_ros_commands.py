"""The generic ROS commands (``ros`` in programs) on the built-in simulator."""
import threading

import pytest

from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros_commands import RosCommands
from rockly_desktop.robot.sim_world import SimBackend, SimWorld


@pytest.fixture
def sim(hobbit):
    world = SimWorld()
    simulator = hobbit.load_object("simulator")(world, speed=20)
    simulator.start()
    said = []
    yield RosCommands(SimBackend(world, Interrupt()), say=said.append), world, said
    simulator.shutdown()


def test_publish_simple_and_any_message(sim):
    ros, world, _ = sim
    ros.publish("/count", "Int64", 3)
    ros.publish_message("/cmd_vel", "geometry_msgs/Twist", '{"angular": {"z": 0.5}}')
    assert world.latest("/count") == {"data": 3}
    assert world.latest("/cmd_vel") == {"angular": {"z": 0.5}}
    with pytest.raises(RobotCommandError, match="not valid JSON"):
        ros.publish_message("/cmd_vel", "geometry_msgs/Twist", "{linear")
    with pytest.raises(RobotCommandError, match="message type"):
        ros.publish("/x", "Float32", 1)


def test_wait_for_a_message_and_read_its_fields(sim):
    ros, _, _ = sim
    message = ros.wait_for_message("/odom", 5)
    assert ros.field(message, "header.frame_id") == "odom"
    assert isinstance(ros.latest("/battery_state", "percentage"), float)
    with pytest.raises(RobotCommandError, match="no field 'pose.nose'"):
        ros.field(message, "pose.nose")
    with pytest.raises(RobotTimeout, match="/nothing"):
        ros.wait_for_message("/nothing", 0.2)


def test_services_goals_and_cancel(sim):
    ros, world, _ = sim
    response = ros.call_service("/MMUI", "hobbit_msgs/Request",
                                {"params": [{"name": "type", "value": "D_PLAIN"}, {"name": "text", "value": "hi"}]})
    assert "params" in response
    assert ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", '{"command": {"data": "MoveToHome"}}') == "succeeded"
    assert ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", {"command": {"data": "Dance"}}) == "aborted"
    goals = []
    world.tap(lambda topic, _type, message: topic == "/hobbit_arm/goal" and goals.append(message))
    outcome = []
    mover = threading.Thread(target=lambda: outcome.append(
        ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", {"command": {"data": "MoveToCandle"}})))
    mover.start()
    assert world.wait_for(lambda: bool(goals), 5)
    ros.cancel_goals("hobbit_arm")
    mover.join(10)
    assert outcome == ["preempted"]
    with pytest.raises(RobotCommandError, match="no action server 'nowhere'"):
        ros.send_goal("nowhere", "x/YAction", {})
    with pytest.raises(RobotTimeout, match="/no_service"):
        ros.call_service("/no_service", "std_srvs/Trigger", {}, timeout=0.2)


def test_parameters_and_logging(sim):
    ros, _, said = sim
    assert ros.get_param("/speed") is None and ros.get_param("/speed", 0.5) == 0.5
    ros.set_param("/speed", 0.3)
    assert ros.get_param("/speed") == 0.3
    ros.log("warn", "battery low")
    assert said == ["[warn] battery low"]
    with pytest.raises(RobotCommandError, match="log level"):
        ros.log("shout", "x")
