"""``rockly profiles new``: the skeleton profile it writes loads, validates and passes its own test.

The command runs as a user runs it (a real process); the generated test runs under this
repository's pytest in a process of its own.
"""
import os
import subprocess
import sys
from pathlib import Path

import pytest
from profile_copies import REPO, SHARED_TOOLBOXES

from rockly_desktop.profiles.profile import load_profile
from rockly_desktop.profiles.skeleton import create_profile
from rockly_desktop.robot.interrupt import Interrupt
from rockly_desktop.robot.sim.sim_world import SimBackend, SimWorld

SKELETON = {"profile.yaml", "blocks.yaml", "toolbox.yaml", "rockly_demo/__init__.py", "rockly_demo/api.py",
            "rockly_demo/sim.py", "rockly_demo/view/__init__.py", "rockly_demo/view/widget.py",
            "rockly_demo/view/texts.py", "tests/test_demo.py", "locale/messages.pot", "locale/de.po"}


def rockly(*args, env=None):
    return subprocess.run([sys.executable, "-m", "rockly_desktop", *map(str, args)],
                          capture_output=True, text=True, timeout=90, cwd=REPO, env=env)


def files_in(folder: Path) -> set:
    return {path.relative_to(folder).as_posix() for path in folder.rglob("*")
            if path.is_file() and "__pycache__" not in path.parts}


@pytest.fixture(scope="module")
def demo(tmp_path_factory) -> Path:
    """A profile made by ``rockly profiles new demo --dir TMP``."""
    parent = tmp_path_factory.mktemp("profiles")
    result = rockly("profiles", "new", "demo", "--dir", parent)
    assert result.returncode == 0, result.stderr
    assert f"Created the robot profile 'demo' in {parent / 'demo'}" in result.stdout
    return parent / "demo"


def test_new_writes_the_skeleton_files(demo):
    assert files_in(demo) == SKELETON
    profile = load_profile(demo, SHARED_TOOLBOXES)
    assert (profile.id, profile.version, profile.block_types) == ("demo", "0.1.0", {"demo_say"})
    assert profile.manifest["api"] == "rockly_demo.api:DemoCommands"
    assert profile.manifest["ros_interface"]["subscribes"]["/demo/say"] == "std_msgs/String"
    assert profile.block("demo_say").definition["message0"] == {"en": "say %1", "de": "sage %1"}
    shared = [category["name"]["en"] for category in profile.toolbox_categories[1:]]
    assert shared == ["Logic", "Loops", "Math", "Text", "Variables"]


def test_the_new_profile_validates(demo):
    result = rockly("profiles", "validate", demo)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("OK  demo 0.1.0: 1 blocks, 6 toolbox categories, "
                                    "commands rockly_demo.api:DemoCommands")


def test_the_generated_test_passes(demo):
    result = subprocess.run([sys.executable, "-m", "pytest", str(demo / "tests"), "-q", "-p", "no:cacheprovider"],
                            capture_output=True, text=True, timeout=120, cwd=REPO)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "3 passed" in result.stdout


@pytest.mark.parametrize("name", ["Demo", "1robot", "my-robot", "../escape", "a" * 41, ""])
def test_a_name_that_is_no_profile_id_is_refused(tmp_path, name):
    result = rockly("profiles", "new", name, "--dir", tmp_path)
    assert result.returncode == 2
    assert f"'{name}' is not a profile id: use lower-case letters, digits and '_'" in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_name_whose_package_exists_or_whose_id_is_installed_is_refused(tmp_path):
    taken = rockly("profiles", "new", "desktop", "--dir", tmp_path)
    installed = rockly("profiles", "new", "hobbit", "--dir", tmp_path)
    assert taken.returncode == installed.returncode == 2
    assert "'desktop' would name the profile's package rockly_desktop, which is already importable" in taken.stderr
    hobbit = REPO / "profiles" / "hobbit"
    assert f"a profile with the id 'hobbit' is already installed (built-in, {hobbit})" in installed.stderr
    assert list(tmp_path.iterdir()) == []


def test_an_existing_folder_is_refused_and_left_alone(tmp_path):
    (tmp_path / "demo").mkdir()
    (tmp_path / "demo" / "notes.txt").write_text("mine")
    result = rockly("profiles", "new", "demo", "--dir", tmp_path)
    assert result.returncode == 1
    assert f"{tmp_path / 'demo'} exists already; nothing was changed" in result.stderr
    assert files_in(tmp_path / "demo") == {"notes.txt"}


def test_a_profile_made_in_the_users_folder_is_listed(tmp_path):
    env = {**os.environ, "XDG_DATA_HOME": str(tmp_path / "xdg")}
    created = rockly("profiles", "new", "mybot", env=env)
    assert created.returncode == 0, created.stderr
    folder = tmp_path / "xdg" / "rockly" / "profiles" / "mybot"
    assert (folder / "profile.yaml").is_file()
    listed = rockly("profiles", "list", env=env)
    assert listed.returncode == 0, listed.stderr
    rows = [line.split() for line in listed.stdout.splitlines()]
    assert ["mybot", "Mybot", "0.1.0", "user", str(folder)] in rows


@pytest.mark.parametrize("name", ["a", "no", "none", "r2_d2__x", "z" * 40])
def test_every_accepted_name_gives_a_profile_that_loads_and_compiles(tmp_path, name):
    folder = create_profile(name, tmp_path)
    profile = load_profile(folder, SHARED_TOOLBOXES)
    assert profile.id == name
    for source in folder.rglob("*.py"):
        compile(source.read_text(encoding="utf-8"), str(source), "exec")


def test_the_new_profiles_view_draws_what_its_simulator_says_and_any_odd_snapshot(qtbot, tmp_path):
    profile = load_profile(create_profile("viewdemo", tmp_path), SHARED_TOOLBOXES)
    view = profile.simulator_view_class()(language="de")
    qtbot.addWidget(view)
    view.resize(320, 200)
    silent = view.grab().toImage()
    world = SimWorld()
    simulator = profile.load_object("simulator")(world)
    simulator.start()
    try:
        profile.load_object("api")(SimBackend(world, Interrupt())).say("Hallo Welt")
        view.set_snapshot(simulator.snapshot())
    finally:
        simulator.shutdown()
    assert view.snapshot() == {"said": "Hallo Welt", "stops": 0}
    assert view.grab().toImage() != silent
    for odd in ({}, {"said": 3, "stops": "many"}, {"said": "long " * 500, "stops": float("nan")}, None):
        view.set_snapshot(odd)
        assert not view.grab().toImage().isNull()
