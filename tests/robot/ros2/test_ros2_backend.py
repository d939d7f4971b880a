"""Rockly's ROS 2 link against a plain rclpy robot in another process (tests/robot/ros2/ros2_test_node.py)."""
import math
import threading

import pytest
from ros2_fixtures import requests_to
from waiting import eventually

from rockly_desktop.core.errors import ProgramStopped, RobotCommandError, RobotTimeout
from rockly_desktop.robot.interface import GoalStatus
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.wrappers import ros_versions
from rockly_desktop.robot.wrappers.ros_versions import link_backend


@pytest.fixture
def backend(ros2_robot):
    return ros2_robot.backend(Interrupt())


def test_a_turtlebot_drive_command_reaches_the_robot_as_a_twist(ros2_robot, test_robot, turtlebot):
    commands = turtlebot.create("api", ros2_robot.backend(Interrupt()))
    commands._twist(0.15, -0.5)  # what drive/turn send each step
    eventually(lambda: any(line["message"]["linear"]["x"] == 0.15 for line in test_robot.received("/cmd_vel")))
    line = [line for line in test_robot.received("/cmd_vel") if line["message"]["linear"]["x"] == 0.15][-1]
    assert line["type"] == "Twist"
    assert line["message"]["angular"] == {"x": 0.0, "y": 0.0, "z": -0.5}


def test_publishing_by_long_and_short_type_names(backend, test_robot):
    backend.publish("/chatter", "std_msgs/msg/String", {"data": "long"})
    backend.publish("/chatter", "std_msgs/String", {"data": "short"})
    eventually(lambda: [line["message"]["data"] for line in test_robot.received("/chatter")][-2:] == ["long", "short"])


def test_odometry_and_a_best_effort_laser_scan_are_read(backend, ros2_robot, turtlebot):
    odom = backend.wait_for_message("/odom", "nav_msgs/Odometry", 10)
    assert odom["pose"]["pose"]["position"]["x"] == 1.5
    assert odom["header"]["frame_id"] == "odom"
    scan = backend.wait_for_message("/scan", "sensor_msgs/msg/LaserScan", 10)  # sensor-data QoS on the robot's side
    assert scan["ranges"][:2] == [0.5, 1.0] and math.isinf(scan["ranges"][2])
    eventually(lambda: backend.latest("/odom", None) is not None)
    commands = turtlebot.create("api", backend)
    assert commands.distance("ahead") == 1.0  # the middle ray


def test_a_latched_topic_is_heard_by_a_late_subscriber(backend, ros2_robot):
    eventually(lambda: "/map_name" in [name for name, _types, _count in ros2_robot.helper.call("graph")["topics"]])
    eventually(lambda: backend.latest("/map_name", "std_msgs/String") == {"data": "arena"})


def test_a_message_of_a_wrong_shape_is_refused_with_the_field_named(backend):
    with pytest.raises(RobotCommandError, match="linear.x"):
        backend.publish("/wrong_shape", "geometry_msgs/Twist", {"linear": {"x": "fast"}})


def test_an_interface_package_ros2_lacks_is_named(backend):
    with pytest.raises(RobotCommandError, match="hobbit_msgs"):
        backend.publish("/head/move", "hobbit_msgs/HeadMove", {})


def test_a_service_call_returns_the_response(backend):
    assert backend.call_service("/set_light", "std_srvs/SetBool", {"data": True}, 10) == {
        "success": True, "message": "light on"}


def test_a_missing_service_times_out_with_its_name(backend):
    with pytest.raises(RobotTimeout, match="/no_such_service"):
        backend.call_service("/no_such_service", "std_srvs/srv/Trigger", {}, 0.3)


def test_an_action_goal_gets_feedback_and_its_result(backend):
    feedback = []
    handle = backend.send_goal("/fibonacci", "test_msgs/action/Fibonacci", {"order": 4}, feedback=feedback.append)
    outcome = handle.wait(10)
    assert outcome.status is GoalStatus.SUCCEEDED
    assert outcome.result == {"sequence": [0, 1, 1, 2, 3, 5]}
    assert [len(each["sequence"]) for each in feedback] == [3, 4, 5, 6]


def test_a_cancelled_goal_ends_preempted(backend):
    feedback = []
    handle = backend.send_goal("/fibonacci", "test_msgs/Fibonacci", {"order": 100}, feedback=feedback.append)
    eventually(lambda: len(feedback) >= 2)
    handle.cancel()
    assert handle.wait(10).status is GoalStatus.PREEMPTED
    assert handle.done()


