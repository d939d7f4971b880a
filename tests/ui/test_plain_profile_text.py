"""A profile's name and labels are shown as written, never rendered as HTML (an image, a link, a style)."""
from profile_copies import copy_profile
from PySide6 import QtGui
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel
from window_tools import WindowDriver

from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.docks.state_panels import StatePanels
from rockly_desktop.ui.plain_text import tooltip_text
from rockly_desktop.ui.preferences.preferences import PreferencesDialog

HOSTILE = "<b>X</b><img src=file:///etc/hostname>"
PIN = "2580"


def shown_as_written(label: QLabel) -> bool:
    """True when ``label`` draws its text as it is (not as HTML)."""
    return label.textFormat() == Qt.TextFormat.PlainText or (
        label.textFormat() == Qt.TextFormat.AutoText and not QtGui.Qt.mightBeRichText(label.text()))


def labels_with(root, text: str) -> list:
    return [label for label in root.findChildren(QLabel) if text in label.text()]


def hostile_profile(tmp_path):
    copy = copy_profile(tmp_path / "profiles" / "html_hobbit", "html_hobbit")
    # its Python package under a name of its own: HOBBIT's may be imported already
    (copy.root / "rockly_hobbit").rename(copy.root / "rockly_html_hobbit")

    def change(data):
        for key in ("api", "simulator", "simulator_view"):
            data[key] = data[key].replace("rockly_hobbit", "rockly_html_hobbit")
        data["name"] = HOSTILE
        data["state"][0]["panel"] = {"en": f"{HOSTILE} panel"}
        data["state"][0]["rows"][0]["label"] = {"en": f"{HOSTILE} row"}
        data["capabilities"][0]["name"] = {"en": f"{HOSTILE} & arm"}
    copy.edit("profile.yaml", change)
    return tmp_path / "profiles"


def test_a_profiles_html_name_and_labels_show_as_literal_text(qtbot, tmp_path):
    profiles = hostile_profile(tmp_path)
    settings = AppSettings(tmp_path / "settings.ini")
    settings.profile_id = "html_hobbit"
    settings.teacher.set_pin(PIN)
    settings.sync()
    driver = WindowDriver(qtbot, tmp_path / "settings.ini", [profiles])
    try:
        window = driver.open_window()
        assert window.profile.id == "html_hobbit"

        status = labels_with(window.statusBar(), HOSTILE)
        assert [label.text() for label in status] == [f"Robot: {HOSTILE}"]
        assert all(shown_as_written(label) for label in status)

        qtbot.waitUntil(lambda: isinstance(window.state_dock.widget(), StatePanels), timeout=10000)
        panels = window.state_dock.widget()
        rows = labels_with(panels, HOSTILE)
        assert [label.text() for label in rows] == [f"{HOSTILE} row"]
        assert all(shown_as_written(label) for label in rows)
        value = panels.findChildren(QLabel, "state:/odom:pose.pose.position.x")[0]  # a robot's text, too
        assert value.textFormat() == Qt.TextFormat.PlainText

        robot_menu = [action.text() for action in window.profile_actions.actions()]
        assert f"{HOSTILE} (1.0.0)" in robot_menu

        dialog = PreferencesDialog("en", window, window.profile, window.settings.teacher)
        qtbot.addWidget(dialog)
        tab = dialog.teacher_tab
        tab.pin.setText(PIN)
        tab.unlock()
        assert tab.unlocked
        teacher = labels_with(tab, HOSTILE)
        assert [label.text() for label in teacher] == [f"Settings for {HOSTILE}"]
        assert all(shown_as_written(label) for label in teacher)
        assert tab.capability_boxes["arm"].text() == f"{HOSTILE} && arm"  # drawn as "& arm", no shortcut
    finally:
        driver.close_all()


def test_a_tool_tip_shows_html_like_text_as_written():
    document = QtGui.QTextDocument()
    document.setHtml(tooltip_text(f"{HOSTILE}\n& more"))
    assert document.toPlainText() == f"{HOSTILE}\n& more"
    assert tooltip_text("") == ""
