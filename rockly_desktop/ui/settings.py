"""What Rockly remembers between starts: layout, language, profile, last and recent files."""
from PySide6.QtCore import QSettings

from rockly_desktop.core.app_texts import languages
from rockly_desktop.core.paths import recordings_dir
from rockly_desktop.ui.teacher_settings import TeacherSettings

MAX_RECENT = 8


class AppSettings:
    """Typed access to Rockly's QSettings. ``path`` selects a settings file (tests use one)."""

    def __init__(self, path=None):
        if path is None:
            self._store = QSettings("Rockly", "Rockly")
        else:
            self._store = QSettings(str(path), QSettings.Format.IniFormat)
        self.language_watchers = []  # called with the new language when it changes

    def _get(self, key, default=None):
        value = self._store.value(key)
        return default if value is None else value

    @property
    def language(self) -> str:
        """The window and block language: one Rockly speaks (anything else stored reads as 'en')."""
        language = str(self._get("language", "en"))
        return language if language in languages() else "en"

    @language.setter
    def language(self, value: str):
        changed = value != self.language
        self._store.setValue("language", value)
        if changed:
            for watcher in list(self.language_watchers):
                watcher(self.language)

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
        value = self._get("recent_files", [])
        return [value] if isinstance(value, str) else list(value)

    def add_recent_file(self, path: str):
        """Put ``path`` at the top of the recent files (and remember it as the last file)."""
        files = [path] + [item for item in self.recent_files if item != path]
        self._store.setValue("recent_files", files[:MAX_RECENT])
        self.last_file = path

    def clear_recent_files(self):
        """Forget the recent files."""
        self._store.setValue("recent_files", [])

    @property
    def last_file(self):
        """The program that was open when Rockly last closed, or None."""
        return self._get("last_file") or None

    @last_file.setter
    def last_file(self, path):
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
    def reset_before_run(self) -> bool:
        """True when the simulated robot is put back before each Run (and on New and Open); off by default."""
        return str(self._get("reset_before_run", "false")).lower() == "true"

    @reset_before_run.setter
    def reset_before_run(self, value: bool):
        self._store.setValue("reset_before_run", "true" if value else "false")

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


def _count(value, default: int) -> int:
    try:
        number = int(value)
    except (TypeError, ValueError):
        return default
    return number if number >= 0 else default
