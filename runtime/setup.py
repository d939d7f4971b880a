"""Build ``rockly-runtime`` from the checkout's ``rockly_desktop`` (one level up): the parts that run a
program without the window (``rockly_desktop.runtime`` and what it uses), Rockly's catalogue and the
built-in profiles. The window's modules (Qt, QtWebEngine, Blockly) are left out; which ones go in is
``RUNTIME_PACKAGES`` and ``TOP_MODULES``, kept honest by the import contract "The runtime never
imports Qt" in the checkout's pyproject.toml.

    pip install ./runtime        (from a checkout)
"""
import os
import re

from setuptools import setup
from setuptools.command.build_py import build_py

SOURCE = os.path.join("..", "rockly_desktop")
RUNTIME_PACKAGES = [
    "rockly_desktop", "rockly_desktop.core", "rockly_desktop.executor", "rockly_desktop.profiles",
    "rockly_desktop.profiles.packs", "rockly_desktop.recording", "rockly_desktop.robot", "rockly_desktop.robot.ros1",
    "rockly_desktop.robot.ros2", "rockly_desktop.robot.ros2.helper", "rockly_desktop.robot.sim",
    "rockly_desktop.robot.wrappers", "rockly_desktop.runtime", "rockly_desktop.runtime.agent",
]
TOP_MODULES = {"__init__", "sdk"}  # of rockly_desktop itself; the rest of it is the window's
LEFT_OUT = {("rockly_desktop.executor", "qt_adapter")}  # the runner's Qt adapter
DATA_FOLDERS = (os.path.join("resources", "locale"), "toolboxes", "profiles")


class RuntimeModules(build_py):
    """build_py taking only the runtime's modules of the packages it shares with the window."""

    def find_package_modules(self, package, package_dir):
        modules = super().find_package_modules(package, package_dir)
        if package == "rockly_desktop":
            return [entry for entry in modules if entry[1] in TOP_MODULES]
        return [entry for entry in modules if (entry[0], entry[1]) not in LEFT_OUT]


def version() -> str:
    with open(os.path.join(SOURCE, "__init__.py"), encoding="utf-8") as init:
        return re.search(r'^__version__ = "([^"]+)"', init.read(), re.M).group(1)


def data_files():
    """(target folder, [files]) for the catalogue, shared toolboxes and built-in profiles: they land in
    ``<prefix>/share/rockly/`` where ``rockly_desktop.core.paths`` finds them."""
    pairs = []
    for top in DATA_FOLDERS:
        for folder, dirs, files in os.walk(os.path.join("..", top)):
            dirs[:] = [d for d in dirs if d != "__pycache__"]
            wanted = [os.path.join(folder, f) for f in files if not f.endswith(".pyc")]
            if wanted:
                pairs.append((os.path.join("share", "rockly", os.path.relpath(folder, "..")), wanted))
    return pairs


setup(
    version=version(),
    packages=RUNTIME_PACKAGES,
    package_dir={package: os.path.join("..", *package.split(".")) for package in RUNTIME_PACKAGES},
    cmdclass={"build_py": RuntimeModules},
    data_files=data_files(),
)
