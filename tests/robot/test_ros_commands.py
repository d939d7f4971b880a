"""The generic ROS commands (``ros`` in programs) on the built-in simulator."""
import threading

import pytest

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError, RobotTimeout
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros_commands import RosCommands
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

ARM = ("hobbit_arm", "hobbit_msgs/ArmServerAction")
PREEMPTED = 2  # actionlib_msgs/GoalStatus


@pytest.fixture
def simulated(hobbit):
    """A running simulated HOBBIT (20 times real time) and its world."""
    world = SimWorld()
    simulator = hobbit.load_object("simulator")(world, speed=20)
    simulator.start()
    yield world, simulator
    simulator.shutdown()


@pytest.fixture
def sim(simulated):
    world, _ = simulated
    said = []
    yield RosCommands(SimBackend(world, Interrupt()), say=said.append), world, said


def trajectory(points):
    """An arm goal that takes ``points`` × 2.5 simulated seconds (1/8 s each at speed 20)."""
    return {"command": {"data": "MoveAlongTrajectory"}, "joints": [{"joint_values": [0.1] * 6}] * points}


def results_of(world):
    """The actionlib status codes of the arm goals that end from now on."""
    results = []
    world.tap(lambda topic, _type, message:
              topic == "/hobbit_arm/result" and results.append(message["status"]["status"]))
    return results


def assert_arm_halted(world, simulator, results):
    assert world.wait_for(lambda: results, 5)
    assert results == [PREEMPTED]
    assert simulator.snapshot()["arm_target"] is None   # the arm is no longer moving


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
    home = '{"command": {"data": "MoveToHome"}}'
    assert ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", home) == "succeeded"
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


def test_while_waiting_gets_the_feedback_in_the_calling_thread(sim):
    ros, _, _ = sim
    calls = []
    outcome = ros.send_goal(*ARM, {"command": {"data": "MoveToCandle"}},
                            while_waiting=lambda feedback: calls.append((threading.get_ident(), feedback)))
    assert outcome == "succeeded"
    assert {thread for thread, _ in calls} == {threading.get_ident()}
    assert calls[-1][1] == {"feedback": {"data": "MoveToCandle 100 %"}}


def test_a_slow_handler_gets_the_newest_feedback_not_a_backlog(simulated):
    world, _ = simulated
    ros = RosCommands(SimBackend(world, Interrupt()))
    results, seen = results_of(world), []

    def slow(feedback):  # busy until the goal has ended: every later feedback arrives meanwhile
        seen.append(feedback["feedback"]["data"])
        assert world.wait_for(lambda: results, 10)

    assert ros.send_goal(*ARM, trajectory(8), while_waiting=slow) == "succeeded"
    # the simulator reported 0, 25, 50, 75 and 100 %; the handler saw the first and then only the newest
    assert seen == ["MoveAlongTrajectory 0 %", "MoveAlongTrajectory 100 %"]


def test_an_error_in_the_handler_cancels_the_goal_and_passes_on(simulated):
    world, simulator = simulated
    ros, results = RosCommands(SimBackend(world, Interrupt())), results_of(world)

    def fail(feedback):
        raise ValueError("no feedback wanted")

    with pytest.raises(ValueError, match="no feedback wanted"):
        ros.send_goal(*ARM, trajectory(40), while_waiting=fail)
    assert_arm_halted(world, simulator, results)


@pytest.mark.parametrize("with_handler", [True, False])
def test_a_stop_during_the_wait_cancels_the_goal(simulated, with_handler):
    world, simulator = simulated
    interrupt = Interrupt()
    ros, results = RosCommands(SimBackend(world, interrupt)), results_of(world)
    if with_handler:
        handler = lambda feedback: interrupt.request_stop()  # noqa: E731 - stop once the goal is under way
    else:
        handler = None
        world.tap(lambda topic, _type, _message: topic == "/hobbit_arm/goal" and interrupt.request_stop())
    with pytest.raises(ProgramStopped):
        ros.send_goal(*ARM, trajectory(40), while_waiting=handler)
    assert_arm_halted(world, simulator, results)


