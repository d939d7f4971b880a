"""On a ROS 1 robot, Programs on the robot… reaches the agent over the robot's ROS graph; pairing there goes over
TCP (TLS: the key never travels over ROS in clear) to the agent beside the master, and the key serves the agent's
ROS address too, so the dialog then lists the robot's programs over ROS (issue 30). The agent and the simulated
HOBBIT in processes of their own on the session's master, the window on HOBBIT over ROS 1."""
from agent_tools import AgentProcess
from ros_helpers import ros_environment
from test_attach_window_over_ros import ros_window  # noqa: F401 (fixture)
from test_robot_pairing import asked_to_pair, code_from_the_robot, type_code_and_pair

from rockly_desktop.runtime.agent.protocol import DEFAULT_NAMESPACE
from rockly_desktop.runtime.agent.robot_keys import RobotKeys, ros_address
from rockly_desktop.ui.agent.robot_programs_dialog import RobotProgramsDialog


def test_on_a_ros_robot_the_dialog_pairs_over_tcp_and_then_reaches_the_agent_over_ros(
        qtbot, ros_window, ros_master, hobbit_on_ros, tmp_path):  # noqa: F811
    agent = AgentProcess(tmp_path / "library", "--master", ros_master.uri, backend="ros1",
                         env=ros_environment(ros_master.uri, tmp_path / "ros"), paired=False)
    window = ros_window
    try:
        window.settings.agent_address = f"127.0.0.1:{agent.port}"   # the port beside the robot's master
        window.show_robot_programs()
        dialog = window.findChild(RobotProgramsDialog)
        assert dialog.via == "auto"
        qtbot.waitUntil(lambda: asked_to_pair(dialog), timeout=30000)
        type_code_and_pair(qtbot, dialog, code_from_the_robot(agent.library))
        qtbot.waitUntil(lambda: dialog.pairing.about.isVisible(), timeout=30000)
        keys = {key.address.split(":")[0]: key for key in RobotKeys().all()}
        assert set(keys) == {"tcp", "ros1"} and keys["tcp"].client == keys["ros1"].client
        assert keys["ros1"].address == ros_address("ros1", ros_master.uri, DEFAULT_NAMESPACE)
        qtbot.waitUntil(lambda: dialog.programs.isVisible() and dialog.status.text() == "no programs on the robot yet",
                        timeout=30000)   # asked again, over ROS now, with the key
        assert dialog.pairing.about.isVisible() and not dialog.pairing.pairing_needed
        dialog.close()
        dialog.calls.wait(30)
        dialog.pairing.calls.wait(30)
    finally:
        agent.stop()
