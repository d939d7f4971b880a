"""Shared fixtures: isolated user folders, the installed profiles, one headless editor page.

Profile copies that plugin tests break live in profile_copies.py."""
import os
import tempfile
from pathlib import Path

# Before anything reads them: no test run sees the real user's profiles or settings.
os.environ["XDG_DATA_HOME"] = tempfile.mkdtemp(prefix="rockly-test-data-")
os.environ["XDG_CONFIG_HOME"] = tempfile.mkdtemp(prefix="rockly-test-config-")
os.environ["XDG_CACHE_HOME"] = tempfile.mkdtemp(prefix="rockly-test-cache-")
# This test process becomes a ROS node in the ROS tests: its logs stay in a temp folder.
os.environ["ROS_HOME"] = tempfile.mkdtemp(prefix="rockly-test-ros-")
os.environ["ROS_LOG_DIR"] = os.path.join(os.environ["ROS_HOME"], "log")
os.environ["ROS_IP"] = "127.0.0.1"
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
os.environ.setdefault("QTWEBENGINE_DISABLE_SANDBOX", "1")

import PySide6.QtWebEngineWidgets  # noqa: F401 - must be imported before the QApplication exists
import pytest

pytest_plugins = ["leak_check", "ros_fixtures", "ros2_fixtures"]

REPO = Path(__file__).resolve().parents[1]
HOBBIT_DIR = REPO / "profiles" / "hobbit"
SHARED_TOOLBOXES = REPO / "toolboxes"


@pytest.fixture(autouse=True)
def isolated_user_folders(tmp_path_factory, monkeypatch):
    """Each test gets its own empty user data and config folders."""
    home = tmp_path_factory.mktemp("home")
    monkeypatch.setenv("XDG_DATA_HOME", str(home / "data"))
    monkeypatch.setenv("XDG_CONFIG_HOME", str(home / "config"))
    return home


@pytest.fixture(scope="session")
def registry():
    """The installed profiles (HOBBIT is built in)."""
    from rockly_desktop.profiles.registry import ProfileRegistry

    return ProfileRegistry.discover()


@pytest.fixture(scope="session")
def hobbit(registry):
    """The HOBBIT profile."""
    return registry.get("hobbit")


@pytest.fixture(scope="session")
def headless_editor(qapp, hobbit):
    """One Blockly page with the HOBBIT blocks, shared by tests that only generate code."""
    from rockly_desktop.bridge.headless import HeadlessEditor

    editor = HeadlessEditor("en")
    editor.use_profile(hobbit)
    yield editor
    editor.close()
