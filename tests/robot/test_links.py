"""The registry of robot links: every kind, its name in the window, the command line built from it,
and clear messages for a kind that does not exist or cannot be used here."""
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import pytest
from program_builder import block, rockly_document

from rockly_desktop import cli
from rockly_desktop.robot import links
from rockly_desktop.robot.health import GREEN
from rockly_desktop.robot.link import RobotLink, RobotUnavailable
from rockly_desktop.robot.links import (
    LinkKind,
    UnknownRobotLink,
    check_available,
    link_kind,
    link_kinds,
    open_link,
    serve_simulator,
)
from rockly_desktop.robot.sim.link import SimulatedRobot
from rockly_desktop.runtime import options
from rockly_desktop.ui.texts import robot_problem, tr

REPO = Path(__file__).resolve().parents[2]
PROTOCOL = [name for name in dir(RobotLink) if not name.startswith("_")]


def test_the_registry_lists_the_simulator_first_then_ros1_and_ros2_each_named_in_both_languages():
    kinds = [entry.kind for entry in link_kinds()]
    assert kinds == ["sim", "ros1", "ros2"] and links.DEFAULT_KIND == "sim"
    names = {entry.kind: (tr(entry.name, "en"), tr(entry.name, "de")) for entry in link_kinds()}
    assert names["sim"] == ("Simulator (built in)", "Simulator (eingebaut)")
    assert names["ros1"] == ("Real robot (ROS 1)…", "Echter Roboter (ROS 1)…")
    assert names["ros2"] == ("Real robot (ROS 2)…", "Echter Roboter (ROS 2)…")
    assert [entry.kind for entry in link_kinds() if entry.simulated] == ["sim"]


def test_each_link_class_has_everything_a_robot_link_offers_and_its_kind():
    assert {"backend", "follow_graph", "graph_topics", "health", "status", "safe_stop", "shutdown",
            "open", "unavailable"} <= set(PROTOCOL)
    for entry in link_kinds():
        link_class = entry.link_class()
        assert link_class.kind == entry.kind
        assert [name for name in PROTOCOL if not hasattr(link_class, name) and name not in ("profile", "state")] == []


def test_each_connection_setting_has_a_window_label_and_ros1_asks_for_master_and_host():
    assert [setting.name for setting in link_kind("ros1").settings] == ["master", "host"]
    for entry in link_kinds():
        for setting in entry.settings:
            assert tr(setting.label, "en") != tr(setting.label, "de")
            assert all(tr(text, "en") != tr(text, "de") for _value, text in setting.choices if text)
        assert bool(entry.settings) == (entry.settings_group is not None) == (not entry.simulated)


def test_the_window_robot_box_lists_every_kind_in_its_language(qtbot):
    from rockly_desktop.ui.run.run_toolbar import RunToolbar

    toolbar = RunToolbar("de")
    qtbot.addWidget(toolbar)
    box = toolbar.backend
    assert [(box.itemText(i), box.itemData(i)) for i in range(box.count())] == [
        (tr(entry.name, "de"), entry.kind) for entry in link_kinds()]
    assert toolbar.reset_action.isEnabled()
    box.setCurrentIndex(box.findData("ros1"))
    assert not toolbar.reset_action.isEnabled()  # only the built-in simulator can be put back


def test_an_unknown_kind_is_refused_naming_the_known_ones(hobbit):
    for attempt in (lambda: link_kind("ros3"), lambda: open_link("ros3", hobbit),
                    lambda: check_available("ros3")):
        with pytest.raises(UnknownRobotLink) as caught:
            attempt()
        assert str(caught.value) == "there is no robot link 'ros3' (Rockly knows: sim, ros1, ros2)"
        assert isinstance(caught.value, RobotUnavailable)


def test_a_kind_that_cannot_serve_a_simulator_says_so(hobbit):
    with pytest.raises(RobotUnavailable, match="the robot link 'sim' cannot serve a simulator"):
        serve_simulator("sim", hobbit)


def test_ros1_without_rospy_is_unavailable_naming_the_set_up_step(monkeypatch, hobbit):
    monkeypatch.setitem(sys.modules, "rospy", None)  # what find_spec then says: not installed
    with pytest.raises(RobotUnavailable) as caught:
        open_link("ros1", hobbit, {"master": "http://127.0.0.1:9"})
    assert caught.value.reason == "no_rospy"
    assert "ROS 1 (rospy) is not installed on this computer" in str(caught.value)
    assert "make setup" in str(caught.value)
    for language in ("en", "de"):
        problem, next_step = robot_problem(caught.value, language)
        assert problem and "make setup" in next_step
    check_available("sim")  # the simulator is always there


def test_ros2_asks_for_domain_discovery_range_and_peers_with_its_own_options(monkeypatch):
    settings = link_kind("ros2").settings
    assert [(setting.name, setting.option) for setting in settings] == [
        ("domain_id", "--domain"), ("discovery", "--discovery"), ("peers", "--peers"),
        ("ros_distribution", "--ros-distro")]
    assert [value for value, _text in settings[1].choices] == ["localhost", "subnet", "off", "system_default"]
    monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    monkeypatch.setenv("ROS_DOMAIN_ID", "42")
    assert (settings[0].default_value(), settings[1].default_value()) == ("42", "localhost")
    args = cli._tool_parser().parse_args(["run", "p.rockly", "--backend", "ros2", "--domain", "7"])
    assert options.connection("ros2", args) == {"domain_id": "7", "discovery": None, "peers": None,
                                             "ros_distribution": None}
    assert [value for value, _text in settings[3].choices] == ["auto", "humble", "iron", "jazzy", "kilted", "rolling"]
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    assert settings[3].default_value() == "auto"
    monkeypatch.setenv("ROS_DISTRO", "Jazzy")
    assert settings[3].default_value() == "jazzy"
    monkeypatch.setenv("ROS_DISTRO", "noetic")  # a ROS 1 set-up's
    assert settings[3].default_value() == "auto"
    assert cli._tool_parser().parse_args(["sim", "turtlebot", "--ros2", "--domain", "7"]).serve_on == "ros2"


