"""A plain rospy node (Debian's rospy and genpy, no Rockly code) whose types no package defines: it makes
its message classes at run time from the .msg texts below (genpy's dynamic generation), publishes
/gadget/state (rockly_test_custom/Gadget, nested Eye, an array, a constant) five times a second and serves
/gadget/blink (rockly_test_custom/Blink, a service whose definition no computer here has). It prints one
JSON line per call, {"service", "request"}; {"ready": true} once both are up. It leaves when stdin ends.
With the argument ``listen`` it only subscribes to /gadget/state with its own class (as a robot listens to a
command topic) and prints {"heard": {"name", "brightness"}} for each message."""
import json
import sys
import threading

import genpy.dynamic
import rospy

GADGET = "rockly_test_custom/Gadget"
GADGET_TEXT = """# a gadget's state
Header header
string name
rockly_test_custom/Eye left_eye
float32[] levels
uint8 MODE_OFF=0
"""
EYE_TEXT = """float64 brightness
bool open
"""
BLINK_REQUEST_TEXT = "int32 times\n"
BLINK_RESPONSE_TEXT = "bool done\n"
SEPARATOR = "=" * 80


def gadget_classes() -> dict:
    """The node's message classes by type name (the full text as a publisher sends it)."""
    header = "uint32 seq\ntime stamp\nstring frame_id\n"
    return genpy.dynamic.generate_dynamic(GADGET, f"{GADGET_TEXT}\n{SEPARATOR}\nMSG: rockly_test_custom/Eye\n{EYE_TEXT}"
                                          f"\n{SEPARATOR}\nMSG: std_msgs/Header\n{header}")


def blink_service():
    """A service class for rockly_test_custom/Blink made from its two halves (genpy makes messages only)."""
    request = genpy.dynamic.generate_dynamic("rockly_test_custom/BlinkRequest", BLINK_REQUEST_TEXT)[
        "rockly_test_custom/BlinkRequest"]
    response = genpy.dynamic.generate_dynamic("rockly_test_custom/BlinkResponse", BLINK_RESPONSE_TEXT)[
        "rockly_test_custom/BlinkResponse"]
    return type("Blink", (), {"_type": "rockly_test_custom/Blink", "_md5sum": "0123456789abcdef0123456789abcdef",
                              "_request_class": request, "_response_class": response}), response


def say(data):
    print(json.dumps(data), flush=True)


def listen():
    rospy.init_node("gadget_listener", disable_signals=True)
    rospy.Subscriber("/gadget/state", gadget_classes()[GADGET], lambda message: say(
        {"heard": {"name": message.name, "brightness": message.left_eye.brightness}}))
    say({"ready": True})
    sys.stdin.read()
    rospy.signal_shutdown("stdin ended")


def main():
    rospy.init_node("gadget", disable_signals=True)
    gadget = gadget_classes()[GADGET]
    service, response = blink_service()
    rospy.Service("/gadget/blink", service, lambda request: (
        say({"service": "/gadget/blink", "request": {"times": request.times}}), response(done=True))[1])
    publisher = rospy.Publisher("/gadget/state", gadget, queue_size=10)
    say({"ready": True})
    threading.Thread(target=lambda: (sys.stdin.read(), rospy.signal_shutdown("stdin ended")), daemon=True).start()
    rate = rospy.Rate(5)
    while not rospy.is_shutdown():
        message = gadget(name="by the gadget", levels=[1.0, 2.0])
        message.left_eye.brightness = 0.25
        publisher.publish(message)
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == "__main__":
    listen() if sys.argv[1:] == ["listen"] else main()
