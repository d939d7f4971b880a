"""A plain rospy node for the ROS 1 tests (Debian's rospy, no Rockly code): it subscribes to /cmd_vel
(geometry_msgs/Twist) and /chatter (std_msgs/String) and prints one JSON line per message it gets,
{"topic", "message"}; {"ready": true} once both subscriptions are registered. It leaves when stdin ends."""
import json
import sys
import threading

import rospy
from geometry_msgs.msg import Twist
from std_msgs.msg import String


def say(data):
    print(json.dumps(data), flush=True)


def main():
    rospy.init_node("recorder", anonymous=True, disable_signals=True)
    rospy.Subscriber("/cmd_vel", Twist, lambda m: say({"topic": "/cmd_vel", "message": {
        "linear": {"x": m.linear.x, "y": m.linear.y, "z": m.linear.z},
        "angular": {"x": m.angular.x, "y": m.angular.y, "z": m.angular.z}}}))
    rospy.Subscriber("/chatter", String, lambda m: say({"topic": "/chatter", "message": {"data": m.data}}))
    say({"ready": True})
    threading.Thread(target=lambda: (sys.stdin.read(), rospy.signal_shutdown("stdin ended")), daemon=True).start()
    rospy.spin()


if __name__ == "__main__":
    main()
