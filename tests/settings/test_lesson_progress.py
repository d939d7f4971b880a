"""The lessons a person passed, kept in Rockly's settings file; a kiosk visitor's never written."""
from PySide6.QtCore import QSettings

from rockly_desktop.settings.app_settings import AppSettings


def test_passed_lessons_are_kept_for_the_next_start(tmp_path):
    settings = AppSettings(tmp_path / "settings.ini")
    assert not settings.lessons.passed("hobbit-smile")
    settings.lessons.mark_passed("hobbit-smile")
    settings.sync()
    assert AppSettings(tmp_path / "settings.ini").lessons.passed("hobbit-smile")  # a list of one reads back too
    settings.lessons.mark_passed("turtlebot-square")
    settings.lessons.mark_passed("hobbit-smile")
    settings.sync()
    again = AppSettings(tmp_path / "settings.ini")
    assert again.lessons.passed("hobbit-smile") and again.lessons.passed("turtlebot-square")
    assert not again.lessons.passed("hobbit-greet")


def test_a_kiosk_visitors_progress_is_never_written_and_goes_with_them(tmp_path):
    settings = AppSettings(tmp_path / "settings.ini")
    settings.kiosk_mode = True
    settings.lessons.mark_passed("hobbit-smile")
    assert settings.lessons.passed("hobbit-smile")
    settings.sync()
    assert QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat).value("lessons/passed") is None
    settings.lessons.forget_visitor()
    assert not settings.lessons.passed("hobbit-smile")


def test_the_challenge_of_the_day_is_a_kiosk_setting(tmp_path):
    settings = AppSettings(tmp_path / "settings.ini")
    assert settings.kiosk.challenge == ""
    settings.kiosk.challenge = "hobbit-smile"
    settings.sync()
    assert AppSettings(tmp_path / "settings.ini").kiosk.challenge == "hobbit-smile"