def test_the_timeout_applies_with_a_handler_and_cancels_the_goal(simulated):
    world, simulator = simulated
    ros, results, seen = RosCommands(SimBackend(world, Interrupt())), results_of(world), []
    with pytest.raises(RobotTimeout, match="the action 'hobbit_arm' did not finish within 0.3 s"):
        ros.send_goal(*ARM, trajectory(40), timeout=0.3, while_waiting=seen.append)
    assert seen  # feedback came while it waited
    assert_arm_halted(world, simulator, results)
    with pytest.raises(RobotCommandError, match="must be a function"):
        ros.send_goal(*ARM, trajectory(1), while_waiting="MoveToHome")


@pytest.fixture
def checked(simulated, hobbit):
    """The generic commands as a program gets them: checking what it sends against the types."""
    world, _ = simulated
    return RosCommands(SimBackend(world, Interrupt()), say=lambda text: None, types=hobbit.ros_types), world


@pytest.mark.parametrize("send, problem", [
    (lambda ros: ros.publish_message("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": "fast"}}),
     "the field linear.x needs a number, not 'fast'"),
    (lambda ros: ros.publish_message("/cmd_vel", "geometry_msgs/Twist", {"linear": {"q": 1}}),
     "linear (a geometry_msgs/Vector3) has no field 'q' (it has: x, y, z)"),
    (lambda ros: ros.publish_message("/cmd_vel", "geometry_msgs/Twist", {"speed": 1}),
     "geometry_msgs/Twist has no field 'speed' (it has: linear, angular)"),
    (lambda ros: ros.publish_message("/cmd_vel", "geometry_msgs/Twist", {"linear": 3}),
     "linear must be a geometry_msgs/Vector3 (a mapping of its fields), not 3"),
    (lambda ros: ros.publish_message("/scan", "sensor_msgs/LaserScan", {"ranges": 1.0}),
     "the field ranges needs a list"),
    (lambda ros: ros.publish_message("/scan", "sensor_msgs/LaserScan", {"ranges": [1.0, "far"]}),
     "the field ranges[1] needs a number, not 'far'"),
    (lambda ros: ros.call_service("/enable", "std_srvs/SetBool", {"data": "yes"}),
     "the field data needs true or false"),
    (lambda ros: ros.send_goal(*ARM, {"command": {"data": 7}}), "the field command.data needs a text, not 7"),
    (lambda ros: ros.send_goal(*ARM, {"joints": [{"joint_values": [0, "up"]}]}),
     "the field joints[0].joint_values[1] needs a number, not 'up'"),
], ids=["text for number", "unknown nested field", "unknown field", "number for message", "number for list",
        "text in list", "service request", "goal", "nested list"])
def test_a_wrong_value_is_named_before_anything_is_sent(checked, send, problem):
    ros, world = checked
    sent = []
    world.tap(lambda topic, _type, message: sent.append(topic))
    with pytest.raises(RobotCommandError) as caught:
        send(ros)
    assert problem in str(caught.value)
    assert sent == []


def test_right_values_and_unknown_types_pass_the_check(checked):
    ros, world = checked
    ros.publish_message("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}, "angular": {"z": -1}})
    ros.publish_message("/scan", "sensor_msgs/LaserScan",
                        {"header": {"stamp": 1.5, "frame_id": "laser"}, "ranges": [1, 2.5]})
    ros.publish_message("/lab", "lab_msgs/Unknown", {"anything": "goes"})   # the robot's side decides
    assert world.latest("/cmd_vel") == {"linear": {"x": 0.1}, "angular": {"z": -1}}
    assert world.latest("/lab") == {"anything": "goes"}
    assert ros.send_goal(*ARM, {"command": {"data": "MoveToHome"}, "velocity": 0}) == "succeeded"
