"""The tabs of docks sharing a side of the window show their titles whole on a 1280×800 screen, in English and
German, even when the person drags the docks' edge as far as it goes ("Lessons", never "Less…"); the blocks
keep their room. (A window of its own on a screen of that size: the tests' screen is smaller.)"""
import json
import os
import subprocess
import sys

import pytest
from window_tools import one_screen_platform

from rockly_desktop.settings.app_settings import AppSettings

RIGHT_TABS = {"en": ["Python code", "Variables", "Robot state", "Lessons"],
              "de": ["Python-Code", "Variablen", "Roboterzustand", "Lektionen"]}

DRAGGED_NARROW = """
import json, sys
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QTabBar
app = QApplication([])
from rockly_desktop.app import build_main_window
window = build_main_window(sys.argv[1])
window.show()
window.lessons_dock.show()
window.lessons_dock.raise_()
app.processEvents()
window.resizeDocks([window.lessons_dock], [100], Qt.Orientation.Horizontal)  # the edge dragged to the right
for _ in range(5):
    app.processEvents()
bars = [bar for bar in window.findChildren(QTabBar, options=Qt.FindChildOption.FindDirectChildrenOnly)
        if bar.isVisible()]
print(json.dumps({"tabs": [[{"title": bar.tabText(i), "width": bar.tabRect(i).width(),
                             "whole": bar.tabSizeHint(i).width()} for i in range(bar.count())] for bar in bars],
                  "window": window.width(), "editor": window.editor.width()}))
window.document.modified = False
window.close()
"""


@pytest.mark.parametrize("language", ["en", "de"])
def test_dock_tabs_show_whole_titles_at_1280x800_however_narrow_the_docks_are_dragged(tmp_path, language):
    settings = AppSettings(tmp_path / "settings.ini")
    settings.language = language
    settings.sync()
    script = tmp_path / "dragged_narrow.py"
    script.write_text(DRAGGED_NARROW)
    env = dict(os.environ, QT_QPA_PLATFORM=one_screen_platform(tmp_path, 1280, 800), QTWEBENGINE_DISABLE_SANDBOX="1")
    done = subprocess.run([sys.executable, str(script), str(tmp_path / "settings.ini")], env=env, timeout=120,
                          capture_output=True, text=True, check=True)
    shown = json.loads(done.stdout.strip().splitlines()[-1])
    [right] = [bar for bar in shown["tabs"] if bar[0]["title"] == RIGHT_TABS[language][0]]
    assert [tab["title"] for tab in right] == RIGHT_TABS[language]
    squeezed = [tab["title"] for bar in shown["tabs"] for tab in bar if tab["width"] < tab["whole"]]
    assert squeezed == [], shown   # Qt elides a tab with less room than its whole title needs
    assert shown["window"] >= 1270 and shown["editor"] >= 700, shown   # the window fits; the blocks keep room
