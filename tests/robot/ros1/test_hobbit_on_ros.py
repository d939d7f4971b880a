"""HOBBIT's commands over real ROS 1: a real master, the ROS-level simulator in its own process."""
import math
import threading

import pytest
from background import Background
from ros_helpers import connected_subscription
from waiting import eventually

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError
from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.interrupt import Interrupt


@pytest.fixture
def hobbit_robot(ros_robot, hobbit):
    return hobbit.load_object("api")(ros_robot.backend(Interrupt()))


def record(ros_robot, topic, msg_type, pick):
    """Record what arrives on ``topic``, once connected to every publisher the master knows.

    A publisher made later (a program's first goal) waits for this subscriber itself: the
    master lists it from here on (Rockly's publishers and goals wait for every listed subscriber)."""
    seen = []
    unsubscribe = ros_robot.backend(Interrupt()).subscribe(topic, msg_type, lambda message: seen.append(pick(message)))
    connected_subscription(ros_robot, topic, msg_type)
    return seen, unsubscribe


def pose(ros_robot):
    message = ros_robot.backend(Interrupt()).wait_for_message("/odom", "nav_msgs/Odometry", 5)
    position, q = message["pose"]["pose"]["position"], message["pose"]["pose"]["orientation"]
    return position["x"], position["y"], math.degrees(math.atan2(2 * q["w"] * q["z"], 1 - 2 * q["z"] ** 2))


def test_the_thesis_pick_up_program_sends_exactly_that_goal_sequence(ros_robot, hobbit_robot):
    goals, unsubscribe = record(ros_robot, "/hobbit_arm/goal", "hobbit_msgs/ArmServerActionGoal",
                                lambda message: message["goal"]["command"]["data"])
    try:
        hobbit_robot.gripper("open")
        hobbit_robot.move_arm("floor")
        hobbit_robot.gripper("close")
        hobbit_robot.move_arm("table")
        hobbit_robot.gripper("open")
    finally:
        unsubscribe()
    assert goals == ["OpenGripper", "MoveToPreGraspFloor", "CloseGripper", "MoveToPreGraspTable", "OpenGripper"]


def test_head_and_emotion_reach_the_robot_as_strings(ros_robot, hobbit_robot):
    heads, stop_heads = record(ros_robot, "/head/move", "std_msgs/String", lambda message: message["data"])
    emotions, stop_emotions = record(ros_robot, "/head/emo", "std_msgs/String", lambda message: message["data"])
    hobbit_robot.look("up_left")
    hobbit_robot.show_emotion("WONDERING")
    eventually(lambda: heads == ["up_left"] and emotions == ["WONDERING"])
    stop_heads()
    stop_emotions()


def test_drive_and_turn_use_the_discrete_motion_commands(ros_robot, hobbit_robot):
    commands, unsubscribe = record(ros_robot, "/DiscreteMotionCmd", "std_msgs/String", lambda message: message["data"])
    x0, y0, _ = pose(ros_robot)
    hobbit_robot.drive(0.5, "backward")
    hobbit_robot.turn(90, "left")
    unsubscribe()
    assert commands == ["Move -0.5", "Turn 90"]
    x1, y1, theta = pose(ros_robot)
    assert math.hypot(x1 - x0, y1 - y0) == pytest.approx(0.5, abs=0.03)


def test_navigation_goes_through_move_base(ros_robot, hobbit_robot):
    targets, unsubscribe = record(ros_robot, "/move_base/goal", "move_base_msgs/MoveBaseActionGoal",
                                  lambda message: message["goal"]["target_pose"])
    hobbit_robot.navigate_to(1.0, 0.5, 90)
    unsubscribe()
    assert targets[0]["header"]["frame_id"] == "map"
    assert (targets[0]["pose"]["position"]["x"], targets[0]["pose"]["position"]["y"]) == (1.0, 0.5)
    x, y, theta = pose(ros_robot)
    assert (x, y) == (pytest.approx(1.0, abs=0.05), pytest.approx(0.5, abs=0.05))


