"""ROS 2 figures through Rockly's robot interface (helper process included), each against plain
rclpy measured in the same run.

An echo node in its own process (plain rclpy, .venv-ros2, one single-threaded executor: rclpy's
multi-threaded one adds milliseconds to every answer, which would hide the helper's hop), on a
domain of this run's own, localhost only:
  - topic round trip: publish Float64 on /ping, the echo node answers on /pong (a round trip not
    back within LOST_AFTER is tried again, so a lost message cannot hang the benchmark);
  - service call: std_srvs/Trigger;
  - action round trip: a test_msgs/Fibonacci goal the server finishes at once;
  - publish rate: a burst of Twists to the subscribed echo node, per second from the first
    publish until the last is on the wire (through Rockly: until the helper, which does
    requests in order, answers a ping sent after them), and the share the echo node got;
  - stop latency on the wire: stop request -> zero Twist received by the echo node;
  - the helper killed (kill -9) while a command waits -> the command fails.
Plain rclpy runs the same loops in another process (rclpy cannot live in Rockly's: Debian's
ROS 1 owns the same module names), against the same echo node.

    python benchmarks/ros2.py
"""
import json
import os
import statistics
import subprocess
import sys
import threading
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO))

from _stop_on_the_wire import stop_latencies  # noqa: E402

ROS2_PYTHON = REPO / ".venv-ros2" / "bin" / "python"
TRIALS = 300
ACTION_TRIALS = 50
BURST = 2000
BURSTS = 5  # each of Rockly and plain rclpy, taking turns: the rate is the median
SETTLED_SECONDS = 0.3
STOP_TRIALS = 20
ROUNDS = 10
LOST_AFTER = 1.0  # a round trip not back by then is taken as lost, and tried again

ECHO_NODE = r'''
import os, sys, time, threading, rclpy
from rclpy.action import ActionServer
from rclpy.executors import SingleThreadedExecutor
from rclpy.qos import QoSProfile, DurabilityPolicy
from std_msgs.msg import Float64
from geometry_msgs.msg import Twist
from std_srvs.srv import Trigger
from test_msgs.action import Fibonacci
rclpy.init()
node = rclpy.create_node("rockly_bench_echo")
pong = node.create_publisher(Float64, "/pong", 1000)
node.create_subscription(Float64, "/ping", lambda m: pong.publish(m), 1000)
seen = node.create_publisher(Float64, "/twist_seen", 1000)
count = [0]
def on_twist(m):
    count[0] += 1
    if m.linear.x == 0 and m.angular.z == 0:
        seen.publish(Float64(data=time.time()))
node.create_subscription(Twist, "/cmd_vel", on_twist, 100000)
counted = node.create_publisher(Float64, "/twist_count", 10)
node.create_subscription(Float64, "/count_please", lambda m: counted.publish(Float64(data=float(count[0]))), 10)
def trigger(request, response):
    response.success, response.message = True, "ok"
    return response
node.create_service(Trigger, "/bench_trigger", trigger)
def execute(goal):
    goal.succeed()
    return Fibonacci.Result(sequence=[0, 1])
ActionServer(node, Fibonacci, "/bench_fib", execute)
executor = SingleThreadedExecutor()
executor.add_node(node)
threading.Thread(target=executor.spin, daemon=True).start()
print("ready", flush=True)
sys.stdin.read()
os._exit(0)
'''

