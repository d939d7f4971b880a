"""A Python block's commands go through the run's `robot`, so the teacher's limits hold below it as below every
block (a real ``rockly run`` process on the simulator, the teacher's settings where the window keeps them)."""
import subprocess
import sys
from pathlib import Path

from program_builder import block, rockly_document, stack

REPO = Path(__file__).resolve().parents[2]
CODE = "import os\nspeed = 0.3 + len(os.sep) * 0\nrobot.drive(speed, 'forward')\nprint(robot.position('x'))"


def test_the_teachers_limits_hold_below_a_python_block(tmp_path, isolated_user_folders):
    from rockly_desktop.settings.app_settings import AppSettings

    settings = AppSettings(isolated_user_folders / "config" / "Rockly" / "Rockly.conf")
    settings.teacher.set_limits("hobbit", max_speed=0.1, switched_off={"arm"})
    settings.sync()
    path = tmp_path / "python.rockly"
    path.write_text(rockly_document([stack(
        block("rockly_python", id="free", extraState={"code": CODE}),
        block("rockly_python", id="arm", extraState={"code": "robot.gripper('open')"}))]))
    result = subprocess.run([sys.executable, "-m", "rockly_desktop", "run", str(path), "--speed", "20"],
                            capture_output=True, text=True, timeout=120, cwd=REPO)
    lines = result.stdout.splitlines()
    assert "print   Speed limit: the robot drives at most 0.1 m/s (set by the teacher)." in lines, result.stdout
    assert result.returncode == 1
    assert ("error in block arm (rockly_python): The robot could not do this: "
            "the teacher switched off “Arm and gripper” for this robot") in result.stderr
