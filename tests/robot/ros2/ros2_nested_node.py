"""A plain rclpy node for the ROS 2 tests (run with .venv-ros2's Python; no Rockly code): it publishes
/nested (test_msgs/msg/Nested, a type no Rockly profile defines: a BasicTypes inside) twice a second with
int32_value 7, and prints {"message": {"int32_value", "float64_value"}} for every message it hears there
(its own and others'). {"ready": true} once it publishes; it leaves when stdin ends."""
import json

import rclpy
from ros2_node_life import serve_until_stdin_ends
from test_msgs.msg import Nested


def main():
    rclpy.init()
    node = rclpy.create_node("nested")
    publisher = node.create_publisher(Nested, "/nested", 10)

    def heard(message):
        values = message.basic_types_value
        print(json.dumps({"message": {"int32_value": values.int32_value, "float64_value": values.float64_value}}),
              flush=True)

    node.create_subscription(Nested, "/nested", heard, 10)

    def publish():
        message = Nested()
        message.basic_types_value.int32_value = 7
        publisher.publish(message)

    node.create_timer(0.5, publish)
    serve_until_stdin_ends(node)


if __name__ == "__main__":
    main()
