"""The language Rockly speaks has one owner (``settings.language.CurrentLanguage``): remembered for the
next start, told to its watchers once per change, and not switched half-way by another Rockly."""
from rockly_desktop.settings.app_settings import AppSettings


def test_the_language_is_remembered_for_the_next_start_and_one_rockly_does_not_speak_reads_as_english(tmp_path):
    settings = AppSettings(tmp_path / "settings.ini")
    assert settings.language == settings.current_language.code == "en"
    settings.language = "de"
    settings.sync()
    assert AppSettings(tmp_path / "settings.ini").current_language.code == "de"
    (tmp_path / "other.ini").write_text("[General]\nlanguage=tlh\n")
    assert AppSettings(tmp_path / "other.ini").language == "en"


def test_watchers_hear_each_change_once_and_nothing_when_it_stays(tmp_path):
    language = AppSettings(tmp_path / "settings.ini").current_language
    heard = []
    language.watch(heard.append)
    language.code = "de"
    language.code = "de"
    language.code = "en"
    language.code = "tlh"  # not spoken: English, as it already was
    assert heard == ["de", "en"]


def test_another_rockly_switching_its_language_leaves_this_ones_as_it_is(tmp_path):
    """Two Rocklys on one settings file: each speaks its own language until it switches itself."""
    this, other = AppSettings(tmp_path / "settings.ini"), AppSettings(tmp_path / "settings.ini")
    other.language = "de"
    other.sync()
    this.sync()
    assert this.language == "en"
    assert AppSettings(tmp_path / "settings.ini").language == "de"  # the next start speaks the last one chosen
