"""Main-window fixtures: a real window with the real editor page, settings in a temp file."""
import pytest
from PySide6.QtWidgets import QMessageBox
from window_tools import WindowDriver

from rockly_desktop.settings.app_settings import AppSettings
from rockly_desktop.ui.qt_language import use_language


@pytest.fixture
def driver(qtbot, tmp_path):
    driver = WindowDriver(qtbot, tmp_path / "settings.ini")
    yield driver
    driver.close_all()


@pytest.fixture
def window(driver):
    return driver.open_window()


@pytest.fixture
def german_window(driver):
    """A window started in German (as remembered from an earlier start)."""
    settings = AppSettings(driver.settings_path)
    settings.language = "de"
    settings.sync()
    return driver.open_window()


@pytest.fixture(autouse=True)
def qt_in_english_afterwards():
    """Qt's own texts are process-wide: a test that switched them to German leaves them English."""
    yield
    use_language("en")


@pytest.fixture
def answer_prompts(monkeypatch):
    """Answer the 'save changes?' question with the given button; records the questions asked."""
    asked = []

    def set_answer(button):
        def fake_exec(box):
            asked.append(box.text())
            return button
        monkeypatch.setattr(QMessageBox, "exec", fake_exec)
        return asked

    return set_answer
