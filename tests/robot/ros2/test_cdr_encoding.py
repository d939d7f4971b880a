"""Messages Rockly encodes itself (cdr_encoding, from the helper's layouts) are what the helper would have
published, checked by rclpy decoding them; whatever Rockly's side is not sure of goes to the helper."""
import math
import pickle
import subprocess
from pathlib import Path

import pytest
from ros2_fixtures import ROS2_PYTHON
from waiting import eventually

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.ros2.cdr_encoding import MessageEncoder, NotEncodable

REFERENCE = Path(__file__).with_name("encoding_reference.py")
QUOTES = "say \"hi\" and 'bye'\nnext line\ttab, ümlaut, 🤖"

# (type, fields) Rockly's side must encode exactly as the helper's way would
ENCODED = [
    ("geometry_msgs/Twist", {"linear": {"x": 0.1}}),
    ("geometry_msgs/Twist", {"linear": {"x": 1, "y": -0.0}, "angular": {"z": -0.5}}),
    ("geometry_msgs/Twist", None),
    ("geometry_msgs/Twist", {}),
    ("geometry_msgs/msg/TwistStamped", {"header": {"stamp": {"secs": 5, "nsecs": 7}, "frame_id": "base_link", "seq": 3},
                                        "twist": {"linear": {"x": 0.2}}}),
    ("std_msgs/String", {"data": QUOTES}),
    ("std_msgs/String", {"data": ""}),
    ("nav_msgs/Odometry", {"header": {"frame_id": "odom"}, "child_frame_id": "base",
                           "pose": {"pose": {"position": {"x": 1.5}, "orientation": {"w": 1}},
                                    "covariance": [0.5] * 36}}),
    ("sensor_msgs/LaserScan", {"ranges": [0.5, 1.0, math.inf, math.nan], "intensities": [1, 2], "angle_min": -1.5}),
    ("sensor_msgs/LaserScan", {"ranges": [3.4e38, -math.inf]}),
    ("sensor_msgs/BatteryState", {"percentage": 0.5, "power_supply_status": 2, "present": True,
                                  "cell_voltage": [3.7, 3.8], "location": "x", "serial_number": "y"}),
    ("sensor_msgs/JointState", {"name": ["a", "b"], "position": [1.0, 2], "velocity": [], "effort": (0.0, 0.0)}),
    ("sensor_msgs/Image", {"height": 2, "width": 1, "encoding": "mono8", "data": [1, 255]}),
    ("std_msgs/UInt8", {"data": 255}), ("std_msgs/Int8", {"data": -128}), ("std_msgs/Int16", {"data": -32768}),
    ("std_msgs/UInt32", {"data": 2 ** 32 - 1}), ("std_msgs/Int64", {"data": -2 ** 63}),
    ("std_msgs/UInt64", {"data": 2 ** 64 - 1}), ("std_msgs/Bool", {"data": True}),
    ("std_msgs/Float32", {"data": 0.1}), ("std_msgs/Float64", {"data": 1e308}),
    ("test_msgs/BasicTypes", {"byte_value": b"x", "char_value": 65, "float32_value": 1.5, "bool_value": True}),
    ("test_msgs/Defaults", {}),
    ("test_msgs/Strings", {}),
    ("test_msgs/Strings", {"bounded_string_value": "x" * 22, "string_value": QUOTES}),
    ("test_msgs/Nested", {"basic_types_value": {"int16_value": -3, "uint64_value": 7}}),
    ("test_msgs/Builtins", {"duration_value": {"sec": -1, "nanosec": 5}, "time_value": {"secs": 3}}),
]

# (type, fields) Rockly's side must leave to the helper (which refuses most, naming the field)
LEFT_TO_THE_HELPER = [
    ("geometry_msgs/Twist", {"linear": {"x": "fast"}}),
    ("geometry_msgs/Twist", {"linear": {"speed": 1.0}}),
    ("geometry_msgs/Twist", {"linear": 1.0}),
    ("geometry_msgs/Twist", {"linear": {"x": None}}),
    ("geometry_msgs/Twist", {"linear": {"x": 10 ** 400}}),
    ("std_msgs/String", {"data": 5}),
    ("std_msgs/String", {"data": "nul \0 inside"}),
    ("std_msgs/String", {"data": "lone \ud800 surrogate"}),
    ("nav_msgs/Odometry", {"pose": {"covariance": [0.5] * 35}}),
    ("sensor_msgs/LaserScan", {"ranges": [1e39]}),
    ("sensor_msgs/LaserScan", {"ranges": ["1.0"]}),
    ("sensor_msgs/LaserScan", {"ranges": 1.0}),
    ("sensor_msgs/Image", {"data": [256]}),
    ("std_msgs/UInt8", {"data": 256}), ("std_msgs/UInt64", {"data": -1}), ("std_msgs/Int8", {"data": 1.0}),
    ("std_msgs/Bool", {"data": 1}), ("std_msgs/Int32", {"data": True}),
    ("std_msgs/Float32", {"data": 1e39}),
    ("test_msgs/BasicTypes", {"byte_value": b"xy"}),
    ("test_msgs/Strings", {"bounded_string_value": "x" * 23}),
    ("test_msgs/Builtins", {"time_value": {"sec": 2 ** 31}}),
]


