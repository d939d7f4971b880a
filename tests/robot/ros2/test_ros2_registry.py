"""ROS 2 from the robot-link registry, as a person reaches it: ``open_link("ros2", ...)`` with the
connection dialog's settings, and the command line (``rockly sim turtlebot --ros2`` served, a
``rockly run --backend ros2`` program driving it), against plain rclpy nodes on this run's domain."""
import signal
import subprocess
import sys

import pytest
from program_builder import block, number, rockly_document, stack
from waiting import eventually

from rockly_desktop.robot.link import RobotLink
from rockly_desktop.robot.links import open_link
from rockly_desktop.robot.ros2.client import Ros2Helper
from rockly_desktop.robot.ros2.environment import PROJECT_ROOT, Ros2Settings

ROS2_PYTHON = PROJECT_ROOT / ".venv-ros2" / "bin" / "python"


@pytest.fixture(scope="module")
def linked(test_robot, turtlebot, ros2_settings):
    """The test robot reached through the registry with the dialog's settings; its helper ends with the module."""
    Ros2Helper.close_current()
    robot = open_link("ros2", turtlebot, {"domain_id": str(ros2_settings.domain_id), "discovery": "localhost",
                                          "peers": None})
    yield robot
    robot.shutdown()
    Ros2Helper.close_current()


def test_the_registry_opens_a_ros2_link_with_the_whole_robot_link_protocol(linked, ros2_settings):
    assert linked.kind == "ros2"
    assert [name for name in dir(RobotLink) if not name.startswith("_") and not hasattr(linked, name)] == []
    assert linked.helper.settings == ros2_settings  # its domain, discovery on this machine only
    assert linked.warnings() == [] and linked.snapshot() is None
    encoder = linked.recording_encoder()  # its topics are recorded as rosbag2 writes them
    assert (encoder.message_encoding, encoder.schema_encoding) == ("cdr", "ros2msg")
    with pytest.raises(NotImplementedError):
        linked.reset()


def test_its_status_and_health_name_the_domain_and_the_discovery_range(linked, ros2_settings):
    where = f"domain {ros2_settings.domain_id}, localhost"
    assert linked.status().state == "connected" and str(linked.status().where) == f"ROS 2, {where}"
    link = linked.health()[0]
    assert (link.name, link.level) == ("ROS 2", "green") and str(link.detail).startswith(where)
    eventually(lambda: linked.status().round_trip is not None)  # measured by the helper's own thread
    german = f"Domäne {ros2_settings.domain_id}, localhost"
    assert linked.status().where.in_language("de") == f"ROS 2, {german}"
    assert link.detail.in_language("de").startswith(german)


def test_the_topic_monitor_sees_the_ros2_graph(linked):
    linked.follow_graph()
    eventually(lambda: ("/odom", "nav_msgs/Odometry", 1) in linked.graph_topics(), timeout=20)


def test_safe_stop_publishes_the_profiles_stop_over_ros2(linked, test_robot):
    before = len(test_robot.received("/cmd_vel"))
    assert linked.safe_stop() == []
    eventually(lambda: len(test_robot.received("/cmd_vel")) > before, timeout=10)
    stop = test_robot.received("/cmd_vel")[-1]
    assert stop["type"] == "Twist" and stop["message"]["linear"]["x"] == 0.0


