"""The example programs run unchanged on a robot over ROS 1: ``rockly run EXAMPLE --backend ros1`` against
``rockly sim PROFILE --ros`` on a master of each example's own (two HOBBITs must not share one)."""
import pytest
from ros_helpers import RocklyProcess, RosMaster
from test_examples import ANSWERS

# simulated time this much faster: the TurtleBot's example steers by its laser, which a loaded
# machine delivers later, so it drives slower than HOBBIT's square
SPEEDS = {"hobbit": 10, "turtlebot": 4}
ENGLISH = sorted(example for example in ANSWERS if not example.startswith("de/"))


@pytest.mark.parametrize("example", ENGLISH)
def test_the_example_runs_to_its_end_on_ros1(example, tmp_path):
    profile = example.split("/")[0]
    answers = [argument for answer in ANSWERS[example] for argument in ("--answer", answer)]
    master = RosMaster(tmp_path).start()
    simulator = run = None
    try:
        simulator = RocklyProcess(["sim", profile, "--ros", "--no-window", "--master", master.uri, "--speed",
                                   SPEEDS[profile], *answers], master, ready_line="on ROS")
        run = RocklyProcess(["run", f"examples/{example}", "--backend", "ros1", "--master", master.uri], master)
        out, err = run.process.communicate(timeout=240)
        assert run.process.returncode == 0, err[-2000:]
        assert out.splitlines()[-1] == "finished"
    finally:
        for process in (run, simulator):
            if process is not None:
                process.stop()
        master.stop()
