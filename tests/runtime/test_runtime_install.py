"""The runtime (``rockly-runtime``, built from ``runtime/``) installs into a fresh venv without PySide6 and runs
a standalone export there on the built-in simulator.

No network here: the wheel is built offline from a copy of the checkout, and the fresh venv (no system
site-packages, so no Qt and no ROS) gets exactly the distributions the runtime declares, with their files
and metadata, from this test's own Python; pip then installs the runtime with ``--no-index``, finding them
installed."""
import importlib.metadata
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from agent_tools import installed_agent
from program_builder import block, number, rockly_document, stack
from standalone_tools import REPO, environment, events, export_standalone, run_file
from waiting import eventually

RUNTIME_PARTS = ("rockly_desktop", "runtime", "resources/locale", "toolboxes", "profiles")
SKIPPED = shutil.ignore_patterns("__pycache__", "build", "*.egg-info")


def build_wheel(folder: Path) -> Path:
    """The rockly-runtime wheel, built offline from a copy of the checkout's runtime parts in ``folder``."""
    source = folder / "checkout"
    for part in RUNTIME_PARTS:
        shutil.copytree(REPO / part, source / part, ignore=SKIPPED)
    subprocess.run([sys.executable, "-m", "pip", "wheel", "--quiet", "--no-deps", "--no-build-isolation",
                    "--no-index", str(source / "runtime"), "-w", str(folder / "wheels")],
                   check=True, capture_output=True, timeout=300)
    (wheel,) = (folder / "wheels").glob("rockly_runtime-*.whl")
    return wheel


def requirement_names(requirements) -> list:
    """The distributions ``requirements`` (Requires-Dist lines) name, leaving out those of extras."""
    return [re.match(r"[A-Za-z0-9._-]+", line).group() for line in requirements or () if "extra ==" not in line]


def seed_dependencies(wheel: Path, site_packages: Path) -> list:
    """Put the runtime's declared dependencies (and theirs) into ``site_packages``, as this Python has them:
    links to their top-level files and folders, metadata included. Returns their names."""
    with zipfile.ZipFile(wheel) as archive:
        metadata = next(name for name in archive.namelist() if name.endswith(".dist-info/METADATA"))
        wanted = requirement_names(line.split(":", 1)[1].strip() for line in
                                   archive.read(metadata).decode().splitlines() if line.startswith("Requires-Dist:"))
    seeded = []
    while wanted:
        distribution = importlib.metadata.distribution(wanted.pop())
        name = distribution.metadata["Name"]
        if name in seeded:
            continue
        seeded.append(name)
        wanted += requirement_names(distribution.requires)
        root = Path(distribution.locate_file(""))
        for top in {Path(entry).parts[0] for entry in distribution.files if not str(entry).startswith("..")}:
            if not (site_packages / top).exists():
                (site_packages / top).symlink_to(root / top)
    return seeded


@pytest.fixture(scope="module")
def fresh_venv(tmp_path_factory):
    """A venv of its own with rockly-runtime installed (and nothing of Qt)."""
    folder = tmp_path_factory.mktemp("runtime-install")
    wheel = build_wheel(folder)
    venv = folder / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=300)
    python = venv / "bin" / "python"
    site_packages = Path(subprocess.run([str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
                                        capture_output=True, text=True, check=True).stdout.strip())
    seeded = seed_dependencies(wheel, site_packages)
    assert {"PyYAML", "numpy", "mcap"} <= set(seeded) and not {"PySide6", "PySide6_Essentials"} & set(seeded)
    installed = subprocess.run([str(python), "-m", "pip", "install", "--no-index", str(wheel)],
                               capture_output=True, text=True, timeout=300)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    return python, wheel


def test_the_runtime_wheel_holds_no_module_of_the_window(fresh_venv):
    _python, wheel = fresh_venv
    modules = [name for name in zipfile.ZipFile(wheel).namelist() if name.endswith(".py")]
    assert "rockly_desktop/runtime/standalone.py" in modules and "rockly_desktop/sdk.py" in modules
    assert not [name for name in modules if re.match(
        r"rockly_desktop/(ui|bridge|plotting|app|cli|sdk_view|run_command|sim_command|executor/qt_adapter)\b", name)]


def test_the_fresh_venv_has_no_qt_and_the_runtime_imports(fresh_venv):
    python, _wheel = fresh_venv
    check = subprocess.run([str(python), "-c", "import importlib.util as u, sys\n"
                            "assert u.find_spec('PySide6') is None and u.find_spec('shiboken6') is None\n"
                            "import rockly_desktop.runtime.standalone, rockly_desktop.sdk\n"
                            "import rockly_desktop.robot.sim.link\n"
                            "assert not [name for name in sys.modules if name.startswith(('PySide6', 'shiboken6'))]\n"
                            "print(rockly_desktop.runtime.standalone.__file__)"],
                           capture_output=True, text=True, timeout=120, cwd="/", env=environment(PYTHONPATH=""))
    assert check.returncode == 0, check.stderr
    assert "/venv/lib/" in check.stdout  # the installed copy, not the checkout


def test_a_standalone_export_runs_in_the_fresh_venv_on_the_simulator(fresh_venv, tmp_path):
    python, _wheel = fresh_venv
    source = tmp_path / "square.rockly"
    side = block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}, id="side")
    source.write_text(rockly_document([stack(side, block(
        "text_print", inputs={"TEXT": block("hobbit_position", {"coordinate": "x"})}, id="where"))]))
    exported = export_standalone(source, tmp_path / "square.py", "--language", "de")
    result = run_file(exported, "--speed", "20", "--events", "-", python=python,
                      env=environment(PYTHONPATH="", ROCKLY_DATA_DIR=""))
    assert result.returncode == 0, result.stderr
    stream = events(result.stdout)
    printed = [record["text"] for record in stream if record["event"] == "print"]
    assert len(printed) == 1 and float(printed[0]) == pytest.approx(0.5, abs=0.1)  # the robot moved
    assert stream[-1] == {"event": "exit", "status": 0} and result.stderr.splitlines()[-1] == "fertig"


def test_the_agent_and_its_client_run_from_the_fresh_venv(fresh_venv, tmp_path):
    """``rockly-agent`` and ``rockly-robot`` as a robot without Qt has them: a program sent, listed, run to its end."""
    python, _wheel = fresh_venv
    bin_folder = python.parent
    source = tmp_path / "ahead.rockly"
    source.write_text(rockly_document([block("hobbit_move", {"direction": "+"}, {"speed": number(0.5)}, id="ahead")]))
    exported = export_standalone(source, tmp_path / "ahead.py", "--language", "en")
    env = environment(PYTHONPATH="", ROCKLY_DATA_DIR="", PATH=f"{bin_folder}:/usr/bin:/bin")
    with installed_agent(bin_folder, tmp_path / "library", "--backend", "sim", "--speed", "20", env=env) as robot:
        assert robot("send", exported) == "'ahead' is on the robot now\n"
        assert robot("list").startswith("ahead  hobbit 1.0.0  came ")
        robot("start", "ahead")
        attached = robot("attach")  # until the run ends (or at once if it has already)
        if '"state": "ended"' not in attached:
            assert '"run": null' in attached
        eventually(lambda: "running:" not in robot("list"), 60)
