"""A plain rospy camera for the memory tests (no Rockly code): a ``sensor_msgs/Image`` of ``SIZE`` bytes
(argv[1]) on /camera/image_raw at ``RATE`` Hz (argv[2]). It prints {"ready": true} once it
publishes, and, when stdin ends, {"published": N} and leaves."""
import json
import sys
import threading

import rospy
from sensor_msgs.msg import Image


def main():
    size, rate = int(sys.argv[1]), float(sys.argv[2])
    rospy.init_node("test_camera", disable_signals=True)
    publisher = rospy.Publisher("/camera/image_raw", Image, queue_size=2)
    image = Image(height=size // 1024 or 1, width=min(size, 1024), encoding="mono8", step=min(size, 1024))
    image.header.frame_id = "camera"
    image.data = bytes(range(256)) * (size // 256) + bytes(size % 256)
    ended = threading.Event()
    threading.Thread(target=lambda: (sys.stdin.read(), ended.set()), daemon=True).start()
    print(json.dumps({"ready": True}), flush=True)
    published, period = 0, rospy.Rate(rate)
    while not ended.is_set():
        image.header.seq = published
        publisher.publish(image)
        published += 1
        period.sleep()
    print(json.dumps({"published": published}), flush=True)
    rospy.signal_shutdown("stdin ended")


if __name__ == "__main__":
    main()
