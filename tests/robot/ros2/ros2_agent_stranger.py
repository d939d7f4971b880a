"""A stranger on the robot's ROS 2 domain (plain rclpy, no Rockly code), for the agent's trust tests: it prints one
JSON line for every message it hears on the agent's topics, ``{"topic": "to_agent"|"from_agent", "message":
{...}}``, and publishes on ``to_agent`` each JSON list of messages it reads on stdin, in order. ``{"ready": true}``
once the agent answered its hello (both ways work). It leaves when stdin ends. Argument: the agent's namespace.

The agent's helper hands it one publisher's messages in order, each before the next: once the agent answers a
request the stranger sent last, it has handled all it sent before."""
import json
import sys
import threading
import time

import rclpy
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import String

HELLO = {"op": "hello", "id": "stranger-ready", "format": 2, "language": "en"}  # the agent protocol's FORMAT
QOS = QoSProfile(depth=1000, reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.VOLATILE)
heard = []
saying = threading.Lock()  # one line at a time, "ready" first


def say(data):
    print(json.dumps(data), flush=True)


def hear(topic, message):
    data = {"topic": topic, "message": json.loads(message.data)}
    with saying:
        if heard:
            say(data)
        elif data["message"].get("reply") == HELLO["id"]:
            say({"ready": True})
            heard.append(data)


def main():
    namespace = "/" + sys.argv[1].strip("/")
    rclpy.init()
    node = rclpy.create_node("stranger")
    for topic in ("to_agent", "from_agent"):
        node.create_subscription(String, f"{namespace}/{topic}", lambda message, topic=topic: hear(topic, message),
                                 QOS)
    out = node.create_publisher(String, f"{namespace}/to_agent", QOS)
    threading.Thread(target=rclpy.spin, args=(node,), daemon=True).start()
    hello = dict(HELLO, **{"from": node.get_name()})
    while not heard:
        if out.get_subscription_count():
            out.publish(String(data=json.dumps(hello)))
        time.sleep(0.1)
    for line in sys.stdin:
        for message in json.loads(line):
            out.publish(String(data=json.dumps(message)))
    rclpy.shutdown()  # its spinning thread ends with it


if __name__ == "__main__":
    main()
