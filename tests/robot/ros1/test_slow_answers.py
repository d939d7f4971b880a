"""A loaded computer answers late, and late is not gone: a master or robot node that pauses for longer than one
look's timeout (SIGSTOP, then SIGCONT) leaves the running block going, where a killed one fails it
(test_connection_loss.py, test_robot_node_loss.py)."""
import signal
import time

from program_builder import block, number, rockly_document, stack
from ros_helpers import RocklyProcess, RosMaster, messages_received
from waiting import eventually

from rockly_desktop.robot.ros1.connection import PROBE_TIMEOUT, WATCH_SECONDS

# A stimulus, not a wait: a pause long enough for at least one look (every WATCH_SECONDS) to time out.
PAUSE = WATCH_SECONDS + PROBE_TIMEOUT + 1.0


def paused(process, seconds: float):
    """Freeze ``process`` for ``seconds``, as a starved process on a loaded machine is."""
    process.send_signal(signal.SIGSTOP)
    try:
        time.sleep(seconds)
    finally:
        process.send_signal(signal.SIGCONT)


def test_a_master_and_a_robot_node_that_pause_leave_the_run_going(tmp_path):
    master = RosMaster(tmp_path / "ros").start()
    simulator = RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", master.uri], master,
                              ready_line="on ROS")
    program = tmp_path / "drive-wait-back.rockly"  # the pauses fall in its first two blocks
    program.write_text(rockly_document([stack(
        block("hobbit_move", {"direction": "+"}, {"speed": number(1)}, id="drive"),
        block("hobbit_wait", inputs={"seconds": number(6)}, id="linger"),
        block("hobbit_move", {"direction": "-"}, {"speed": number(1)}, id="back"))]))
    run = RocklyProcess(["run", program, "--backend", "ros1", "--master", master.uri], master,
                        ready_line="block   drive")
    try:
        eventually(lambda: messages_received(master.uri, "/DiscreteMotionCmd") >= 1, 60)  # the robot is driving
        paused(master.process, PAUSE)
        paused(simulator.process, PAUSE)
        output, errors = run.process.communicate(timeout=110)
        assert run.process.returncode == 0, errors
        assert "block   back" in output

    finally:
        run.stop()
        simulator.stop()
        master.stop()
