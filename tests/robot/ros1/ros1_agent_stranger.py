"""A stranger on the robot's ROS 1 master (Debian's rospy, no Rockly code), for the agent's trust tests: it prints
one JSON line for every message it hears on the agent's topics, ``{"topic": "to_agent"|"from_agent", "message":
{...}}``, and publishes on ``to_agent`` each JSON list of messages it reads on stdin, in order. ``{"ready": true}``
once the agent answered its hello (both ways work). It leaves when stdin ends. Argument: the agent's namespace.

rospy handles one publisher's messages in order, each before the next: once the agent answers a request the
stranger sent last, it has handled all it sent before."""
import json
import sys
import threading
import time

import rospy
from std_msgs.msg import String

HELLO = {"op": "hello", "id": "stranger-ready", "format": 2, "language": "en"}  # the agent protocol's FORMAT
heard = []
saying = threading.Lock()  # rospy calls back on a thread per connection: one line at a time, "ready" first


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
    rospy.init_node("stranger", anonymous=True, disable_signals=True)
    for topic in ("to_agent", "from_agent"):
        rospy.Subscriber(f"{namespace}/{topic}", String,
                         lambda message, topic=topic: hear(topic, message))
    out = rospy.Publisher(f"{namespace}/to_agent", String, queue_size=1000)
    hello = dict(HELLO, **{"from": rospy.get_name()})
    while not heard:
        if out.get_num_connections():
            out.publish(String(json.dumps(hello)))
        time.sleep(0.1)
    for line in sys.stdin:
        for message in json.loads(line):
            out.publish(String(json.dumps(message)))
    rospy.signal_shutdown("stdin ended")


if __name__ == "__main__":
    main()
