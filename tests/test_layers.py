"""The layering contracts in pyproject.toml hold, and they do catch a violation."""
import ast
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rockly_desktop.core.python_syntax import parse_python

REPO = Path(__file__).resolve().parents[1]
LINT_IMPORTS = Path(sys.executable).with_name("lint-imports")


def lint_imports(cwd: Path):
    return subprocess.run([str(LINT_IMPORTS), "--no-cache"], capture_output=True, text=True, cwd=cwd,
                          env={"PYTHONPATH": str(cwd), "PATH": "/usr/bin:/bin"}, timeout=120)


def copy_of_rockly(folder: Path):
    """Rockly's package and its contracts (with the contract types of its own), copied into ``folder`` to
    break a contract there."""
    for package in ("rockly_desktop", "tools"):
        shutil.copytree(REPO / package, folder / package, ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(REPO / "pyproject.toml", folder)


def append_to(module: Path, text: str):
    """Add ``text`` at the end of the copied ``module`` (a function importing what it must not, say)."""
    module.write_text(module.read_text(encoding="utf-8") + text, encoding="utf-8")


def broken_contracts(folder: Path) -> str:
    """What lint-imports says of the copy in ``folder``, whose contracts must break (on one line)."""
    result = lint_imports(folder)
    assert result.returncode == 1, result.stdout + result.stderr
    return " ".join(result.stdout.split())


def test_layer_contracts_are_kept():
    result = lint_imports(REPO)
    assert result.returncode == 0, result.stdout + result.stderr
    contracts = (REPO / "pyproject.toml").read_text(encoding="utf-8").count("[[tool.importlinter.contracts]]")
    assert f"Contracts: {contracts} kept, 0 broken." in result.stdout


def test_a_core_module_importing_qt_breaks_the_contracts(tmp_path):
    copy_of_rockly(tmp_path)
    (tmp_path / "rockly_desktop" / "core" / "sneaky.py").write_text(
        "from PySide6.QtWidgets import QWidget\nfrom rockly_desktop.ui import main_window\n")
    result = lint_imports(tmp_path)
    assert result.returncode == 1
    assert "rockly_desktop.core.sneaky -> rockly_desktop.ui.main_window" in result.stdout
    assert "BROKEN" in result.stdout


@pytest.mark.parametrize("wing, reach", [
    ("agent", "rockly_desktop.ui.run.run_session"),
    ("blockmaker", "rockly_desktop.robot.links"),
    ("docks", "rockly_desktop.ui.run.run_session"),
    ("files", "rockly_desktop.executor.runner"),
    ("kiosk", "rockly_desktop.ui.replay.replay"),
    ("preferences", "rockly_desktop.bridge.editor_view"),
    ("replay", "rockly_desktop.ui.kiosk.kiosk"),
    ("robot", "rockly_desktop.ui.files.program_files"),
    ("run", "rockly_desktop.ui.main_window"),
])
def test_a_ui_wing_using_what_its_contract_does_not_name_breaks_it(tmp_path, wing, reach):
    """Each of ui/'s wings has a contract of its own naming what it may use; reaching past it is caught."""
    copy_of_rockly(tmp_path)
    (tmp_path / "rockly_desktop" / "ui" / wing / "sneaky.py").write_text(f"import {reach}\n")
    output = broken_contracts(tmp_path)
    assert f"ui.{wing} uses only" in output and f"rockly_desktop.ui.{wing}.sneaky -> {reach}" in output
    assert ", 1 broken." in output


RUNTIME_CONTRACT = ("The runtime (rockly-runtime) never imports Qt, the window or Blockly's bridge, directly or "
                    "indirectly")
QT_ADAPTER_CONTRACT = ("Only the window (ui) uses the runner's Qt adapter (executor.qt_adapter), which rockly-runtime "
                       "leaves out")


@pytest.mark.parametrize("where, sneaky, caught, contract", [
    # indirectly: through a module outside the runtime that imports Qt itself (the other contracts allow that)
    ("runtime", "from rockly_desktop.settings import app_settings\n",
     "rockly_desktop.runtime.sneaky -> rockly_desktop.settings.app_settings", RUNTIME_CONTRACT),
    ("robot", "from rockly_desktop import sim_command\n", "rockly_desktop.robot.sneaky -> rockly_desktop.sim_command",
     RUNTIME_CONTRACT),
    ("executor", "from rockly_desktop.executor import qt_adapter\n",
     "rockly_desktop.executor.sneaky -> rockly_desktop.executor.qt_adapter", QT_ADAPTER_CONTRACT),
])
def test_the_runtime_reaching_qt_even_indirectly_breaks_its_contract(tmp_path, where, sneaky, caught, contract):
    """What rockly-runtime installs never imports Qt, not even through a module that is not its own."""
    copy_of_rockly(tmp_path)
    (tmp_path / "rockly_desktop" / where / "sneaky.py").write_text(sneaky)
    output = broken_contracts(tmp_path)
    assert f"{contract} BROKEN" in output and caught in output


def test_ros_outside_its_link_package_breaks_the_contracts(tmp_path):
    """Only robot/ros1 imports rospy, only robot/ros2 rclpy, and the rest reaches them through the registry."""
    copy_of_rockly(tmp_path)
    (tmp_path / "rockly_desktop" / "robot" / "sneaky.py").write_text("import rospy\nimport rclpy\n")
    (tmp_path / "rockly_desktop" / "ui" / "sneaky.py").write_text("from rockly_desktop.robot.ros1 import link\n")
    output = broken_contracts(tmp_path)
    assert "rockly_desktop.robot.sneaky -> rospy" in output and "rockly_desktop.robot.sneaky -> rclpy" in output
    assert "rockly_desktop.ui.sneaky -> rockly_desktop.robot.ros1.link" in output
    assert ", 3 broken." in output


def test_the_simulator_naming_a_middleware_breaks_the_contracts(tmp_path):
    """By package: the simulator's link (its recording encoder is the registry's) and any module of
    robot/sim, one added later too, name no ROS link and no ROS package."""
    copy_of_rockly(tmp_path)
    sim = tmp_path / "rockly_desktop" / "robot" / "sim"
    append_to(sim / "link.py", "\n\ndef encoder():\n    from rockly_desktop.robot.ros1.recording_codec import "
                               "Ros1Encoder\n\n    return Ros1Encoder()\n")
    (sim / "later.py").write_text("from rockly_desktop.robot.ros2 import client\n")
    output = broken_contracts(tmp_path)
    assert "The built-in simulator (robot.sim) names no middleware" in output
    assert "rockly_desktop.robot.sim.link -> rockly_desktop.robot.ros1.recording_codec" in output
    assert "rockly_desktop.robot.sim.later -> rockly_desktop.robot.ros2.client" in output
    assert ", 1 broken." in output


def test_a_wrapper_naming_the_simulator_a_link_or_the_registry_breaks_the_contracts(tmp_path):
    """By package: a backend wrapper (robot/wrappers, one added later too) works on any RobotBackend."""
    copy_of_rockly(tmp_path)
    wrappers = tmp_path / "rockly_desktop" / "robot" / "wrappers"
    append_to(wrappers / "limits.py", "\n\ndef simulated(backend):\n    from rockly_desktop.robot.sim.sim_world import "
                                      "SimBackend\n\n    return isinstance(backend, SimBackend)\n")
    (wrappers / "later.py").write_text(
        "from rockly_desktop.robot import links\nfrom rockly_desktop.robot.ros1 import link\n")
    output = broken_contracts(tmp_path)
    assert "The backend wrappers (robot.wrappers) work on any backend" in output
    assert "rockly_desktop.robot.wrappers.limits -> rockly_desktop.robot.sim.sim_world" in output
    assert "rockly_desktop.robot.wrappers.later -> rockly_desktop.robot.links" in output
    assert "rockly_desktop.robot.wrappers.later -> rockly_desktop.robot.ros1.link" in output
    assert ", 1 broken." in output


def test_rclpy_on_rocklys_side_of_ros2_or_the_helper_imported_there_breaks_the_contracts(tmp_path):
    """By package: any module of robot/ros2 outside helper/ (sim_bridge, or one added later) is Rockly's side."""
    copy_of_rockly(tmp_path)
    ros2 = tmp_path / "rockly_desktop" / "robot" / "ros2"
    append_to(ros2 / "sim_bridge.py", "\n\ndef spin():\n    import rclpy\n\n    rclpy.init()\n")
    (ros2 / "later.py").write_text("from rockly_desktop.robot.ros2.helper import ros_values\n")
    output = broken_contracts(tmp_path)
    assert "rockly_desktop.robot.ros2.sim_bridge -> rclpy" in output
    assert "rockly_desktop.robot.ros2.later -> rockly_desktop.robot.ros2.helper.ros_values" in output
    assert ", 2 broken." in output


def test_settings_reaching_past_qtcore_up_into_ui_or_into_robots_break_the_contracts(tmp_path):
    """Settings are data on QSettings (QtCore) only, below the window: the command line reads them without widgets."""
    copy_of_rockly(tmp_path)
    settings = tmp_path / "rockly_desktop" / "settings"
    kiosk = settings / "kiosk.py"
    append_to(kiosk, "\n\ndef chord_text(chord):\n    from PySide6 import QtGui\n\n"
                     "    return QtGui.QKeySequence(chord).toString()\n")
    (settings / "sneaky.py").write_text("from PySide6.QtWidgets import QWidget\nimport PySide6.QtWebEngineCore\n"
                                        "from rockly_desktop.ui import texts\n"
                                        "from rockly_desktop.recording import library\n")
    output = broken_contracts(tmp_path)
    assert "settings use only QtCore of Qt" in output
    assert "rockly_desktop.settings.kiosk -> PySide6.QtGui (l." in output
    assert "rockly_desktop.settings.sneaky -> PySide6.QtWidgets (l.1)" in output
    assert "rockly_desktop.settings.sneaky -> PySide6.QtWebEngineCore (l.2)" in output
    assert "rockly_desktop.settings.sneaky -> rockly_desktop.ui.texts" in output
    assert "rockly_desktop.settings.sneaky -> rockly_desktop.recording.library" in output
    assert "app_settings ->" not in output and "teacher ->" not in output  # QtCore's QSettings; the teacher's Limits
    assert ", 3 broken." in output


def test_no_rockly_module_mentions_a_particular_robot():
    """Robots are profiles: Rockly's own code must not know any of them by name."""
    robots = [folder.name for folder in (REPO / "profiles").iterdir() if (folder / "profile.yaml").exists()]
    assert len(robots) >= 2
    for path in (REPO / "rockly_desktop").rglob("*.py"):
        text = path.read_text(encoding="utf-8").lower()
        for robot in robots:
            assert robot not in text, f"{path.relative_to(REPO)} mentions {robot}"


def python_files(folder: Path, skip=()):
    return [path for path in folder.rglob("*.py") if not set(path.relative_to(folder).parts) & set(skip)]


def rockly_imports(source: str) -> set:
    """The ``rockly_desktop`` modules ``source`` imports, by absolute name."""
    found = set()
    for node in ast.walk(parse_python(source)):
        if isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            found |= {node.module} if node.module != "rockly_desktop" else {
                f"rockly_desktop.{alias.name}" for alias in node.names}
    return {name for name in found if name.split(".")[0] == "rockly_desktop"}


def test_only_the_profiles_package_reads_a_profiles_manifest():
    """Everything else asks the Profile's typed properties (safe_stop, ros_interface, state_panels, ...)."""
    readers = []
    for path in python_files(REPO / "rockly_desktop", skip=("profiles",)):
        tree = parse_python(path.read_text(encoding="utf-8"))
        if any(isinstance(node, ast.Attribute) and node.attr == "manifest" for node in ast.walk(tree)):
            readers.append(str(path.relative_to(REPO)))
    assert readers == []


def test_no_rockly_module_knows_a_robots_tablet_codes():
    """Tablet questions are TabletQuestions in Rockly; a profile maps its robot's own codes onto them."""
    for path in (REPO / "rockly_desktop").rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        for code in ("D_YES_NO", "D_NAME", "D_OK"):
            assert code not in text, f"{path.relative_to(REPO)} mentions {code}"


PROFILE_SDK = {"rockly_desktop.sdk", "rockly_desktop.sdk_view"}


def test_profile_code_imports_only_the_sdk_from_rockly():
    """The built-in profiles' packages and the skeleton ``rockly profiles new`` writes use Rockly only
    through the SDK. (A profile's own tests, in its tests/ folder, may drive Rockly's internals.)"""
    from rockly_desktop.profiles.skeleton import render

    sources = {str(path.relative_to(REPO)): path.read_text(encoding="utf-8")
               for path in python_files(REPO / "profiles", skip=("tests",))}
    sources.update({f"skeleton: {path}": text for path, text in render("demo").items()
                    if path.endswith(".py") and not path.startswith("tests/")})
    assert len(sources) > 20
    wrong = {name: sorted(rockly_imports(text) - PROFILE_SDK) for name, text in sources.items()}
    assert {name: modules for name, modules in wrong.items() if modules} == {}


def test_the_import_check_sees_every_way_of_importing_rockly():
    source = ("import rockly_desktop.robot.sim.sim_world\nfrom rockly_desktop import sdk, core\n"
              "from rockly_desktop.sdk_view import card\nfrom . import palette\nimport math\n")
    assert rockly_imports(source) == {"rockly_desktop.robot.sim.sim_world", "rockly_desktop.sdk", "rockly_desktop.core",
                                      "rockly_desktop.sdk_view"}


ROS_VERSION_NAMES = ("ros1", "ros2")
ROS_VERSION_HOMES = ("rockly_desktop/robot/ros1/", "rockly_desktop/robot/ros2/", "rockly_desktop/robot/links.py")
# {module: (how many it keeps, why)}: the places that still name a ROS version, each with its reason
ROS_VERSION_EXCEPTIONS = {
    "rockly_desktop/core/ros_distributions.py": (
        2, "the profile format's vocabulary: the version keys a profile's ros_versions may use"),
    "rockly_desktop/runtime/agent/client.py": (
        3, "chosen_via's master (ROS 1) and domain (ROS 2) arguments name one version each; the agent's options "
           "per registry entry are issue 34's one link contract, still to do"),
    "rockly_desktop/runtime/agent/commands.py": (
        3, "the agent command line's --master and --domain options, as client.py"),
}


def ros_version_literals(source: str) -> int:
    """How many string literals in ``source`` are exactly a ROS version's name (docstrings and comments aside)."""
    return sum(isinstance(node, ast.Constant) and node.value in ROS_VERSION_NAMES
               for node in ast.walk(parse_python(source)))


def test_a_ros_version_is_named_only_by_its_link_folder_and_the_registry():
    """A link's ROS version, its agent's texts and where its agent runs are the registry's (robot/links.py) and
    its link class's (RobotLink.ros_version); everything else asks them."""
    found = {}
    for path in (REPO / "rockly_desktop").rglob("*.py"):
        name = path.relative_to(REPO).as_posix()
        count = ros_version_literals(path.read_text(encoding="utf-8"))
        if count and not name.startswith(ROS_VERSION_HOMES):
            found[name] = count
    assert found == {name: count for name, (count, _why) in ROS_VERSION_EXCEPTIONS.items()}


def test_the_ros_version_check_sees_a_literal_and_not_a_docstring():
    assert ros_version_literals('"""On ros1 or ros2."""\nif kind == "ros1":\n    pass  # ros2\n') == 1
