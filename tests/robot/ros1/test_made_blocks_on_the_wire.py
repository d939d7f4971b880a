"""What a made block puts on a real ROS 1 wire, heard by an independent plain rospy node."""
import os
import subprocess
import sys
from pathlib import Path

import yaml
from program_builder import block, number, rockly_document, stack
from ros_helpers import ros_environment
from waiting import eventually
from wire_recorder import WireRecorder

REPO = Path(__file__).resolve().parents[3]


def rockly(master, *args):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)], capture_output=True, text=True,
                          timeout=180, cwd=REPO, env=ros_environment(master.uri, master.home / "rockly"))


def test_a_fixed_field_left_empty_sends_its_default(ros_master, tmp_path):
    from geometry_msgs.msg import Twist

    made = rockly(ros_master, "blocks", "make", "--profile", "hobbit", "--pack", "wire_made", "--id", "made_speed",
                  "--kind", "publish", "--interface", "/cmd_vel", "--type", "geometry_msgs/Twist",
                  "--input", "speed=linear.x", "--fixed", "angular.z=", "--sentence-en", "drive at %1",
                  "--colour", "#4c97ff", "--category-en", "Made")
    assert made.returncode == 0, made.stderr
    blocks = yaml.safe_load((Path(os.environ["XDG_DATA_HOME"]) / "rockly" / "packs" / "wire_made" / "blocks.yaml")
                            .read_text())["blocks"]
    assert blocks[0]["python"]["code"] == ("ros.publish_message('/cmd_vel', 'geometry_msgs/Twist', "
                                           "{{'linear': {{'x': {speed}}}}})")  # no angular.z: its default

    recorder = WireRecorder(ros_master, ["/cmd_vel"])
    try:
        program = tmp_path / "drive.rockly"
        program.write_text(rockly_document([stack(block("made_speed", inputs={"speed": number(0.1)}))]))
        ran = rockly(ros_master, "run", program, "--backend", "ros1", "--master", ros_master.uri)
        assert ran.returncode == 0, ran.stderr + ran.stdout

        def heard():
            return [Twist().deserialize(data) for _type, data in recorder.on("/cmd_vel")]
        eventually(lambda: any(twist.linear.x == 0.1 for twist in heard()), timeout=15)
        sent = next(twist for twist in heard() if twist.linear.x == 0.1)
        assert sent.angular.z == 0.0
    finally:
        recorder.stop()