# The same loops with plain rclpy (its executor spinning in a thread, as the helper's does), on
# request: a line "topic|service|action|rate N" answers one JSON line.
PLAIN_CLIENT = r'''
import json, os, sys, threading, time, rclpy
from rclpy.action import ActionClient
from rclpy.executors import SingleThreadedExecutor
from std_msgs.msg import Float64
from geometry_msgs.msg import Twist
from std_srvs.srv import Trigger
from test_msgs.action import Fibonacci
LOST_AFTER = 1.0
rclpy.init()
node = rclpy.create_node("rockly_bench_plain")
executor = SingleThreadedExecutor()
executor.add_node(node)
threading.Thread(target=executor.spin, daemon=True).start()

def wait_for(predicate, timeout=10.0):
    """Whether ``predicate`` came true within ``timeout`` seconds."""
    deadline = time.perf_counter() + timeout
    while not predicate():
        if time.perf_counter() > deadline:
            return False
        time.sleep(0.00005)
    return True

arrivals, counts = {}, []
node.create_subscription(Float64, "/pong", lambda m: arrivals.setdefault(m.data, time.perf_counter()), 1000)
node.create_subscription(Float64, "/twist_count", lambda m: counts.append(m.data), 10)
ping = node.create_publisher(Float64, "/ping", 1000)
ask = node.create_publisher(Float64, "/count_please", 10)
twist = node.create_publisher(Twist, "/cmd_vel", 10)  # the QoS Rockly publishes commands with: reliable, depth 10
client = node.create_client(Trigger, "/bench_trigger")
actions = ActionClient(node, Fibonacci, "/bench_fib")
wait_for(lambda: ping.get_subscription_count() > 0 and node.count_publishers("/pong") > 0
         and ask.get_subscription_count() > 0 and twist.get_subscription_count() > 0
         and node.count_publishers("/twist_count") > 0)
client.wait_for_service(timeout_sec=10)
actions.wait_for_server(timeout_sec=10)

def topic(n):
    times = []
    while len(times) < n:  # a ping or pong lost (rarely) is sent again
        key = time.perf_counter()  # each ping its own value: a late pong is not taken for the next
        started = time.perf_counter()
        ping.publish(Float64(data=key))
        if wait_for(lambda: key in arrivals, LOST_AFTER):
            times.append(arrivals[key] - started)
    return times

def service(n):
    times = []
    for _ in range(n):
        started = time.perf_counter()
        done = threading.Event()
        client.call_async(Trigger.Request()).add_done_callback(lambda f: done.set())
        done.wait(5)
        times.append(time.perf_counter() - started)
    return times

def action(n):
    times = []
    for _ in range(n):
        started = time.perf_counter()
        ended = threading.Event()
        def accepted(future):
            future.result().get_result_async().add_done_callback(lambda f: ended.set())
        actions.send_goal_async(Fibonacci.Goal(order=0)).add_done_callback(accepted)
        ended.wait(5)
        times.append(time.perf_counter() - started)
    return times

def received_total():
    before = len(counts)
    ask.publish(Float64(data=0.0))
    assert wait_for(lambda: len(counts) > before), "the echo node did not say its count"
    return counts[-1]

def settled_total():
    """The echo node's count once it stops growing (what is on its way has arrived)."""
    previous = -1.0
    while previous != (total := received_total()):
        previous = total
        time.sleep(0.3)
    return total

def rate(n):
    start_count = settled_total()
    started = time.perf_counter()
    for _ in range(n):  # a new message each time, as a program's block makes one from its values
        message = Twist()
        message.linear.x = 0.1
        twist.publish(message)
    elapsed = time.perf_counter() - started
    return [n / elapsed, (settled_total() - start_count) / n]

print("ready", flush=True)
for line in sys.stdin:
    what, amount = line.split()
    print(json.dumps({"topic": topic, "service": service, "action": action, "rate": rate}[what](int(amount))),
          flush=True)
os._exit(0)  # the spinning thread would abort a normal interpreter exit
'''


class PlainRclpy:
    """The plain rclpy client process; ``measure(what, amount)`` runs one block of trials there."""

    def __init__(self, env):
        self.process = subprocess.Popen([str(ROS2_PYTHON), "-c", PLAIN_CLIENT], env=env, stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, text=True)
        assert self.process.stdout.readline().startswith("ready")

    def measure(self, what, amount):
        self.process.stdin.write(f"{what} {amount}\n")
        self.process.stdin.flush()
        return json.loads(self.process.stdout.readline())

    def close(self):
        self.process.stdin.close()
        self.process.wait(10)


