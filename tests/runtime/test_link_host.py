"""The link host and the program's own process (decision 039), on HOBBIT's real simulator and real processes:
STOP makes the robot safe in the host at once, even for a program that ignores it (which is then killed); the
program's process ends when its host goes; what crosses the wire comes back as it was sent."""
import array
import signal
import subprocess
import sys
import threading
import time
from collections import deque
from pathlib import Path

import pytest
from waiting import eventually

from rockly_desktop.core.errors import ProgramStopped, RobotTimeout
from rockly_desktop.executor.events import OutputPrinted, RunFinished
from rockly_desktop.executor.run_setup import limited_backend
from rockly_desktop.robot.links import open_link
from rockly_desktop.robot.wrappers.limits import Limits
from rockly_desktop.robot.wrappers.ros_versions import link_backend
from rockly_desktop.runtime import link_host
from rockly_desktop.runtime.link_host import HostControl, LinkHost, ProgramMirror, ProgramProcess
from rockly_desktop.runtime.link_wire import MAX_LINE, LineTooLong, decoded, encoded, error_record, raised_error

REPO = Path(__file__).resolve().parents[2]
STUBBORN = ("import time\n"
            "while True:\n"
            "    try:\n"
            "        ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.3}})\n"
            "        ros.wait(0.02)\n"
            "    except BaseException as error:\n"
            "        print('ignored ' + type(error).__name__)\n"
            "        time.sleep(0.02)\n")


@pytest.fixture
def simulated(hobbit):
    robot = open_link("sim", hobbit)
    yield robot
    robot.shutdown()


def test_stop_makes_the_robot_safe_at_once_and_a_program_ignoring_it_is_killed(hobbit, simulated, monkeypatch):
    monkeypatch.setattr(link_host, "STOP_GRACE", 0.5)
    twists, events = [], []
    simulated.world.subscribe("/cmd_vel", lambda message: twists.append(
        (time.perf_counter(), (message.get("linear") or {}).get("x", 0.0))))
    control = HostControl()
    backend = limited_backend(hobbit, link_backend(simulated, control.interrupt), Limits(max_speed=0.2), "en")
    host = LinkHost(ProgramProcess.start(hobbit), backend, simulated, control, events.append, "en", ProgramMirror())
    results = []
    serving = threading.Thread(target=lambda: results.append(host.serve({"code": STUBBORN, "variables": {}})))
    serving.start()
    try:
        eventually(lambda: any(speed == 0.2 for _at, speed in twists), 30)  # driving, held to the limit
        asked = time.perf_counter()
        control.request_stop()
        stopped_at = time.perf_counter()
        zeros = [at for at, speed in twists if at >= asked and speed == 0.0]
        assert zeros and zeros[0] - asked < 0.010  # the host's own safe stop, before the program hears of it
        serving.join(30)
    finally:
        control.request_stop()
        serving.join(30)
    assert not serving.is_alive() and host.process.process.returncode is not None  # killed: it ignored the stop
    assert results[0].outcome == "stopped"
    assert [speed for at, speed in twists if at > stopped_at] in ([], [0.0])  # nothing it sent after reached the robot
    assert OutputPrinted("ignored ProgramStopped") in events  # it was told, and went on: refused every command


HOST = ("import time\n"
        "from rockly_desktop.runtime.link_host import ProgramProcess\n"
        "process = ProgramProcess.start()\n"
        "process.reader.read()\n"  # it is up
        "print(process.process.pid, flush=True)\n"
        "time.sleep(120)\n")


def ended(pid: int) -> bool:
    """True once the process ``pid`` is gone (or a zombie no one has reaped yet)."""
    try:
        with open(f"/proc/{pid}/status") as status:
            return "State:\tZ" in status.read()
    except FileNotFoundError:
        return True


def test_the_programs_process_ends_when_its_host_is_killed():
    host = subprocess.Popen([sys.executable, "-c", HOST], stdout=subprocess.PIPE, text=True, cwd=REPO)
    try:
        child = int(host.stdout.readline())
        assert not ended(child)
        host.send_signal(signal.SIGKILL)
        eventually(lambda: ended(child), 30)
    finally:
        host.kill()
        host.wait(10)


def test_values_and_errors_cross_the_wire_as_they_were():
    message = {"data": b"\x00\xff", "ranges": array.array("f", [1.5, 2.0]), "pair": (1, 2), "text": "äö\n",
               "nan": float("inf")}
    assert decoded(encoded(message)) == {"data": b"\x00\xff", "ranges": [1.5, 2.0], "pair": [1, 2], "text": "äö\n",
                                         "nan": float("inf")}
    again = raised_error(error_record(RobotTimeout("no answer from /arm"), "en"))
    assert type(again) is RobotTimeout and str(again) == "no answer from /arm"
    assert type(raised_error(error_record(ProgramStopped("stopped"), "en"))) is ProgramStopped
    assert type(raised_error(error_record(OSError("odd"), "en"))) is RuntimeError
    with pytest.raises(LineTooLong):
        encoded({"data": "x" * MAX_LINE})
    with pytest.raises(ValueError):
        decoded(b"[1, 2]\n")


def test_a_run_that_finishes_says_so_after_the_safe_stop(hobbit, simulated):
    events = []
    control = HostControl(trace=True)
    backend = limited_backend(hobbit, link_backend(simulated, control.interrupt), Limits(), "en")
    host = LinkHost(ProgramProcess.start(hobbit), backend, simulated, control, events.append, "en", ProgramMirror())
    result = host.serve({"code": "__rockly__.block('a')\nx = robot.backend.latest('/odom', None)\n"
                                 "print(type(x).__name__)\n", "variables": {}})
    assert result == RunFinished("finished") and events[-1] == result
    assert OutputPrinted("dict") in events


def test_a_tight_loop_costs_the_host_a_line_a_sample_and_a_recording_gets_its_blocks_in_order(hobbit, simulated):
    # The window's run (decision 041): no block reported one by one; the program's process says where it is, and
    # for a recording the blocks entered with their times, in samples.
    records = []

    class Counting(LinkHost):
        def _take(self, record):
            records.append(record.get("op"))
            super()._take(record)

    entered = deque()
    control = HostControl()
    backend = limited_backend(hobbit, link_backend(simulated, control.interrupt), Limits(), "en")
    mirror = ProgramMirror(entered)
    host = Counting(ProgramProcess.start(hobbit), backend, simulated, control, lambda _event: None, "en", mirror)
    result = host.serve({"code": "__rockly__.block('first')\nfor _ in range(20000):\n    __rockly__.block('loop')\n"
                                 "__rockly__.block('last')\n", "variables": {}})
    assert result == RunFinished("finished")
    assert records.count("sample") < 1000 and len(records) < 1000, len(records)  # not one line per block (20,002)
    assert mirror.hooks.current_block == "last"
    blocks = [block for _stamp, block in entered]
    assert blocks[0] == "first" and blocks[-1] == "last" and "loop" in blocks
    stamps = [stamp for stamp, _block in entered]
    assert stamps == sorted(stamps)
