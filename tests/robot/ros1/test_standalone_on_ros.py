"""A standalone export on ROS 1 against ``rockly sim hobbit --ros``: SIGTERM mid-drive (a launch file
ending it) sends the robot's safe stop, seen on the wire by an independent rospy node."""
import signal
import struct

from program_builder import block, number
from ros_helpers import hobbit_on_own_master, messages_received, ros_environment
from standalone_tools import end, events, exported_program, start_file, wait_for_event
from waiting import eventually
from wire_recorder import WireRecorder


def string_data(raw: bytes) -> str:
    """A std_msgs/String's text from its wire bytes (a length, then UTF-8)."""
    (length,) = struct.unpack_from("<I", raw)
    return raw[4:4 + length].decode()


def far_drive():
    """Drive 50 m: long enough for a stop to come mid-drive."""
    return block("hobbit_move", {"direction": "+"}, {"speed": number(50)}, id="far")


def test_sigterm_mid_drive_sends_the_safe_stop_on_the_wire(tmp_path):
    exported, _source = exported_program(tmp_path, far_drive(), "far")
    master, simulator = hobbit_on_own_master(tmp_path)
    wire = WireRecorder(master, ["/DiscreteMotionCmd", "/cmd_vel"])
    run = start_file(exported, "--backend", "ros1", "--master", master.uri, "--events", "-",
                     env=ros_environment(master.uri, master.home))
    seen = []
    try:
        wait_for_event(run, lambda record: record.get("id") == "far", seen)
        eventually(lambda: messages_received(master.uri, "/DiscreteMotionCmd") >= 1)  # HOBBIT is driving 50 m
        eventually(lambda: wire.on("/DiscreteMotionCmd"))
        run.send_signal(signal.SIGTERM)
        run.wait(60)
        seen += events(run.stdout.read())
        assert run.returncode == 143, run.stderr.read()
        assert seen[-2]["outcome"] == "stopped" and seen[-1] == {"event": "exit", "status": 143}
        eventually(lambda: len(wire.on("/DiscreteMotionCmd")) >= 2 and wire.on("/cmd_vel"))
        commands = [string_data(raw) for _type, raw in wire.on("/DiscreteMotionCmd")]
        # the drive halted by the stop, then the safe stop
        assert commands[0] == "Move 50" and set(commands[1:]) == {"Stop"}, commands
        assert {struct.unpack("<6d", raw) for _type, raw in wire.on("/cmd_vel")} == {(0.0,) * 6}
    finally:
        end(run)
        wire.stop()
        simulator.stop()
        master.stop()
