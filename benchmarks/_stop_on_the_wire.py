"""Stop on the wire, as the ROS benchmarks measure it: a run that drives is stopped, and the zero
Twist its safe stop sends is timed where a separate node receives it."""
import threading
import time

DRIVE_AND_WAIT = "robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.2}})\nrobot.wait(60)\n"
SETTLE = 0.1  # seconds the drive runs before the stop: the run is in its wait then


def stop_latencies(profile, robot, seen: list, trials: int) -> list:
    """Seconds from each of ``trials`` stop requests to the zero Twist's arrival. ``seen`` is the
    list the separate node's echo appends its receive times (``time.time()``) to."""
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.run_setup import make_runner

    latencies = []
    for _ in range(trials):
        control = RunControl()
        runner = make_runner(profile, robot, {"code": DRIVE_AND_WAIT, "variables": {}}, control, lambda _event: None)
        thread = threading.Thread(target=runner.run)
        thread.start()
        time.sleep(SETTLE)
        before = len(seen)
        requested = time.time()
        control.request_stop()
        thread.join(5)
        deadline = time.monotonic() + 5
        while len(seen) == before and time.monotonic() < deadline:
            time.sleep(0.0005)
        latencies.append(seen[before] - requested)
    return latencies
