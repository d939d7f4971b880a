"""A robot that vanishes mid-run: the block fails within 2 s with a clear message, no hang."""
import time

from program_builder import block, number, rockly_document, stack
from ros_helpers import RocklyProcess, RosMaster


def test_killing_the_master_mid_run_fails_the_running_block_quickly(tmp_path):
    master = RosMaster(tmp_path / "ros").start()
    simulator = RocklyProcess(["sim", "hobbit", "--ros", "--master", master.uri], master, ready_line="on ROS")
    program = tmp_path / "long-drive.rockly"
    program.write_text(rockly_document([stack(block("hobbit_emo", {"emotion": "HAPPY"}, id="emo"),
                                              block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="drive"))]))
    run = RocklyProcess(["run", program, "--backend", "ros1", "--master", master.uri], master, ready_line="block   drive")
    try:
        time.sleep(0.5)  # well into the drive
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
