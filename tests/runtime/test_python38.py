"""rockly-runtime on a real Python 3.8 (Ubuntu 20.04's, with ROS Noetic), beyond what vermin reads
(test_python_versions.py): the wheel installs into a fresh 3.8 venv without PySide6, every module of it
compiles there, every one imports but for binary dependencies this machine has no 3.8 build of, and the agent and
its client run there.

The interpreter: ``ROCKLY_PYTHON38``, else ``python3.8`` on the PATH, else pyenv's; without one the tests skip
and say so. No network: the runtime's pure-Python dependencies (PyYAML without its C part, mcap and its ROS
supports) are linked in from this test's Python, and the venv sees Debian's own rospy (pure Python) as a Noetic
robot's venv made with ``--system-site-packages`` does. numpy, lz4, zstandard and cryptography are binary and exist
here only for this Python, so a program cannot run on 3.8 here (the SDK's simulated world needs numpy when a
profile loads): on a robot, pip installs their 3.8 builds."""
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest
from agent_tools import installed_agent
from program_builder import block, number, rockly_document
from standalone_tools import environment, export_standalone
from test_runtime_install import build_wheel

from rockly_desktop.runtime.agent.pairings import agent_folder
from rockly_desktop.runtime.agent.tls import agent_certificate

# binary distributions with no 3.8 build on this machine, and ROS 2's (on a robot: the helper's own Python)
NOT_HERE = {"numpy", "lz4", "zstandard", "rclpy", "rosidl_parser"}
PURE_DEPENDENCIES = ("yaml", "mcap", "mcap_ros1", "mcap_ros2")


def python38():
    """A Python 3.8 interpreter on this machine that runs (a pyenv shim may not), or None."""
    found = [os.environ.get("ROCKLY_PYTHON38"), shutil.which("python3.8"),
             *sorted(str(path) for path in Path.home().glob(".pyenv/versions/3.8*/bin/python3.8"))]
    return next((path for path in found if path and _is_python38(path)), None)


def _is_python38(path) -> bool:
    try:
        answer = subprocess.run([path, "-c", "import sys; print(sys.version_info[:2] == (3, 8))"],
                                capture_output=True, text=True, timeout=60)
    except OSError:
        return False
    return answer.stdout.strip() == "True"


PYTHON38 = python38()
pytestmark = pytest.mark.skipif(PYTHON38 is None, reason="no Python 3.8 here (set ROCKLY_PYTHON38): Debian 12 "
                                                           "has no python3.8 package")


@pytest.fixture(scope="module")
def venv38(tmp_path_factory):
    """``bin`` of a fresh Python 3.8 venv with rockly-runtime installed (nothing of Qt)."""
    folder = tmp_path_factory.mktemp("runtime-py38")
    wheel = build_wheel(folder)
    venv = folder / "venv"
    subprocess.run([PYTHON38, "-m", "venv", str(venv)], check=True, timeout=300)
    python = venv / "bin" / "python"
    site_packages = Path(subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                                        capture_output=True, text=True, check=True).stdout.strip())
    for package in PURE_DEPENDENCIES:
        found = __import__(package).__file__
        (site_packages / package).symlink_to(Path(found).parent)
    (site_packages / "ros1.pth").write_text(str(Path(__import__("rospy").__file__).parents[1]) + "\n")
    installed = subprocess.run([str(python), "-m", "pip", "install", "--no-index", "--no-deps", str(wheel)],
                               capture_output=True, text=True, timeout=300)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return venv / "bin"


def python_code(bin_folder, code) -> subprocess.CompletedProcess:
    return subprocess.run([str(bin_folder / "python"), "-c", code], capture_output=True, text=True, timeout=300,
                          cwd="/", env=environment(PYTHONPATH=""))


def test_the_fresh_venv_is_python_3_8_without_qt(venv38):
    result = python_code(venv38, "import sys, importlib.util as u\n"
                                 "assert u.find_spec('PySide6') is None and u.find_spec('shiboken6') is None\n"
                                 "import rockly_desktop\nprint(sys.version_info[:2], rockly_desktop.__file__)")
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("(3, 8) ") and "/venv/lib/python3.8/site-packages/" in result.stdout


def test_every_runtime_module_compiles_on_python_3_8(venv38):
    result = python_code(venv38, "import compileall, sys, rockly_desktop\n"
                                 "sys.exit(0 if compileall.compile_dir(rockly_desktop.__path__[0], quiet=1, "
                                 "force=True) else 1)")
    assert result.returncode == 0, result.stdout + result.stderr


def test_every_runtime_module_imports_on_python_3_8_but_for_binaries_missing_here(venv38):
    result = python_code(venv38, "import importlib, json, pkgutil, rockly_desktop\n"
                                 "failed = {}\n"
                                 "for module in pkgutil.walk_packages(rockly_desktop.__path__, 'rockly_desktop.'):\n"
                                 "    try:\n"
                                 "        importlib.import_module(module.name)\n"
                                 "    except ModuleNotFoundError as error:\n"
                                 "        failed[module.name] = 'missing ' + str(error.name).split('.')[0]\n"
                                 "    except Exception as error:\n"
                                 "        failed[module.name] = repr(error)\n"
                                 "print(json.dumps(failed))")
    assert result.returncode == 0, result.stderr
    failed = json.loads(result.stdout)
    assert {name: why for name, why in failed.items() if why.split(" ", 1)[-1] not in NOT_HERE
            or not why.startswith("missing ")} == {}
    assert "rockly_desktop.runtime.standalone" not in failed and "rockly_desktop.runtime.agent.server" not in failed


def test_the_agent_keeps_a_program_and_its_client_lists_it_on_python_3_8(venv38, tmp_path):
    source = tmp_path / "ahead.rockly"
    source.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}, id="ahead")]))
    exported = export_standalone(source, tmp_path / "ahead.py", "--language", "en")
    env = environment(PYTHONPATH="", ROCKLY_DATA_DIR="", PATH=f"{venv38}:/usr/bin:/bin")
    # cryptography (binary, no 3.8 build here) only makes the agent's TLS certificate on its first start: made
    # here by this Python, the 3.8 agent serves TLS with its own ssl, and pairs
    agent_certificate(agent_folder(tmp_path / "library"))
    with installed_agent(venv38, tmp_path / "library", "--backend", "ros1", env=env) as robot:
        assert robot("send", exported) == "'ahead' is on the robot now\n"
        assert robot("list").startswith("ahead  hobbit 1.0.0  came ")