def alternating(plain, what, rockly_block, trials):
    """Blocks of ``trials / ROUNDS`` trials, plain rclpy and Rockly taking turns (a busy machine's
    load then weighs on both alike); all the times of each."""
    plain_times, rockly_times = [], []
    for _ in range(ROUNDS):
        plain_times += plain.measure(what, trials // ROUNDS)
        rockly_times += rockly_block(trials // ROUNDS)
    return rockly_times, plain_times


def median_ms(values):
    return statistics.median(values) * 1000


def report(name, rockly, plain, aim=1.3):
    ratio = statistics.median(rockly) / statistics.median(plain)
    print(f"{name}: Rockly median {median_ms(rockly):.3f} ms, rclpy median {median_ms(plain):.3f} ms, "
          f"ratio {ratio:.2f} (aim <= {aim})")


def main():
    import tempfile

    from rockly_desktop.robot.ros2.environment import Ros2Settings

    if not ROS2_PYTHON.exists():
        sys.exit(f"no {ROS2_PYTHON}: run 'make ros2' first")
    settings = Ros2Settings(domain_id=200 + os.getpid() % 30, discovery="localhost")
    home = Path(tempfile.mkdtemp(prefix="rockly-bench-ros2-"))
    env = settings.environment()
    env.update(ROS_HOME=str(home), ROS_LOG_DIR=str(home / "log"))
    os.environ.update(ROS_HOME=str(home), ROS_LOG_DIR=str(home / "log"))
    echo = subprocess.Popen([str(ROS2_PYTHON), "-c", ECHO_NODE], env=env, stdin=subprocess.PIPE,
                            stdout=subprocess.PIPE, text=True)
    assert echo.stdout.readline().startswith("ready")
    plain = PlainRclpy(env)
    try:
        run_all(settings, plain)
    finally:
        from rockly_desktop.robot.ros2.client import Ros2Helper

        plain.close()
        Ros2Helper.close_current()
        echo.stdin.close()
        echo.wait(10)


def run_all(settings, plain):
    from rockly_desktop.profiles.registry import ProfileRegistry
    from rockly_desktop.robot.interrupt import Interrupt
    from rockly_desktop.robot.ros2.link import Ros2Robot

    turtlebot = ProfileRegistry.discover().get("turtlebot")
    started = time.perf_counter()
    robot = Ros2Robot(turtlebot, settings)
    print(f"link up (helper started, safe stop's publisher matched): {(time.perf_counter() - started) * 1000:.0f} ms")
    backend = robot.backend(Interrupt())

    def wait_for(predicate, timeout=10.0):
        """Whether ``predicate`` came true within ``timeout`` seconds."""
        deadline = time.perf_counter() + timeout
        while not predicate():
            if time.perf_counter() > deadline:
                return False
            time.sleep(0.00005)
        return True

    # --- topic round trip ---------------------------------------------------------------
    arrivals = {}
    backend.subscribe("/pong", "std_msgs/Float64", lambda m: arrivals.setdefault(m["data"], time.perf_counter()))
    backend.publish("/ping", "std_msgs/Float64", {"data": 0.0})  # the first waits for the echo node to match
    assert wait_for(lambda: arrivals), "the echo node did not answer"

    def topic(n):
        times = []
        while len(times) < n:  # a ping or pong lost (rarely) is sent again
            key = time.perf_counter()  # each ping its own value: a late pong is not taken for the next
            started = time.perf_counter()
            backend.publish("/ping", "std_msgs/Float64", {"data": key})
            if wait_for(lambda key=key: key in arrivals, LOST_AFTER):
                times.append(arrivals[key] - started)
        return times

    report("topic round trip (/ping -> echo node -> /pong)", *alternating(plain, "topic", topic, TRIALS))

    # --- service call -------------------------------------------------------------------
    backend.call_service("/bench_trigger", "std_srvs/Trigger", {}, 10)

    def service(n):
        times = []
        for _ in range(n):
            started = time.perf_counter()
            backend.call_service("/bench_trigger", "std_srvs/Trigger", {}, 5)
            times.append(time.perf_counter() - started)
        return times

    report("service call (std_srvs/Trigger)", *alternating(plain, "service", service, TRIALS))

    # --- action round trip --------------------------------------------------------------
    backend.send_goal("/bench_fib", "test_msgs/Fibonacci", {"order": 0}).wait(10)

    def action(n):
        times = []
        for _ in range(n):
            started = time.perf_counter()
            backend.send_goal("/bench_fib", "test_msgs/Fibonacci", {"order": 0}).wait(5)
            times.append(time.perf_counter() - started)
        return times

    report("action round trip (goal -> succeeded)", *alternating(plain, "action", action, ACTION_TRIALS))

    # --- publish rate ------------------------------------------------------------------
    counts = []
    backend.subscribe("/twist_count", "std_msgs/Float64", lambda m: counts.append(m["data"]))
    backend.publish("/count_please", "std_msgs/Float64", {"data": 0.0})
    assert wait_for(lambda: counts), "the echo node did not say its count"

    def received_total():
        before = len(counts)
        backend.publish("/count_please", "std_msgs/Float64", {"data": 0.0})
        assert wait_for(lambda: len(counts) > before), "the echo node did not say its count"
        return counts[-1]

    def settled_total():
        previous = -1.0
        while previous != (total := received_total()):
            previous = total
            time.sleep(SETTLED_SECONDS)
        return total

    def rate(n):
        start_count = settled_total()
        started = time.perf_counter()
        for _ in range(n):
            backend.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
        robot.helper.call("ping", timeout=30)  # the helper does requests in order: every Twist is out
        elapsed = time.perf_counter() - started
        return [n / elapsed, (settled_total() - start_count) / n]

    backend.publish("/cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 0.1}})
    rockly_runs, plain_runs = [], []
    for _ in range(BURSTS):
        plain_runs.append(plain.measure("rate", BURST))
        rockly_runs.append(rate(BURST))
    rockly_rate = statistics.median(run[0] for run in rockly_runs)
    plain_rate = statistics.median(run[0] for run in plain_runs)
    print(f"publish rate (bursts of {BURST:,} Twists to the echo node, until the last is on the wire): "
          f"Rockly {rockly_rate:,.0f}/s, rclpy {plain_rate:,.0f}/s, ratio {plain_rate / rockly_rate:.2f} "
          f"(aim <= 1.3); the echo node got {min(run[1] for run in rockly_runs):.0%} of Rockly's, "
          f"{min(run[1] for run in plain_runs):.0%} of rclpy's")
    settled_total()

    # --- stop latency on the wire -------------------------------------------------------
    seen = []
    backend.subscribe("/twist_seen", "std_msgs/Float64", lambda m: seen.append(m["data"]))
    latencies = stop_latencies(turtlebot, robot, seen, STOP_TRIALS)
    print(f"stop latency on the wire (stop -> zero Twist at the echo node): median {median_ms(latencies):.2f} ms, "
          f"max {max(latencies) * 1000:.2f} ms over {STOP_TRIALS} stops (aim max <= 20 ms)")

    # --- the helper killed mid-wait ----------------------------------------------------
    import signal

    failed = []

    def wait():
        try:
            robot.backend(Interrupt()).wait_for_message("/nobody_publishes_this", "std_msgs/String", 60)
        except Exception:
            failed.append(time.perf_counter())

    waiter = threading.Thread(target=wait)
    waiter.start()
    time.sleep(0.5)
    killed = time.perf_counter()
    os.kill(robot.helper.process.pid, signal.SIGKILL)
    waiter.join(10)
    print(f"helper killed mid-wait -> the command fails: {(failed[0] - killed) * 1000:.1f} ms (aim <= 2 s)")
    robot.shutdown()


if __name__ == "__main__":
    main()