def test_a_goal_inside_furniture_is_aborted_over_ros_with_the_reason_as_status_text(hobbit_robot):
    with pytest.raises(RobotCommandError) as caught:
        hobbit_robot.navigate_to(3.7, 1.2)     # the middle of the table
    assert str(caught.value) == "HOBBIT could not reach the goal: at the goal HOBBIT would bump into the table"
    assert caught.value.in_language("de").endswith("am Ziel würde HOBBIT gegen den Tisch stoßen")


def test_tablet_dialogs_go_through_mmui_and_come_back_answered(hobbit_robot, ros_robot):
    hobbit_robot.show_info('Hello "world"\nnew line')
    assert hobbit_robot.ask_yes_no("Tea?") is True          # the simulator answers from --answer yes
    assert hobbit_robot.ask_text("Your name?") == "Ada"      # and --answer Ada
    # The Tablet panel's rows: this node's last /MMUI call, as on the simulator.
    assert ros_robot.state.value("/MMUI", "request.params[1].value") == "Your name?"
    assert ros_robot.state.value("/MMUI", "response.params[0].value") == "Ada"
    hobbit_robot.call_sos()
    hobbit_robot.change_volume("louder")


def test_stop_during_a_drive_publishes_a_zero_twist(ros_robot, hobbit):
    twists, unsubscribe = record(ros_robot, "/cmd_vel", "geometry_msgs/Twist", lambda message: message)
    commands, stop_commands = record(ros_robot, "/DiscreteMotionCmd", "std_msgs/String",
                                     lambda message: message["data"])
    control = RunControl()
    runner = make_runner(hobbit, ros_robot, {"code": "robot.drive(30, 'forward')\n", "variables": {}}, control,
                         lambda e: None)
    thread = threading.Thread(target=runner.run)
    thread.start()
    eventually(lambda: commands[:1] == ["Move 30"])  # the drive is under way
    control.request_stop()
    thread.join(10)
    assert not thread.is_alive()
    eventually(lambda: any(not t["linear"]["x"] and not t["angular"]["z"] for t in twists))
    unsubscribe()
    stop_commands()


def test_an_unknown_service_times_out_naming_it(ros_robot):
    from rockly_desktop.core.errors import RobotTimeout

    with pytest.raises(RobotTimeout, match="/no_such_service"):
        ros_robot.backend(Interrupt()).call_service("/no_such_service", "std_srvs/Trigger", {}, 0.3)


def test_stop_ends_a_wait_for_a_service(ros_robot):
    class Watched(Interrupt):
        waiting = threading.Event()

        def nap(self, seconds):
            self.waiting.set()
            super().nap(seconds)

    interrupt = Watched()
    call = Background(lambda: ros_robot.backend(interrupt).call_service("/no_such_service", "std_srvs/Trigger", {}, 30))
    assert interrupt.waiting.wait(10)  # the call waits for the service now
    interrupt.request_stop()
    assert isinstance(call.join().error, ProgramStopped)


def test_the_ros_level_simulator_publishes_odometry_battery_and_joint_states(ros_robot, hobbit_robot):
    backend = ros_robot.backend(Interrupt())
    hobbit_robot.move_arm("candle")
    hobbit_robot.gripper("open")
    joints = backend.wait_for_message("/joint_states", "sensor_msgs/JointState", 5)
    assert joints["name"][:6] == [f"arm_joint_{i}" for i in range(1, 7)] and joints["name"][6] == "gripper"
    assert joints["position"][:6] == pytest.approx([0.0] * 6, abs=1e-6) and joints["position"][6] > 0
    battery = backend.wait_for_message("/battery_state", "sensor_msgs/BatteryState", 5)
    assert 0 < battery["percentage"] <= 1 and battery["present"] is True
    odometry = backend.wait_for_message("/odom", "nav_msgs/Odometry", 5)
    assert odometry["header"]["frame_id"] == "odom" and odometry["child_frame_id"] == "base_link"


