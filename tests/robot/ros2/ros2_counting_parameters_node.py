"""A plain rclpy node for the ROS 2 tests (run with .venv-ros2's Python; no Rockly code) whose
/counted/list_parameters service (rcl_interfaces/ListParameters) answers one parameter name and prints
{"asked": "list_parameters"} for each request, so a test counts the asks on the node's side. It prints
{"ready": true} once the service is up, and leaves when stdin ends."""
import json

import rclpy
from rcl_interfaces.srv import ListParameters
from ros2_node_life import serve_until_stdin_ends


def main():
    rclpy.init()
    node = rclpy.create_node("counted", start_parameter_services=False)

    def answer(_request, response):
        print(json.dumps({"asked": "list_parameters"}), flush=True)
        response.result.names = ["volume"]
        return response

    node.create_service(ListParameters, "/counted/list_parameters", answer)
    serve_until_stdin_ends(node)


if __name__ == "__main__":
    main()
