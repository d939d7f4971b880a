"""A plain rclpy camera for the memory tests (run with .venv-ros2's Python; no Rockly code).

Publishes a ``sensor_msgs/Image`` of ``SIZE`` bytes (argv[1], default 1 MB) on /camera/image_raw
at ``RATE`` Hz (argv[2], default 100) with sensor-data QoS, as camera drivers do. It prints
{"ready": true} once the publisher is up, and, when stdin ends, {"published": N} and leaves.
"""
import json
import sys
import threading

import rclpy
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import Image


def main():
    size = int(sys.argv[1]) if len(sys.argv) > 1 else 1 << 20
    rate = float(sys.argv[2]) if len(sys.argv) > 2 else 100.0
    rclpy.init()
    node = rclpy.create_node("test_camera")
    publisher = node.create_publisher(Image, "/camera/image_raw", qos_profile_sensor_data)
    image = Image(height=size // 1024 or 1, width=min(size, 1024), encoding="mono8", step=min(size, 1024))
    image.header.frame_id = "camera"
    image.data = bytes(range(256)) * (size // 256) + bytes(size % 256)
    published = [0]

    def publish():
        image.header.stamp = node.get_clock().now().to_msg()
        publisher.publish(image)
        published[0] += 1

    node.create_timer(1.0 / rate, publish)
    spin = threading.Thread(target=rclpy.spin, args=(node,), daemon=True)
    spin.start()
    print(json.dumps({"ready": True}), flush=True)
    sys.stdin.read()  # until the test closes our stdin (or dies)
    print(json.dumps({"published": published[0]}), flush=True)
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
