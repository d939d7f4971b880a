"""A robot that vanishes mid-run: the block fails within 2 s with a clear message, no hang."""
import time

from program_builder import block, number, rockly_document, stack
from ros_helpers import RocklyProcess, RosMaster, messages_received, publishes
from waiting import eventually


def test_killing_the_master_mid_run_fails_the_running_block_quickly(tmp_path):
    master = RosMaster(tmp_path / "ros").start()
    simulator = RocklyProcess(["sim", "hobbit", "--ros", "--master", master.uri], master, ready_line="on ROS")
    program = tmp_path / "long-drive.rockly"
    drive = block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="drive")
    program.write_text(rockly_document([stack(block("hobbit_emo", {"emotion": "HAPPY"}, id="emo"), drive)]))
    run = RocklyProcess(["run", program, "--backend", "ros1", "--master", master.uri], master,
                        ready_line="block   drive")
    try:
        eventually(lambda: messages_received(master.uri, "/DiscreteMotionCmd") >= 1)  # the robot is driving
        killed = time.monotonic()
        master.stop()
        run.process.wait(20)
        ended = time.monotonic()
        errors = run.process.stderr.read()
        assert run.process.returncode == 1
        assert "error in block drive (hobbit_move)" in errors
        assert "connection to the robot was lost" in errors
        assert ended - killed < 2.5 + 1.0  # 2 s to notice, plus process exit
    finally:
        run.stop()
        simulator.stop()
        master.stop()


def test_no_master_is_explained_at_once(tmp_path):
    master = RosMaster(tmp_path / "ros")  # never started: nothing listens on its port
    program = tmp_path / "p.rockly"
    program.write_text(rockly_document([block("hobbit_sos")]))
    run = RocklyProcess(["run", program, "--backend", "ros1", "--master", master.uri], master)
    run.process.wait(30)
    assert run.process.returncode == 1
    assert f"no ROS master answers at {master.uri}" in run.process.stderr.read()


RECONNECTING_CLIENT = r"""
import sys
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot.ros1.link import RosRobot
from rockly_desktop.robot.interrupt import Interrupt
hobbit = ProfileRegistry.discover().get("hobbit")
robot = RosRobot(hobbit, sys.argv[1])
commands = hobbit.load_object("api")(robot.backend(Interrupt()))
commands.drive(0.2)
print("first drive done", flush=True)
Interrupt().wait_until(lambda: robot.connection.lost, 20)   # the test stopped the master
print("lost", flush=True)
sys.stdin.readline()                       # the test restarts the master now
Interrupt().wait_until(lambda: robot.connection.status == "connected", 20)
commands = hobbit.load_object("api")(robot.backend(Interrupt()))
commands.drive(0.2)
commands.look("up_left")
print("second drive done", robot.connection.status, flush=True)
"""


def test_after_the_master_comes_back_the_same_rockly_drives_again(tmp_path):
    import subprocess
    import sys

    from ros_helpers import REPO, ros_environment

    master = RosMaster(tmp_path / "ros").start()
    simulator = RocklyProcess(["sim", "hobbit", "--ros", "--master", master.uri, "--speed", "10"], master,
                              ready_line="on ROS")
    client = subprocess.Popen([sys.executable, "-c", RECONNECTING_CLIENT, master.uri], cwd=REPO, text=True,
                              env=ros_environment(master.uri, master.home), stdin=subprocess.PIPE,
                              stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    try:
        assert client.stdout.readline().strip() == "first drive done"
        master.stop()
        assert client.stdout.readline().strip() == "lost"
        master.start()
        eventually(lambda: publishes(master.uri, "/odom"))  # the simulator's node told the new master of itself
        client.stdin.write("go\n")
        client.stdin.flush()
        output, errors = client.communicate(timeout=60)
        assert output.strip() == "second drive done connected", errors
    finally:
        client.kill()
        simulator.stop()
        master.stop()


def test_without_rospy_the_ros_backend_says_so_and_the_simulator_still_runs(tmp_path):
    import subprocess
    import sys

    from ros_helpers import REPO

    blocker = tmp_path / "no_ros" / "rospy"
    blocker.mkdir(parents=True)
    (blocker / "__init__.py").write_text("raise ImportError('No module named rospy')\n")
    program = tmp_path / "p.rockly"
    program.write_text(rockly_document([block("hobbit_emo", {"emotion": "HAPPY"})]))
    env = dict(__import__("os").environ, PYTHONPATH=str(blocker.parent))
    on_ros = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(program), "--backend", "ros1"],
                            capture_output=True, text=True, cwd=REPO, env=env, timeout=60)
    assert on_ros.returncode == 1 and "ROS 1 (rospy) is not installed on this computer" in on_ros.stderr
    on_simulator = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(program)],
                                  capture_output=True, text=True, cwd=REPO, env=env, timeout=60)
    assert on_simulator.returncode == 0, on_simulator.stderr


def test_a_master_restarted_between_two_looks_is_told_of_this_node_again(monkeypatch):
    import threading

    from rockly_desktop.robot.ros1 import connection

    # The session's own connection may be watching a real master in this process: the stand-ins
    # answer only for this test's thread and pass everyone else on to the real functions.
    tester, real_pid, real_register = threading.current_thread(), connection.master_pid, connection._register_again
    uri, pid, registered = "http://127.0.0.1:9", [100], []

    def master_pid(master_uri):
        return (pid[0], 0.001) if master_uri == uri else real_pid(master_uri)

    def register_again():
        if threading.current_thread() is tester:
            registered.append(pid[0])
        else:
            real_register()

    monkeypatch.setattr(connection, "master_pid", master_pid)
    monkeypatch.setattr(connection, "_register_again", register_again)
    watched = connection.RosConnection(uri)
    watched.status, watched._master_pid = connection.CONNECTED, 100
    for _ in range(3):
        watched._look()
    assert registered == []          # the same master knows this node
    pid[0] = 200                     # another master answers there now
    watched._look()
    assert registered == [200]       # the node registers again, though it never saw the master gone
    assert watched.status == connection.CONNECTED
    watched._look()
    assert registered == [200]       # once
