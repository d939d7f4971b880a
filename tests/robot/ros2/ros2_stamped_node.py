"""A plain rclpy TurtleBot as on ROS 2 Jazzy (run with .venv-ros2's Python; no Rockly code).

Subscribes to /cmd_vel as geometry_msgs/TwistStamped (TurtleBot3 from Jazzy on) and prints one
JSON line per message: {"topic", "type", "frame_id", "stamped", "message"}; publishes /odom with
time stamps at 20 Hz (standing still). Prints {"ready": true} once up, leaves when stdin ends.
"""
import json
import sys
import threading

import rclpy
from geometry_msgs.msg import TwistStamped
from nav_msgs.msg import Odometry
from rclpy.executors import SingleThreadedExecutor


def say(data):
    print(json.dumps(data), flush=True)


def heard(message):
    twist = message.twist
    say({"topic": "/cmd_vel", "type": type(message).__name__, "frame_id": message.header.frame_id,
         "stamped": message.header.stamp.sec > 0,
         "message": {"linear": {"x": twist.linear.x}, "angular": {"z": twist.angular.z}}})


def main():
    rclpy.init()
    node = rclpy.create_node("jazzy_test_robot")
    node.create_subscription(TwistStamped, "/cmd_vel", heard, 10)
    odom = node.create_publisher(Odometry, "/odom", 10)

    def publish():
        message = Odometry()
        message.header.stamp = node.get_clock().now().to_msg()
        message.header.frame_id = "odom"
        message.pose.pose.orientation.w = 1.0
        odom.publish(message)

    node.create_timer(0.05, publish)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    threading.Thread(target=executor.spin, daemon=True).start()
    say({"ready": True})
    sys.stdin.read()  # until the test closes our stdin (or dies)
    executor.shutdown()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
