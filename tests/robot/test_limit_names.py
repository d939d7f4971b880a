"""A teacher's limits compare names as the robot's middleware resolves them (``resolve_name``), not as written."""
import pytest

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld
from rockly_desktop.robot.wrappers.limits import Capability, LimitedBackend, Limits

ARM = Capability("arm", "Arm", topics=frozenset({"arm/command"}), services=frozenset({"arm/home"}),
                 actions=frozenset({"arm"}))


class RemappingRobot(SimBackend):
    """A simulated robot whose middleware resolves names as ROS does here: in the namespace /lab, with
    ``{ns}`` expanded and two remappings; it counts how often it is asked."""

    REMAPPED = {"/lab/teleop": "/lab/cmd_vel", "/lab/grab": "/lab/arm/command"}

    def __init__(self):
        super().__init__(SimWorld(), Interrupt())
        self.asked = []
        self.sent = []

    def resolve_name(self, name, kind="topics"):
        self.asked.append((kind, name))
        if " " in name:
            raise RobotCommandError(f"bad name {name}")
        name = name.replace("{ns}", "/lab/")
        resolved = name if name.startswith("/") else "/lab/" + name
        return self.REMAPPED.get(resolved, resolved)

    def publish(self, topic, msg_type, message):
        self.sent.append((topic, message))

    def call_service(self, name, srv_type, request, timeout):
        return {"called": name}


def limited(robot, limits, velocity_topics=("cmd_vel",), capabilities=(ARM,)):
    return LimitedBackend(robot, limits, velocity_topics, capabilities)


@pytest.mark.parametrize("name", ["cmd_vel", "{ns}cmd_vel", "teleop", "/lab/cmd_vel"])
def test_a_velocity_reaching_the_drive_topic_by_any_name_is_clamped(name):
    robot = RemappingRobot()
    limited(robot, Limits(max_speed=0.1)).publish(name, "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    assert robot.sent == [(name, {"linear": {"x": 0.1}})]


@pytest.mark.parametrize(("kind", "name"), [("topics", "grab"), ("topics", "{ns}arm/command"),
                                            ("services", "/lab/arm/home"), ("actions", "/lab/arm")])
def test_a_switched_off_capability_is_refused_by_any_name_that_reaches_it(kind, name):
    backend = limited(RemappingRobot(), Limits(switched_off=frozenset({"arm"})))
    with pytest.raises(RobotCommandError, match="switched off “Arm”"):
        if kind == "topics":
            backend.publish(name, "std_msgs/String", {"data": "grab"})
        elif kind == "services":
            backend.call_service(name, "std_srvs/Trigger", {}, 1.0)
        else:
            backend.send_goal(name, "lab_msgs/ArmAction", {})


def test_a_name_the_middleware_refuses_is_not_sent_under_a_limit():
    robot = RemappingRobot()
    with pytest.raises(RobotCommandError, match="bad name"):
        limited(robot, Limits(max_speed=0.1)).publish("cmd vel", "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    assert robot.sent == []


def test_each_name_is_resolved_once_and_without_limits_not_at_all():
    robot = RemappingRobot()
    backend = limited(robot, Limits(max_speed=0.1), capabilities=())
    for _ in range(3):
        backend.publish("{ns}cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    assert sorted(robot.asked) == [("topics", "cmd_vel"), ("topics", "{ns}cmd_vel")]
    open_robot = RemappingRobot()
    limited(open_robot, Limits()).publish("{ns}cmd_vel", "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    assert open_robot.asked == [] and open_robot.sent == [("{ns}cmd_vel", {"linear": {"x": 1.0}})]


def test_under_a_speed_limit_a_twist_is_clamped_on_any_topic():
    """A drive topic remapped where the manifest cannot know (``/mobile_base/cmd_vel``) is covered too."""
    robot = RemappingRobot()
    backend = limited(robot, Limits(max_speed=0.1))
    backend.publish("/mobile_base/cmd_vel", "geometry_msgs/msg/Twist", {"linear": {"x": 1.0}})
    backend.publish("/base/stamped", "geometry_msgs/TwistStamped", {"twist": {"linear": {"x": -2.0}}})
    backend.publish("/speech", "std_msgs/Float64", {"data": 3.0})
    assert [message for _topic, message in robot.sent] == [
        {"linear": {"x": 0.1}}, {"twist": {"linear": {"x": -0.1}}}, {"data": 3.0}]


def test_the_simulator_matches_names_exactly_so_its_rule_covers_what_reaches_a_topic():
    """On the built-in simulator only ``/cmd_vel`` itself reaches the robot's ``/cmd_vel``; its
    rule (one leading slash) also clamps the names that look like it."""
    world = SimWorld()
    seen = []
    world.subscribe("/cmd_vel", seen.append)
    backend = limited(SimBackend(world, Interrupt()), Limits(max_speed=0.1), velocity_topics=("/cmd_vel",))
    for name in ("/cmd_vel", "cmd_vel/", "{ns}cmd_vel", "~/cmd_vel"):
        backend.publish(name, "geometry_msgs/Twist", {"linear": {"x": 1.0}})
    assert seen == [{"linear": {"x": 0.1}}]
    assert backend.resolved("cmd_vel/") == "/cmd_vel"
