"""The link host's cost (decision 039): the program in a process of its own, the link in the runtime's.

Each figure against a baseline measured in the same run: the same program in the link's own process,
as runs were before (``executor.run_setup.make_runner`` on the link).

(a) per command: 1,000 ``ros.publish`` and 1,000 ``ros.latest`` on HOBBIT's simulator, timed inside the
    program: in-process vs through the host;
(a') per block: a 10,000-block loop, each block reported (as ``rockly run`` and the agent do), timed inside
    the program: in-process vs through the host;
(b) Run -> first block: from ``Run.run`` (the link opens) to the first block entered, with the program's
    process started as the link opens (cold) and started beforehand (warm); baseline: the link opened and
    the runner made in-process;
(c) STOP -> zero on the wire: from the stop request to the safe stop's zero Twist on the simulator's
    /cmd_vel while the program drives and waits (the host stops the robot itself, without the program).

    python benchmarks/link_host.py
"""
import statistics
import threading
import time

import _paths  # noqa: F401 - its set-up: Rockly importable

CALLS = 1000
BLOCKS = 10_000
TRIALS = 7
STOP_TRIALS = 15
FIRST_BLOCK_AIM, STOP_AIM = 0.100, 0.010
TIMED = ("import time\n"
         "started = time.perf_counter()\n"
         "for _ in range({calls}):\n"
         "    {call}\n"
         "print(time.perf_counter() - started)\n")
PUBLISH = "ros.publish('/rockly_bench', 'String', 'x')"
LATEST = "ros.latest('/odom', 'pose.pose.position.x')"
DRIVE_AND_WAIT = ("__rockly__.block('d')\n"
                  "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.2}})\n"
                  "ros.wait(60)\n")
FIRST = "__rockly__.block('first')\n"


def hobbit():
    from rockly_desktop.profiles.registry import ProfileRegistry

    return ProfileRegistry.discover().get("hobbit")


def printed_seconds(events) -> float:
    from rockly_desktop.executor.events import OutputPrinted

    return float(next(event.text for event in events if isinstance(event, OutputPrinted)))


def in_process(profile, code: str, emit, control=None):
    """Run ``code`` as runs were before: the runner in the link's process; the link opened here."""
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.run_setup import make_runner
    from rockly_desktop.robot.links import open_link

    robot = open_link("sim", profile)
    try:
        runner = make_runner(profile, robot, {"code": code, "variables": {}}, control or RunControl(trace=True), emit)
        return runner.run()
    finally:
        robot.shutdown()


def through_host(profile, code: str, emit, process=None):
    """Run ``code`` with the runtime's ``Run``: its process of its own, the link here."""
    from rockly_desktop.runtime.run import Run

    run = Run(profile, {"code": code, "variables": {}}, {}, out=lambda _line: None, end_out=lambda _line: None,
              on_event=emit, trace=True, process=process)
    return run.run("sim", print_blocks=False)


def per_command(profile):
    print(f"(a) {CALLS:,} calls, timed inside the program (median of {TRIALS}):")
    for name, call in (("ros.publish", PUBLISH), ("ros.latest", LATEST)):
        code = TIMED.format(calls=CALLS, call=call)
        before, after = [], []
        for _ in range(TRIALS):
            events = []
            in_process(profile, code, events.append)
            before.append(printed_seconds(events))
            events = []
            through_host(profile, code, events.append)
            after.append(printed_seconds(events))
        base, host = statistics.median(before), statistics.median(after)
        print(f"    {name}: in-process {base / CALLS * 1e6:.1f} µs a call, through the host "
              f"{host / CALLS * 1e6:.1f} µs a call, ratio {host / base:.1f}")


def per_block(profile):
    code = TIMED.format(calls=BLOCKS, call="__rockly__.block('b')")
    before, after = [], []
    for _ in range(TRIALS):
        events = []
        in_process(profile, code, events.append)
        before.append(printed_seconds(events))
        events = []
        through_host(profile, code, events.append)
        after.append(printed_seconds(events))
    base, host = statistics.median(before), statistics.median(after)
    print(f"(a') {BLOCKS:,} blocks, each reported: in-process {base / BLOCKS * 1e6:.1f} µs a block, through the "
          f"host {host / BLOCKS * 1e6:.1f} µs a block, ratio {host / base:.1f}")


