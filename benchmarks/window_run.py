"""The window's own runs with the program in a process of its own (decision 041), against the same runs in the
window's process as before (``executor.run_setup.make_runner``), measured in the same run on HOBBIT's simulator.

The window's program thread runs ``runtime.hosted_run.HostedRunner``; this measures that runner on a plain
thread (the QThread adds nothing to these figures), with the window's controls (``HostControl``; no block
reported one by one: the window samples where the program is every 33 ms).

(a) per block: a 100,000-block loop at full speed, timed inside the program: in the window's process vs in a
    process of its own;
(b) Run -> first block: from the moment the window has the page's code (it takes the waiting process and makes
    the runner) to the program's first block, as the program's own clock says (one monotonic clock for both
    processes); with a warm process (``WarmProcess``, started while the person looked) and a cold one;
(c) STOP -> zero on the wire: from the stop request (the window's thread) to the safe stop's zero Twist on the
    simulator's /cmd_vel while the program drives and waits.

    python benchmarks/window_run.py
"""
import statistics
import threading
import time

import _paths  # noqa: F401 - its set-up: Rockly importable

BLOCKS = 100_000
TRIALS = 7
STOP_TRIALS = 15
WARM_SECONDS = 1.5  # a warm process imports Rockly and the profile's commands meanwhile, as while a person looks
FIRST_BLOCK_AIM, STOP_AIM = 0.100, 0.010
PER_BLOCK = ("import time\n"
             "started = time.perf_counter()\n"
             f"for _ in range({BLOCKS}):\n"
             "    __rockly__.block('b')\n"
             "print(time.perf_counter() - started)\n")
FIRST = "import time\n__rockly__.block('first')\nprint(repr(time.monotonic()))\n"
DRIVE_AND_WAIT = ("__rockly__.block('d')\n"
                  "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.2}})\n"
                  "ros.wait(60)\n")


def hobbit():
    from rockly_desktop.profiles.registry import ProfileRegistry

    return ProfileRegistry.discover().get("hobbit")


def printed(events) -> float:
    from rockly_desktop.executor.events import OutputPrinted

    return float(next(event.text for event in events if isinstance(event, OutputPrinted)))


def window_runner(profile, robot, code: str, emit, own_process: bool, warm=None):
    """The runner and controls the window makes for ``code``: in its own process (taken from ``warm``, a
    WarmProcess) or, as before, in this one."""
    run_code = {"code": code, "variables": {}}
    if own_process:
        from rockly_desktop.runtime.hosted_run import hosted_runner
        from rockly_desktop.runtime.link_host import HostControl

        control = HostControl()
        return hosted_runner(warm.take(profile), profile, robot, run_code, control, emit), control
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.run_setup import make_runner

    control = RunControl()
    return make_runner(profile, robot, run_code, control, emit), control


def timed_run(profile, robot, code: str, own_process: bool, warm=None, wait=0.0) -> tuple:
    """Run ``code`` once as the window does, on a thread of its own; (seconds from the code to the thread's
    start, the run's events)."""
    if own_process and wait:
        warm.warm(profile)
        time.sleep(wait)
    events = []
    started = time.monotonic()
    runner, _control = window_runner(profile, robot, code, events.append, own_process, warm)
    thread = threading.Thread(target=runner.run)
    thread.start()
    thread.join()
    return started, events


def per_block(profile, robot, warm):
    before = [printed(timed_run(profile, robot, PER_BLOCK, False)[1]) for _ in range(TRIALS)]
    after = [printed(timed_run(profile, robot, PER_BLOCK, True, warm)[1]) for _ in range(TRIALS)]
    base, own = statistics.median(before), statistics.median(after)
    print(f"(a) {BLOCKS:,} blocks at full speed, timed inside the program (median of {TRIALS}): in the window's "
          f"process {base / BLOCKS * 1e9:.0f} ns a block, in its own {own / BLOCKS * 1e9:.0f} ns a block, "
          f"ratio {own / base:.2f}")


def first_block(profile, robot, warm):
    print(f"(b) Run -> first block (median and max of {TRIALS}; aim <= {FIRST_BLOCK_AIM * 1000:.0f} ms):")
    cases = (("in the window's process (before)", False, 0.0), ("own process, warm", True, WARM_SECONDS),
             ("own process, cold", True, 0.0))
    baseline = None
    for name, own_process, wait in cases:
        seconds = []
        for _ in range(TRIALS):
            if own_process and not wait:
                warm.close()
            started, events = timed_run(profile, robot, FIRST, own_process, warm, wait)
            seconds.append(printed(events) - started)
        baseline = baseline or statistics.median(seconds)
        print(f"    {name}: median {statistics.median(seconds) * 1000:.1f} ms, max {max(seconds) * 1000:.1f} ms, "
              f"ratio {statistics.median(seconds) / baseline:.1f}")


def stop_to_zero(profile, robot, own_process: bool, warm) -> list:
    """Seconds from each stop request to the zero Twist on the simulator's /cmd_vel."""
    zero, moving = threading.Event(), threading.Event()
    arrivals = []

    def on_twist(message):
        if (message.get("linear") or {}).get("x"):
            moving.set()
        else:
            arrivals.append(time.perf_counter())
            zero.set()

    robot.world.subscribe("/cmd_vel", on_twist)
    latencies = []
    for _ in range(STOP_TRIALS):
        if own_process:
            warm.warm(profile)
            time.sleep(WARM_SECONDS)
        runner, control = window_runner(profile, robot, DRIVE_AND_WAIT, lambda _event: None, own_process, warm)
        moving.clear()
        thread = threading.Thread(target=runner.run)
        thread.start()
        assert moving.wait(10), "the program never drove"
        time.sleep(0.1)
        zero.clear()
        arrivals.clear()
        requested = time.perf_counter()
        control.request_stop()
        assert zero.wait(5), "no zero Twist after the stop"
        latencies.append(arrivals[0] - requested)
        thread.join(10)
    return latencies


def stop_latency(profile, robot, warm):
    print(f"(c) STOP -> zero Twist on /cmd_vel, driving then waiting ({STOP_TRIALS} trials; aim <= "
          f"{STOP_AIM * 1000:.0f} ms):")
    before = stop_to_zero(profile, robot, False, warm)
    after = stop_to_zero(profile, robot, True, warm)
    print(f"    in the window's process (before): median {statistics.median(before) * 1000:.2f} ms, "
          f"max {max(before) * 1000:.2f} ms")
    print(f"    own process (the window's thread stops the robot): median {statistics.median(after) * 1000:.2f} ms, "
          f"max {max(after) * 1000:.2f} ms, ratio {statistics.median(after) / statistics.median(before):.1f}")


if __name__ == "__main__":
    from rockly_desktop.robot.links import open_link
    from rockly_desktop.runtime.hosted_run import WarmProcess

    profile = hobbit()
    robot = open_link("sim", profile)
    warm = WarmProcess()
    try:
        per_block(profile, robot, warm)
        first_block(profile, robot, warm)
        stop_latency(profile, robot, warm)
    finally:
        warm.close()
        robot.shutdown()
