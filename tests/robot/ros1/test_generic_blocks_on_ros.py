"""A program of generic ROS blocks, run by ``rockly run --backend ros1`` against the ROS-level HOBBIT."""
import subprocess
import sys

from ros_helpers import REPO, ros_environment
from test_hobbit_on_ros import record

EXAMPLE = REPO / "examples" / "hobbit" / "arm-with-progress.rockly"


def test_typed_publish_and_a_goal_with_a_while_waiting_handler_run_on_ros(ros_master, hobbit_on_ros, ros_robot):
    turns, stop_recording = record(ros_robot, "/cmd_vel", "geometry_msgs/Twist",
                                   lambda message: message["angular"]["z"])
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(EXAMPLE), "--backend", "ros1",
                             "--master", ros_master.uri], capture_output=True, text=True, cwd=REPO, timeout=120,
                            env=ros_environment(ros_master.uri, ros_master.home))
    stop_recording()
    assert result.returncode == 0, result.stderr[-2000:]
    lines = result.stdout.splitlines()
    assert lines[-1] == "finished"
    assert 0.4 in turns and turns[-1] == 0.0          # the typed Twist went out, then the stop's zero Twist
    progress = [line for line in lines if line.startswith("print") and "arm: MoveToCandle" in line]
    # feedback from the real action server; ROS 1 keeps no order between an action's feedback and result
    # topics, and actionlib drops feedback after the result, so the last one seen may be short of 100 %
    assert progress and all(line.endswith(" %") for line in progress)
    handler_steps = [line for line in lines if line.split()[:2] == ["block", "progress"]]
    assert len(handler_steps) == len(progress)        # the handler's block ran as a step of the program
    assert "print   [info] The arm's goal ended: succeeded" in lines