def first_block_seconds(run, started_at) -> float:
    from rockly_desktop.executor.events import BlockEntered

    entered = []

    def emit(event):
        if isinstance(event, BlockEntered) and not entered:
            entered.append(time.perf_counter())
    started = started_at()
    run(emit)
    return entered[0] - started


def first_block(profile):
    from rockly_desktop.runtime.link_host import ProgramProcess

    def warm_process():
        process = ProgramProcess.start(profile)
        time.sleep(1.5)  # it imports Rockly and the profile's commands meanwhile, as it would while a person looks
        return process

    cases = {
        "in-process (before)": lambda emit: in_process(profile, FIRST, emit),
        "own process, cold (started as the link opens)": lambda emit: through_host(profile, FIRST, emit),
    }
    print(f"(b) Run -> first block (median and max of {TRIALS}; aim <= {FIRST_BLOCK_AIM * 1000:.0f} ms):")
    baseline = None
    for name, run in cases.items():
        seconds = [first_block_seconds(run, time.perf_counter) for _ in range(TRIALS)]
        baseline = baseline or statistics.median(seconds)
        print(f"    {name}: median {statistics.median(seconds) * 1000:.1f} ms, max {max(seconds) * 1000:.1f} ms, "
              f"ratio {statistics.median(seconds) / baseline:.1f}")
    warm = []
    for _ in range(TRIALS):
        process = warm_process()
        warm.append(first_block_seconds(lambda emit, process=process: through_host(profile, FIRST, emit, process),
                                        time.perf_counter))
    print(f"    own process, warm (started before): median {statistics.median(warm) * 1000:.1f} ms, "
          f"max {max(warm) * 1000:.1f} ms, ratio {statistics.median(warm) / baseline:.1f}")


def stop_to_zero(profile, through: bool) -> list:
    """Seconds from each stop request to the zero Twist on the simulator's /cmd_vel."""
    from rockly_desktop.executor.control import RunControl
    from rockly_desktop.executor.run_setup import limited_backend, make_runner
    from rockly_desktop.robot.links import open_link
    from rockly_desktop.robot.wrappers.limits import Limits
    from rockly_desktop.robot.wrappers.ros_versions import link_backend
    from rockly_desktop.runtime.link_host import HostControl, LinkHost, ProgramMirror, ProgramProcess

    robot = open_link("sim", profile)
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
    try:
        for _ in range(STOP_TRIALS):
            if through:
                control = HostControl()
                backend = limited_backend(profile, link_backend(robot, control.interrupt), Limits(), "en")
                host = LinkHost(ProgramProcess.start(profile), backend, robot, control, lambda _event: None, "en",
                                ProgramMirror())
                serve = threading.Thread(target=host.serve, args=({"code": DRIVE_AND_WAIT, "variables": {}},))
            else:
                control = RunControl()
                runner = make_runner(profile, robot, {"code": DRIVE_AND_WAIT, "variables": {}}, control,
                                     lambda _event: None)
                serve = threading.Thread(target=runner.run)
            moving.clear()
            serve.start()
            assert moving.wait(10), "the program never drove"
            time.sleep(0.1)
            zero.clear()
            arrivals.clear()
            requested = time.perf_counter()
            control.request_stop()
            assert zero.wait(5), "no zero Twist after the stop"
            latencies.append(arrivals[0] - requested)
            serve.join(10)
    finally:
        robot.shutdown()
    return latencies


def stop_latency(profile):
    print(f"(c) STOP -> zero Twist on /cmd_vel, driving then waiting ({STOP_TRIALS} trials; aim <= "
          f"{STOP_AIM * 1000:.0f} ms):")
    before = stop_to_zero(profile, through=False)
    after = stop_to_zero(profile, through=True)
    print(f"    in-process (before): median {statistics.median(before) * 1000:.2f} ms, max {max(before) * 1000:.2f} ms")
    print(f"    the host's own safe stop: median {statistics.median(after) * 1000:.2f} ms, "
          f"max {max(after) * 1000:.2f} ms, ratio {statistics.median(after) / statistics.median(before):.1f}")


if __name__ == "__main__":
    profile = hobbit()
    per_command(profile)
    per_block(profile)
    first_block(profile)
    stop_latency(profile)
