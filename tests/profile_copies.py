"""Throw-away copies of the HOBBIT profile that plugin tests may break, and the source tree's folders."""
import shutil
from pathlib import Path

import yaml

REPO = Path(__file__).resolve().parents[1]
HOBBIT_DIR = REPO / "profiles" / "hobbit"
SHARED_TOOLBOXES = REPO / "toolboxes"


class EditableProfile:
    """A copy of the HOBBIT profile folder whose YAML files a test may change."""

    def __init__(self, root: Path):
        self.root = root

    def path(self, name: str) -> Path:
        return self.root / name

    def read(self, name: str):
        return yaml.safe_load(self.path(name).read_text(encoding="utf-8"))

    def write(self, name: str, data) -> Path:
        text = yaml.safe_dump(data, allow_unicode=True, sort_keys=False)
        self.path(name).write_text(text, encoding="utf-8")
        return self.path(name)

    def write_text(self, name: str, text: str) -> Path:
        self.path(name).write_text(text, encoding="utf-8")
        return self.path(name)

    def edit(self, name: str, change) -> Path:
        """Load ``name``, let ``change(data)`` alter it in place, write it back; return its path."""
        data = self.read(name)
        change(data)
        return self.write(name, data)

    def edit_block(self, block_type: str, change) -> Path:
        """Let ``change(raw)`` alter one block definition in blocks.yaml; return blocks.yaml's path."""
        def apply(data):
            change(next(raw for raw in data["blocks"] if raw.get("type") == block_type))
        return self.edit("blocks.yaml", apply)


def copy_profile(target: Path, profile_id: str = None) -> EditableProfile:
    """Copy profiles/hobbit to ``target`` (created); optionally give the copy another id."""
    shutil.copytree(HOBBIT_DIR, target, ignore=shutil.ignore_patterns("__pycache__"))
    copy = EditableProfile(target)
    if profile_id is not None:
        copy.edit("profile.yaml", lambda data: data.update(id=profile_id))
    return copy
