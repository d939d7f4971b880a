"""What Rockly remembers between starts: layout, language, profile, last and recent files."""
from PySide6.QtCore import QSettings

from rockly_desktop.core.app_texts import languages
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

    def ros_connection(self, profile_id: str):
        """The ROS master URI and host remembered for a robot profile: (uri or None, host or None)."""
        return self._get(f"ros/{profile_id}/master") or None, self._get(f"ros/{profile_id}/host") or None

    def remember_ros_connection(self, profile_id: str, master_uri: str, host: str):
        """Remember how to reach this robot over ROS."""
        self._store.setValue(f"ros/{profile_id}/master", master_uri)
        self._store.setValue(f"ros/{profile_id}/host", host or "")

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

    def sync(self):
        """Write to disk now."""
        self._store.sync()
