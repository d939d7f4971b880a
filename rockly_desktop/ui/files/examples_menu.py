"""File → Examples: the example programs shipped for the active robot (and for every robot),
in the window's language where they are translated (``examples/<language>/``), each opened as
an untitled copy so the shipped file is never overwritten."""
from pathlib import Path

from PySide6.QtWidgets import QMenu

from rockly_desktop.core.paths import examples_dir
from rockly_desktop.core.program import PROGRAM_SUFFIX
from rockly_desktop.ui.plain_text import mnemonic_free
from rockly_desktop.ui.texts import tr


def example_programs(profile_id: str, folder: Path = None, language: str = "en") -> list:
    """(readable name, path) of the examples for ``profile_id``, then the shared ones, each sorted by name:
    those of ``folder/language`` when it has examples for the robot, else the English ones."""
    folder = examples_dir() if folder is None else folder
    translated = folder / language
    if language != "en" and any((translated / profile_id).glob(f"*{PROGRAM_SUFFIX}")):
        folder = translated
    found = []
    for where in (folder / profile_id, folder):
        found += sorted((readable_name(path), path) for path in where.glob(f"*{PROGRAM_SUFFIX}") if path.is_file())
    return found


def readable_name(path: Path) -> str:
    """A file name as a person says it: ``drive-a-square.rockly`` is "Drive a square"."""
    words = path.stem.replace("_", " ").replace("-", " ").split()
    text = " ".join(words)
    return text[:1].upper() + text[1:]


class ExamplesMenu(QMenu):
    """The submenu, filled each time it opens with the examples of ``profile()``'s robot;
    choosing one calls ``files.open_copy`` (ProgramFiles, which asks to save changes first)."""

    def __init__(self, files, profile, language: str, parent=None):
        super().__init__(tr("menu_examples", language), parent)
        self.setObjectName("examples_menu")
        self._files = files
        self._profile = profile
        self._language = language
        self.aboutToShow.connect(self.fill)

    def fill(self):
        """List the active robot's examples (a disabled line when it has none)."""
        self.clear()
        examples = example_programs(self._profile().id, language=self._language)
        for name, path in examples:
            action = self.addAction(mnemonic_free(name), lambda p=str(path), n=name: self._files.open_copy(p, n))
            action.setData(str(path))
        if not examples:
            self.addAction(tr("no_examples", self._language)).setEnabled(False)
