"""A plain rospy node for the block maker's ROS 1 tests (Debian's rospy, no Rockly code): it serves
/lamp/switch (std_srvs/SetBool, a type no Rockly profile declares), sets the parameter
/lamp/brightness to 7, and prints one JSON line per call, {"service", "request"}; {"ready": true}
once both are up. It leaves when stdin ends."""
import json
import sys
import threading

import rospy
from std_srvs.srv import SetBool, SetBoolResponse


def say(data):
    print(json.dumps(data), flush=True)


def switch(request):
    say({"service": "/lamp/switch", "request": {"data": request.data}})
    return SetBoolResponse(success=True, message=f"lamp {'on' if request.data else 'off'}")


def main():
    rospy.init_node("lamp", disable_signals=True)
    rospy.set_param("/lamp/brightness", 7)
    rospy.Service("/lamp/switch", SetBool, switch)
    say({"ready": True})
    threading.Thread(target=lambda: (sys.stdin.read(), rospy.signal_shutdown("stdin ended")), daemon=True).start()
    rospy.spin()


if __name__ == "__main__":
    main()
