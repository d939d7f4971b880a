"""The kiosk mode's settings: the folder visitors may open and save in, the folder their programs
are kept in after an idle reset, the idle minutes, and the key chord that leaves kiosk mode."""
from pathlib import Path

from rockly_desktop.core import paths
from rockly_desktop.settings.group import SettingsGroup

DEFAULT_IDLE_MINUTES = 3


def default_programs_folder() -> Path:
    """Where visitors open and save programs when no folder was chosen: ``~/.local/share/rockly/kiosk``."""
    return paths.user_data_dir() / "kiosk"


def default_visitors_folder() -> Path:
    """Where idle resets keep visitors' programs when no folder was chosen: ``~/.local/share/rockly/visitors``."""
    return paths.user_data_dir() / "visitors"


class KioskSettings(SettingsGroup):
    """The kiosk part of Rockly's QSettings ``store`` (keys under ``kiosk/``)."""

    prefix = "kiosk"

    @property
    def programs_folder(self) -> Path:
        """The only folder the kiosk's file dialogs show (and its sub-folders)."""
        return Path(self._get("programs_folder") or default_programs_folder())

    @programs_folder.setter
    def programs_folder(self, folder):
        self._set("programs_folder", str(folder or ""))

    @property
    def visitors_folder(self) -> Path:
        """Where a visitor's program is saved, in a dated file, when the kiosk resets after idling."""
        return Path(self._get("visitors_folder") or default_visitors_folder())

    @visitors_folder.setter
    def visitors_folder(self, folder):
        self._set("visitors_folder", str(folder or ""))

    @property
    def idle_minutes(self) -> float:
        """Minutes without input after which the kiosk starts over (3 by default)."""
        try:
            minutes = float(self._get("idle_minutes", DEFAULT_IDLE_MINUTES))
        except (TypeError, ValueError):
            return DEFAULT_IDLE_MINUTES
        return minutes if minutes > 0 else DEFAULT_IDLE_MINUTES

    @idle_minutes.setter
    def idle_minutes(self, minutes: float):
        self._set("idle_minutes", minutes)

    @property
    def quit_chord(self) -> str:
        """The key chord that leaves kiosk mode without the PIN ("" when none is set), as
        ``QKeySequence.toString()`` writes it, e.g. "Ctrl+Alt+Shift+K"."""
        return str(self._get("quit_chord", ""))

    @quit_chord.setter
    def quit_chord(self, chord: str):
        self._set("quit_chord", chord or "")

    @property
    def challenge(self) -> str:
        """The id of the lesson ("challenge of the day") the kiosk opens for every visitor; "" for none."""
        return str(self._get("challenge", ""))

    @challenge.setter
    def challenge(self, lesson_id: str):
        self._set("challenge", lesson_id or "")
