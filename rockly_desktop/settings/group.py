"""A group of keys in Rockly's settings file (the teacher's, the kiosk's)."""


class SettingsGroup:
    """The keys under ``prefix/`` in Rockly's QSettings ``store``; an empty value reads as none."""

    prefix = ""

    def __init__(self, store):
        self._store = store

    def _get(self, key, default=None):
        value = self._store.value(f"{self.prefix}/{key}")
        return default if value is None or value == "" else value

    def _set(self, key, value):
        self._store.setValue(f"{self.prefix}/{key}", value)
