"""Keeps the editor page offline: only local files, Qt resources and inline data load."""
from PySide6.QtWebEngineCore import QWebEngineUrlRequestInterceptor

LOCAL_SCHEMES = frozenset({"file", "qrc", "data", "blob", "about"})


class LocalOnlyInterceptor(QWebEngineUrlRequestInterceptor):
    """Blocks every request that would leave the machine and remembers it.

    ``requested`` lists every URL asked for; ``blocked`` the ones refused.
    """

    def __init__(self, parent=None):
        super().__init__(parent)
        self.requested = []
        self.blocked = []

    def interceptRequest(self, info):
        """Qt override: let local requests through, block the rest."""
        url = info.requestUrl()
        self.requested.append(url.toString())
        if url.scheme() not in LOCAL_SCHEMES:
            self.blocked.append(url.toString())
            info.block(True)
