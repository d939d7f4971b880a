"""Where Rockly finds its data (editor page, toolboxes, built-in profiles) and the user's."""
import os
import sys
from pathlib import Path

_SOURCE_TREE = Path(__file__).resolve().parents[2]


def data_root() -> Path:
    """The folder holding ``resources/``, ``toolboxes/`` and ``profiles/``.

    A source checkout (also an editable install) uses the checkout itself; a regular
    ``pip install .`` uses ``<prefix>/share/rockly``. ``ROCKLY_DATA_DIR`` overrides both.
    """
    override = os.environ.get("ROCKLY_DATA_DIR")
    if override:
        return Path(override)
    if (_SOURCE_TREE / "resources" / "blockly" / "index.html").is_file():
        return _SOURCE_TREE
    return Path(sys.prefix) / "share" / "rockly"


def editor_page() -> Path:
    """The Blockly editor page loaded into the web view."""
    return data_root() / "resources" / "blockly" / "index.html"


def blockly_vendor_dir() -> Path:
    """The unpacked Blockly release (fetched at set-up, never at run time)."""
    return data_root() / "resources" / "blockly" / "vendor"


def shared_toolboxes_dir() -> Path:
    """Toolbox categories every profile can include by name (logic, loops, ...)."""
    return data_root() / "toolboxes"


def builtin_profiles_dir() -> Path:
    """Robot profiles shipped with Rockly."""
    return data_root() / "profiles"


def examples_dir() -> Path:
    """Example programs shipped with Rockly: ``<profile id>/*.rockly``, and shared ones at the top."""
    return data_root() / "examples"


def user_data_dir() -> Path:
    """Rockly's folder in the user's data home (XDG): ``~/.local/share/rockly`` by default."""
    base = os.environ.get("XDG_DATA_HOME") or str(Path.home() / ".local" / "share")
    return Path(base) / "rockly"


def user_profiles_dir() -> Path:
    """Robot profiles a user installed by copying a folder (XDG data home)."""
    return user_data_dir() / "profiles"


def user_packs_dir() -> Path:
    """Block packs: blocks made in Rockly, each pack adding to one robot profile (XDG data home)."""
    return user_data_dir() / "packs"


def recovery_dir() -> Path:
    """Copies of programs with unsaved changes, kept for after a crash (XDG data home)."""
    return user_data_dir() / "recovery"


def user_cache_dir() -> Path:
    """What Rockly keeps only to start faster; anything in it may go (XDG cache home)."""
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "rockly"


def recordings_dir() -> Path:
    """Where runs are recorded unless the preferences name another folder (XDG data home)."""
    return user_data_dir() / "recordings"
