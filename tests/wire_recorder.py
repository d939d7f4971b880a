"""An independent plain rospy node recording what goes over the wire on some topics, whatever its type.

Run as a process (``WireRecorder``): it subscribes with ``rospy.AnyMsg`` (any type, as raw bytes)
and prints one JSON line per message (``{"topic", "type", "data": hex}``) and one per change of
its connections (``{"topic", "connections"}``). Nothing of Rockly runs in it. With ``connect_after``, it is a node
on a busy robot: it connects to each new publisher only that many seconds after the master told it of one.
"""
import json
import subprocess
import sys
import threading
from pathlib import Path

from waiting import eventually

NAME = "rockly_wire_recorder"  # the node's, as the master lists it: /NAME


class WireRecorder:
    """The recorder node as a process on ``master`` (tests' RosMaster), listening to ``topics`` (connecting to a
    new publisher ``connect_after`` seconds late, when given)."""

    def __init__(self, master, topics, connect_after: float = 0.0):
        from ros_helpers import ros_environment

        self.messages, self._connections = [], {}
        self._master_uri = master.uri
        self._process = subprocess.Popen([sys.executable, __file__, str(connect_after), *topics], text=True,
                                         stdout=subprocess.PIPE, env=ros_environment(master.uri, master.home))
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()
        for topic in topics:
            self.wait_connected(topic)

    def _read(self):
        for line in self._process.stdout:
            entry = json.loads(line)
            if "connections" in entry:
                self._connections[entry["topic"]] = entry["connections"]
            else:
                self.messages.append((entry["topic"], entry["type"], bytes.fromhex(entry["data"])))

    def wait_connected(self, topic):
        """Return once every publisher of ``topic`` the master lists has connected the node (as the publisher says:
        the node's own count of its connections includes those still being made)."""
        from ros_helpers import publishers_reach

        eventually(lambda: topic in self._connections and publishers_reach(self._master_uri, topic, "/" + NAME))

    def on(self, topic):
        """``(type, raw bytes)`` of every message seen on ``topic`` so far."""
        return [(msg_type, data) for seen, msg_type, data in list(self.messages) if seen == topic]

    def stop(self):
        self._process.terminate()
        try:
            self._process.wait(10)
        except subprocess.TimeoutExpired:
            self._process.kill()
            self._process.wait(10)
        self._reader.join(10)


def _record(topics, connect_after: float):
    import time

    import rospy
    from rospy.impl import tcpros_pubsub

    if connect_after:  # rospy connects a subscriber to each new publisher on a thread of its own: delay that thread
        connect = tcpros_pubsub.robust_connect_subscriber
        tcpros_pubsub.robust_connect_subscriber = lambda *args: (time.sleep(connect_after), connect(*args))
    rospy.init_node(NAME, disable_signals=True)
    lock = threading.Lock()

    def show(entry):
        with lock:
            print(json.dumps(entry), flush=True)

    subscribers = {topic: rospy.Subscriber(topic, rospy.AnyMsg, lambda message, topic=topic: show(
        {"topic": topic, "type": message._connection_header["type"], "data": message._buff.hex()}))
        for topic in topics}
    known = {}
    while not rospy.is_shutdown():
        for topic, subscriber in subscribers.items():
            count = subscriber.get_num_connections()
            if known.get(topic) != count:
                known[topic] = count
                show({"topic": topic, "connections": count})
        rospy.sleep(0.02)


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    import signal

    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    _record(sys.argv[2:], float(sys.argv[1]))
