"""The agent on a ROS 2 robot (``rockly agent --backend ros2`` against ``rockly sim turtlebot --ros2``): a STOP
while the program drives puts the safe stop's zero velocity on the wire, seen by a plain rclpy node."""

from agent_tools import AgentProcess
from json_line_node import JsonLineNode
from ros2_fixtures import ROS2_PYTHON
from test_standalone_on_ros2 import RECORDER, long_drive_exported, turtlebot_sim_on_ros2
from waiting import eventually

from rockly_desktop.runtime.agent.client import AgentClient

ZERO = {"linear": [0.0, 0.0, 0.0], "angular": [0.0, 0.0, 0.0]}


def test_a_stop_from_a_client_puts_the_zero_velocity_on_the_wire(tmp_path, ros2_settings):
    exported, source = long_drive_exported(tmp_path)
    on_the_domain = ["--domain", str(ros2_settings.domain_id), "--discovery", "localhost"]
    simulator = turtlebot_sim_on_ros2(on_the_domain)
    wire = agent = client = None
    events = []
    try:
        wire = JsonLineNode([ROS2_PYTHON, "-c", RECORDER], ros2_settings.environment(), "the wire recorder")
        agent = AgentProcess(tmp_path / "library", *on_the_domain, backend="ros2")
        client = AgentClient("127.0.0.1", agent.port, on_event=events.append)
        client.send("long", exported.read_text(), source.read_text())
        client.attach()
        client.start("long")
        eventually(lambda: any(line["linear"][0] == 0.1 for line in list(wire.lines)), timeout=60)  # driving
        assert client.stop() is True
        eventually(lambda: any(event.get("state") == "ended" for event in list(events)), 60)
        eventually(lambda: wire.lines[-1] == ZERO)  # the safe stop's zero velocity came last
        last_drive = max(i for i, line in enumerate(wire.lines) if line["linear"][0] == 0.1)
        assert ZERO in wire.lines[last_drive:]
        finished = next(event for event in events if event.get("event") == "finished")
        assert (finished["outcome"], finished["block"]) == ("stopped", "long")
    finally:
        if client is not None:
            client.close()
        if agent is not None:
            agent.stop()
        if wire is not None:
            wire.stop()
        simulator.terminate()
        simulator.wait(30)
