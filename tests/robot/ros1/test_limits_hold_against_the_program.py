"""The limits hold against any code the program runs (issue 30, decision 039): a standalone file whose code walks
Python's object graph (``gc.get_objects()``, every thread's frames, closures, ``robot._backend._inner...``) for the
link, the wrapped backends and the Limits, lifts every Limits it finds and publishes 3 m/s through each, drives no
faster than the robot's limit of 0.2 m/s, as an independent rospy node on a real roscore and the simulator's own
odometry see. The program's process has no network either. And a program's process killed mid-drive (SIGKILL)
still ends with the robot's safe stop: zero velocity on the wire."""
import os
import re
import signal
import struct
import subprocess
import sys

import pytest
from agent_tools import REPO
from program_builder import block, number, rockly_document
from ros_helpers import hobbit_on_own_master, ros_environment
from standalone_tools import end, events, export_standalone, start_file
from waiting import eventually
from wire_recorder import WireRecorder

HOSTILE = """import gc, os, socket, sys
found = []
def consider(thing):
    try:
        kind = type(thing).__name__
    except Exception:
        return
    if kind.endswith('Backend') or kind.endswith('Link') or kind in ('Limits', 'HostConnection'):
        found.append(thing)
for thing in gc.get_objects():
    consider(thing)
    closure = getattr(thing, '__closure__', None) if type(thing).__name__ == 'function' else None
    for cell in closure or ():
        try:
            consider(cell.cell_contents)
        except ValueError:
            pass
for frame in list(sys._current_frames().values()):
    while frame is not None:
        for value in list(frame.f_locals.values()) + list(frame.f_globals.values()):
            consider(value)
        frame = frame.f_back
found.append(robot._backend)
inner = robot._backend
while getattr(inner, '_inner', None) is not None:
    inner = inner._inner
    found.append(inner)
for thing in found:
    if type(thing).__name__ == 'Limits':
        object.__setattr__(thing, 'max_speed', None)
        object.__setattr__(thing, 'max_turn', None)
    for name in ('limits', '_limits'):
        try:
            object.__setattr__(thing, name, None)
        except Exception:
            pass
fast = {'linear': {'x': 3.0}, 'angular': {'z': 2.0}}
for thing in found:
    try:
        if type(thing).__name__ == 'HostConnection':
            thing.send({'op': 'limits', 'max_speed': 10})
            thing.call('publish', ['/cmd_vel', 'geometry_msgs/Twist', fast])
        elif type(thing).__name__.endswith('Link'):
            thing.backend(robot._backend.interrupt).publish('/cmd_vel', 'geometry_msgs/Twist', fast)
        else:
            thing.publish('/cmd_vel', 'geometry_msgs/Twist', fast)
    except Exception:
        pass
print('found: ' + ' '.join(sorted(set(type(thing).__name__ for thing in found))))
master = os.environ['ROS_MASTER_URI'].split('//')[1].split('/')[0].rsplit(':', 1)
try:
    socket.create_connection((master[0], int(master[1])), 2).close()
    print('network: reached the master')
except OSError:
    print('network: none')
ros.wait(1)
"""

DRIVE_ON = ("while True:\n"
            "    ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.1}})\n"
            "    ros.wait(0.05)\n")


@pytest.fixture(scope="module")
def robot(tmp_path_factory):
    """``(master, exported standalone text of a 1 s wait, wire recorder of /cmd_vel and /odom, the robot's limits file
    of 0.2 m/s)``: HOBBIT simulated on a rosmaster of its own."""
    folder = tmp_path_factory.mktemp("hostile")
    source = folder / "wait.rockly"
    source.write_text(rockly_document([block("hobbit_wait", inputs={"seconds": number(1)})]))
    exported = export_standalone(source, folder / "wait.py", "--language", "en").read_text()
    limits = folder / "robot-limits.json"
    made = subprocess.run([sys.executable, "-m", "rockly_desktop", "agent", "--robot-limits", str(limits), "limits",
                           "--max-speed", "0.2", "--max-turn", "30"], capture_output=True, text=True, cwd=REPO,
                          timeout=120)
    assert made.returncode == 0, made.stderr
    master, simulator = hobbit_on_own_master(folder)
    wire = WireRecorder(master, ["/cmd_vel", "/odom"])  # one independent node: a second of that name ends the first
    try:
        yield master, exported, wire, limits
    finally:
        wire.stop()
        simulator.stop()
        master.stop()

def with_code(exported: str, code: str, folder) -> object:
    """The exported file with ``code`` as its program (as a stranger or a hand-edited file has it)."""
    path = folder / "program.py"
    path.write_text(re.sub(r'RUN_CODE = """.*?"""', lambda _: f'RUN_CODE = """{code}"""', exported, flags=re.S))
    return path


def twists(wire) -> list:
    """``(linear.x, angular.z)`` of every Twist seen on /cmd_vel."""
    return [(twist[0], twist[5]) for twist in (struct.unpack("<6d", raw) for _type, raw in wire.on("/cmd_vel"))]


