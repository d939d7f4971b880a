"""Dicts converted to ROS 1 messages and back (robot/ros1/message_values.py), with real genpy classes."""
import io
from pathlib import Path

import pytest

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.ros1.message_classes import MessageTypes
from rockly_desktop.robot.ros1.message_values import from_message, to_message

HOBBIT_MSG = Path(__file__).resolve().parents[3] / "profiles" / "hobbit" / "msg"


@pytest.fixture(scope="module")
def types(tmp_path_factory):
    """HOBBIT's definitions, generated into this module's cache."""
    return MessageTypes([HOBBIT_MSG], cache_dir=tmp_path_factory.mktemp("ros1-cache"))


def roundtrip(msg):
    """Serialize and deserialize with genpy, as rospy does on the wire."""
    buffer = io.BytesIO()
    msg.serialize(buffer)
    copy = type(msg)()
    copy.deserialize(buffer.getvalue())
    return copy


def test_twist_round_trip(types):
    twist_class = types.message_class("geometry_msgs/Twist")
    twist = to_message(twist_class, {"linear": {"x": 0.5}, "angular": {"z": -1}})
    assert isinstance(twist, twist_class) and (twist.linear.x, twist.linear.y, twist.angular.z) == (0.5, 0.0, -1.0)
    expected = {"linear": {"x": 0.5, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": -1.0}}
    assert from_message(twist) == expected
    assert from_message(roundtrip(twist)) == expected
    assert to_message(twist_class, expected) == twist
    assert from_message(to_message(twist_class, {})) == {"linear": {"x": 0.0, "y": 0.0, "z": 0.0},
                                                         "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}
    assert types.from_message(types.to_message("geometry_msgs/Twist", {"linear": {"x": 2}})) == \
        {"linear": {"x": 2.0, "y": 0.0, "z": 0.0}, "angular": {"x": 0.0, "y": 0.0, "z": 0.0}}


def test_pose_stamped_round_trip_with_stamps(types):
    pose_class = types.message_class("geometry_msgs/PoseStamped")
    data = {"header": {"frame_id": "map", "stamp": 12.25},
            "pose": {"position": {"x": 1.5, "y": -2}, "orientation": {"z": 0.7071, "w": 0.7071}}}
    pose = to_message(pose_class, data)
    assert (pose.header.stamp.secs, pose.header.stamp.nsecs) == (12, 250_000_000)
    assert pose.header.seq == 0 and pose.pose.position.z == 0.0
    back = from_message(roundtrip(pose))
    assert back["header"] == {"seq": 0, "stamp": {"secs": 12, "nsecs": 250_000_000}, "frame_id": "map"}
    assert back["pose"]["position"] == {"x": 1.5, "y": -2.0, "z": 0.0}
    assert to_message(pose_class, back) == pose
    exact = to_message(pose_class, {"header": {"stamp": {"secs": 1_700_000_000, "nsecs": 123_456_789}}})
    assert from_message(exact)["header"]["stamp"] == {"secs": 1_700_000_000, "nsecs": 123_456_789}


def test_mmui_request_with_params_round_trip(types):
    request_class = types.service_class("hobbit_msgs/Request")._request_class
    assert types.message_class("hobbit_msgs/RequestRequest") is request_class
    data = {"header": {"seq": 3, "stamp": {"secs": 5, "nsecs": 6}, "frame_id": ""},
            "sessionID": "0", "requestText": "",
            "params": [{"name": "type", "value": "D_YES_NO"}, {"name": "text", "value": "Möchten Sie Tee?"},
                       {"name": "Timeout", "value": "15"}]}
    request = to_message(request_class, data)
    assert [p.name for p in request.params] == ["type", "text", "Timeout"]
    assert from_message(roundtrip(request)) == data
    response_class = types.service_class("hobbit_msgs/Request")._response_class
    response = roundtrip(to_message(response_class, {"params": [{"name": "result", "value": "yes"}]}))
    assert from_message(response) == {"params": [{"name": "result", "value": "yes"}]}


def test_arm_goal_with_joints_round_trip(types):
    arm = types.action_classes("hobbit_msgs/ArmServer")
    data = {"command": {"data": "MoveAlongTrajectory"}, "velocity": 0.5,
            "joints": [{"joint_values": [0, 0.5, 1, 1.5, 2, 2.5]}, {"joint_values": [1, 1, 1, 1, 1, 1]}]}
    goal = to_message(arm.goal, data)
    assert len(goal.joints) == 2 and goal.joints[0].joint_values == [0.0, 0.5, 1.0, 1.5, 2.0, 2.5]
    back = from_message(roundtrip(goal))
    assert back == {"command": {"data": "MoveAlongTrajectory"}, "velocity": 0.5,
                    "joints": [{"joint_values": [0.0, 0.5, 1.0, 1.5, 2.0, 2.5]}, {"joint_values": [1.0] * 6}]}
    assert from_message(to_message(arm.goal, {"command": {"data": "MoveToHome"}}))["joints"] == []
    result = roundtrip(to_message(arm.result, {"result": {"data": True}}))
    assert from_message(result) == {"result": {"data": True}}
    wrapped = to_message(arm.action_goal, {"goal_id": {"id": "g1", "stamp": 1.0}, "goal": goal})
    assert from_message(roundtrip(wrapped))["goal"] == back


def test_byte_arrays_are_lists_of_numbers(types):
    array_class = types.message_class("std_msgs/UInt8MultiArray")
    message = to_message(array_class, {"data": [1, 2, 255]})
    assert message.data == b"\x01\x02\xff"
    assert from_message(roundtrip(message))["data"] == [1, 2, 255]


@pytest.mark.parametrize("type_name, data, error", [
    ("geometry_msgs/PoseStamped", {"pose": {"position": {"x": "far"}}},
     "pose.position.x: expected a number, got 'far'"),
    ("geometry_msgs/PoseStamped", {"pose": {"positon": {}}}, "pose.positon: geometry_msgs/Pose has no field 'positon'"),
    ("geometry_msgs/PoseStamped", {"header": {"seq": -1}}, "header.seq: -1 is out of range for uint32"),
    ("geometry_msgs/PoseStamped", {"header": {"stamp": "now"}}, "header.stamp: expected a time in seconds"),
    ("geometry_msgs/PoseStamped", {"header": {"stamp": -3.0}}, "header.stamp: -3.0 is not a valid time"),
    ("geometry_msgs/PoseStamped", {"pose": 3}, "pose: expected a dict for geometry_msgs/Pose, got 3"),
    ("geometry_msgs/Twist", {"linear": {"x": True}}, "linear.x: expected a number, got True"),
    ("geometry_msgs/Twist", [1, 2], "geometry_msgs/Twist: expected a dict for geometry_msgs/Twist"),
    ("hobbit_msgs/RequestRequest", {"params": [{"name": "type"}, {"name": "text", "value": 3}]},
     "params[1].value: expected a string, got 3"),
    ("hobbit_msgs/RequestRequest", {"params": {"name": "type"}}, "params: expected a list, got {'name': 'type'}"),
    ("hobbit_msgs/RequestRequest", {"header": {"stamp": {"secs": 1, "nanos": 2}}},
     "header.stamp: a time has only 'secs' and 'nsecs', not 'nanos'"),
    ("hobbit_msgs/ArmServerGoal", {"joints": [{"joint_values": [1, 2, 3, 4, 5]}]},
     "joints[0].joint_values: expected 6 values, got 5"),
    ("hobbit_msgs/ArmServerGoal", {"joints": [{"joint_values": [1, 2, 3, 4, 5, "x"]}]},
     "joints[0].joint_values[5]: expected a number, got 'x'"),
    ("hobbit_msgs/ArmServerGoal", {"joints": [{"joint_values": [1e39, 0, 0, 0, 0, 0]}]},
     "joints[0].joint_values[0]: 1e+39 is too large for a float32"),
    ("hobbit_msgs/ArmServerGoal", {"command": {"data": "MoveToHome"}, "velocity": None},
     "velocity: expected a number, got None"),
    ("hobbit_msgs/ArmServerResult", {"result": {"data": "yes"}}, "result.data: expected true or false, got 'yes'"),
    ("std_msgs/Int8", {"data": 2.5}, "data: expected a whole number, got 2.5"),
    ("std_msgs/Int8", {"data": 200}, "data: 200 is out of range for int8 (-128 to 127)"),
])
def test_a_bad_field_names_its_path(types, type_name, data, error):
    with pytest.raises(RobotCommandError) as caught:
        to_message(types.message_class(type_name), data)
    assert error in str(caught.value)


def test_whole_floats_fill_integer_fields(types):
    assert to_message(types.message_class("std_msgs/Int64"), {"data": 3.0}).data == 3
    assert to_message(types.message_class("std_msgs/Bool"), {"data": 1}).data is True


def test_from_message_needs_a_message():
    with pytest.raises(RobotCommandError, match="from_message needs a ROS message"):
        from_message({"linear": {}})
    with pytest.raises(RobotCommandError, match="to_message needs a ROS message class"):
        to_message("geometry_msgs/Twist", {})

