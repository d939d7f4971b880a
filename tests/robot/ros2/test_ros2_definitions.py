"""The typed ROS blocks' types on ROS 2: read from the ROS 2 environment's installed interface packages."""
from rockly_desktop.core.ros_definitions import COMMON_PACKAGES, DefinitionCatalog
from rockly_desktop.robot.ros2.environment import ros2_definition_dirs


def test_the_ros2_environments_definitions_give_the_typed_blocks_their_fields(ros2_settings):
    catalog = DefinitionCatalog([], installed_dirs=ros2_definition_dirs(), packages=COMMON_PACKAGES + ("test_msgs",))
    assert [(f.path, f.check) for f in catalog.fields("geometry_msgs/TwistStamped")][:4] == [
        ("header.stamp.sec", "Number"), ("header.stamp.nanosec", "Number"), ("header.frame_id", "String"),
        ("twist.linear.x", "Number")]
    assert [(f.path, f.start) for f in catalog.fields("test_msgs/Defaults")][:2] == [
        ("bool_value", True), ("byte_value", 50)]
    assert [f.path for f in catalog.fields("std_srvs/SetBool", "srv")] == ["data"]
    assert [f.path for f in catalog.fields("test_msgs/FibonacciAction", "action")] == ["order"]
    assert "sensor_msgs/BatteryState" in catalog.editor_catalog["messages"]
