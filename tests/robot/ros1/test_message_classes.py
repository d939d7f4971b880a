"""Finding and generating ROS 1 message classes (robot/ros1/message_classes.py, message_generation.py)
on real files and real genpy.

No ROS master is needed. The reference for generated code is genpy's own catkin-style
command-line build (/usr/lib/genpy/genmsg_py.py and gensrv_py.py), run as subprocesses on
the same definition files and imported in a separate Python, so its packages never meet
the ones under test in sys.modules.
"""
import io
import json
import re
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from rockly_desktop.core.errors import RobotCommandError
from rockly_desktop.robot.ros1.message_classes import MessageTypes
from rockly_desktop.robot.ros1.message_generation import MessageDefinitionError, default_cache_dir, expand_action
from rockly_desktop.robot.ros1.message_values import to_message

REPO = Path(__file__).resolve().parents[3]
HOBBIT_MSG = REPO / "profiles" / "hobbit" / "msg"
SYSTEM_PYTHON = "/usr/bin/python3"
GENMSG_PY = "/usr/lib/genpy/genmsg_py.py"
GENSRV_PY = "/usr/lib/genpy/gensrv_py.py"
SHARE = Path("/usr/share")

# Published md5 sums of the standard types (the same in every ROS 1 distribution since Hydro).
MOVE_BASE_MD5 = {
    "MoveBaseAction": "70b6aca7c7f7746d8d1609ad94c80bb8",
    "MoveBaseActionGoal": "660d6895a1b9a16dce51fbdd9a64a56b",
    "MoveBaseGoal": "257d089627d7eb7136c24d3593d05a16",
}
ODOMETRY_MD5 = "cd5e73d190d741a2f92e81eda573aca7"

ARM_SERVER = [f"ArmServer{suffix}" for suffix in
              ("Action", "Goal", "ActionGoal", "Result", "ActionResult", "Feedback", "ActionFeedback")]


# -- the reference: genpy's command-line build ------------------------------------------------------

def command_line_build(definitions: Path, package: str, out: Path, work: Path) -> Path:
    """Build ``package`` from ``definitions/<package>`` the catkin way into ``out``: actions
    expanded to .msg files (genaction's expansion, checked against Debian's own output below),
    then genmsg_py.py, gensrv_py.py and --initpy as subprocesses."""
    source = definitions / package
    expanded = work / f"{package}-expanded"
    expanded.mkdir(parents=True)
    for action in sorted((source / "action").glob("*.action")):
        for name, text in expand_action(action.stem, action.read_text()).items():
            (expanded / f"{name}.msg").write_text(text)
    includes = ["-I", f"{package}:{source / 'msg'}", "-I", f"{package}:{expanded}"]
    for dependency in ("std_msgs", "geometry_msgs", "actionlib_msgs"):
        includes += ["-I", f"{dependency}:{SHARE / dependency / 'msg'}"]
    msg_files = sorted((source / "msg").glob("*.msg")) + sorted(expanded.glob("*.msg"))
    srv_files = sorted((source / "srv").glob("*.srv"))
    package_dir = out / package
    for script, kind, files in ((GENMSG_PY, "msg", msg_files), (GENSRV_PY, "srv", srv_files)):
        if files:
            run([SYSTEM_PYTHON, script, "-p", package, "-o", str(package_dir / kind), *includes, *map(str, files)])
            run([SYSTEM_PYTHON, script, "--initpy", "-p", package, "-o", str(package_dir / kind)])
    (package_dir / "__init__.py").write_text("")
    return out


def run(command):
    result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, f"{command}\n{result.stdout}\n{result.stderr}"
    return result.stdout


def describe_in_fresh_python(root: Path, names: list) -> dict:
    """``{"pkg.kind.Name": {md5, full_text, file}}`` for classes imported from ``root`` by Debian's Python."""
    script = textwrap.dedent(f"""
        import importlib, json, sys
        sys.path.insert(0, {str(root)!r})
        out = {{}}
        for dotted in {names!r}:
            module, name = dotted.rsplit(".", 1)
            cls = getattr(importlib.import_module(module), name)
            out[dotted] = {{"md5": cls._md5sum, "full_text": getattr(cls, "_full_text", None),
                            "file": sys.modules[cls.__module__].__file__}}
        print(json.dumps(out))
    """)
    described = json.loads(run([SYSTEM_PYTHON, "-c", script]))
    for dotted, info in described.items():
        assert info["file"].startswith(str(root)), f"{dotted} came from {info['file']}, not the reference build"
    return described


def installed_in_fresh_python(package: str) -> bool:
    return subprocess.run([SYSTEM_PYTHON, "-c", f"import {package}.msg"], capture_output=True).returncode == 0


