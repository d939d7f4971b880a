"""The language Rockly speaks now, and its one owner."""
from rockly_desktop.core.app_texts import languages


class CurrentLanguage:
    """The language of the window, the blocks, the helpers' messages and Qt's own dialogs.

    Everything that speaks reads ``code`` here, so no copy can fall behind: the window changes it
    once (``code = …``, after the page gave its program) and every watcher is told. It is read
    from the settings ``store`` (a QSettings) when Rockly starts and written there on a change;
    another Rockly switching its language in the same file does not switch this one's half-way.
    """

    def __init__(self, store):
        self._store = store
        self._watchers = []
        self._code = _spoken(store.value("language", "en"))

    @property
    def code(self) -> str:
        """A language Rockly speaks ("en", "de")."""
        return self._code

    @code.setter
    def code(self, value: str):
        old, self._code = self._code, _spoken(value)
        self._store.setValue("language", value)
        if self._code != old:
            for watcher in list(self._watchers):
                watcher(self._code)

    def watch(self, watcher):
        """Call ``watcher(code)`` after every change from now on."""
        self._watchers.append(watcher)


def _spoken(code) -> str:
    """``code`` if Rockly speaks it, else English."""
    return str(code) if str(code) in languages() else "en"