def test_sensor_commands_work_over_ros(hobbit_robot):
    hobbit_robot.look("to_grasp")
    assert hobbit_robot.head_position() == "to_grasp"       # what this node last commanded
    assert 0 < hobbit_robot.battery_level() <= 100
    x = hobbit_robot.position("x")
    assert hobbit_robot.latest_value("/odom", "pose.pose.position.x") == pytest.approx(x, abs=0.05)  # type looked up
    from rockly_desktop.core.errors import RobotTimeout

    with pytest.raises(RobotTimeout, match="no topic '/nowhere'"):
        hobbit_robot.latest_value("/nowhere", "data")


def test_generic_ros_commands_over_ros(ros_robot):
    from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
    from rockly_desktop.robot.ros_commands import RosCommands

    said = []
    ros = RosCommands(ros_robot.backend(Interrupt()), say=said.append)
    heads, stop = record(ros_robot, "/head/move", "std_msgs/String", lambda message: message["data"])
    ros.publish("/head/move", "String", "down_right")
    eventually(lambda: heads[-1:] == ["down_right"])
    stop()
    odometry = ros.wait_for_message("/odom", 5)                      # from the separate simulator node
    assert ros.field(odometry, "child_frame_id") == "base_link"
    response = ros.call_service("/MMUI", "hobbit_msgs/Request",
                                {"sessionID": "0", "params": [{"name": "type", "value": "D_PLAIN"},
                                                              {"name": "text", "value": "generic"}]})
    assert isinstance(response["params"], list)
    home = {"command": {"data": "MoveToHome"}}
    assert ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", home) == "succeeded"
    outcome = []
    progress, stop_progress = record(ros_robot, "/hobbit_arm/feedback", "hobbit_msgs/ArmServerActionFeedback",
                                     lambda message: message["feedback"]["feedback"]["data"])
    mover = threading.Thread(target=lambda: outcome.append(
        ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", {"command": {"data": "MoveToCandle"}})))
    mover.start()
    eventually(lambda: any(data.startswith("MoveToCandle ") for data in progress))  # the server works on the goal
    ros.cancel_goals("hobbit_arm")
    mover.join(10)
    stop_progress()
    assert outcome == ["preempted"]
    ros.set_param("/rockly_test/speed", 0.25)
    assert ros.get_param("/rockly_test/speed") == 0.25
    with pytest.raises(RobotTimeout, match="/no_such_topic"):
        ros.wait_for_message("/no_such_topic", 0.5)
    with pytest.raises(RobotTimeout, match="/no_such_service"):
        ros.call_service("/no_such_service", "std_srvs/Trigger", {}, timeout=0.3)
    with pytest.raises(RobotCommandError, match="no action server 'no_such_action'"):
        ros.send_goal("no_such_action", "hobbit_msgs/ArmServerAction", {})


def test_a_goal_runs_its_while_waiting_handler_on_feedback_from_the_action_server(ros_robot):
    from rockly_desktop.robot.ros_commands import RosCommands

    ros, seen = RosCommands(ros_robot.backend(Interrupt())), []
    outcome = ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", {"command": {"data": "MoveToHome"}},
                            while_waiting=lambda feedback: seen.append((threading.get_ident(), feedback)))
    assert outcome == "succeeded"
    assert seen and {thread for thread, _ in seen} == {threading.get_ident()}
    assert all(feedback["feedback"]["data"].startswith("MoveToHome ") for _, feedback in seen)


def test_a_stop_while_a_handler_waits_preempts_the_goal_on_the_server(ros_robot):
    from rockly_desktop.robot.ros_commands import RosCommands

    results, unsubscribe = record(ros_robot, "/hobbit_arm/result", "hobbit_msgs/ArmServerActionResult",
                                  lambda message: message["status"]["status"])
    interrupt = Interrupt()
    ros = RosCommands(ros_robot.backend(interrupt))
    long_motion = {"command": {"data": "MoveAlongTrajectory"}, "joints": [{"joint_values": [0.1] * 6}] * 40}  # 5 s
    try:
        with pytest.raises(ProgramStopped):
            ros.send_goal("hobbit_arm", "hobbit_msgs/ArmServerAction", long_motion,
                          while_waiting=lambda feedback: interrupt.request_stop())
        eventually(lambda: results)
    finally:
        unsubscribe()
    assert results == [2]  # actionlib's PREEMPTED: the server stopped the arm


def test_the_teachers_limits_hold_over_ros(ros_robot, hobbit):
    from rockly_desktop.robot.wrappers.limits import Limits

    twists, stop_twists = record(ros_robot, "/cmd_vel", "geometry_msgs/Twist",
                                 lambda message: (message["linear"]["x"], message["angular"]["z"]))
    goals, stop_goals = record(ros_robot, "/hobbit_arm/goal", "hobbit_msgs/ArmServerActionGoal",
                               lambda message: message)
    fast = "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': %s}, 'angular': {'z': %s}})\n"
    code = fast % (1.5, 2.0) + fast % (-0.9, -4.0) + fast % (0.1, 0.2) + "robot.gripper('open')\n"
    limits = Limits(max_speed=0.2, max_turn=45, switched_off=frozenset({"arm"}))
    result = make_runner(hobbit, ros_robot, {"code": code, "variables": {}}, RunControl(), lambda e: None,
                         "de", limits).run()
    assert "Die Lehrkraft hat „Arm und Greifer“" in result.message
    eventually(lambda: len(twists) >= 4)  # three from the program, a zero one from the safe stop
    stop_twists()
    stop_goals()
    turn = math.radians(45)
    assert twists[:3] == [(0.2, pytest.approx(turn)), (-0.2, pytest.approx(-turn)), (0.1, 0.2)]
    assert all(abs(x) <= 0.2 and abs(z) <= turn + 1e-9 for x, z in twists)
    assert goals == []


def test_a_limited_drive_and_turn_send_no_cmd_vel_above_the_limit_and_end_where_asked_over_ros(ros_robot, hobbit,
                                                                                             hobbit_robot):
    """HOBBIT's Move/Turn go at the base's own speed (0.3 m/s, 45°/s): under a lower limit the
    commands drive them with /cmd_vel instead, stopped by the odometry the ROS-level base publishes."""
    from rockly_desktop.robot.wrappers.limits import Limits

    hobbit_robot.navigate_to(1.0, 0.5, 0)  # a known free place, whatever earlier tests did
    twists, stop_twists = record(ros_robot, "/cmd_vel", "geometry_msgs/Twist",
                                 lambda message: (message["linear"]["x"], message["angular"]["z"]))
    commands, stop_commands = record(ros_robot, "/DiscreteMotionCmd", "std_msgs/String",
                                     lambda message: message["data"])
    speeds, stop_speeds = record(ros_robot, "/odom", "nav_msgs/Odometry",
                                 lambda message: abs(message["twist"]["twist"]["linear"]["x"]))
    x0, y0, theta0 = pose(ros_robot)
    code = "robot.drive(0.5)\nrobot.turn(90, 'left')\n"
    result = make_runner(hobbit, ros_robot, {"code": code, "variables": {}}, RunControl(), lambda e: None,
                         "en", Limits(max_speed=0.1, max_turn=20)).run()
    assert result.outcome == "finished", result.message
    eventually(lambda: "Stop" in commands)  # the safe stop after the run
    x1, y1, theta1 = pose(ros_robot)
    for stop in (stop_twists, stop_commands, stop_speeds):
        stop()
    assert commands == ["Stop"], "a discrete motion goes at the base's own speed"
    assert twists and all(abs(x) <= 0.1 and abs(z) <= math.radians(20) + 1e-9 for x, z in twists)
    assert max(speeds) == pytest.approx(0.1)
    assert math.hypot(x1 - x0, y1 - y0) == pytest.approx(0.5, abs=0.005)
    assert math.remainder(theta1 - theta0 - 90, 360) == pytest.approx(0.0, abs=0.5)
