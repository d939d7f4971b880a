"""State panels under load: odometry at 1 kHz from a separate node for 60 s while the
Topic monitor and a Plot of it are open, against the same panels with no stream.

Reports the GUI event-loop delay p99 (a 10 ms timer's lateness), how often the plot
redrew, the GUI process's CPU share and its memory at start and end.

    python benchmarks/state.py [--seconds 60]
"""
import argparse
import os
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from _paths import REPO
from ros_helpers import RosMaster, ros_environment

PUBLISHER = r'''
import math, sys, time, rospy
sys.path.insert(0, sys.argv[1])
from rockly_desktop.robot.ros1.message_classes import MessageTypes
Odometry = MessageTypes().message_class("nav_msgs/Odometry")  # Debian ships only its definition
rospy.init_node("rockly_bench_odometry", disable_signals=True)
publisher = rospy.Publisher("/odom", Odometry, queue_size=1000)
time.sleep(1.0)
print("publishing", flush=True)
message, rate, started = Odometry(), rospy.Rate(1000), time.time()
message.header.frame_id = "odom"
while not rospy.is_shutdown():
    t = time.time() - started
    message.pose.pose.position.x = math.sin(t)
    message.twist.twist.angular.z = math.cos(t)
    publisher.publish(message)
    rate.sleep()
'''


def rss_mb() -> float:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return 0.0


def measure(app, plot, seconds: float) -> dict:
    """Event-loop lateness of a 10 ms timer, plot redraws, CPU share and memory over ``seconds``."""
    from PySide6.QtCore import QElapsedTimer, QEventLoop, QTimer

    delays, clock, expected = [], QElapsedTimer(), [0.010]

    def tick():
        now = clock.nsecsElapsed() / 1e9
        delays.append(max(0.0, now - expected[0]))
        expected[0] = now + 0.010

    redraws = [0]
    original = plot.refresh

    def counted_refresh(*args):
        redraws[0] += 1
        return original(*args)

    plot.refresh = counted_refresh
    timer = QTimer()
    timer.setInterval(10)
    timer.timeout.connect(tick)
    memory_start, cpu_start, wall_start = rss_mb(), time.process_time(), time.monotonic()
    clock.start()
    timer.start()
    loop = QEventLoop()
    QTimer.singleShot(int(seconds * 1000), loop.quit)
    loop.exec()
    timer.stop()
    wall = time.monotonic() - wall_start
    plot.refresh = original
    return {"p99": sorted(delays)[int(len(delays) * 0.99) - 1] * 1000, "median": statistics.median(delays) * 1000,
            "redraw": redraws[0] / wall, "cpu": (time.process_time() - cpu_start) / wall * 100,
            "memory_start": memory_start, "memory_end": rss_mb()}


def report(name, figures):
    growth = (figures["memory_end"] - figures["memory_start"]) / figures["memory_start"] * 100
    print(f"{name}: event-loop delay p99 {figures['p99']:.1f} ms "
          f"(median {figures['median']:.2f} ms; aim p99 <= 30 ms), "
          f"plot redraws {figures['redraw']:.1f}/s, CPU {figures['cpu']:.0f} % of one core, "
          f"memory {figures['memory_start']:.0f} -> {figures['memory_end']:.0f} MB ({growth:+.1f} %; aim within 10 %)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=60.0)
    seconds = parser.parse_args().seconds
    home = Path(tempfile.mkdtemp(prefix="rockly-bench-state-"))
    master = RosMaster(home).start()
    os.environ.update(ros_environment(master.uri, home))
    publisher = None
    try:
        from rockly_desktop.app import create_application
        from rockly_desktop.profiles.registry import ProfileRegistry
        from rockly_desktop.robot.ros1.link import RosRobot
        from rockly_desktop.ui.docks.plot_panel import PlotPanel
        from rockly_desktop.ui.docks.topic_monitor import TopicMonitor

        app = create_application()
        robot = RosRobot(ProfileRegistry.discover().get("hobbit"), master.uri)
        robot.follow_graph()
        monitor = TopicMonitor(robot.state, robot.graph_topics)
        monitor.resize(900, 400)
        monitor.show()
        plot = PlotPanel(robot.state)
        plot.resize(800, 400)
        plot.show()
        plot.add_curve("/odom", "pose.pose.position.x")
        report("no stream (baseline)", measure(app, plot, seconds))

        publisher = subprocess.Popen(["/usr/bin/python3", "-c", PUBLISHER, str(REPO)],
                                     env=ros_environment(master.uri, home), stdout=subprocess.PIPE, text=True)
        assert publisher.stdout.readline().startswith("publishing")
        deadline = time.monotonic() + 10
        while not robot.state.latest("/odom") and time.monotonic() < deadline:
            app.processEvents()
            time.sleep(0.05)
        monitor.select_topic("/odom")
        figures = measure(app, plot, seconds)
        rate = next((info.rate for info in robot.state.topics() if info.topic == "/odom"), 0.0)
        report(f"/odom at {rate:,.0f} Hz from a separate node", figures)
    finally:
        if publisher is not None:
            publisher.kill()
        master.stop()


if __name__ == "__main__":
    main()
