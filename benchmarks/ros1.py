"""ROS 1 figures through Rockly's robot interface, each against plain rospy in the same run.

A real rosmaster on a free port and an echo node in its own process (plain rospy):
  - topic round trip: publish Float64 on /ping, the echo node answers on /pong;
  - publish rate: Twists per second a separate node receives;
  - service latency: std_srvs/Trigger;
  - action round trip: a goal to an actionlib server that succeeds at once;
  - stop latency on the wire: stop request -> zero Twist received by the separate node;
  - stop during a service call: stop request -> the waiting call (on a connected service) raises.

    python benchmarks/ros1.py
"""
import os
import statistics
import subprocess
import threading
import time
from pathlib import Path

from _paths import REPO  # its set-up: Rockly and the tests' helpers importable
from _stop_on_the_wire import stop_latencies
from ros_helpers import RosMaster, ros_environment

TRIALS = 300
RATE_SECONDS = 2.0
STOP_TRIALS = 20

ECHO_NODE = r'''
import sys, time, threading, rospy, actionlib
from std_msgs.msg import Float64
from geometry_msgs.msg import Twist
from std_srvs.srv import SetBool, SetBoolResponse, Trigger, TriggerResponse
sys.path.insert(0, sys.argv[1])
from rockly_desktop.robot.ros1.message_classes import MessageTypes
classes = MessageTypes([sys.argv[2]]).action_classes("hobbit_msgs/ArmServerAction")
rospy.init_node("rockly_bench_echo", disable_signals=True)
pong = rospy.Publisher("/pong", Float64, queue_size=1000)
rospy.Subscriber("/ping", Float64, lambda m: pong.publish(m), queue_size=1000)
seen = rospy.Publisher("/twist_seen", Float64, queue_size=1000)
count = [0]
def on_twist(m):
    count[0] += 1
    if m.linear.x == 0 and m.angular.z == 0:
        seen.publish(Float64(time.time()))
rospy.Subscriber("/cmd_vel", Twist, on_twist, queue_size=100000)
counted = rospy.Publisher("/twist_count", Float64, queue_size=10, latch=True)
rospy.Subscriber("/count_please", Float64, lambda m: counted.publish(Float64(count[0])))
rospy.Service("/bench_trigger", Trigger, lambda r: TriggerResponse(True, "ok"))
rospy.Service("/bench_hold", SetBool, lambda r: (time.sleep(2 if r.data else 0), SetBoolResponse(True, "ok"))[1])
server = actionlib.SimpleActionServer("bench_arm", classes.action, auto_start=False,
                                      execute_cb=lambda goal: server.set_succeeded(classes.result()))
server.start()
print("ready", flush=True)
rospy.spin()
'''


def median_ms(values):
    return statistics.median(values) * 1000


def report(name, rockly, plain, aim=None):
    ratio = statistics.median(rockly) / statistics.median(plain)
    aim_text = f" (aim <= {aim})" if aim else ""
    print(f"{name}: Rockly median {median_ms(rockly):.3f} ms, rospy median {median_ms(plain):.3f} ms, "
          f"ratio {ratio:.2f}{aim_text}")


def main():
    import tempfile

    home = Path(tempfile.mkdtemp(prefix="rockly-bench-ros-"))
    master = RosMaster(home).start()
    os.environ.update(ros_environment(master.uri, home))
    echo = subprocess.Popen(["/usr/bin/python3", "-c", ECHO_NODE, str(REPO), str(REPO / "profiles" / "hobbit" / "msg")],
                            env=ros_environment(master.uri, home), stdout=subprocess.PIPE, text=True)
    assert echo.stdout.readline().startswith("ready")
    try:
        run_all(master)
    finally:
        echo.kill()
        master.stop()