def generated_root(cls) -> Path:
    """The cache folder a generated class was imported from."""
    return Path(sys.modules[cls.__module__].__file__).parents[2]


# -- fixtures ----------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def cache(tmp_path_factory):
    return tmp_path_factory.mktemp("ros1-cache")


@pytest.fixture(scope="module")
def types(cache):
    """HOBBIT's definitions, generated into this module's cache."""
    return MessageTypes([HOBBIT_MSG], cache_dir=cache)


@pytest.fixture(scope="module")
def hobbit_reference(tmp_path_factory):
    work = tmp_path_factory.mktemp("hobbit-reference")
    root = command_line_build(HOBBIT_MSG, "hobbit_msgs", work / "out", work)
    names = ([f"hobbit_msgs.msg.{n}" for n in ["Parameter", "arm_joints"] + ARM_SERVER]
             + [f"hobbit_msgs.srv.{n}" for n in ("Request", "RequestRequest", "RequestResponse")])
    return describe_in_fresh_python(root, names)


@pytest.fixture
def hobbit_copy(tmp_path):
    """A copy of HOBBIT's definitions to edit or break."""
    return Path(shutil.copytree(HOBBIT_MSG, tmp_path / "msg"))


def roundtrip(msg):
    """Serialize and deserialize with genpy, as rospy does on the wire."""
    buffer = io.BytesIO()
    msg.serialize(buffer)
    copy = type(msg)()
    copy.deserialize(buffer.getvalue())
    return copy


# -- generation and the md5 sums ------------------------------------------------------------------

def test_hobbit_msgs_generate_into_the_cache_and_import(types, cache):
    parameter = types.message_class("hobbit_msgs/Parameter")
    assert parameter._type == "hobbit_msgs/Parameter" and parameter.__slots__ == ["name", "value"]
    assert types.message_class("hobbit_msgs/arm_joints")._slot_types == ["float32[6]"]
    request = types.service_class("hobbit_msgs/Request")
    assert request._request_class._slot_types == ["std_msgs/Header", "string", "string", "hobbit_msgs/Parameter[]"]
    assert request._response_class.__slots__ == ["params"]
    arm = types.action_classes("hobbit_msgs/ArmServerAction")
    assert arm == types.action_classes("hobbit_msgs/ArmServer")
    assert arm.goal.__slots__ == ["command", "velocity", "joints"]
    assert arm.action.__slots__ == ["action_goal", "action_result", "action_feedback"]
    assert arm.action_goal._type == "hobbit_msgs/ArmServerActionGoal"
    action, goal, result, feedback = arm  # what actionlib needs, in that order
    assert (result._type, feedback._type) == ("hobbit_msgs/ArmServerResult", "hobbit_msgs/ArmServerFeedback")
    root = generated_root(parameter)
    assert root.parent == cache and root.name.startswith("hobbit_msgs-")
    assert generated_root(request) == root == generated_root(action)


def test_hobbit_md5_sums_and_full_texts_equal_genpys_command_line_build(types, hobbit_reference):
    ours = {f"hobbit_msgs.msg.{n}": types.message_class(f"hobbit_msgs/{n}")
            for n in ["Parameter", "arm_joints"] + ARM_SERVER}
    service = types.service_class("hobbit_msgs/Request")
    ours.update({"hobbit_msgs.srv.Request": service, "hobbit_msgs.srv.RequestRequest": service._request_class,
                 "hobbit_msgs.srv.RequestResponse": service._response_class})
    assert set(ours) == set(hobbit_reference)
    for dotted, cls in ours.items():
        assert cls._md5sum == hobbit_reference[dotted]["md5"], dotted
        assert getattr(cls, "_full_text", None) == hobbit_reference[dotted]["full_text"], dotted
    arm = types.action_classes("hobbit_msgs/ArmServer")
    for suffix, cls in (("Action", arm.action), ("ActionGoal", arm.action_goal), ("ActionResult", arm.action_result),
                        ("ActionFeedback", arm.action_feedback), ("Goal", arm.goal)):
        assert cls._md5sum == hobbit_reference[f"hobbit_msgs.msg.ArmServer{suffix}"]["md5"]


