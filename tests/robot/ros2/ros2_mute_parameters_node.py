"""A plain rclpy node for the ROS 2 tests (run with .venv-ros2's Python; no Rockly code) whose
/mute/list_parameters service (rcl_interfaces/ListParameters) takes every request and never
answers. It prints {"ready": true} once the service is up, and leaves when stdin ends."""
import json
import sys
import threading

import rclpy
from rcl_interfaces.srv import ListParameters


def main():
    rclpy.init()
    node = rclpy.create_node("mute", start_parameter_services=False)
    never = threading.Event()

    def hold(_request, _response):
        never.wait()  # the answer never comes (the executor has other threads for nothing else)

    node.create_service(ListParameters, "/mute/list_parameters", hold)
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    print(json.dumps({"ready": True}), flush=True)
    sys.stdin.read()
    never.set()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
