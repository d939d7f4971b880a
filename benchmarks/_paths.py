"""What a benchmark of the window or the executor sets up first (``from _paths import REPO``): Rockly
and its test helpers importable, Qt offscreen, QtWebEngine without its sandbox (as the tests run)."""
import os
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
for folder in (REPO / "tests", REPO):
    if str(folder) not in sys.path:
        sys.path.insert(0, str(folder))
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
os.environ.setdefault("QTWEBENGINE_DISABLE_SANDBOX", "1")
