"""The life the plain rclpy test nodes share (run with .venv-ros2's Python; no Rockly code): a node spins in a
thread, says {"ready": true} and leaves when stdin ends (the test's JsonLineNode closes it)."""
import json
import sys
import threading

import rclpy


def serve_until_stdin_ends(node):
    """Spin ``node`` in a thread, print {"ready": true}, and shut rclpy down once stdin ends."""
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    print(json.dumps({"ready": True}), flush=True)
    sys.stdin.read()
    rclpy.try_shutdown()
