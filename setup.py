"""Install the editor page, shared toolboxes, built-in profiles, examples and lessons as data files.

Metadata lives in pyproject.toml; this file only lists the data folders, which
setuptools cannot glob recursively on its own. They land in
``<prefix>/share/rockly/`` where ``rockly_desktop.core.paths`` finds them; the launcher
(``rockly.desktop``, with its kiosk action) goes to ``<prefix>/share/applications/``.
"""
import os

from setuptools import setup

DATA_FOLDERS = ("resources", "toolboxes", "profiles", "examples", "lessons")


def data_files():
    """Return (target folder, [files]) pairs for every file below DATA_FOLDERS."""
    pairs = []
    for top in DATA_FOLDERS:
        for folder, dirs, files in os.walk(top):
            dirs[:] = [d for d in dirs if d != "__pycache__"]
            wanted = [os.path.join(folder, f) for f in files if not f.endswith(".pyc")]
            if wanted:
                pairs.append((os.path.join("share", "rockly", folder), wanted))
    pairs.append((os.path.join("share", "applications"), ["rockly.desktop"]))
    return pairs


if not os.path.isfile(os.path.join("resources", "blockly", "vendor", ".version")):
    raise SystemExit("Blockly is not fetched yet: run `make setup` (or scripts/fetch-blockly.sh) before installing.")
setup(data_files=data_files())
