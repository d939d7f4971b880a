"""What Rockly remembers between starts: layout, language, profile, last and recent files.

The settings file holds the teacher's PIN hash and limits: only its owner may read it (0600,
in a folder of Rockly's own kept 0700). QSettings rewrites the file through a temporary one
and keeps the mode the file had, so the file is made private before QSettings first writes it.
"""
import os
from pathlib import Path

from PySide6.QtCore import QSettings

from rockly_desktop.core.paths import recordings_dir
from rockly_desktop.settings.kiosk import KioskSettings
from rockly_desktop.settings.language import CurrentLanguage
from rockly_desktop.settings.lessons import LessonProgress
from rockly_desktop.settings.teacher import TeacherSettings

MAX_RECENT = 8


class AppSettings:
    """Typed access to Rockly's QSettings. ``path`` selects a settings file (tests use one).

    In kiosk mode (``kiosk_mode``) the visitors' session leaves the teacher's own untouched: no
    recent or last file, window layout or stage is remembered, and "Put the robot back before
    each Run" is a setting of its own, on by default.
    """

    def __init__(self, path=None):
        if path is None:
            self._store = QSettings("Rockly", "Rockly")
        else:
            self._store = QSettings(str(path), QSettings.Format.IniFormat)
        keep_private(Path(self._store.fileName()), own_folder=path is None)
        self.current_language = CurrentLanguage(self._store)  # the language's one owner
        self.kiosk_mode = False
        self._lessons = None  # made when first asked for: kiosk mode is known by then

    @property
    def folder(self) -> Path:
        """The folder the settings file is in."""
        return Path(self._store.fileName()).parent

    def _get(self, key, default=None):
        value = self._store.value(key)
        return default if value is None else value

    @property
    def language(self) -> str:
        """The window and block language (``current_language.code``, which owns it)."""
        return self.current_language.code

    @language.setter
    def language(self, value: str):
        self.current_language.code = value

    @property
    def profile_id(self):
        """The robot profile used last, or None."""
        return self._get("profile")

    @profile_id.setter
    def profile_id(self, value: str):
        self._store.setValue("profile", value)

    @property
    def recent_files(self) -> list:
        """Recently used program files, newest first."""
        value = [] if self.kiosk_mode else self._get("recent_files", [])
        return [value] if isinstance(value, str) else list(value)

    def add_recent_file(self, path: str):
        """Put ``path`` at the top of the recent files (and remember it as the last file)."""
        if self.kiosk_mode:
            return
        files = [path] + [item for item in self.recent_files if item != path]
        self._store.setValue("recent_files", files[:MAX_RECENT])
        self.last_file = path

    def clear_recent_files(self):
        """Forget the recent files (not from a kiosk, which shows none)."""
        if self.kiosk_mode:
            return
        self._store.setValue("recent_files", [])

    @property
    def last_file(self):
        """The program that was open when Rockly last closed, or None."""
        return self._get("last_file") or None

    @last_file.setter
    def last_file(self, path):
        if self.kiosk_mode:
            return
        self._store.setValue("last_file", path or "")

    @property
    def window_geometry(self):
        """Saved window geometry (QByteArray) or None."""
        return self._get("window/geometry")

    @property
    def window_state(self):
        """Saved dock and toolbar layout (QByteArray) or None."""
        return self._get("window/state")

    def save_window(self, geometry, state):
        """Remember the window geometry and dock layout."""
        if self.kiosk_mode:
            return
        self._store.setValue("window/geometry", geometry)
        self._store.setValue("window/state", state)

    def link_connection(self, link_kind, profile_id: str) -> dict:
        """The connection settings remembered for a robot profile on a kind of robot link (a
        ``robot.links.LinkKind``): {setting name: value or None}."""
        return {setting.name: self._get(f"{link_kind.settings_group}/{profile_id}/{setting.name}") or None
                for setting in link_kind.settings}

    def remember_link_connection(self, link_kind, profile_id: str, values: dict):
        """Remember how to reach this robot over this kind of link."""
        for setting in link_kind.settings:
            self._store.setValue(f"{link_kind.settings_group}/{profile_id}/{setting.name}",
                                 values.get(setting.name) or "")

    @property
    def teacher(self) -> TeacherSettings:
        """The teacher's settings (toolbox level, limits, PIN), in the same store."""
        return TeacherSettings(self._store)

    @property
    def normal_window_state(self):
        """The dock layout to go back to when the window was closed on stage (QByteArray), or None."""
        return self._get("window/normal_state")

    @normal_window_state.setter
    def normal_window_state(self, state):
        if not self.kiosk_mode:
            self._store.setValue("window/normal_state", state)

    @property
    def stage(self) -> bool:
        """True when the window was on stage (View → Stage) when it last closed."""
        return not self.kiosk_mode and str(self._get("window/stage", "false")).lower() == "true"

    @stage.setter
    def stage(self, value: bool):
        if not self.kiosk_mode:
            self._store.setValue("window/stage", "true" if value else "false")

    @property
    def stage_share(self):
        """The share of the window's width the simulator had on stage (0..1), or None."""
        try:
            return float(self._get("window/stage_share"))
        except (TypeError, ValueError):
            return None

    @stage_share.setter
    def stage_share(self, share: float):
        if not self.kiosk_mode:
            self._store.setValue("window/stage_share", share)

    @property
    def lessons(self) -> LessonProgress:
        """The lessons passed: the computer user's, or (in kiosk mode) the visitor's, never written."""
        if self._lessons is None:
            self._lessons = LessonProgress(self._store, kept=not self.kiosk_mode)
        return self._lessons

    @property
    def kiosk(self) -> KioskSettings:
        """The kiosk mode's settings (folders, idle minutes, the key chord that leaves it)."""
        return KioskSettings(self._store)

    @property
    def _reset_key(self):
        return ("kiosk/reset_before_run", "true") if self.kiosk_mode else ("reset_before_run", "false")

    @property
    def reset_before_run(self) -> bool:
        """True when the simulated robot is put back before each Run (and on New and Open); off by
        default, on by default in kiosk mode (which keeps its own setting)."""
        key, default = self._reset_key
        return str(self._get(key, default)).lower() == "true"

    @reset_before_run.setter
    def reset_before_run(self, value: bool):
        self._store.setValue(self._reset_key[0], "true" if value else "false")

    @property
    def block_look(self) -> dict:
        """How the blocks look: {"highContrast": bool, "largeText": bool} (both off by default)."""
        return {"highContrast": str(self._get("blocks/high_contrast", "false")).lower() == "true",
                "largeText": str(self._get("blocks/large_text", "false")).lower() == "true"}

    @block_look.setter
    def block_look(self, look: dict):
        self._store.setValue("blocks/high_contrast", "true" if look.get("highContrast") else "false")
        self._store.setValue("blocks/large_text", "true" if look.get("largeText") else "false")

    @property
    def agent_address(self) -> str:
        """``host:port`` where the robot's agent was last reached (Robot → Programs on the robot…); empty: never."""
        return str(self._get("agent/address", "") or "")

    @agent_address.setter
    def agent_address(self, value: str):
        self._store.setValue("agent/address", value or "")

    @property
    def recordings_folder(self) -> str:
        """Where runs are recorded (default: ``recordings`` in Rockly's XDG data folder)."""
        return str(self._get("recordings/folder", "") or recordings_dir())

    @recordings_folder.setter
    def recordings_folder(self, value: str):
        self._store.setValue("recordings/folder", value or "")

    @property
    def recordings_kept(self) -> int:
        """How many recordings are kept (the oldest go); 20 by default, 0: runs are not recorded."""
        return _count(self._get("recordings/kept"), 20)

    @recordings_kept.setter
    def recordings_kept(self, value: int):
        self._store.setValue("recordings/kept", int(value))

    @property
    def recording_topic_rate(self) -> float:
        """At most this many messages a second of each robot topic are recorded; 10 by default."""
        try:
            rate = float(self._get("recordings/topic_rate", 10.0))
        except (TypeError, ValueError):
            return 10.0
        return rate if rate >= 0 else 10.0

    @recording_topic_rate.setter
    def recording_topic_rate(self, value: float):
        self._store.setValue("recordings/topic_rate", float(value))

    def sync(self):
        """Write to disk now."""
        self._store.sync()


def keep_private(file: Path, own_folder: bool) -> None:
    """Make the settings ``file`` readable by its owner only (0600), made empty if missing; its folder
    0700 when Rockly makes it or when it is Rockly's ``own_folder``. Failures are left to QSettings
    (a read-only home still starts Rockly)."""
    try:
        if not file.parent.exists():
            file.parent.mkdir(mode=0o700, parents=True)
        elif own_folder:
            os.chmod(file.parent, 0o700)
        os.close(os.open(file, os.O_WRONLY | os.O_CREAT | os.O_CLOEXEC, 0o600))
        os.chmod(file, 0o600)
    except OSError:
        pass


def _count(value, default: int) -> int:
    try:
        number = int(value)
    except (TypeError, ValueError):
        return default
    return number if number >= 0 else default
