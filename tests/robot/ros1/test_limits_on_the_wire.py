"""A teacher's limits hold on the ROS 1 wire, seen by an independent plain rospy node (tests/wire_recorder.py):
no velocity of another type, no goal of a switched-off arm by its action's topic, no motion at the
robot's own speed under a lower limit."""
import struct

import pytest
from profile_copies import copy_profile
from waiting import eventually
from wire_recorder import WireRecorder

from rockly_desktop.executor.control import RunControl
from rockly_desktop.executor.run_setup import make_runner
from rockly_desktop.robot.wrappers.limits import Limits

ARM_GOAL = "ros.publish_message('/hobbit_arm/goal', 'hobbit_msgs/ArmServerActionGoal', " \
           "{'goal': {'command': {'data': '%s'}}})\n"


def run(profile, robot, code, limits):
    return make_runner(profile, robot, {"code": code, "variables": {}}, RunControl(), lambda event: None,
                       "en", limits).run()


@pytest.fixture
def recorder(ros_master):
    made = []

    def start(*topics):
        made.append(WireRecorder(ros_master, topics))
        return made[-1]

    yield start
    for recorder in made:
        recorder.stop()


@pytest.fixture
def lab_robot(tmp_path, ros_master, hobbit_on_ros):
    """HOBBIT's profile copied with a lab's own lab_msgs/Twist (a Twist's fields) and drive topic /lab/cmd_vel."""
    from rockly_desktop.core.paths import shared_toolboxes_dir
    from rockly_desktop.profiles.profile import load_profile
    from rockly_desktop.robot.ros1.link import RosRobot

    copy = copy_profile(tmp_path / "labbot", "labbot")
    (copy.root / "rockly_hobbit").rename(copy.root / "rockly_labbot")  # one module name, one profile per process
    copy.edit("profile.yaml", lambda data: data.update({field: data[field].replace("rockly_hobbit", "rockly_labbot")
                                                        for field in ("api", "simulator", "simulator_view")}))
    folder = copy.path("msg") / "lab_msgs" / "msg"
    folder.mkdir(parents=True)
    (folder / "Twist.msg").write_text("geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n")
    copy.edit("profile.yaml", lambda data: data.update(velocity_topics=["/lab/cmd_vel"]))
    profile = load_profile(copy.root, shared_toolboxes_dir())
    return profile, RosRobot(profile, ros_master.uri)


def test_a_velocity_of_a_labs_own_type_never_reaches_the_wire_above_the_limit(lab_robot, recorder):
    profile, robot = lab_robot
    wire = recorder("/lab/cmd_vel")
    fast = "ros.publish_message('/lab/cmd_vel', 'lab_msgs/Twist', {'linear': {'x': 1.0}})\n"
    result = run(profile, robot, fast, Limits(max_speed=0.1))
    assert result.outcome == "error"
    assert "can only be kept on /lab/cmd_vel for geometry_msgs/Twist" in result.message
    assert run(profile, robot, fast, None).outcome == "finished"  # without a limit it goes: the wire is heard
    eventually(lambda: wire.on("/lab/cmd_vel"))
    assert [(msg_type, struct.unpack("<6d", data)[0]) for msg_type, data in wire.on("/lab/cmd_vel")] == [
        ("lab_msgs/Twist", 1.0)]


def test_a_speed_as_text_is_refused_on_ros_1_too(ros_robot, hobbit, recorder):
    wire = recorder("/cmd_vel")
    code = "robot.backend.publish('/cmd_vel', 'geometry_msgs/Twist', {'linear': {'x': '1.0'}})\n"
    result = run(hobbit, ros_robot, code, Limits(max_speed=0.1))
    assert result.message.endswith("the teacher's speed limit needs real numbers on /cmd_vel: linear.x is '1.0'")
    eventually(lambda: wire.on("/cmd_vel"))  # the safe stop's zero velocity
    assert all(struct.unpack("<6d", data) == (0.0,) * 6 for _type, data in wire.on("/cmd_vel"))


def test_a_switched_off_arm_gets_no_goal_by_its_action_topic(ros_robot, hobbit, recorder):
    wire = recorder("/hobbit_arm/goal")
    result = run(hobbit, ros_robot, ARM_GOAL % "MoveToCandle", Limits(switched_off=frozenset({"arm"})))
    assert result.message.endswith("the teacher switched off “Arm and gripper” for this robot")
    for name, kind in (("/hobbit_arm/_action/send_goal", "call_service"), ("hobbit_arm/goal/", "publish")):
        code = (f"robot.backend.call_service('{name}', 'x/Y', {{}}, 1)\n" if kind == "call_service"
                else f"robot.backend.publish('{name}', 'hobbit_msgs/ArmServerActionGoal', {{}})\n")
        assert "Arm and gripper" in run(hobbit, ros_robot, code, Limits(switched_off=frozenset({"arm"}))).message
    assert run(hobbit, ros_robot, ARM_GOAL % "MoveToHome", None).outcome == "finished"
    eventually(lambda: wire.on("/hobbit_arm/goal"))
    assert [msg_type for msg_type, _data in wire.on("/hobbit_arm/goal")] == ["hobbit_msgs/ArmServerActionGoal"]
    assert b"MoveToHome" in wire.on("/hobbit_arm/goal")[0][1]


def test_no_motion_at_the_bases_own_speed_goes_out_under_a_lower_limit(ros_robot, hobbit, recorder):
    wire = recorder("/DiscreteMotionCmd", "/move_base/goal", "/move_base_simple/goal")
    limits = Limits(max_speed=0.1)
    for code in ("robot.publish('/DiscreteMotionCmd', 'String', 'Move 0.05')\n",
                 "ros.publish('/DiscreteMotionCmd', 'String', 'Turn 5')\n",
                 "ros.send_goal('move_base', 'move_base_msgs/MoveBaseAction', "
                 "{'target_pose': {'header': {'frame_id': 'map'}, 'pose': {'position': {'x': 3.7, 'y': 1.2}}}})\n",
                 "robot.backend.publish('/move_base_simple/goal', 'geometry_msgs/PoseStamped', {})\n"):
        result = run(hobbit, ros_robot, code, limits)
        assert result.outcome == "error" and "at its own speed" in result.message, code
    eventually(lambda: wire.on("/DiscreteMotionCmd"))  # the safe stops' Stop, which always passes
    assert {data[4:] for _type, data in wire.on("/DiscreteMotionCmd")} == {b"Stop"}
    assert wire.on("/move_base/goal") == [] and wire.on("/move_base_simple/goal") == []
