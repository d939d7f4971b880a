"""A run on the built-in simulator, recorded: what the mcap library reads back."""
import json
import subprocess
import sys
from pathlib import Path

import pytest
from recorded_reading import channels_and_messages, metadata_and_attachments

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.executor.run_to_mcap import RunRecording
from rockly_desktop.recording.reading import read_recording
from rockly_desktop.robot.sim.link import SimulatedRobot

PROGRAM = {"code": "\n".join([
    "__rockly__.block('set')", "n = 1",
    "__rockly__.block('look')", "robot.look('up_left')",
    "__rockly__.block('emo')", "robot.show_emotion('WONDERING')",
    "__rockly__.block('drive')", "robot.drive(0.3, 'forward')",
    "__rockly__.block('again')", "n = n + 1",
    "__rockly__.block('say')", "print('done', n)", ""]), "variables": {"n": "n"}}
TYPES = {"set": "variables_set", "look": "hobbit_look", "emo": "hobbit_emo", "drive": "hobbit_move",
         "again": "math_change", "say": "text_print"}
REPO = Path(__file__).resolve().parents[2]
DOCUMENT = json.dumps({"rockly": 1, "profile": "hobbit", "workspace": {}}).encode()


@pytest.fixture(scope="module")
def recorded(hobbit, tmp_path_factory):
    """A finished recording of PROGRAM on the simulator, and the robot (shut down)."""
    path = tmp_path_factory.mktemp("recordings") / "run.mcap"
    robot = SimulatedRobot(hobbit, speed=10)
    try:
        recording = RunRecording(path, hobbit, robot, "square.rockly", DOCUMENT, TYPES, topic_rate=10)
        result = make_runner(hobbit, robot, PROGRAM, RunControl(), lambda event: None, recording=recording).run()
    finally:
        robot.shutdown()
    assert result.outcome == "finished", result
    return path


def test_rocklys_channels_have_json_schemas_and_robot_topics_their_ros1_schemas(recorded):
    found, _messages = channels_and_messages(recorded)
    for channel in ("/rockly/run", "/rockly/blocks", "/rockly/variables", "/rockly/commands", "/rockly/output",
                    "/rockly/simulator", "/rockly/recording"):
        assert found[channel][0] == "json" and found[channel][2] == "jsonschema", channel
    assert found["/odom"] == ("ros1", "nav_msgs/Odometry", "ros1msg")
    assert found["/head/move"] == ("ros1", "std_msgs/String", "ros1msg")
    assert found["/DiscreteMotionCmd"] == ("ros1", "std_msgs/String", "ros1msg")


def test_the_block_channel_reproduces_the_runs_block_order(recorded):
    _found, messages = channels_and_messages(recorded)
    assert [(m["block"], m["type"]) for m in messages["/rockly/blocks"]] == list(TYPES.items())
    assert [m["event"] for m in messages["/rockly/run"]] == ["start", "safe_stop", "end"]
    assert messages["/rockly/run"][-1]["outcome"] == "finished"
    assert messages["/rockly/output"] == [{"text": "done 2"}]
    assert messages["/rockly/variables"][-1] == {"values": {"n": "2"}}


def test_what_the_program_sent_is_recorded_with_its_block_and_decodes_as_ros1(recorded):
    _found, messages = channels_and_messages(recorded)
    sent = [(m["kind"], m["name"], m["block"]) for m in messages["/rockly/commands"] if m["kind"] == "publish"]
    assert ("publish", "/head/move", "look") in sent and ("publish", "/head/emo", "emo") in sent
    assert ("publish", "/DiscreteMotionCmd", "drive") in sent
    assert [message.data for message in messages["/head/move"]] == ["up_left"]
    assert [message.data for message in messages["/DiscreteMotionCmd"]] == ["Move 0.3", "Stop"]  # Stop: safe stop


def test_robot_topics_are_held_to_the_rate_cap(recorded):
    recording = read_recording(recorded)
    _found, messages = channels_and_messages(recorded)
    odom = messages["/odom"]
    assert odom and all(message._type == "nav_msgs/Odometry" for message in odom)
    assert len(odom) <= recording.duration * 10 + 2
    assert messages["/rockly/recording"][-1]["capped"]["/odom"] > 0  # the simulator publishes faster


def test_the_program_and_what_ran_are_stored_in_the_file(recorded):
    metadata, attachments = metadata_and_attachments(recorded)
    assert attachments["program.rockly"] == DOCUMENT
    assert metadata["rockly"]["program"] == "square.rockly"
    assert (metadata["rockly"]["profile"], metadata["rockly"]["robot"]) == ("hobbit", "sim")
    assert read_recording(recorded).complete


FRESH_PROCESS = """
import sys
from rockly_desktop.profiles.registry import ProfileRegistry
from rockly_desktop.robot.sim.link import SimulatedRobot
robot = SimulatedRobot(ProfileRegistry.discover().get("hobbit"))
encoder = robot.recording_encoder()
assert robot.recording_encoder() is encoder
modules = set(sys.modules)
for _topic, msg_type in robot.world.topics():
    encoder(msg_type, {})
robot.shutdown()
print(sorted(set(sys.modules) - modules))
"""


def test_the_simulators_encoder_is_made_once_with_its_topics_message_classes_ready():
    """The recording's writer must not import message classes while a program runs beside it (in a
    fresh process: this one has imported them all by now)."""
    done = subprocess.run([sys.executable, "-c", FRESH_PROCESS], capture_output=True, text=True, timeout=60,
                          cwd=REPO)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"
