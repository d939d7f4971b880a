"""Build ``rockly-runtime`` from the checkout's ``rockly_desktop`` (one level up): the parts that run a
program without the window (``rockly_desktop.runtime`` and what it uses), Rockly's catalogue and the
built-in profiles. The window's modules (Qt, QtWebEngine, Blockly) are left out; which ones go in is
``RUNTIME_TOPS`` (with their sub-packages) and ``TOP_MODULES``, kept honest by the import contract
"The runtime never imports Qt" in the checkout's pyproject.toml.

    pip install ./runtime        (from a checkout)
"""
import os
import re
import shutil

from setuptools import setup
from setuptools.command.build_py import build_py

SOURCE = os.path.join("..", "rockly_desktop")
RUNTIME_TOPS = ["core", "executor", "lessons", "profiles", "recording", "robot", "runtime"]  # and sub-packages
TOP_MODULES = {"__init__", "sdk"}  # of rockly_desktop itself; the rest of it is the window's
LEFT_OUT = {("rockly_desktop.executor", "qt_adapter")}  # the runner's Qt adapter
DATA_FOLDERS = (os.path.join("resources", "locale"), "toolboxes", "profiles")


class RuntimeModules(build_py):
    """build_py taking only the runtime's modules of the packages it shares with the window, into a fresh
    folder (pip builds in ``runtime/build``, where a module deleted from the checkout would linger)."""

    def run(self):
        shutil.rmtree(os.path.join(self.build_lib, "rockly_desktop"), ignore_errors=True)
        super().run()

    def find_package_modules(self, package, package_dir):
        modules = super().find_package_modules(package, package_dir)
        if package == "rockly_desktop":
            return [entry for entry in modules if entry[1] in TOP_MODULES]
        return [entry for entry in modules if (entry[0], entry[1]) not in LEFT_OUT]


def runtime_packages() -> list:
    """``rockly_desktop`` and the runtime's packages with every sub-package in the checkout, so a new
    sub-package (a wing) goes in without editing a list."""
    packages = ["rockly_desktop"]
    for top in RUNTIME_TOPS:
        for folder, dirs, files in os.walk(os.path.join(SOURCE, top)):
            dirs[:] = sorted(d for d in dirs if d != "__pycache__")
            if "__init__.py" in files:
                packages.append(".".join(["rockly_desktop"] + os.path.relpath(folder, SOURCE).split(os.sep)))
    return packages


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


PACKAGES = runtime_packages()

setup(
    version=version(),
    packages=PACKAGES,
    package_dir={package: os.path.join("..", *package.split(".")) for package in PACKAGES},
    cmdclass={"build_py": RuntimeModules},
    data_files=data_files(),
)