def test_move_base_msgs_shipped_by_the_profile_match_the_command_line_build_and_the_real_type(tmp_path):
    # The machine may have move_base_msgs installed (then it is used, see the next test): the
    # profile's file is checked under another package name, which md5 sums do not depend on.
    package = "rockly_check_move_base_msgs"
    definitions = tmp_path / "defs"
    shutil.copytree(HOBBIT_MSG / "move_base_msgs", definitions / package)
    reference = describe_in_fresh_python(
        command_line_build(definitions, package, tmp_path / "out", tmp_path),
        [f"{package}.msg.MoveBase{suffix}" for suffix in
         ("Action", "Goal", "ActionGoal", "Result", "ActionResult", "Feedback", "ActionFeedback")])
    types = MessageTypes([definitions], cache_dir=tmp_path / "cache")
    move_base = types.action_classes(f"{package}/MoveBaseAction")
    assert generated_root(move_base.action).parent == tmp_path / "cache"
    classes = {"Action": move_base.action, "Goal": move_base.goal, "Result": move_base.result,
               "Feedback": move_base.feedback, "ActionGoal": move_base.action_goal,
               "ActionResult": move_base.action_result, "ActionFeedback": move_base.action_feedback}
    for suffix, cls in classes.items():
        expected = reference[f"{package}.msg.MoveBase{suffix}"]
        assert (cls._md5sum, cls._full_text) == (expected["md5"], expected["full_text"]), suffix
    for name, md5 in MOVE_BASE_MD5.items():
        assert classes[name[len("MoveBase"):]]._md5sum == md5, name
    assert move_base.goal._slot_types == ["geometry_msgs/PoseStamped"]


def test_move_base_comes_from_the_machine_when_installed_else_from_the_profile(types, cache):
    move_base = types.action_classes("move_base_msgs/MoveBaseAction")
    module_file = Path(sys.modules[move_base.action.__module__].__file__)
    if installed_in_fresh_python("move_base_msgs"):
        assert cache not in module_file.parents
        assert "installed Python package move_base_msgs" in types.prepare()["move_base_msgs"]
    else:
        assert generated_root(move_base.action).parent == cache
    assert move_base.action._md5sum == MOVE_BASE_MD5["MoveBaseAction"]
    assert move_base.action_goal._md5sum == MOVE_BASE_MD5["MoveBaseActionGoal"]
    assert move_base.goal._md5sum == MOVE_BASE_MD5["MoveBaseGoal"]


def test_installed_packages_resolve_from_the_system(types, cache):
    import geometry_msgs.msg
    import std_msgs.msg

    assert types.message_class("std_msgs/String") is std_msgs.msg.String
    assert types.message_class("geometry_msgs/Twist") is geometry_msgs.msg.Twist
    assert types.message_class("Header") is std_msgs.msg.Header
    assert not any(cache in Path(p).parents for p in (std_msgs.msg.__file__, geometry_msgs.msg.__file__))


def test_installed_definitions_without_python_code_are_generated(types, cache):
    # Debian's ros-nav-msgs ships /usr/share/nav_msgs without Python (python3-nav-msgs is avoided).
    odometry = types.message_class("nav_msgs/Odometry")
    assert odometry._md5sum == ODOMETRY_MD5
    if not installed_in_fresh_python("nav_msgs"):
        assert generated_root(odometry).parent == cache


def test_action_expansion_is_genactions_byte_for_byte():
    # Debian's ros-nav-msgs ships genaction's output for GetMap.action next to it.
    action = SHARE / "nav_msgs" / "action" / "GetMap.action"
    expanded = expand_action("GetMap", action.read_text())
    assert len(expanded) == 7
    for name, text in expanded.items():
        assert (SHARE / "nav_msgs" / "msg" / f"{name}.msg").read_text() == text, name


def test_actions_match_debians_catkin_built_actionlib_test_action(tmp_path):
    import actionlib.msg

    # actionlib's TwoInts.action, as its generated Goal/Result/Feedback full texts show it.
    (tmp_path / "defs" / "rockly_twoints_msgs" / "action").mkdir(parents=True)
    (tmp_path / "defs" / "rockly_twoints_msgs" / "action" / "TwoInts.action").write_text(
        "int64 a\nint64 b\n---\nint64 sum\n---\n")
    types = MessageTypes([tmp_path / "defs"], cache_dir=tmp_path / "cache")
    ours = types.action_classes("rockly_twoints_msgs/TwoInts")
    for field in ("action", "goal", "result", "feedback", "action_goal", "action_result", "action_feedback"):
        cls = getattr(ours, field)
        debian = getattr(actionlib.msg, cls.__name__)
        assert cls._md5sum == debian._md5sum, field
        assert cls._full_text.replace("rockly_twoints_msgs/", "actionlib/") == debian._full_text, field


# -- cache ----------------------------------------------------------------------------------------