def test_cancel_all_goals_stops_a_goal_sent_by_someone_else(backend, ros2_robot):
    other = ros2_robot.backend(Interrupt())
    feedback = []
    handle = other.send_goal("/fibonacci", "test_msgs/Fibonacci", {"order": 100}, feedback=feedback.append)
    eventually(lambda: feedback)
    backend.cancel_all_goals("/fibonacci")
    assert handle.wait(10).status is GoalStatus.PREEMPTED


def test_parameters_are_read_from_their_node(backend):
    assert backend.get_param("test_robot:max_speed") == 0.22
    assert backend.get_param("/test_robot/robot_name") == "tb"
    assert backend.get_param("test_robot:not_declared", "fallback") == "fallback"


def test_a_stop_ends_a_wait_for_a_message_at_once(ros2_robot):
    interrupt = Interrupt()
    backend = ros2_robot.backend(interrupt)
    threading.Timer(0.1, interrupt.request_stop).start()
    with pytest.raises(ProgramStopped):
        backend.wait_for_message("/nobody_publishes_this", "std_msgs/String", 30)


def test_the_safe_stop_publishes_a_zero_twist(ros2_robot, test_robot):
    ros2_robot.backend(Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    eventually(lambda: any(line["message"]["linear"]["x"] == 0.1 for line in test_robot.received("/cmd_vel")))
    assert ros2_robot.safe_stop() == []
    eventually(lambda: test_robot.received("/cmd_vel")[-1]["message"]["linear"]["x"] == 0.0)


def test_the_safe_stop_does_not_wait_for_a_graph_query_once_a_run_learnt_the_type(ros2_robot, test_robot,
                                                                                 monkeypatch):
    """A Twist robot's type is looked at again every RECHECK_SECONDS by runs (it may be discovered late);
    the safe stop sends the type learnt, so its zero velocity never waits for the graph."""
    monkeypatch.setattr(ros_versions, "RECHECK_SECONDS", 0.0)
    link_backend(ros2_robot, Interrupt()).publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.12}})
    eventually(lambda: any(line["message"]["linear"]["x"] == 0.12 for line in test_robot.received("/cmd_vel")))
    with requests_to(ros2_robot.helper) as asked:
        assert ros2_robot.safe_stop() == []
    assert "graph" not in asked
    eventually(lambda: test_robot.received("/cmd_vel")[-1]["message"]["linear"]["x"] == 0.0)


def test_the_graph_lists_the_robots_topics_with_types_and_health(ros2_robot):
    ros2_robot.follow_graph()
    eventually(lambda: ("/odom", "nav_msgs/Odometry", 1) in ros2_robot.graph_topics())
    assert ("/scan", "sensor_msgs/LaserScan", 1) in ros2_robot.graph_topics()
    eventually(lambda: "/odom" in {info.topic for info in ros2_robot.state.topics()})
    health = {str(item.name): item for item in ros2_robot.health()}
    assert health["ROS 2"].level == "green" and "localhost" in str(health["ROS 2"].detail)
    # the TurtleBot's bumper: turtlebot3_msgs is not in ROS 2's environment here, which is said, in German too
    bumper = health["/sensor_state"]
    assert bumper.level == "amber" and "turtlebot3_msgs is not installed" in str(bumper.detail)
    assert "turtlebot3_msgs ist in der ROS-2-Umgebung nicht installiert" in bumper.detail.in_language("de")


def test_the_connection_says_where_and_how_fast(ros2_robot):
    connection = ros2_robot.connection
    assert connection.status == "connected" and not connection.lost
    assert str(connection.master_uri).startswith("ROS 2, domain ")
    assert connection.master_uri.in_language("de").startswith("ROS 2, Domäne ")
    ros2_robot.health()
    # measured by the helper's own thread every 0.5 s from its start: as the module's first test, none may be yet
    eventually(lambda: connection.round_trip is not None)


def test_an_ended_subscription_hears_nothing_more_and_a_new_one_hears_again(ros2_robot):
    helper = ros2_robot.helper
    first, second = helper.new_id(), helper.new_id()
    heard = {first: [], second: []}
    for sid in heard:
        helper.on("msg", sid, heard[sid].append)
    try:
        helper.call("subscribe", first, "/odom", "nav_msgs/Odometry", timeout=10)
        eventually(lambda: heard[first])
        helper.call("unsubscribe", first, timeout=10)
        ended_with = len(heard[first])
        helper.call("subscribe", second, "/odom", "nav_msgs/Odometry", timeout=10)
        eventually(lambda: len(heard[second]) >= 5)  # a quarter of a second of the robot's 20 Hz odometry
        assert len(heard[first]) <= ended_with + 1  # one taken as it ended may still come
    finally:
        helper.call("unsubscribe", second, timeout=10)
        for sid in heard:
            helper.off("msg", sid)