def run_all(master):
    import rospy
    from std_msgs.msg import Float64
    from std_srvs.srv import Trigger

    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.robot.interrupt import Interrupt
    from rockly_desktop.robot.ros1.link import RosRobot

    hobbit = ProfileRegistry.discover().get("hobbit")
    robot = RosRobot(hobbit, master.uri)
    backend = robot.backend(Interrupt())

    # --- topic round trip ---------------------------------------------------------------
    plain_in = []
    plain_pub = rospy.Publisher("/ping", Float64, queue_size=1000)
    rospy.Subscriber("/pong", Float64, lambda m: plain_in.append(time.perf_counter()))
    rockly_in = []
    backend.subscribe("/pong", "std_msgs/Float64", lambda m: rockly_in.append(time.perf_counter()))
    time.sleep(1.0)

    def round_trips(send, arrivals):
        times = []
        for _ in range(TRIALS):
            before = len(arrivals)
            started = time.perf_counter()
            send()
            while len(arrivals) == before:
                time.sleep(0.00005)
            times.append(arrivals[-1] - started)
        return times

    backend.publish("/ping", "std_msgs/Float64", {"data": 0.0})
    time.sleep(0.2)
    rockly_rt = round_trips(lambda: backend.publish("/ping", "std_msgs/Float64", {"data": 1.0}), rockly_in)
    plain_rt = round_trips(lambda: plain_pub.publish(Float64(1.0)), plain_in)
    report("topic round trip (/ping -> echo node -> /pong)", rockly_rt, plain_rt, aim=1.2)

    # --- service latency ----------------------------------------------------------------
    proxy = rospy.ServiceProxy("/bench_trigger", Trigger, persistent=True)
    proxy.wait_for_service(5)
    backend.call_service("/bench_trigger", "std_srvs/Trigger", {}, 5)
    rockly_srv, plain_srv = [], []
    for _ in range(TRIALS):
        started = time.perf_counter()
        backend.call_service("/bench_trigger", "std_srvs/Trigger", {}, 5)
        rockly_srv.append(time.perf_counter() - started)
        started = time.perf_counter()
        proxy()
        plain_srv.append(time.perf_counter() - started)
    report("service call (std_srvs/Trigger)", rockly_srv, plain_srv, aim=1.2)

    # --- action round trip --------------------------------------------------------------
    import actionlib

    classes = robot.graph.types.action_classes("hobbit_msgs/ArmServerAction")
    client = actionlib.SimpleActionClient("bench_arm", classes.action)
    client.wait_for_server(rospy.Duration(5))
    goal = {"command": {"data": "MoveToHome"}}
    rockly_act, plain_act = [], []
    for _ in range(50):
        started = time.perf_counter()
        backend.send_goal("bench_arm", "hobbit_msgs/ArmServerAction", goal).wait(5)
        rockly_act.append(time.perf_counter() - started)
        started = time.perf_counter()
        client.send_goal(classes.goal())
        client.wait_for_result(rospy.Duration(5))
        plain_act.append(time.perf_counter() - started)
    report("action round trip (goal -> succeeded)", rockly_act, plain_act, aim=1.2)

    # --- publish rate ------------------------------------------------------------------
    from geometry_msgs.msg import Twist

    counts = []
    rospy.Subscriber("/twist_count", Float64, lambda m: counts.append(m.data))
    ask = rospy.Publisher("/count_please", Float64, queue_size=10)
    time.sleep(0.5)

    def received_total():
        before = len(counts)
        ask.publish(Float64(0))
        while len(counts) == before:
            time.sleep(0.001)
        return counts[-1]

    def rate(send):
        start_count = received_total()
        deadline = time.perf_counter() + RATE_SECONDS
        while time.perf_counter() < deadline:
            send()
        time.sleep(0.3)
        return (received_total() - start_count) / RATE_SECONDS

    plain_twist = rospy.Publisher("/cmd_vel", Twist, queue_size=100000)
    backend.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    time.sleep(0.3)
    rockly_rate = rate(lambda: backend.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}}))
    plain_rate = rate(lambda: plain_twist.publish(Twist()))
    print(f"publish rate (Twist, received by a separate node): Rockly {rockly_rate:,.0f}/s, rospy {plain_rate:,.0f}/s, "
          f"ratio {plain_rate / max(rockly_rate, 1):.2f}")

    # --- stop latency on the wire -------------------------------------------------------
    seen = []
    rospy.Subscriber("/twist_seen", Float64, lambda m: seen.append(m.data))
    time.sleep(0.3)
    latencies = stop_latencies(hobbit, robot, seen, STOP_TRIALS)
    print(f"stop latency on the wire (stop -> zero Twist at a separate node): median {median_ms(latencies):.2f} ms, "
          f"max {max(latencies) * 1000:.2f} ms over {STOP_TRIALS} stops (aim max <= 50 ms)")

    # --- stop during a service call ----------------------------------------------------
    from rockly_desktop.core.errors import ProgramStopped

    ended = []
    for _ in range(STOP_TRIALS):
        interrupt = Interrupt()
        held = robot.backend(interrupt)
        held.call_service("/bench_hold", "std_srvs/SetBool", {"data": False}, 5)  # connected: the next call waits here
        requested = []
        threading.Timer(0.05, lambda requested=requested, interrupt=interrupt: (
            requested.append(time.perf_counter()), interrupt.request_stop())).start()
        try:
            held.call_service("/bench_hold", "std_srvs/SetBool", {"data": True}, 5)
        except ProgramStopped:
            ended.append(time.perf_counter() - requested[0])
    print(f"stop during a service call (stop -> the waiting call raises): median {median_ms(ended):.2f} ms, "
          f"max {max(ended) * 1000:.2f} ms over {len(ended)} of {STOP_TRIALS} stops (aim max <= 50 ms)")


if __name__ == "__main__":
    main()