@pytest.fixture(scope="module")
def encoders(ros2_robot):
    """An encoder per type of the cases, from the helper's layouts."""
    types = {type_name for type_name, _fields in ENCODED + LEFT_TO_THE_HELPER}
    return {type_name: MessageEncoder(ros2_robot.helper.call("layout", type_name, timeout=10)) for type_name in types}


def reference(cases):
    """rclpy's verdicts (encoding_reference.py) on ``(type, fields, raw)`` cases."""
    answer = subprocess.run([str(ROS2_PYTHON), str(REFERENCE)], input=pickle.dumps(cases), capture_output=True,
                            check=True, timeout=120)
    return pickle.loads(answer.stdout)


def encoded_or_none(encoder, fields):
    try:
        return encoder.encode(fields)
    except NotEncodable:
        return None


def test_what_rockly_encodes_is_what_the_helper_would_have_published(encoders):
    cases = [(type_name, fields, encoders[type_name].encode(fields)) for type_name, fields in ENCODED]
    for (type_name, fields, _raw), (by_fields, decoded) in zip(cases, reference(cases), strict=True):
        assert not by_fields.startswith("refused"), (type_name, fields, by_fields)
        assert decoded == by_fields, (type_name, fields)


def test_what_rockly_is_not_sure_of_is_left_to_the_helper(encoders):
    cases = [(type_name, fields, encoded_or_none(encoders[type_name], fields))
             for type_name, fields in LEFT_TO_THE_HELPER]
    assert [(type_name, fields) for type_name, fields, raw in cases if raw is not None] == []
    verdicts = zip(cases, reference(cases), strict=True)
    taken = [(type_name, fields) for (type_name, fields, _raw), (by_fields, _decoded) in verdicts
             if not by_fields.startswith("refused")]
    # the helper's way takes these two, and sends what rclpy makes of them; the rest it refuses, saying why
    # (a number as a text in a float array too, as rclpy would: no "1.0" becomes a speed or a range)
    assert taken == [("std_msgs/String", {"data": "nul \0 inside"}), ("std_msgs/Int32", {"data": True})]


def test_types_of_wide_strings_octet_arrays_or_no_fields_have_no_layout(ros2_robot):
    for type_name in ("test_msgs/WStrings", "test_msgs/Arrays", "std_msgs/Empty"):
        assert ros2_robot.helper.call("layout", type_name, timeout=10) is None


def test_published_messages_go_encoded_and_arrive_whole(ros2_robot, test_robot):
    backend = ros2_robot.backend(Interrupt())
    casts = []
    cast = ros2_robot.helper.cast
    ros2_robot.helper.cast = lambda op, *args: casts.append(op) or cast(op, *args)
    try:
        for count in range(30):
            backend.publish("/chatter", "std_msgs/String", {"data": f"{QUOTES} {count}"})
            if "publish_raw" in casts:
                break
            eventually(lambda count=count: f"{QUOTES} {count}" in
                       [line["message"]["data"] for line in test_robot.received("/chatter")])
        backend.publish("/chatter", "std_msgs/String", {"data": f"{QUOTES} last"})
    finally:
        del ros2_robot.helper.cast
    assert casts[-1] == "publish_raw"
    eventually(lambda: f"{QUOTES} last" in [line["message"]["data"] for line in test_robot.received("/chatter")])


def test_a_bad_value_after_encoded_messages_is_named_by_the_helper(ros2_robot):
    backend = ros2_robot.backend(Interrupt())
    backend.publish("/encoded_then_bad", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    eventually(lambda: ros2_robot.helper.encoder("geometry_msgs/Twist") is not None)
    backend.publish("/encoded_then_bad", "geometry_msgs/Twist", {"linear": {"x": 0.2}})
    backend.publish("/encoded_then_bad", "geometry_msgs/Twist", {"angular": {"z": "left"}})

    said = []

    def refused():  # a one-way publish's failure is raised by a later command, once the helper told it
        try:
            backend.publish("/encoded_then_bad", "geometry_msgs/Twist", {})
        except RobotCommandError as error:
            said.append(str(error))
            return True
        return False
    eventually(refused)
    assert "angular.z" in said[0] and "left" in said[0]