def rockly_process(home, *args, **extra_env):
    """``rockly ARGS`` in its own process, discovering on this machine only, with its own home."""
    env = {"PATH": "/usr/bin:/bin", "HOME": str(home), "ROS_AUTOMATIC_DISCOVERY_RANGE": "LOCALHOST",
           "QT_QPA_PLATFORM": "offscreen", **extra_env}
    return subprocess.Popen([sys.executable, "-m", "rockly_desktop", *map(str, args)], cwd=PROJECT_ROOT, env=env,
                            text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


@pytest.mark.parametrize("distribution", ["auto", "jazzy"])  # jazzy: a TwistStamped /cmd_vel on both sides
def test_rockly_run_on_ros2_drives_rockly_sim_turtlebot_on_ros2(tmp_path, ros2_settings, distribution):
    program = tmp_path / "drive.rockly"
    program.write_text(rockly_document([stack(
        block("text_print", id="before", inputs={"TEXT": block("turtlebot_distance", {"direction": "ahead"})}),
        block("turtlebot_drive", {"direction": "forward"}, inputs={"distance": number(0.3)}),
        block("text_print", id="after", inputs={"TEXT": block("turtlebot_distance", {"direction": "ahead"})}),
    )], profile="turtlebot"))
    # the simulated TurtleBot's own domain: the test robot also has /odom, /cmd_vel
    domain = ros2_settings.domain_id + (1 if distribution == "auto" else 2)
    simulator = rockly_process(tmp_path, "sim", "turtlebot", "--ros2", "--no-window", "--domain", domain,
                               "--discovery", "localhost", "--speed", "5", "--ros-distro", distribution)
    try:
        assert "is up on ROS" in simulator.stdout.readline()
        run = rockly_process(tmp_path, "run", program, "--backend", "ros2", "--domain", domain, "--language", "en",
                             "--ros-distro", distribution)
        out, err = run.communicate(timeout=180)
    finally:
        simulator.terminate()
        simulator.wait(timeout=30)
    assert run.returncode == 0, err
    before, after = (float(line) for line in out.split() if line.replace(".", "", 1).isdigit())
    assert before == pytest.approx(1.9, abs=0.03)  # the first box, from the start
    assert after == pytest.approx(1.6, abs=0.03)
    assert simulator.returncode == 0


@pytest.mark.parametrize(("example", "language", "distribution"), [
    ("turtlebot/avoid-obstacles.rockly", "en", "auto"), ("de/turtlebot/Hindernissen-ausweichen.rockly", "de", "jazzy")])
def test_the_turtlebot_examples_run_unchanged_on_ros2(tmp_path, ros2_settings, example, language, distribution):
    domain = ros2_settings.domain_id + 3
    # 3 times real time: the example steers by its laser, which a loaded machine delivers later
    simulator = rockly_process(tmp_path, "sim", "turtlebot", "--ros2", "--no-window", "--domain", domain,
                               "--discovery", "localhost", "--speed", "3", "--ros-distro", distribution)
    try:
        assert "is up on ROS" in simulator.stdout.readline()
        run = rockly_process(tmp_path, "run", PROJECT_ROOT / "examples" / example, "--backend", "ros2",
                             "--domain", domain, "--language", language, "--ros-distro", distribution)
        out, err = run.communicate(timeout=180)
    finally:
        simulator.terminate()
        simulator.wait(timeout=30)
    assert run.returncode == 0, err
    assert out.splitlines()[-1] == {"en": "finished", "de": "fertig"}[language]


def test_rockly_sim_ends_on_a_burst_of_signals(tmp_path, ros2_settings):
    """SIGTERM and then Ctrl+C, or Ctrl+C pressed again while it ends, end it too: a signal handler that
    took a lock (an Event's set()) once hung for good when a second signal interrupted the first."""
    simulator = rockly_process(tmp_path, "sim", "turtlebot", "--ros2", "--no-window", "--domain",
                               ros2_settings.domain_id + 4, "--discovery", "localhost")
    try:
        assert "is up on ROS" in simulator.stdout.readline()
        for _ in range(20):
            simulator.send_signal(signal.SIGTERM)
            simulator.send_signal(signal.SIGINT)
        simulator.wait(timeout=30)  # a late signal may find the default handlers back: any exit will do
    finally:
        if simulator.poll() is None:
            simulator.kill()
            simulator.wait()


def test_rockly_run_on_ros2_without_ros2_names_the_set_up_step(tmp_path):
    program = tmp_path / "p.rockly"
    program.write_text(rockly_document([block("text_print", id="p")], profile="turtlebot"))
    run = rockly_process(tmp_path, "run", program, "--backend", "ros2", "--domain", "3", "--language", "en",
                         ROCKLY_ROS2_PYTHON=str(tmp_path / "no-ros2" / "bin" / "python"))
    _out, err = run.communicate(timeout=120)
    assert run.returncode == 1
    assert err.startswith("rockly run: ROS 2 is not set up on this computer") and "run 'make ros2'" in err


def test_a_bad_domain_id_is_refused_before_anything_starts(tmp_path):
    program = tmp_path / "p.rockly"
    program.write_text(rockly_document([block("text_print", id="p")], profile="turtlebot"))
    run = rockly_process(tmp_path, "run", program, "--backend", "ros2", "--domain", "300", "--language", "en")
    _out, err = run.communicate(timeout=120)
    assert run.returncode == 1
    assert "a ROS 2 domain id is a whole number from 0 to 232, not '300'" in err


def test_errors_on_blocks_are_said_in_the_runs_language(linked):
    from rockly_desktop.core.errors import RobotCommandError, RobotTimeout
    from rockly_desktop.robot.interrupt import Interrupt

    backend = linked.backend(Interrupt())
    with pytest.raises(RobotCommandError) as missing:  # said by the helper process, worded by Rockly
        backend.publish("/head/move", "hobbit_msgs/HeadMove", {})
    assert missing.value.in_language("de") == "das ROS-2-Schnittstellenpaket „hobbit_msgs“ ist nicht installiert"
    with pytest.raises(RobotCommandError) as bad_name:
        backend.get_param("max_speed")
    assert "Knoten:Parameter" in bad_name.value.in_language("de")
    with pytest.raises(RobotTimeout) as silent:
        backend.call_service("/nobody_here", "std_srvs/SetBool", {"data": True}, 0.2)
    assert silent.value.in_language("de").startswith("der Dienst")
    assert str(silent.value) == "the service '/nobody_here' is not available (waited 0.2 s)"


def test_rockly_sim_on_ros2_with_its_window_serves_odometry_and_ends_on_sigterm(tmp_path, ros2_settings):
    domain = ros2_settings.domain_id + 2
    simulator = rockly_process(tmp_path, "sim", "turtlebot", "--ros2", "--domain", domain, "--discovery", "localhost")
    try:
        assert "is up on ROS (close its window" in simulator.stdout.readline()
        heard = subprocess.run([str(ROS2_PYTHON), "-c", ODOMETRY_LISTENER], capture_output=True, text=True,
                               timeout=60, env=Ros2Settings(domain, "localhost").environment())
    finally:
        simulator.terminate()
        simulator.wait(timeout=30)
    assert heard.stdout.strip() == "odom frame: odom", heard.stderr
    assert simulator.returncode == 0, simulator.stderr.read()


ODOMETRY_LISTENER = r"""
import rclpy
from nav_msgs.msg import Odometry
rclpy.init()
node = rclpy.create_node("odometry_listener")
heard = []
node.create_subscription(Odometry, "/odom", heard.append, 10)
while not heard:
    rclpy.spin_once(node, timeout_sec=0.1)
print("odom frame:", heard[0].header.frame_id)
"""
