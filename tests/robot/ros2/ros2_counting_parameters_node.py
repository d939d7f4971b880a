"""A plain rclpy node for the ROS 2 tests (run with .venv-ros2's Python; no Rockly code) whose
/counted/list_parameters service (rcl_interfaces/ListParameters) answers one parameter name and prints
{"asked": "list_parameters"} for each request, so a test counts the asks on the node's side. It prints
{"ready": true} once the service is up, and leaves when stdin ends."""
import json
import sys
import threading

import rclpy
from rcl_interfaces.srv import ListParameters


def main():
    rclpy.init()
    node = rclpy.create_node("counted", start_parameter_services=False)

    def answer(_request, response):
        print(json.dumps({"asked": "list_parameters"}), flush=True)
        response.result.names = ["volume"]
        return response

    node.create_service(ListParameters, "/counted/list_parameters", answer)
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    print(json.dumps({"ready": True}), flush=True)
    sys.stdin.read()
    rclpy.try_shutdown()


if __name__ == "__main__":
    main()