def odometry_speeds(wire) -> list:
    """The simulator's own ``twist.twist.linear.x`` of every nav_msgs/Odometry it sent."""
    speeds = []
    for _type, raw in wire.on("/odom"):
        offset = 12  # header: seq, stamp
        for _string in range(2):  # header.frame_id, child_frame_id
            (length,) = struct.unpack_from("<I", raw, offset)
            offset += 4 + length
        offset += 8 * (3 + 4 + 36)  # pose: position, orientation, covariance
        speeds.append(struct.unpack_from("<d", raw, offset)[0])
    return speeds


def test_a_program_walking_the_object_graph_drives_no_faster_than_the_limit(robot, tmp_path):
    master, exported, wire, limits = robot
    program = with_code(exported, HOSTILE, tmp_path)
    seen, odometry_seen = len(wire.on("/cmd_vel")), len(wire.on("/odom"))
    done = subprocess.run([sys.executable, str(program), "--backend", "ros1", "--master", master.uri,
                           "--robot-limits", str(limits), "--events", "-"], capture_output=True, text=True,
                          timeout=120, cwd=tmp_path, env=ros_environment(master.uri, master.home))
    printed = [record["text"] for record in events(done.stdout) if record.get("event") == "print"]
    assert done.returncode == 0, done.stderr
    eventually(lambda: len(wire.on("/cmd_vel")) > seen, 30)  # the safe stop's zero, at least
    speeds = twists(wire)[seen:]
    assert all(abs(linear) <= 0.2 + 1e-9 and abs(angular) <= 0.5236 + 1e-3 for linear, angular in speeds), speeds
    assert any(linear > 0 for linear, _ in speeds), speeds  # it drove, held to the limit
    eventually(lambda: len(wire.on("/odom")) > odometry_seen + 10, 30)
    simulated = [abs(speed) for speed in odometry_speeds(wire)[odometry_seen:]]
    assert 0 < max(simulated) <= 0.2 + 1e-6, simulated  # the simulator drove, no faster than the limit
    assert any(line.startswith("found: ") for line in printed), printed  # it walked the graph, and found ...
    assert "LimitedBackend" not in " ".join(printed) and "Limits" not in " ".join(printed), printed  # ... no limit
    assert "network: none" in printed, printed  # the program's process cannot reach the master itself


def program_process_of(pid: int) -> int:
    """The pid of the program's process that the run ``pid`` started (its child running runtime.program_process)."""
    children = []
    for task in os.listdir(f"/proc/{pid}/task"):
        with open(f"/proc/{pid}/task/{task}/children") as listed:
            children += [int(child) for child in listed.read().split()]
    for child in children:
        with open(f"/proc/{child}/cmdline", "rb") as cmdline:
            if b"rockly_desktop.runtime.program_process" in cmdline.read():
                return child
    return None


def test_the_program_process_killed_mid_drive_ends_with_zero_on_the_wire(robot, tmp_path):
    master, exported, wire, limits = robot
    program = with_code(exported, DRIVE_ON, tmp_path)
    seen = len(wire.on("/cmd_vel"))
    run = start_file(program, "--backend", "ros1", "--master", master.uri, "--robot-limits", limits,
                     "--events", "-", env=ros_environment(master.uri, master.home))
    try:
        eventually(lambda: (0.1, 0.0) in twists(wire)[seen:], 60)  # driving
        os.kill(program_process_of(run.pid), signal.SIGKILL)
        run.wait(60)
        records = events(run.stdout.read())
        assert run.returncode == 1
        finished = next(record for record in records if record.get("event") == "finished")
        assert finished["outcome"] == "error" and "ended without finishing" in finished["message"], finished
        eventually(lambda: twists(wire)[-1] == (0.0, 0.0), 30)  # the host's safe stop, after the last drive
    finally:
        end(run)


def test_an_overlong_or_broken_line_from_the_program_ends_it_safely(robot, tmp_path):
    master, exported, wire, limits = robot
    breaker = ("import gc\n"
               "wire = [thing for thing in gc.get_objects() if type(thing).__name__ == 'HostConnection'][0]\n"
               "ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': 0.1}})\n"
               "wire._sock.sendall(b'[1, 2]' + bytes(10))\n"
               "wire._sock.sendall(bytes([10]))\n"
               "ros.wait(30)\n")
    program = with_code(exported, breaker, tmp_path)
    done = subprocess.run([sys.executable, str(program), "--backend", "ros1", "--master", master.uri,
                           "--robot-limits", str(limits), "--events", "-"], capture_output=True, text=True,
                          timeout=60, cwd=tmp_path, env=ros_environment(master.uri, master.home))
    finished = [record for record in events(done.stdout) if record.get("event") == "finished"]
    assert done.returncode == 1 and finished[0]["outcome"] == "error", (done.stdout, done.stderr)
    eventually(lambda: twists(wire)[-1] == (0.0, 0.0), 30)