def test_the_cache_is_reused_and_an_edit_regenerates(hobbit_copy, tmp_path):
    cache = tmp_path / "cache"
    first = MessageTypes([hobbit_copy], cache_dir=cache).message_class("hobbit_msgs/Parameter")
    first_root = generated_root(first)
    generated_file = first_root / "hobbit_msgs" / "msg" / "_Parameter.py"
    stamp = generated_file.stat().st_mtime_ns

    again = MessageTypes([hobbit_copy], cache_dir=cache).message_class("hobbit_msgs/Parameter")
    assert generated_root(again) == first_root and generated_file.stat().st_mtime_ns == stamp

    (hobbit_copy / "hobbit_msgs" / "msg" / "Parameter.msg").write_text("string name\nstring value\nstring unit\n")
    edited_types = MessageTypes([hobbit_copy], cache_dir=cache)
    edited = edited_types.message_class("hobbit_msgs/Parameter")
    assert generated_root(edited) != first_root
    assert edited.__slots__ == ["name", "value", "unit"]
    assert edited._md5sum != first._md5sum
    # what uses Parameter is regenerated with it
    request = edited_types.service_class("hobbit_msgs/Request")
    assert to_message(request._request_class, {"params": [{"unit": "s"}]}).params[0].unit == "s"
    # classes handed out before keep working
    assert first.__slots__ == ["name", "value"] and roundtrip(to_message(first, {"name": "a"})).name == "a"


def test_the_default_cache_is_under_xdg_cache_home(tmp_path, monkeypatch):
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg-cache"))
    assert default_cache_dir() == tmp_path / "xdg-cache" / "rockly" / "ros1_messages"
    types = MessageTypes([HOBBIT_MSG])
    assert types.cache_dir == tmp_path / "xdg-cache" / "rockly" / "ros1_messages"
    arm_joints = types.message_class("hobbit_msgs/arm_joints")
    assert generated_root(arm_joints).parent == types.cache_dir


# -- errors -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("lookup, type_name", [
    ("message_class", "hobbit_msgs/Nope"),
    ("message_class", "nosuch_msgs/Thing"),
    ("message_class", "std_msgs/Nope"),
    ("service_class", "hobbit_msgs/Parameter"),
    ("action_classes", "hobbit_msgs/Request"),
    ("action_classes", "nosuch_msgs/Fly"),
])
def test_a_missing_type_names_it_and_where_it_looked(types, lookup, type_name):
    with pytest.raises(RobotCommandError) as caught:
        getattr(types, lookup)(type_name)
    message = str(caught.value)
    assert f"'{type_name}'" in message
    package = type_name.split("/")[0]
    if package == "nosuch_msgs":
        assert str(HOBBIT_MSG) in message and "/usr/share" in message and "installed Python packages" in message
    elif package == "hobbit_msgs":
        assert str(HOBBIT_MSG / "hobbit_msgs") in message
    else:
        assert "installed Python package std_msgs" in message


def test_a_type_name_must_be_package_slash_name(types):
    with pytest.raises(RobotCommandError, match="'Twist' is not a ROS message type name"):
        types.message_class("Twist")


@pytest.mark.parametrize("file, text, problem", [
    ("msg/arm_joints.msg", "flaot64[6] joint_values\n", "unknown type hobbit_msgs/flaot64"),
    ("msg/Parameter.msg", "string\n", "Invalid declaration: string"),
    ("srv/Request.srv", "Header header\nfoo_msgs/Thing thing\n---\n", "unknown type foo_msgs/Thing"),
    ("action/ArmServer.action", "string command\n---\nbool result\n", "three parts"),
    ("action/ArmServer.action", "string command\n---\nint32 LIMIT = lots\n---\n", "ArmServerResult"),
])
def test_a_broken_definition_names_the_file(hobbit_copy, tmp_path, file, text, problem):
    broken = hobbit_copy / "hobbit_msgs" / file
    broken.write_text(text)
    types = MessageTypes([hobbit_copy], cache_dir=tmp_path / "cache")
    with pytest.raises(MessageDefinitionError) as caught:
        types.message_class("hobbit_msgs/Parameter")
    assert isinstance(caught.value, RobotCommandError)
    assert caught.value.path == str(broken)
    assert str(caught.value).startswith(f"{broken}: ") and problem in str(caught.value)
    with pytest.raises(MessageDefinitionError, match=problem):
        MessageTypes([hobbit_copy], cache_dir=tmp_path / "cache").prepare()
    assert not [p for p in (tmp_path / "cache").glob("hobbit_msgs-*")]  # nothing half-made is left


def test_a_missing_definitions_folder_is_named(tmp_path):
    with pytest.raises(MessageDefinitionError, match=re.escape(f"{tmp_path / 'nowhere'}: ") + ".*does not exist"):
        MessageTypes([tmp_path / "nowhere"], cache_dir=tmp_path / "cache")


def test_a_cache_that_cannot_be_written_is_named(tmp_path):
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    types = MessageTypes([HOBBIT_MSG], cache_dir=blocker / "cache")
    expected = re.escape(f"Cannot write generated ROS message code to {blocker / 'cache'}")
    with pytest.raises(RobotCommandError, match=expected):
        types.message_class("hobbit_msgs/Parameter")
