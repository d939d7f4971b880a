"""ROS definitions read as text: the fields typed blocks offer, from real files on disk."""
from pathlib import Path

import pytest

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.core.ros_definitions import DefinitionCatalog, FieldInput, installed_definition_dirs


def write(root, relative, text):
    path = root / relative
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")


@pytest.fixture
def folders(tmp_path):
    own, installed = tmp_path / "own", tmp_path / "installed"
    write(own, "robo_msgs/msg/Wheel.msg", "# a wheel\nfloat64 speed  # m/s\nbool enabled\nuint8 LEFT=0\nstring  name\n")
    write(own, "robo_msgs/msg/Cart.msg",
          "Header header\nWheel left\nrobo_msgs/Wheel right\nWheel[] spares\nfloat32[4] load\nother_msgs/Tag tag\n"
          "missing_msgs/Ghost ghost\ntime started\n")
    write(own, "robo_msgs/srv/Park.srv", "string spot\nint32 tries\n---\nbool parked\n")
    write(own, "robo_msgs/action/Fetch.action", "string item\n---\nbool found\n---\nfloat32 progress\n")
    write(installed, "std_msgs/msg/Header.msg", "uint32 seq\ntime stamp\nstring frame_id\n")
    write(installed, "std_msgs/msg/Bool.msg", "bool data\n")
    write(installed, "other_msgs/msg/Tag.msg", "string label\n")
    return own, installed


def test_nested_fields_flatten_to_paths_with_the_editors_checks(folders):
    catalog = DefinitionCatalog([folders[0]], installed_dirs=[folders[1]])
    assert [(f.path, f.check) for f in catalog.fields("robo_msgs/Cart")] == [
        ("header.stamp", "Number"), ("header.frame_id", "String"),           # seq is ROS's own business
        ("left.speed", "Number"), ("left.enabled", "Boolean"), ("left.name", "String"),
        ("right.speed", "Number"), ("right.enabled", "Boolean"), ("right.name", "String"),
        ("load", "Array"),                                                    # messages in a list cannot be built
        ("tag.label", "String"),                                              # found in another package
        ("started", "Number"),                                                # unknown types are left out
    ]
    assert catalog.fields("robo_msgs/Cart")[8] == FieldInput("load", "float32[]", "Array")
    assert catalog.fields("robo_msgs/Cart")[2] == FieldInput("left.speed", "float64", "Number", 0)


def test_a_service_offers_its_request_and_an_action_its_goal(folders):
    catalog = DefinitionCatalog([folders[0]], installed_dirs=[folders[1]])
    assert [f.path for f in catalog.fields("robo_msgs/Park", "srv")] == ["spot", "tries"]
    assert [f.path for f in catalog.fields("robo_msgs/FetchAction", "action")] == ["item"]
    assert catalog.fields("robo_msgs/Nothing") == [] and catalog.fields("nonsense") == []


def test_the_editor_catalog_offers_the_profiles_packages_and_the_common_ones(folders):
    catalog = DefinitionCatalog([folders[0]], installed_dirs=[folders[1]]).editor_catalog
    assert sorted(catalog["messages"]) == ["robo_msgs/Cart", "robo_msgs/Wheel", "std_msgs/Bool", "std_msgs/Header"]
    assert catalog["messages"]["std_msgs/Bool"] == [["data", "Boolean", False]]
    assert catalog["services"] == {"robo_msgs/Park": [["spot", "String", ""], ["tries", "Number", 0]]}
    assert catalog["actions"] == {"robo_msgs/FetchAction": [["item", "String", ""]]}


def test_a_profiles_own_package_wins_over_an_installed_one_of_the_same_name(folders, tmp_path):
    write(folders[1], "robo_msgs/msg/Wheel.msg", "int8 different\n")
    catalog = DefinitionCatalog([folders[0]], installed_dirs=[folders[1]])
    assert [f.path for f in catalog.fields("robo_msgs/Wheel")] == ["speed", "enabled", "name"]


def test_the_installed_common_packages_are_found(monkeypatch):
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    catalog = DefinitionCatalog()
    scan = {f.path: f.check for f in catalog.fields("sensor_msgs/LaserScan")}
    assert scan["ranges"] == "Array" and scan["angle_min"] == "Number" and scan["header.frame_id"] == "String"
    assert [f.path for f in catalog.fields("geometry_msgs/Twist")] == [
        "linear.x", "linear.y", "linear.z", "angular.x", "angular.y", "angular.z"]
    assert {"std_srvs/Trigger", "std_srvs/SetBool"} <= set(catalog.editor_catalog["services"])
    pose = {f.path: f.start for f in catalog.fields("geometry_msgs/PoseStamped")}
    assert pose["pose.orientation.w"] == 1 and pose["pose.orientation.z"] == 0   # a valid "no rotation"


def test_ros_package_path_comes_before_the_system_folder(monkeypatch, tmp_path):
    monkeypatch.setenv("ROS_PACKAGE_PATH", f"{tmp_path / 'a'}:{tmp_path / 'b'}:{tmp_path / 'a'}")
    assert installed_definition_dirs() == [tmp_path / "a", tmp_path / "b", Path("/usr/share")]


def test_ros2_definitions_with_bounds_defaults_and_constants(tmp_path):
    write(tmp_path, "robo2_msgs/msg/Light.msg",
          "# ROS 2 syntax\nuint8 RED=1\nstring NAME_CONST=\"a # not a comment\"\n"
          "string<=8 label \"lamp\"  # a bounded string with a default\nfloat64 brightness 0.5\n"
          "bool on true\nint32[<=3] pattern [1, 2]\nfloat32[2] size\nwstring note\n"
          "builtin_interfaces/Time since\n")
    write(tmp_path, "builtin_interfaces/msg/Time.msg", "int32 sec\nuint32 nanosec\n")
    catalog = DefinitionCatalog([], installed_dirs=[tmp_path], packages=("robo2_msgs",))
    assert [(f.path, f.check, f.start) for f in catalog.fields("robo2_msgs/Light")] == [
        ("label", "String", "lamp"), ("brightness", "Number", 0.5), ("on", "Boolean", True),
        ("pattern", "Array", [1, 2]), ("size", "Array", None), ("note", "String", ""),
        ("since.sec", "Number", 0), ("since.nanosec", "Number", 0)]
    catalog.check("robo2_msgs/Light", "msg", {"label": "desk", "pattern": [1, 2, 3]})
    with pytest.raises(RobotCommandError, match="label holds at most 8 characters"):
        catalog.check("robo2_msgs/Light", "msg", {"label": "a long lamp"})
    with pytest.raises(RobotCommandError, match="pattern holds at most 3 items"):
        catalog.check("robo2_msgs/Light", "msg", {"pattern": [1, 2, 3, 4]})