def test_ros2_without_its_environment_is_unavailable_naming_the_set_up_step(monkeypatch, tmp_path, hobbit):
    monkeypatch.setenv("ROCKLY_ROS2_PYTHON", str(tmp_path / "no-ros2" / "bin" / "python"))
    with pytest.raises(RobotUnavailable) as caught:
        open_link("ros2", hobbit, {"domain_id": "7"})
    assert caught.value.reason == "no_ros2" and "run 'make ros2' in Rockly's folder" in str(caught.value)
    for language in ("en", "de"):
        problem, next_step = robot_problem(caught.value, language)
        assert "ROS 2" in problem and "make ros2" in next_step


@pytest.mark.parametrize("connection, reason, named", [
    ({"domain_id": "233"}, "bad_domain", "233"), ({"domain_id": "seven"}, "bad_domain", "seven"),
    ({"discovery": "planet"}, "bad_discovery", "planet"), ({"ros_distribution": "foxy"}, "bad_distribution", "foxy")])
def test_a_ros2_setting_it_cannot_take_is_said_in_the_window_language(hobbit, connection, reason, named):
    with pytest.raises(RobotUnavailable) as caught:
        open_link("ros2", hobbit, connection)
    assert caught.value.reason == reason
    for language in ("en", "de"):
        problem, next_step = robot_problem(caught.value, language)
        assert named in problem and next_step


def test_the_command_line_offers_the_registry_kinds_and_their_options(monkeypatch):
    fake = LinkKind("fake", "rockly_desktop.robot.sim.link:SimulatedRobot", "backend_simulator", "a fake robot",
                    settings=(replace(link_kind("ros1").settings[0], name="where", option="--where"),),
                    settings_group="fake", sim_option="--fake", sim_server="rockly_desktop.robot.ros1.sim_bridge:x")
    monkeypatch.setitem(links.LINKS, "fake", fake)
    parser = cli._tool_parser()
    for entry in link_kinds():
        assert parser.parse_args(["run", "p.rockly", "--backend", entry.kind]).backend == entry.kind
    args = parser.parse_args(["run", "p.rockly", "--backend", "fake", "--where", "there"])
    assert options.connection("fake", args) == {"where": "there"}
    assert options.connection("ros1", parser.parse_args(["run", "p.rockly", "--master", "http://m:1"])) == {
        "master": "http://m:1"}
    assert parser.parse_args(["sim", "hobbit", "--fake"]).serve_on == "fake"
    assert parser.parse_args(["sim", "hobbit", "--ros"]).serve_on == "ros1"


def rockly(*args, prelude=""):
    code = f"import sys; {prelude}from rockly_desktop.cli import main; sys.exit(main(sys.argv[1:]))"
    return subprocess.run([sys.executable, "-c", code, *map(str, args)], capture_output=True, text=True,
                          timeout=120, cwd=REPO)


def test_run_with_an_unknown_backend_names_the_kinds_there_are(tmp_path):
    result = rockly("run", tmp_path / "p.rockly", "--backend", "ros3")
    assert result.returncode == 2
    assert "invalid choice: 'ros3' (choose from 'sim', 'ros1', 'ros2')" in result.stderr


def test_run_on_ros1_without_rospy_names_the_set_up_step(tmp_path):
    program = tmp_path / "p.rockly"
    program.write_text(rockly_document([block("text_print", id="p")]))
    result = rockly("run", program, "--backend", "ros1", prelude="sys.modules['rospy'] = None; ")
    assert result.returncode == 1
    assert result.stderr.startswith("rockly run: ROS 1 (rospy) is not installed on this computer: run `make setup`")


def test_the_simulator_link_opens_from_the_registry_and_needs_no_connection(hobbit):
    robot = open_link("sim", hobbit, speed=20)
    try:
        assert robot.kind == "sim" and robot.status() is None and robot.warnings() == []
        robot.follow_graph()  # nothing to start: its world fills the state store from the beginning
        assert ("/odom", "nav_msgs/Odometry", 1) in robot.graph_topics()
        link = robot.health()[0]
        assert (str(link.name), link.level) == ("simulator", GREEN)
        assert str(link.detail) == "the built-in simulator is running"
        assert link.detail.in_language("de") == "der eingebaute Simulator läuft"
        assert robot.snapshot() is not None and robot.safe_stop() == []
    finally:
        robot.shutdown()


def test_each_kind_names_its_recording_encoder_and_the_simulator_records_as_ros1(hobbit):
    """The registry chooses a link's encoder, so the simulator's link names no middleware itself."""
    encodings = {entry.kind: links.recording_encoder(entry.kind, hobbit) for entry in link_kinds()}
    assert {kind: encoder.message_encoding for kind, encoder in encodings.items()} == {
        "sim": "ros1", "ros1": "ros1", "ros2": "cdr"}


def test_an_encoder_whose_middleware_is_not_installed_records_as_json(monkeypatch, hobbit):
    monkeypatch.setitem(links.LINKS, "sim", replace(link_kind("sim"), recording_encoder="no_such_middleware:encoder"))
    assert links.recording_encoder("sim", hobbit) is None
    robot = SimulatedRobot(hobbit, speed=20)
    try:
        assert robot.recording_encoder() is None
    finally:
        robot.shutdown()
