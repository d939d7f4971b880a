"""A robot node killed mid-command, or the master killed during a wait: the block fails with a
clear message in about a second, not at the command's two-minute timeout."""
import pytest
from program_builder import block, number, rockly_document
from ros_helpers import RocklyProcess, RosMaster, messages_received
from waiting import eventually

NOT_THE_TIMEOUT = 20  # seconds: far below the 120 s a motion may take, far above the ~1 s it takes


@pytest.mark.parametrize(("program", "command_topic"), [
    (block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="cmd"), "/DiscreteMotionCmd"),
    (block("hobbit_arm_move", {"movement": "MoveToCandle"}, id="cmd"), "/hobbit_arm/goal"),
], ids=["drive", "arm"])
def test_killing_the_robot_node_mid_command_fails_the_block(tmp_path, program, command_topic):
    master = RosMaster(tmp_path / "ros").start()
    # Slow simulated time: the command is still under way when the node is killed.
    simulator = RocklyProcess(["sim", "hobbit", "--ros", "--no-window", "--master", master.uri, "--speed", "0.05"],
                              master, ready_line="on ROS")
    source = tmp_path / "long-command.rockly"
    source.write_text(rockly_document([program]))
    run = RocklyProcess(["run", source, "--backend", "ros1", "--master", master.uri], master, ready_line="block   cmd")
    try:
        eventually(lambda: messages_received(master.uri, command_topic) >= 1)
        simulator.process.kill()  # kill -9: the master still lists the dead node's topics
        run.process.wait(NOT_THE_TIMEOUT)
        errors = run.process.stderr.read()
        assert run.process.returncode == 1, errors
        assert "the robot stopped answering: the node publishing" in errors
    finally:
        run.stop()
        simulator.stop()
        master.stop()


def test_killing_the_master_during_a_long_wait_fails_the_wait(tmp_path):
    master = RosMaster(tmp_path / "ros").start()
    source = tmp_path / "wait.rockly"
    source.write_text(rockly_document([block("ros_wait", inputs={"seconds": number(60)}, id="wait")]))
    run = RocklyProcess(["run", source, "--backend", "ros1", "--master", master.uri], master, ready_line="block   wait")
    try:
        master.stop()
        run.process.wait(NOT_THE_TIMEOUT)
        errors = run.process.stderr.read()
        assert run.process.returncode == 1, errors
        assert "error in block wait (ros_wait)" in errors
        assert "connection to the robot was lost" in errors
    finally:
        run.stop()
        master.stop()
