"""A plain rclpy robot for the ROS 2 tests (run with .venv-ros2's Python; no Rockly code).

Publishes /odom (reliable) and /scan (sensor-data QoS, best effort, as laser drivers do) at
20 Hz, /map_name once (transient local, as a map server keeps its map for late joiners),
serves /set_light (std_srvs/SetBool) and /fibonacci (test_msgs/Fibonacci, a feedback
per step every 50 ms, cancellable), has parameters max_speed and robot_name, and prints
one JSON line per message it gets on /cmd_vel and /chatter and per /set_light request:
{"topic", "type", "message"}.
It prints {"ready": true} once everything is up, and leaves when stdin ends.
"""
import json
import sys
import threading
import time

import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.action import ActionServer, CancelResponse
from rclpy.executors import MultiThreadedExecutor
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String
from std_srvs.srv import SetBool
from test_msgs.action import Fibonacci


def say(data):
    print(json.dumps(data), flush=True)


def twist_dict(message):
    return {"linear": {"x": message.linear.x, "y": message.linear.y, "z": message.linear.z},
            "angular": {"x": message.angular.x, "y": message.angular.y, "z": message.angular.z}}


def main():
    rclpy.init()
    node = rclpy.create_node("test_robot", parameter_overrides=[])
    node.declare_parameter("max_speed", 0.22)
    node.declare_parameter("robot_name", "tb")
    node.create_subscription(Twist, "/cmd_vel", lambda m: say(
        {"topic": "/cmd_vel", "type": type(m).__name__, "message": twist_dict(m)}), 10)
    node.create_subscription(String, "/chatter", lambda m: say(
        {"topic": "/chatter", "type": type(m).__name__, "message": {"data": m.data}}), 10)
    odom = node.create_publisher(Odometry, "/odom", 10)
    scan = node.create_publisher(LaserScan, "/scan", qos_profile_sensor_data)
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
    map_name = node.create_publisher(String, "/map_name", latched)
    map_name.publish(String(data="arena"))
    tick = [0]

    def publish():
        tick[0] += 1
        message = Odometry()
        message.header.frame_id = "odom"
        message.pose.pose.position.x = 1.5
        message.pose.pose.orientation.w = 1.0
        message.twist.twist.linear.x = 0.1 * tick[0]
        odom.publish(message)
        laser = LaserScan(angle_min=-1.0, angle_max=1.0, angle_increment=1.0, range_min=0.1, range_max=3.5,
                          ranges=[0.5, 1.0, float("inf")])
        scan.publish(laser)

    node.create_timer(0.05, publish)

    def set_light(request, response):
        say({"topic": "/set_light", "type": "SetBool", "message": {"data": request.data}})
        response.success = request.data
        response.message = f"light {'on' if request.data else 'off'}"
        return response

    node.create_service(SetBool, "/set_light", set_light)

    def execute(goal_handle):
        sequence = [0, 1]
        for _step in range(goal_handle.request.order):
            if goal_handle.is_cancel_requested:
                goal_handle.canceled()
                return Fibonacci.Result(sequence=sequence)
            sequence.append(sequence[-1] + sequence[-2])
            goal_handle.publish_feedback(Fibonacci.Feedback(sequence=sequence))
            time.sleep(0.05)
        goal_handle.succeed()
        return Fibonacci.Result(sequence=sequence)

    ActionServer(node, Fibonacci, "/fibonacci", execute, cancel_callback=lambda _goal: CancelResponse.ACCEPT)
    executor = MultiThreadedExecutor(4)
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    say({"ready": True})
    sys.stdin.read()  # until the test closes our stdin (or dies)
    executor.shutdown()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
